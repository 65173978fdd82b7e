# Quadrics clipped by boxes, plain, under transforms and malformed.
eye 0 2 8
light -5 8 6  1 1 1
surface 0.8 0.2 0.2  0.7 0.3 0  20 1
quadric 1 1 0 0 0 0 0 0 -1 0  -1 -1 0  1 1 1
quadric 1 1 -1 0 0.5 0 0 0 0 -0.25  -2 -2 -2  2 2 2
push
  translate 0 2 0
  rotate 1 2 3 30
  scale 1 0.5 2
  quadric 0.25 1 0 0 0 0 0 0 0 -1  -3 -2 0  3 2 1
  quadric 1e-200 2e-200 0 3e-200 0 0 0 0 -1e-200 0  1 1 1  -1 -1 -1
pop
lookat 0 0 0
up 0 1 0
quadric 1 1 -1 0 0 0 0 0 0 0  -1 -1 -1  1 1 1
push scale 1 1 1e-11 quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1 pop
quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  2e30 1 1
quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1 2
