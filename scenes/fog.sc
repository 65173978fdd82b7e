# fog.sc -- fog and coloured glass: a corridor receding into fog, lit by a
# row of lamps, with panes of the same amber glass in three thicknesses, a
# blue glass ball and a green glass wedge.
#
# What to look for:
#  * the fog (`fog R G B DENSITY`) thickening with distance: the far end of
#    the corridor, and everything reflected in the floor, fades to its colour;
#  * the three amber panes in front: one glass (`absorption`), 0.1, 0.4 and
#    1.2 thick, nearly clear, amber and deep red-brown (Beer-Lambert:
#    exp(-absorption * length) per channel);
#  * the blue ball darker at its centre than at its rim (longer path
#    inside), the green wedge darkening from its edge to its back.
#
# Units: metres. Floor y = 0, corridor x in [-3, 3].

resolution 640 400
eye 0 1.7 14
lookat 0 0.7 -10
up 0 1 0
fov 40

background 0 0 0
ambient 0.06 0.06 0.07
fog 0.2 0.22 0.27  0.05

# ------------------------------------------------------------ the lamps, along the ceiling
light 0 3.4 6     3.2 3 2.6
light 0 3.4 -2    3.2 3 2.6
light 0 3.4 -10   3.2 3 2.6
light 0 3.4 -18   3.2 3 2.6
light 0 3.4 -26   3.2 3 2.6

# ------------------------------------------------------------ the corridor
push
  # a polished dark floor
  surface 0.25 0.24 0.22  0.7 0.25 0  60 1
  box -3 -0.2 -60  3 0 12
  # walls
  surface 0.5 0.42 0.36  0.9 0 0  1 1
  box -3.4 0 -60  -3 3.8 12
  box 3 0 -60  3.4 3.8 12
  # ceiling
  box -3.4 3.8 -60  3.4 4.1 12
  # pillars every 4 m along both walls
  surface 0.55 0.5 0.45  0.8 0.1 0  20 1
  box -3 0 5.6  -2.6 3.8 6.4     box 2.6 0 5.6  3 3.8 6.4
  box -3 0 1.6  -2.6 3.8 2.4     box 2.6 0 1.6  3 3.8 2.4
  box -3 0 -2.4  -2.6 3.8 -1.6   box 2.6 0 -2.4  3 3.8 -1.6
  box -3 0 -6.4  -2.6 3.8 -5.6   box 2.6 0 -6.4  3 3.8 -5.6
  box -3 0 -10.4  -2.6 3.8 -9.6  box 2.6 0 -10.4  3 3.8 -9.6
  box -3 0 -14.4  -2.6 3.8 -13.6 box 2.6 0 -14.4  3 3.8 -13.6
  box -3 0 -18.4  -2.6 3.8 -17.6 box 2.6 0 -18.4  3 3.8 -17.6
  box -3 0 -22.4  -2.6 3.8 -21.6 box 2.6 0 -22.4  3 3.8 -21.6
  box -3 0 -26.4  -2.6 3.8 -25.6 box 2.6 0 -26.4  3 3.8 -25.6
  box -3 0 -30.4  -2.6 3.8 -29.6 box 2.6 0 -30.4  3 3.8 -29.6
  # lamp housings: small discs under the ceiling
  surface 1 0.95 0.85  1 0 0  1 1
  disc 0 3.79 6  0 -1 0  0.25    disc 0 3.79 -2  0 -1 0  0.25
  disc 0 3.79 -10  0 -1 0  0.25  disc 0 3.79 -18  0 -1 0  0.25
  disc 0 3.79 -26  0 -1 0  0.25
pop

# ------------------------------------------------------------ amber panes: 0.1, 0.4 and 1.2 thick
push
  surface 1 1 1  0 0.06 0.94  200 1.5
  absorption 0.4 1.6 4
  box -2.2 0 4.45   -1.0 1.1 4.55
  box -0.6 0 4.3    0.6 1.1 4.7
  box  1.0 0 3.9     2.2 1.1 5.1
pop

# ------------------------------------------------------------ a blue glass ball
push
  surface 1 1 1  0 0.06 0.94  200 1.5
  absorption 2.4 1.1 0.15
  sphere -1.4 0.8 0.5  0.8
pop

# ------------------------------------------------------------ a green glass wedge
push
  surface 1 1 1  0 0.06 0.94  200 1.5
  absorption 2 0.2 1.6
  translate 1.4 0 -1.5
  csg intersection
    box -0.7 0 -0.8  0.7 1.8 0.8
    push
      rotate 0 1 0 30
      box -3 -1 -3  0 3 3
    pop
  end
pop
