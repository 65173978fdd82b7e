# Refraction, mirrors and total internal reflection: deep ray trees.
eye 0 0 6
ambient 0.1 0.1 0.1
light 2 5 5 1 1 1
surface 1 1 1  0.05 0.1 0.9  80 1.5
sphere 0 0 0 1
surface 1 1 1  0 1 0  100 1
polygon 4  -3 -3 -2  3 -3 -2  3 3 -2  -3 3 -2
surface 0.9 0.9 1  0 0.2 0.8  10 2.4
sphere 0.3 0.2 0.5 0.3
surface 1 1 1  0.1 0.1 1  5 0.7
cone 1.5 -1 0 0.4  1.5 1 0 0.4
