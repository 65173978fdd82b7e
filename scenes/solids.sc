# solids.sc -- the closed solids: boxes, capped cylinders and cones, discs.
#
# What to look for:
#  * a stack of boxes, the upper ones turned (rotated boxes are any
#    parallelepiped: the top one is sheared by a scale after a rotation);
#  * a glass cylinder refracting the checker of boxes behind it, closed by
#    its caps (a ray inside it leaves through the side or a cap);
#  * a chrome frustum and a pointed gold cone, capped at their bases;
#  * discs: a coaster under the glass cylinder and a round mirror, tilted to
#    show the floor, in a cylinder's frame.
#
# Units: roughly decimetres. Floor y = 0, back wall z = -6.

resolution 640 480
eye 2.0 5.5 11.0
lookat 0 1.6 0
up 0 1 0
fov 38

background 0.04 0.04 0.06
ambient 0.08 0.08 0.08

light -6 9 6      90 88 80     # key light, upper left front
light 6 7 3       45 48 55     # fill from the right, cool
light 0 9 -3      30 30 30     # behind, for rims on the glass

# ---------------------------------------------------------------- the room
push
  # floor: one large flat box, slightly glossy
  surface 0.6 0.55 0.5  0.9 0.1 0  20 1
  box -20 -0.5 -6  20 0 20
  # back wall
  surface 0.7 0.72 0.78  0.9 0 0  1 1
  box -20 0 -6.5  20 12 -6
pop

# ---------------------------------------------------------------- a round mirror, tilted down
push
  translate 3.0 3.7 -5.4
  rotate 1 0 0 22
  # the frame: a short dark cylinder; the mirror: a disc just in front of it
  surface 0.2 0.15 0.1  0.8 0.1 0  30 1
  cylinder 0 0 -0.12  0 0 0  1.3
  surface 0.9 0.9 0.92  0.05 0.9 0  200 1
  disc 0 0 0.01  0 0 1  1.15
pop

# ---------------------------------------------------------------- a row of blocks behind the glass
push
  translate -1 0 -3.5
  surface 0.85 0.2 0.15  0.8 0.2 0  40 1
  box -1.8 0 0  -1.0 0.8 0.8
  box -0.2 0 0   0.6 0.8 0.8
  box  1.4 0 0   2.2 0.8 0.8
  surface 0.95 0.9 0.85  0.8 0.2 0  40 1
  box -1.0 0 0  -0.2 0.8 0.8
  box  0.6 0 0   1.4 0.8 0.8
pop

# ---------------------------------------------------------------- a stack of boxes, turning
push
  translate -3.6 0 0
  surface 0.25 0.45 0.8  0.8 0.3 0  60 1
  box -1 0 -1  1 1 1
  push
    translate 0 1 0
    rotate 0 1 0 25
    surface 0.95 0.75 0.2  0.8 0.3 0  60 1
    box -0.75 0 -0.75  0.75 0.8 0.75
    push
      translate 0 0.8 0
      rotate 0 1 0 25
      scale 1 1 0.6
      rotate 0 0 1 20
      surface 0.3 0.7 0.35  0.8 0.3 0  60 1
      box -0.45 0 -0.45  0.45 0.9 0.45
    pop
  pop
pop

# ---------------------------------------------------------------- a glass cylinder on a coaster
push
  translate 0.2 0 0.8
  surface 0.25 0.2 0.18  0.9 0.1 0  20 1
  disc 0 0.002 0  0 1 0  1.25
  surface 1 1 1  0 0.1 0.9  200 1.5
  cylinder 0 0.004 0  0 2.6 0  0.9
pop

# ---------------------------------------------------------------- cones
push
  translate 3.3 0 0.2
  # a chrome frustum
  surface 0.9 0.9 0.92  0.15 0.8 0  300 1
  capped_cone 0 0 0 1.1  0 1.6 0 0.55
  # a pointed gold cone standing on it
  surface 0.95 0.7 0.25  0.5 0.5 0  120 1
  capped_cone 0 1.6 0 0.5  0 3.1 0 0
pop
push
  # a cone lying on its side in front
  translate 1.8 0.502 3.2
  rotate 0 1 0 -35
  surface 0.55 0.25 0.65  0.8 0.3 0  60 1
  capped_cone -0.8 0 0 0.5  0.8 0 0 0.2
pop
