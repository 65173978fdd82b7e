# csg.sc -- constructive solid geometry: `csg union | intersection |
# difference` ... `end`.
#
# What to look for:
#  * a glass lens, the intersection of two spheres, standing over a checker
#    page: it magnifies and turns the squares as one solid would (entering
#    at one spherical face, leaving at the other);
#  * a die: a cube intersected with a sphere (rounded corners), minus small
#    spheres for the pips, whose hollows show the subtracted spheres' surfaces
#    inside out and in a colour of their own;
#  * a nut: a hexagonal prism (three turned boxes intersected) minus a
#    cylinder, casting a shadow with a hole in it;
#  * a magnifying glass held over the back left of the page, its handle
#    running out of the picture: a thin lens (the intersection of two
#    spheres) in a brass torus ring, a brass ferrule (a capped cone and a
#    small torus) and a wooden capped-cylinder handle; through it the
#    squares look half as large again or more, and its own shadow falls in
#    front of the patch it magnifies.
#
# Units: roughly centimetres. Page y = 0.

resolution 640 400
eye 0 9 12
lookat 0 1 0
up 0 1 0
fov 40

background 0.05 0.05 0.07
ambient 0.1 0.1 0.1

light -6 12 8     110 105 95   # key, upper left front
light 7 8 4       40 44 50     # fill from the right

# ---------------------------------------------------------------- the page: a checker of flat boxes
push
  surface 0.92 0.9 0.85  0.9 0 0  1 1
  box -9 -0.2 -6  9 0 6
  surface 0.15 0.15 0.18  0.9 0 0  1 1
  box -9 0 -6  -8 0.01 -5   box -7 0 -6  -6 0.01 -5   box -5 0 -6  -4 0.01 -5
  box -3 0 -6  -2 0.01 -5   box -1 0 -6   0 0.01 -5   box  1 0 -6   2 0.01 -5
  box  3 0 -6   4 0.01 -5   box  5 0 -6   6 0.01 -5   box  7 0 -6   8 0.01 -5
  box -8 0 -5  -7 0.01 -4   box -6 0 -5  -5 0.01 -4   box -4 0 -5  -3 0.01 -4
  box -2 0 -5  -1 0.01 -4   box  0 0 -5   1 0.01 -4   box  2 0 -5   3 0.01 -4
  box  4 0 -5   5 0.01 -4   box  6 0 -5   7 0.01 -4   box  8 0 -5   9 0.01 -4
  box -9 0 -4  -8 0.01 -3   box -7 0 -4  -6 0.01 -3   box -5 0 -4  -4 0.01 -3
  box -3 0 -4  -2 0.01 -3   box -1 0 -4   0 0.01 -3   box  1 0 -4   2 0.01 -3
  box  3 0 -4   4 0.01 -3   box  5 0 -4   6 0.01 -3   box  7 0 -4   8 0.01 -3
  box -8 0 -3  -7 0.01 -2   box -6 0 -3  -5 0.01 -2   box -4 0 -3  -3 0.01 -2
  box -2 0 -3  -1 0.01 -2   box  0 0 -3   1 0.01 -2   box  2 0 -3   3 0.01 -2
  box  4 0 -3   5 0.01 -2   box  6 0 -3   7 0.01 -2   box  8 0 -3   9 0.01 -2
  box -9 0 -2  -8 0.01 -1   box -7 0 -2  -6 0.01 -1   box -5 0 -2  -4 0.01 -1
  box -3 0 -2  -2 0.01 -1   box -1 0 -2   0 0.01 -1   box  1 0 -2   2 0.01 -1
  box  3 0 -2   4 0.01 -1   box  5 0 -2   6 0.01 -1   box  7 0 -2   8 0.01 -1
  box -8 0 -1  -7 0.01  0   box -6 0 -1  -5 0.01  0   box -4 0 -1  -3 0.01  0
  box -2 0 -1  -1 0.01  0   box  0 0 -1   1 0.01  0   box  2 0 -1   3 0.01  0
  box  4 0 -1   5 0.01  0   box  6 0 -1   7 0.01  0   box  8 0 -1   9 0.01  0
  box -9 0  0  -8 0.01  1   box -7 0  0  -6 0.01  1   box -5 0  0  -4 0.01  1
  box -3 0  0  -2 0.01  1   box -1 0  0   0 0.01  1   box  1 0  0   2 0.01  1
  box  3 0  0   4 0.01  1   box  5 0  0   6 0.01  1   box  7 0  0   8 0.01  1
  box -8 0  1  -7 0.01  2   box -6 0  1  -5 0.01  2   box -4 0  1  -3 0.01  2
  box -2 0  1  -1 0.01  2   box  0 0  1   1 0.01  2   box  2 0  1   3 0.01  2
  box  4 0  1   5 0.01  2   box  6 0  1   7 0.01  2   box  8 0  1   9 0.01  2
  box -9 0  2  -8 0.01  3   box -7 0  2  -6 0.01  3   box -5 0  2  -4 0.01  3
  box -3 0  2  -2 0.01  3   box -1 0  2   0 0.01  3   box  1 0  2   2 0.01  3
  box  3 0  2   4 0.01  3   box  5 0  2   6 0.01  3   box  7 0  2   8 0.01  3
  box -8 0  3  -7 0.01  4   box -6 0  3  -5 0.01  4   box -4 0  3  -3 0.01  4
  box -2 0  3  -1 0.01  4   box  0 0  3   1 0.01  4   box  2 0  3   3 0.01  4
  box  4 0  3   5 0.01  4   box  6 0  3   7 0.01  4   box  8 0  3   9 0.01  4
pop

# ---------------------------------------------------------------- a glass lens on its edge
# Two spheres of radius 4 with centres 7 apart: a lens 1 thick, 3.9 across.
push
  translate 0 2.2 1.5
  rotate 1 0 0 -30
  surface 1 1 1  0 0.08 0.92  200 1.5
  csg intersection
    sphere 0 0 -3.5  4
    sphere 0 0  3.5  4
  end
pop

# ---------------------------------------------------------------- a die
push
  translate -4.2 1.01 2.2
  rotate 0 1 0 30
  surface 0.92 0.9 0.86  0.85 0.15 0  30 1
  csg difference
    csg intersection
      box -1 -1 -1  1 1 1
      sphere 0 0 0 1.38
    end
    surface 0.7 0.05 0.05  0.9 0.1 0  30 1
    # one on top
    sphere 0 1.18 0  0.3
    # two on the front (+z)
    sphere -0.45 0.45 1.18  0.24   sphere 0.45 -0.45 1.18  0.24
    # three on the right (+x)
    sphere 1.18 0.5 -0.5  0.22   sphere 1.18 0 0  0.22   sphere 1.18 -0.5 0.5  0.22
  end
pop

# ---------------------------------------------------------------- a nut
push
  translate 4.3 0.61 2.0
  surface 0.75 0.7 0.55  0.5 0.5 0  60 1
  csg difference
    csg intersection
      box -1.2 -0.6 -2  1.2 0.6 2
      push rotate 0 1 0 60  box -1.2 -0.6 -2  1.2 0.6 2 pop
      push rotate 0 1 0 -60 box -1.2 -0.6 -2  1.2 0.6 2 pop
    end
    cylinder 0 -1 0  0 1 0  0.6
  end
pop

# ---------------------------------------------------------------- a magnifying glass
# A lens 2.4 across: two spheres of radius 9 with centres 17.84 apart, 0.16
# thick in the middle (focal length about 9), in a ring of major radius 1.26
# that covers its sharp rim. Built with the lens axis along y and the handle
# along +x, then raised, turned and tilted toward the camera. (A stronger
# lens, or one tilted less, shows a single square at a slant; held higher or
# farther back it shows the page's edge; lower or nearer the light, its
# patch of page lies in its own shadow: glass blocks shadow rays.)
push
  translate -4.8 2.4 -0.6
  rotate 1 0 0 40      # lens face toward the camera
  rotate 0 1 0 172     # handle toward the left, a little back
  rotate 0 0 1 12      # handle end raised
  surface 1 1 1  0 0.08 0.92  200 1.5
  csg intersection
    sphere 0 -8.92 0  9
    sphere 0  8.92 0  9
  end
  surface 0.85 0.62 0.3  0.35 0.6 0  90 1     # brass
  torus 0 0 0  0 1 0  1.26 0.1
  capped_cone 1.32 0 0 0.07  1.85 0 0 0.11
  torus 1.85 0 0  1 0 0  0.11 0.035
  surface 0.3 0.14 0.07  0.8 0.25 0  40 1     # wood, varnished
  capped_cone 1.87 0 0 0.12  3.7 0 0 0.16
  sphere 3.7 0 0 0.16
pop
