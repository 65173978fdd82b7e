# Every command once, the way the docs write them.
resolution 64 48
eye 0 2 8
lookat 0 0.5 0
up 0 1 0
fov 40
background 0.1 0.1 0.2
ambient 0.2 0.2 0.2
light -5 8 6  1 1 1
light 4 3 5  0.4 0.3 0.2
surface 0.8 0.2 0.2  0.7 0.3 0  20 1
sphere 0 1 0 1
surface 0.5 0.5 0.5  1 0 0  1 1
polygon 4  -5 0 -5  -5 0 5  5 0 5  5 0 -5
surface 0.2 0.6 0.9  0.6 0.4 0  40 1
cone -2 0 0 0.5  -2 2 0 0
cone 2 0 0 0.6  2 1.5 0 0.3
triangle -1 0 2  1 0 2  0 1.5 2
ptriangle 2 0 2  0 0 1  3 0 2  0.3 0 1  2.5 1 2  0 0.3 1
