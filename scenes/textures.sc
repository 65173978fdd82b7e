# textures.sc -- textures: a marble ball, a wooden log, a noise-clouded ball
# and a striped block (procedural solid textures), an image-textured globe,
# and a floor of image tiles running to the horizon
# (docs/scene-language.md#textures, #image-textures).
#
# What to look for:
#  * the floor's tiles stay crisp near the camera and fade smoothly to their
#    mean toward the horizon, with no moire: each lookup is filtered over the
#    ray's footprint (docs/rendering-model.md#image-textures compares it
#    unfiltered). The floor is
#    a faint mirror, and the tiles seen in the objects' reflections are
#    filtered by the reflected rays' footprints too;
#  * the marble veins and the log's rings are solid: the log's end shows the
#    rings, its side the grain they make where the surface cuts them;
#  * the globe is tilted 23.4 degrees and turned: its image turns with it;
#  * every textured object is placed by push/translate/rotate and its
#    texture moves with it (object space).
#
# The images are made by tools/texture_gen (from Prism's own noise).
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
# One repeat of the image is 2 x 2 tiles; uv 1/3: tiles of 1.5 m.
surface 1 1 1  0.85 0.12 0  300 1
image "images/tiles.png" repeat
uv 0.3333333333 0.3333333333  0 0
polygon 4  -150 0 150  150 0 150  150 0 -150  -150 0 -150

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

# ------------------------------------------------------------ globe
# A sphere under a rotation keeps its image turned
# with it (a turned, image-textured sphere is stored as an ellipsoid).
push
  translate 0.3 1.15 -2.6
  rotate 0 0 1 23.4                                     # the axis tilted
  rotate 0 1 0 -70                                      # a continent toward us
  surface 1 1 1  0.9 0.25 0  60 1
  image "images/globe.png" repeat srgb
  sphere 0 0 0 1.15
pop

# ------------------------------------------------------------ noise ball
push
  translate 2.0 0.5 2.6
  surface 0.12 0.25 0.6  0.9 0.3 0  120 1               # deep blue ...
  texture noise 0.3  0.85 0.9 0.95  0.9 0.3 0  120      # ... clouded white
  sphere 0 0 0 0.5
pop

# ------------------------------------------------------------ striped block
push
  translate -0.2 0.35 2.1
  rotate 0 1 0 25
  surface 0.85 0.2 0.15  0.9 0.1 0  40 1
  texture stripes 0.25  0.95 0.92 0.85  0.9 0.1 0  40
  box -0.7 -0.35 -0.35  0.7 0.35 0.35
pop
