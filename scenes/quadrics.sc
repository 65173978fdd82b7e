# quadrics.sc -- a gallery of quadric surfaces, each clipped by a box:
#   quadric A B C D E F G H I J  X0 Y0 Z0  X1 Y1 Z1
# is A x^2 + B y^2 + C z^2 + D xy + E yz + F xz + G x + H y + I z + J = 0
# inside the box, in coordinates the current transform places. Each shape
# here is written around its own z axis and stood up by `rotate 1 0 0 -90`.
#
# What to look for:
#  * a gold paraboloid dish with a light at its focus: the inside of the
#    dish glows evenly, its rim is a circle where the clip box cuts it;
#  * a hyperboloid cooling tower, narrowest near its top, its inside seen
#    through the open top (the surface is two-sided);
#  * a clear glass elliptic tube and a chrome elliptic double cone, the
#    floor's checker refracted and reflected through them.
#
# Units: roughly decimetres. Floor y = 0, back wall z = -5.

resolution 480 360
eye 0 3.2 9.5
lookat 0 1.3 0
up 0 1 0
fov 42

background 0.03 0.03 0.05
ambient 0.08 0.08 0.08

light -5 8 7      70 68 62     # key light, upper left front
light 6 6 4       30 32 38     # fill from the right, cool

# ---------------------------------------------------------------- the room
push
  surface 0.55 0.55 0.6  0.9 0.1 0  20 1
  box -20 -0.5 -5  20 0 20
  surface 0.3 0.3 0.34  0.9 0.1 0  20 1
  # dark squares on the floor: a checker for the glass and chrome to show
  box -1.5 0 -1.5  -0.5 0.001 -0.5
  box 0.5 0 -1.5  1.5 0.001 -0.5
  box -0.5 0 -0.5  0.5 0.001 0.5
  box -1.5 0 0.5  -0.5 0.001 1.5
  box 0.5 0 0.5  1.5 0.001 1.5
  surface 0.7 0.68 0.64  0.9 0 0  1 1
  box -20 0 -5.5  20 12 -5
pop

# ---------------------------------------------------------------- the dish
# z = (x^2 + y^2) / 2.4: focal length 0.6; cut at z = 0.9, a circular rim
# of radius 1.47 inside the clip box. Tilted up and turned toward the
# camera, on a short stalk, with a warm light at its focus.
push
  translate -2.6 1.7 -0.6
  rotate 0 1 0 38
  rotate 1 0 0 -22
  surface 0.95 0.75 0.35  0.2 0.75 0  60 1
  quadric 1 1 0 0 0 0 0 0 -2.4 0  -1.5 -1.5 0  1.5 1.5 0.9
  light 0 0 0.6   0.45 0.38 0.28
  surface 0.2 0.2 0.22  0.6 0.4 0  80 1
  cylinder 0 0 -0.02  0 0 -1.2  0.08
pop
push
  translate -2.6 0 -0.6
  surface 0.2 0.2 0.22  0.6 0.4 0  80 1
  cylinder 0 0 0  0 0.55 0  0.09
pop

# ---------------------------------------------------------------- the tower
# x^2 + y^2 - 0.09 (z - 3)^2 = 0.36: radius 1.08 at the ground, 0.6 at the
# waist (z = 3), 0.67 at the top (z = 4).
push
  translate 2.4 0 -1.8
  rotate 1 0 0 -90
  surface 0.85 0.82 0.78  0.85 0.15 0  30 1
  quadric 1 1 -0.09 0 0 0 0 0 0.54 -1.17  -1.2 -1.2 0  1.2 1.2 4
pop

# ---------------------------------------------------------------- glass tube and chrome double cone
# x^2 / 0.25 + y^2 / 0.09 = 1 (semi-axes 0.5 and 0.3), 1.5 tall.
push
  translate 0 0.002 0.2
  rotate 0 1 0 -25
  rotate 1 0 0 -90
  surface 0.95 0.97 1  0 0.1 0.85  200 1.5
  quadric 4 11.111111111111111 0 0 0 0 0 0 0 -1  -0.6 -0.4 0  0.6 0.4 1.5
pop
# x^2 + 2 y^2 = 0.16 (z - 0.7)^2: an hourglass of two elliptic cones.
push
  translate 1.2 0.002 1.6
  rotate 1 0 0 -90
  surface 0.9 0.9 0.95  0.05 0.85 0  300 1
  quadric 1 2 -0.16 0 0 0 0 0 0.224 -0.0784  -0.3 -0.3 0  0.3 0.3 1.4
pop
