# The closed solids and the disc, plain and under transforms.
eye 0 2 8
light -5 8 6  1 1 1
surface 0.8 0.2 0.2  0.7 0.3 0  20 1
box -1 0 -1  1 1 1
disc 0 0 0  0 1 0  3
cylinder 2 0 0  2 2 0  0.5
capped_cone -2 0 0 0.6  -2 1.5 0 0
push
  translate 0 2 0
  rotate 1 2 3 30
  scale 1 0.5 2
  box 0 0 0  1 1 1
  disc 0 0 0  1 1 0  1
  capped_cone 0 0 0 1  0 0 1 0.4
pop
