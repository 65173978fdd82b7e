# blobs.sc -- a blob sculpture: metaballs (POV-Ray's blob of spherical
# components) in chrome, clear glass and gold on a two-tone floor.
#
# Centre: a chrome molecule, six components on a ring around a seventh,
# fused into one smooth body. Left: a glass dumbbell whose neck is barely
# thicker than nothing -- the field at its waist exceeds the threshold by
# 0.04% -- which the root finder must not lose (it brackets the field's
# quartics with Bernstein bounds: docs/rendering-model.md#blobs). Right: a
# gold apple bitten by a negative component. Front: a glass droplet, a
# blob stretched by a non-uniform scale. Depth >= 5 for the glass.

resolution 480 320
eye 0 3.2 9
lookat 0 1.0 0
up 0 1 0
fov 40

background 0.07 0.08 0.11
ambient 0.1 0.1 0.1

light -5 9 7    90 90 90
light 6 7 4     55 55 60
light 0 6 -6    25 25 25      # behind: rims on the glass

# ---------------------------------------------------------------- floor and
# a backdrop
push
  surface 0.72 0.7 0.66  0.8 0.2 0  40 1
  polygon 4  -10 0 -8  10 0 -8  10 0 6  -10 0 6
  surface 0.25 0.28 0.34  0.9 0.1 0  20 1
  polygon 4  -10 0 -8  -10 8 -8  10 8 -8  10 0 -8
pop

# ---------------------------------------------------------------- centre:
# the chrome molecule, a ring of six around one, tilted toward the camera
push
  translate 0 1.55 -0.6
  rotate 1 0 0 62
  surface 0.8 0.8 0.84  0.2 0.75 0  200 1
  blob 0.6 7
    0 0 0        1.1 1.2
    1.05 0 0     0.75 1
    0.525 0.909 0  0.75 1
    -0.525 0.909 0  0.75 1
    -1.05 0 0    0.75 1
    -0.525 -0.909 0  0.75 1
    0.525 -0.909 0  0.75 1
pop

# ---------------------------------------------------------------- left: the
# glass dumbbell, two components 2 a = 1.4 apart whose field at the waist,
# 2 (1 - a^2)^2 = 0.5202, is 0.04% over the threshold 0.52 (the waist's
# radius is about 0.01, scaled by 1.2)
push
  translate -2.9 1.0 0.2
  rotate 0 0 1 30
  scale 1.2 1.2 1.2
  surface 0.9 0.95 1  0.05 0.15 0.8  200 1.5
  blob 0.52 2
    -0.7 0 0  1 1
     0.7 0 0  1 1
pop

# ---------------------------------------------------------------- right:
# the gold apple, bitten on its upper right by a negative component
push
  translate 2.9 0.95 0.1
  surface 1 0.75 0.3  0.6 0.35 0  80 1
  blob 0.5 4
    0 0 0       1.5 1.6
    0 0.75 0    0.6 0.9
    0.85 0.55 0.45  0.75 -1.5
    0 -0.6 0    0.9 0.6
pop

# ---------------------------------------------------------------- front: a
# glass droplet, a two-component blob stretched upward
push
  translate 0.4 0.0 2.4
  scale 0.6 1.4 0.6
  surface 0.85 0.95 0.9  0.05 0.15 0.8  200 1.5
  blob 0.5 2
    0 0.45 0    0.6 1.2
    0 0.85 0    0.4 1
pop
