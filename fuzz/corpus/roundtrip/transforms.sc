# push/pop with every transform; a non-uniform scale makes an ellipsoid and an
# elliptic cone, a stretched torus and a stretched blob, a negative one mirrors.
eye 3 4 9
light 0 10 10 1 1 1
push
  translate 1 0 0
  rotate 0 1 0 30
  scale 1 2 0.5
  surface 1 0.8 0.2  0.5 0.5 0  30 1
  sphere 0 0 0 1
  cone 0 -1 0 1  0 1 0 0.2
  torus 0 1 0  1 1 0  0.8 0.2
  blob 0.5 2  0 0 0 1 1  0.8 0 0 0.6 1.5
  push
    scale -1 1 1
    polygon 3  0 0 0  1 0 0  0 1 0
    triangle 0 0 1  1 0 1  0 1 1
    ptriangle 0 0 2  0 0 1  1 0 2  0 0 1  0 1 2  0 0 1
  pop
pop
push
  rotate 1 1 1 -45
  translate -2 0 0
  scale 0.001 0.001 0.001
  sphere 0 0 0 500
pop
sphere 0 -1001 0 1000
