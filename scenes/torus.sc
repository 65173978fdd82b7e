# torus.sc -- a chain of interlocked tori: five links of alternating chrome
# and clear glass, hovering over a checker floor, with a gold ring lying on
# the floor behind them.
#
# Each link has major radius 1 and minor radius 0.22; neighbours are 1.45
# apart along the chain, one standing in the chain's plane, the next lying
# across it, so each passes through the other's hole with 0.11 to spare.
# The glass links show the chrome ones and the floor refracted through the
# tube, and the inner rims, where rays graze the surface, stay free of
# speckles (the quartic's crossings are isolated between its critical
# points: docs/rendering-model.md#tori). Depth >= 5 for the glass.

resolution 512 384
eye 0 3.4 9.5
lookat 0 1.1 0
up 0 1 0
fov 40

background 0.08 0.09 0.12
ambient 0.1 0.1 0.1

light -5 9 7    100 100 100
light 6 7 4     60 60 65
light 0 6 -6    25 25 25      # behind: rims on the glass

# ---------------------------------------------------------------- floor: a
# checker of 1.5-unit squares, warm grey and dark slate
push
  surface 0.75 0.72 0.66  0.8 0.2 0  40 1
  polygon 4  -9 0 -7.5  -7.5 0 -7.5  -7.5 0 -9  -9 0 -9
  polygon 4  -9 0 -4.5  -7.5 0 -4.5  -7.5 0 -6  -9 0 -6
  polygon 4  -9 0 -1.5  -7.5 0 -1.5  -7.5 0 -3  -9 0 -3
  polygon 4  -9 0 1.5  -7.5 0 1.5  -7.5 0 0  -9 0 0
  polygon 4  -9 0 4.5  -7.5 0 4.5  -7.5 0 3  -9 0 3
  polygon 4  -7.5 0 -6  -6 0 -6  -6 0 -7.5  -7.5 0 -7.5
  polygon 4  -7.5 0 -3  -6 0 -3  -6 0 -4.5  -7.5 0 -4.5
  polygon 4  -7.5 0 0  -6 0 0  -6 0 -1.5  -7.5 0 -1.5
  polygon 4  -7.5 0 3  -6 0 3  -6 0 1.5  -7.5 0 1.5
  polygon 4  -7.5 0 6  -6 0 6  -6 0 4.5  -7.5 0 4.5
  polygon 4  -6 0 -7.5  -4.5 0 -7.5  -4.5 0 -9  -6 0 -9
  polygon 4  -6 0 -4.5  -4.5 0 -4.5  -4.5 0 -6  -6 0 -6
  polygon 4  -6 0 -1.5  -4.5 0 -1.5  -4.5 0 -3  -6 0 -3
  polygon 4  -6 0 1.5  -4.5 0 1.5  -4.5 0 0  -6 0 0
  polygon 4  -6 0 4.5  -4.5 0 4.5  -4.5 0 3  -6 0 3
  polygon 4  -4.5 0 -6  -3 0 -6  -3 0 -7.5  -4.5 0 -7.5
  polygon 4  -4.5 0 -3  -3 0 -3  -3 0 -4.5  -4.5 0 -4.5
  polygon 4  -4.5 0 0  -3 0 0  -3 0 -1.5  -4.5 0 -1.5
  polygon 4  -4.5 0 3  -3 0 3  -3 0 1.5  -4.5 0 1.5
  polygon 4  -4.5 0 6  -3 0 6  -3 0 4.5  -4.5 0 4.5
  polygon 4  -3 0 -7.5  -1.5 0 -7.5  -1.5 0 -9  -3 0 -9
  polygon 4  -3 0 -4.5  -1.5 0 -4.5  -1.5 0 -6  -3 0 -6
  polygon 4  -3 0 -1.5  -1.5 0 -1.5  -1.5 0 -3  -3 0 -3
  polygon 4  -3 0 1.5  -1.5 0 1.5  -1.5 0 0  -3 0 0
  polygon 4  -3 0 4.5  -1.5 0 4.5  -1.5 0 3  -3 0 3
  polygon 4  -1.5 0 -6  0 0 -6  0 0 -7.5  -1.5 0 -7.5
  polygon 4  -1.5 0 -3  0 0 -3  0 0 -4.5  -1.5 0 -4.5
  polygon 4  -1.5 0 0  0 0 0  0 0 -1.5  -1.5 0 -1.5
  polygon 4  -1.5 0 3  0 0 3  0 0 1.5  -1.5 0 1.5
  polygon 4  -1.5 0 6  0 0 6  0 0 4.5  -1.5 0 4.5
  polygon 4  0 0 -7.5  1.5 0 -7.5  1.5 0 -9  0 0 -9
  polygon 4  0 0 -4.5  1.5 0 -4.5  1.5 0 -6  0 0 -6
  polygon 4  0 0 -1.5  1.5 0 -1.5  1.5 0 -3  0 0 -3
  polygon 4  0 0 1.5  1.5 0 1.5  1.5 0 0  0 0 0
  polygon 4  0 0 4.5  1.5 0 4.5  1.5 0 3  0 0 3
  polygon 4  1.5 0 -6  3 0 -6  3 0 -7.5  1.5 0 -7.5
  polygon 4  1.5 0 -3  3 0 -3  3 0 -4.5  1.5 0 -4.5
  polygon 4  1.5 0 0  3 0 0  3 0 -1.5  1.5 0 -1.5
  polygon 4  1.5 0 3  3 0 3  3 0 1.5  1.5 0 1.5
  polygon 4  1.5 0 6  3 0 6  3 0 4.5  1.5 0 4.5
  polygon 4  3 0 -7.5  4.5 0 -7.5  4.5 0 -9  3 0 -9
  polygon 4  3 0 -4.5  4.5 0 -4.5  4.5 0 -6  3 0 -6
  polygon 4  3 0 -1.5  4.5 0 -1.5  4.5 0 -3  3 0 -3
  polygon 4  3 0 1.5  4.5 0 1.5  4.5 0 0  3 0 0
  polygon 4  3 0 4.5  4.5 0 4.5  4.5 0 3  3 0 3
  polygon 4  4.5 0 -6  6 0 -6  6 0 -7.5  4.5 0 -7.5
  polygon 4  4.5 0 -3  6 0 -3  6 0 -4.5  4.5 0 -4.5
  polygon 4  4.5 0 0  6 0 0  6 0 -1.5  4.5 0 -1.5
  polygon 4  4.5 0 3  6 0 3  6 0 1.5  4.5 0 1.5
  polygon 4  4.5 0 6  6 0 6  6 0 4.5  4.5 0 4.5
  polygon 4  6 0 -7.5  7.5 0 -7.5  7.5 0 -9  6 0 -9
  polygon 4  6 0 -4.5  7.5 0 -4.5  7.5 0 -6  6 0 -6
  polygon 4  6 0 -1.5  7.5 0 -1.5  7.5 0 -3  6 0 -3
  polygon 4  6 0 1.5  7.5 0 1.5  7.5 0 0  6 0 0
  polygon 4  6 0 4.5  7.5 0 4.5  7.5 0 3  6 0 3
  polygon 4  7.5 0 -6  9 0 -6  9 0 -7.5  7.5 0 -7.5
  polygon 4  7.5 0 -3  9 0 -3  9 0 -4.5  7.5 0 -4.5
  polygon 4  7.5 0 0  9 0 0  9 0 -1.5  7.5 0 -1.5
  polygon 4  7.5 0 3  9 0 3  9 0 1.5  7.5 0 1.5
  polygon 4  7.5 0 6  9 0 6  9 0 4.5  7.5 0 4.5
  surface 0.2 0.22 0.26  0.8 0.2 0  40 1
  polygon 4  -9 0 -6  -7.5 0 -6  -7.5 0 -7.5  -9 0 -7.5
  polygon 4  -9 0 -3  -7.5 0 -3  -7.5 0 -4.5  -9 0 -4.5
  polygon 4  -9 0 0  -7.5 0 0  -7.5 0 -1.5  -9 0 -1.5
  polygon 4  -9 0 3  -7.5 0 3  -7.5 0 1.5  -9 0 1.5
  polygon 4  -9 0 6  -7.5 0 6  -7.5 0 4.5  -9 0 4.5
  polygon 4  -7.5 0 -7.5  -6 0 -7.5  -6 0 -9  -7.5 0 -9
  polygon 4  -7.5 0 -4.5  -6 0 -4.5  -6 0 -6  -7.5 0 -6
  polygon 4  -7.5 0 -1.5  -6 0 -1.5  -6 0 -3  -7.5 0 -3
  polygon 4  -7.5 0 1.5  -6 0 1.5  -6 0 0  -7.5 0 0
  polygon 4  -7.5 0 4.5  -6 0 4.5  -6 0 3  -7.5 0 3
  polygon 4  -6 0 -6  -4.5 0 -6  -4.5 0 -7.5  -6 0 -7.5
  polygon 4  -6 0 -3  -4.5 0 -3  -4.5 0 -4.5  -6 0 -4.5
  polygon 4  -6 0 0  -4.5 0 0  -4.5 0 -1.5  -6 0 -1.5
  polygon 4  -6 0 3  -4.5 0 3  -4.5 0 1.5  -6 0 1.5
  polygon 4  -6 0 6  -4.5 0 6  -4.5 0 4.5  -6 0 4.5
  polygon 4  -4.5 0 -7.5  -3 0 -7.5  -3 0 -9  -4.5 0 -9
  polygon 4  -4.5 0 -4.5  -3 0 -4.5  -3 0 -6  -4.5 0 -6
  polygon 4  -4.5 0 -1.5  -3 0 -1.5  -3 0 -3  -4.5 0 -3
  polygon 4  -4.5 0 1.5  -3 0 1.5  -3 0 0  -4.5 0 0
  polygon 4  -4.5 0 4.5  -3 0 4.5  -3 0 3  -4.5 0 3
  polygon 4  -3 0 -6  -1.5 0 -6  -1.5 0 -7.5  -3 0 -7.5
  polygon 4  -3 0 -3  -1.5 0 -3  -1.5 0 -4.5  -3 0 -4.5
  polygon 4  -3 0 0  -1.5 0 0  -1.5 0 -1.5  -3 0 -1.5
  polygon 4  -3 0 3  -1.5 0 3  -1.5 0 1.5  -3 0 1.5
  polygon 4  -3 0 6  -1.5 0 6  -1.5 0 4.5  -3 0 4.5
  polygon 4  -1.5 0 -7.5  0 0 -7.5  0 0 -9  -1.5 0 -9
  polygon 4  -1.5 0 -4.5  0 0 -4.5  0 0 -6  -1.5 0 -6
  polygon 4  -1.5 0 -1.5  0 0 -1.5  0 0 -3  -1.5 0 -3
  polygon 4  -1.5 0 1.5  0 0 1.5  0 0 0  -1.5 0 0
  polygon 4  -1.5 0 4.5  0 0 4.5  0 0 3  -1.5 0 3
  polygon 4  0 0 -6  1.5 0 -6  1.5 0 -7.5  0 0 -7.5
  polygon 4  0 0 -3  1.5 0 -3  1.5 0 -4.5  0 0 -4.5
  polygon 4  0 0 0  1.5 0 0  1.5 0 -1.5  0 0 -1.5
  polygon 4  0 0 3  1.5 0 3  1.5 0 1.5  0 0 1.5
  polygon 4  0 0 6  1.5 0 6  1.5 0 4.5  0 0 4.5
  polygon 4  1.5 0 -7.5  3 0 -7.5  3 0 -9  1.5 0 -9
  polygon 4  1.5 0 -4.5  3 0 -4.5  3 0 -6  1.5 0 -6
  polygon 4  1.5 0 -1.5  3 0 -1.5  3 0 -3  1.5 0 -3
  polygon 4  1.5 0 1.5  3 0 1.5  3 0 0  1.5 0 0
  polygon 4  1.5 0 4.5  3 0 4.5  3 0 3  1.5 0 3
  polygon 4  3 0 -6  4.5 0 -6  4.5 0 -7.5  3 0 -7.5
  polygon 4  3 0 -3  4.5 0 -3  4.5 0 -4.5  3 0 -4.5
  polygon 4  3 0 0  4.5 0 0  4.5 0 -1.5  3 0 -1.5
  polygon 4  3 0 3  4.5 0 3  4.5 0 1.5  3 0 1.5
  polygon 4  3 0 6  4.5 0 6  4.5 0 4.5  3 0 4.5
  polygon 4  4.5 0 -7.5  6 0 -7.5  6 0 -9  4.5 0 -9
  polygon 4  4.5 0 -4.5  6 0 -4.5  6 0 -6  4.5 0 -6
  polygon 4  4.5 0 -1.5  6 0 -1.5  6 0 -3  4.5 0 -3
  polygon 4  4.5 0 1.5  6 0 1.5  6 0 0  4.5 0 0
  polygon 4  4.5 0 4.5  6 0 4.5  6 0 3  4.5 0 3
  polygon 4  6 0 -6  7.5 0 -6  7.5 0 -7.5  6 0 -7.5
  polygon 4  6 0 -3  7.5 0 -3  7.5 0 -4.5  6 0 -4.5
  polygon 4  6 0 0  7.5 0 0  7.5 0 -1.5  6 0 -1.5
  polygon 4  6 0 3  7.5 0 3  7.5 0 1.5  6 0 1.5
  polygon 4  6 0 6  7.5 0 6  7.5 0 4.5  6 0 4.5
  polygon 4  7.5 0 -7.5  9 0 -7.5  9 0 -9  7.5 0 -9
  polygon 4  7.5 0 -4.5  9 0 -4.5  9 0 -6  7.5 0 -6
  polygon 4  7.5 0 -1.5  9 0 -1.5  9 0 -3  7.5 0 -3
  polygon 4  7.5 0 1.5  9 0 1.5  9 0 0  7.5 0 0
  polygon 4  7.5 0 4.5  9 0 4.5  9 0 3  7.5 0 3
pop

# ---------------------------------------------------------------- the chain
# Along x in its own frame, turned to recede to the right and tilted so that
# it rises from left to right.
push
  translate 0 1.5 0.5
  rotate 0 1 0 -20
  rotate 0 0 1 10
  # chrome, standing: the ring in the chain's plane (axis z)
  surface 0.75 0.75 0.78  0.25 0.7 0  200 1
  torus -2.9 0 0  0 0 1  1 0.22
  torus  0   0 0  0 0 1  1 0.22
  torus  2.9 0 0  0 0 1  1 0.22
  # clear glass, lying across it (axis y)
  surface 0.9 0.95 1  0.05 0.15 0.8  200 1.5
  torus -1.45 0 0  0 1 0  1 0.22
  torus  1.45 0 0  0 1 0  1 0.22
pop

# ---------------------------------------------------------------- a gold ring
# lying on the floor, behind on the left
surface 1 0.75 0.3  0.6 0.35 0  80 1
torus -3.2 0.3 -2.8  0 1 0  1.2 0.3
