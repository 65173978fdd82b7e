# textures.sc -- procedural solid textures: a marble ball, a wooden log, a
# noise-clouded ball and a striped block on a floor whose checker tiles
# alternate between matt stone and mirror (docs/scene-language.md#textures).
#
# What to look for:
#  * the floor's mirror tiles reflect the objects and the sky, its stone
#    tiles are lit and shadowed as usual: one `texture checker` varies kdr,
#    ksr and the colour between the two ends;
#  * the marble veins and the log's rings are solid: the log's end shows the
#    rings, its side the grain they make where the surface cuts them;
#  * every textured object is placed by push/translate/rotate and its
#    texture moves with it (object space).
#
# Units: metres. The floor is at y = 0.

resolution 640 400
eye 0.6 3.4 9.5
lookat 0 0.9 0
up 0 1 0
fov 38

background 0.32 0.4 0.55
ambient 0.12 0.12 0.12

light -6 9 6      90 86 80    # key light, upper left front
light 7 6 3       35 38 45    # fill from the right, cool

# ------------------------------------------------------------ the floor
# The polygon lies at y = 0.5 of its own space, inside a checker cell (a
# tile boundary in the surface would speckle it), moved down to y = 0.
push
  translate 0 -0.5 0
  surface 0.78 0.74 0.68  0.9 0 0  1 1                  # matt stone ...
  texture checker 1.5  0.1 0.11 0.13  0.1 0.85 0  400   # ... and dark mirror tiles
  polygon 4  -40 0.5 40  40 0.5 40  40 0.5 -40  -40 0.5 -40
pop

# ------------------------------------------------------------ marble ball
push
  translate -2.3 1.2 0.3
  rotate 0 0 1 35                                       # veins on a slant
  surface 0.93 0.91 0.87  0.8 0.2 0  80 1               # white marble ...
  texture marble 0.8  0.3 0.26 0.34  0.75 0.2 0  80     # ... grey-violet veins
  sphere 0 0 0 1.2
pop

# ------------------------------------------------------------ wooden log
# Along the z axis of its own space, which the wood's rings go around.
push
  translate 2.2 0.8 0.6
  rotate 0 1 0 -40
  surface 0.78 0.55 0.32  0.9 0.08 0  25 1              # light early wood ...
  texture wood 0.14  0.45 0.26 0.12  0.9 0.08 0  25     # ... dark late wood
  cylinder 0 0 -1.3  0 0 1.3  0.8
pop

# ------------------------------------------------------------ noise ball
push
  translate 0.1 0.75 -2.2
  surface 0.12 0.25 0.6  0.9 0.3 0  120 1               # deep blue ...
  texture noise 0.45  0.85 0.9 0.95  0.9 0.3 0  120     # ... clouded white
  sphere 0 0 0 0.75
pop

# ------------------------------------------------------------ striped block
push
  translate -0.2 0.35 2.1
  rotate 0 1 0 25
  surface 0.85 0.2 0.15  0.9 0.1 0  40 1
  texture stripes 0.25  0.95 0.92 0.85  0.9 0.1 0  40
  box -0.7 -0.35 -0.35  0.7 0.35 0.35
pop
