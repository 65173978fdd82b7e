# One of each kind of error the parser reports.
Sphere 0 0 0 1
sphere 0 0 0 -1
sphere 0 0 0 0
sphere 0 0 nan 1
sphere 0 0 inf 1
sphere 1 2
surface 1 1 1 1 0 0 1 0
surface -1 1 1 1 0 0 1 1
polygon 2 0 0 0 1 1 1
polygon 3 0 0 0 1 1 1 2 2 2
polygon 3 0 0 0 1 0 0 0 1
polygon x
cone 0 0 0 1 0 0 0 1
cone 0 0 0 -1 0 1 0 1
torus 0 0 0 0 0 0 1 0.5
torus 0 0 0 0 0 1 1 1
torus 0 0 0 0 0 1 0 0.5
blob 0 1  0 0 0 1 1
blob 0.5 2  0 0 0 0 1  1 0 0 1 0
blob 1 1  0 0 0 1 -2
blob 0.5 3  0 0 0 1 1
ptriangle 0 0 0 0 0 0 1 0 0 0 0 1 0 1 0 0 0 1
triangle 0 0 0 1 1 1 2 2 2
scale 0 1 1
rotate 0 0 0 45
resolution 0 100000
resolution 10 10
fov 180
fov 0
eye 0 0 0
lookat 0 0 0
up 0 1 0
pop
push
12 34
quadric 0 0 0 0 0 0 0 0 0 1  -1 -1 -1  1 1 1
quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 -1 1
quadric 1 1 1 0 0 0 0 0 0 nan  -1 -1 -1  1 1
