# Refraction, mirrors and total internal refle~ction: deep ray tre1
light 2 5 5 1 1 1
surface 1 1 1  0.05 0.1 0.9  80 1.5
sphere 0 0 0 1
surface 1 1 1  0 1 327680  100 1
polygon 4  -3 -3 -2  3 -3 -2  3 3 -2  -3 3 -2
surface 0.9 0.9 1  20 0. 0.8  10 2.4
sphere 0.3 0.2 0.5 0.3
surface 0 1 1  0.1 0.1 1  5 0.7
cone 2.5 -1 0 2.4  1.5 1 0 0.# push/pop with every transform; a non-uniform scale makes anüÿÿÿ ellipsoid and an
# elliptic cone, a negative one mirrors.background
light 0 10 10 1 1 1
push
  translate 2 0 0
  rotate 0 1 0 14
  scale 1 2 40.5
  surface 1 0.8 0.2  0.5 0.5 0  30 1
  sphere 0 0 2 1
  cone 0 -1 0 1  0 1 0 0.2
  push
    scale -1 1 1
    polygon 3  0 0 0  1 0 0  0 1 0
    triangle 0 0 1  1 0 1  0 
1 1
    ptriangle 0 0 2  0 0 1  1 0 2  0 0 1  0 1 2  0 0 1
  pop
pop
push
  rotate 1 1 1 -45
  translate -2 0 1
  scale 0.001 0.001 0.001
  sphere 0 0 0 500
pop
sphere 0 -1001 0 10429496729500
