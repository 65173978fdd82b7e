# table.sc -- shadows and specular reflection on a table setting.
#
# What to look for:
#  * three point lights at different places, so every object casts up to three
#    separate, clearly visible shadows (on the table top and on the floor
#    under the table);
#  * mirror reflection: a chrome ball mirrors the whole room, the table top is a
#    little glossy and reflects the plates and bowl, the plates and the bowl have
#    sharp highlights (e = 60..200), the cutlery is polished metal;
#  * a few transparent pieces (wine glasses, a tumbler) as a preview of glass.sc;
#  * transforms and includes: the table, legs and cutlery are parts/cube.sc
#    scaled into boxes; plates, bowl and glasses are spheres under non-uniform
#    scale (ellipsoids).
#
# Units: roughly decimetres. Floor y = 0, table top at y = 2.5, back wall z = -7.

resolution 640 480
eye 1.0 7.4 11.0
lookat 0 3.0 0
up 0 1 0
fov 39

background 0.05 0.05 0.08
ambient 0.08 0.08 0.08

# Lights (1/r^2 falloff: intensity ~ distance^2 gives radiance ~1).
light -6.5 8 1.5     100 95 85    # key light, upper left, warm: shadows fall to the right
light 5 8.5 6        70 72 80     # right front, slightly cool: shadows fall back-left
light 1 10 -3.5      45 45 45     # high behind the table: shadows fall toward the camera

# ---------------------------------------------------------------- the room
push
  # floor: plain and slightly glossy, so the shadows are easy to read
  surface 0.62 0.56 0.5  0.9 0.05 0  10 1
  polygon 4  -30 0 30  30 0 30  30 0 -7  -30 0 -7
  # back wall, facing +z
  surface 0.7 0.72 0.78  0.9 0 0  1 1
  polygon 4  -30 0 -7  30 0 -7  30 20 -7  -30 20 -7
  # left wall (facing +x) and the wall behind the camera (facing -z), so the
  # mirror ball and the glasses have a room to reflect
  surface 0.75 0.65 0.45  0.9 0 0  1 1
  polygon 4  -12 0 -7  -12 20 -7  -12 20 30  -12 0 30
  surface 0.45 0.6 0.5  0.9 0 0  1 1
  polygon 4  -30 0 16  -30 20 16  30 20 16  30 0 16
  # ceiling (facing down)
  surface 0.85 0.85 0.8  0.9 0 0  1 1
  polygon 4  -30 14 -7  -30 14 30  30 14 30  30 14 -7
  # a picture on the back wall (dark wood frame, blue sky, yellow mountain)
  surface 0.25 0.15 0.08  0.8 0.1 0  20 1
  polygon 4  -2.0 3.9 -6.99  2.0 3.9 -6.99  2.0 6.1 -6.99  -2.0 6.1 -6.99
  surface 0.2 0.35 0.7  0.9 0 0  1 1
  polygon 4  -1.75 4.15 -6.98  1.75 4.15 -6.98  1.75 5.85 -6.98  -1.75 5.85 -6.98
  surface 0.95 0.8 0.3  0.9 0 0  1 1
  polygon 3  -1.2 4.15 -6.97  0.6 4.15 -6.97  -0.4 5.5 -6.97
pop

# A big ball on the floor beside the table: its shadows on the floor and on the
# table leg show the lights at a glance.
push
  surface 0.9 0.75 0.2  0.75 0.25 0  80 1
  sphere 4.6 0.8 0.6 0.8
pop

# ---------------------------------------------------------------- the table
push
  # slightly glossy wood: reflects what stands on it
  surface 0.55 0.32 0.16  0.75 0.18 0  40 1
  push translate 0 2.425 0 scale 7.2 0.15 4.4 include parts/cube.sc pop   # top, y 2.35..2.5
  push
    surface 0.45 0.26 0.13  0.85 0.05 0  20 1
    push translate -3.25 1.175 -1.85 scale 0.28 2.35 0.28 include parts/cube.sc pop
    push translate  3.25 1.175 -1.85 scale 0.28 2.35 0.28 include parts/cube.sc pop
    push translate -3.25 1.175  1.85 scale 0.28 2.35 0.28 include parts/cube.sc pop
    push translate  3.25 1.175  1.85 scale 0.28 2.35 0.28 include parts/cube.sc pop
    # an apron under the top
    push translate 0 2.2 1.85 scale 6.3 0.3 0.1 include parts/cube.sc pop
    push translate 0 2.2 -1.85 scale 6.3 0.3 0.1 include parts/cube.sc pop
  pop
pop

# A cloth runner across the table (a thin red rectangle lying on the top).
push
  surface 0.65 0.1 0.1  0.9 0 0  1 1
  polygon 4  -3.6 2.502 0.55  3.6 2.502 0.55  3.6 2.502 -0.55  -3.6 2.502 -0.55
pop

# ---------------------------------------------------------------- left place setting
push
  translate -2.1 2.5 0.9
  # plate: a flat white ellipsoid with a strong highlight, and a raised rim
  surface 0.93 0.93 0.9  0.7 0.3 0  120 1
  push translate 0 0.05 0 scale 0.95 0.06 0.95 sphere 0 0 0 1 pop
  push translate 0 0.08 0 scale 0.6 0.045 0.6 sphere 0 0 0 1 pop
  # fork (left) and knife (right): thin polished boxes
  surface 0.75 0.75 0.78  0.25 0.7 0  200 1
  push translate -1.2 0.02 0.05 scale 0.08 0.03 1.2 include parts/cube.sc pop
  push translate  1.2 0.02 0.05 scale 0.1 0.03 1.3 include parts/cube.sc pop
  # wine glass: base, stem and bowl, all clear glass
  push
    translate 1.0 0 -1.0
    surface 0.9 0.95 1  0.35 0.3 0.4  200 1.5     # foot and stem: thick, a little frosted
    push translate 0 0.02 0 scale 0.32 0.02 0.32 sphere 0 0 0 1 pop
    push translate 0 0.4 0 scale 0.045 0.4 0.045 sphere 0 0 0 1 pop
    surface 0.9 0.95 1  0.05 0.15 0.8  200 1.5     # bowl: clear glass
    push translate 0 1.1 0 scale 0.36 0.42 0.36 sphere 0 0 0 1 pop
  pop
pop

# ---------------------------------------------------------------- right place setting
push
  translate 2.2 2.5 0.9
  surface 0.93 0.93 0.9  0.7 0.3 0  120 1
  push translate 0 0.05 0 scale 0.95 0.06 0.95 sphere 0 0 0 1 pop
  push translate 0 0.08 0 scale 0.6 0.045 0.6 sphere 0 0 0 1 pop
  # an orange on the plate
  surface 1 0.5 0.08  0.8 0.2 0  60 1
  sphere 0.1 0.38 0.05 0.3
  surface 0.75 0.75 0.78  0.25 0.7 0  200 1
  push translate -1.2 0.02 0.05 scale 0.08 0.03 1.2 include parts/cube.sc pop
  push translate  1.2 0.02 0.05 scale 0.1 0.03 1.3 include parts/cube.sc pop
  push
    translate -1.0 0 -1.0
    surface 0.9 0.95 1  0.35 0.3 0.4  200 1.5
    push translate 0 0.02 0 scale 0.32 0.02 0.32 sphere 0 0 0 1 pop
    push translate 0 0.4 0 scale 0.045 0.4 0.045 sphere 0 0 0 1 pop
    surface 0.9 0.95 1  0.05 0.15 0.8  200 1.5
    push translate 0 1.1 0 scale 0.36 0.42 0.36 sphere 0 0 0 1 pop
  pop
pop

# ---------------------------------------------------------------- centre piece
# A glossy blue bowl (a half-sunk ellipsoid) with fruit.
push
  translate -0.4 2.5 -0.9
  surface 0.15 0.3 0.75  0.6 0.4 0  150 1
  push translate 0 0.2 0 scale 0.95 0.42 0.95 sphere 0 0 0 1 pop
  surface 0.85 0.1 0.08  0.8 0.25 0  80 1     # apples
  sphere -0.3 0.7 0.1 0.32
  sphere  0.32 0.68 -0.05 0.3
  surface 0.95 0.85 0.15  0.8 0.2 0  40 1     # a lemon: an ellipsoid
  push translate 0.0 0.78 0.35 rotate 0 1 0 30 scale 0.3 0.22 0.22 sphere 0 0 0 1 pop
  surface 0.3 0.6 0.12  0.8 0.2 0  60 1       # a green apple
  sphere 0.05 0.95 -0.3 0.3
pop

# The mirror ball: almost perfectly reflecting chrome, resting on the table.
push
  surface 0.8 0.8 0.85  0.08 0.9 0  400 1
  sphere 1.1 3.15 -0.6 0.65
pop

# A tumbler: parts/cup.sc, a closed glass solid with a cavity open at the top.
push
  translate -3.0 2.502 -1.0   # just above the table top: no coincident faces
  scale 0.32 0.34 0.32
  surface 0.85 0.95 0.9  0.05 0.12 0.82  150 1.5
  include parts/cup.sc
pop

# A green vase: an ellipsoid body and a neck, glossy and opaque.
push
  translate 3.0 2.5 -1.3
  surface 0.1 0.4 0.15  0.5 0.45 0  200 1
  push translate 0 0.75 0 scale 0.38 0.75 0.38 sphere 0 0 0 1 pop
  push translate 0 1.6 0 scale 0.1 0.45 0.1 sphere 0 0 0 1 pop
pop
