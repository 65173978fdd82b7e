# Twig variant 3: a thin brown stalk (an ellipsoid) along +y, length 1, with
# 13 leaves (parts/leaf.sc) in a spiral 137.5 degrees apart and one at the tip.
# 29 primitives. The leaves take the surface current where the twig is
# included (tools/tree_gen.cpp gives each twig its colour: this variant's
# green (0.17 0.42 0.1) or an autumn tint); the stalk sets its own.
push
  push translate 0 0.12 0 rotate 0 1 0 75 rotate 0 0 1 68 scale 0.2295 0.2295 0.2295 include leaf.sc pop
  push translate 0 0.1908 0 rotate 0 1 0 212.5 rotate 0 0 1 66.5 scale 0.243 0.243 0.243 include leaf.sc pop
  push translate 0 0.2617 0 rotate 0 1 0 350 rotate 0 0 1 65 scale 0.2565 0.2565 0.2565 include leaf.sc pop
  push translate 0 0.3325 0 rotate 0 1 0 127.5 rotate 0 0 1 63.5 scale 0.27 0.27 0.27 include leaf.sc pop
  push translate 0 0.4033 0 rotate 0 1 0 265 rotate 0 0 1 62 scale 0.2835 0.2835 0.2835 include leaf.sc pop
  push translate 0 0.4742 0 rotate 0 1 0 42.5 rotate 0 0 1 60.5 scale 0.297 0.297 0.297 include leaf.sc pop
  push translate 0 0.545 0 rotate 0 1 0 180 rotate 0 0 1 59 scale 0.3105 0.3105 0.3105 include leaf.sc pop
  push translate 0 0.6158 0 rotate 0 1 0 317.5 rotate 0 0 1 57.5 scale 0.297 0.297 0.297 include leaf.sc pop
  push translate 0 0.6867 0 rotate 0 1 0 95 rotate 0 0 1 56 scale 0.2835 0.2835 0.2835 include leaf.sc pop
  push translate 0 0.7575 0 rotate 0 1 0 232.5 rotate 0 0 1 54.5 scale 0.27 0.27 0.27 include leaf.sc pop
  push translate 0 0.8283 0 rotate 0 1 0 10 rotate 0 0 1 53 scale 0.2565 0.2565 0.2565 include leaf.sc pop
  push translate 0 0.8992 0 rotate 0 1 0 147.5 rotate 0 0 1 51.5 scale 0.243 0.243 0.243 include leaf.sc pop
  push translate 0 0.97 0 rotate 0 1 0 285 rotate 0 0 1 50 scale 0.2295 0.2295 0.2295 include leaf.sc pop
  push translate 0 1 0 rotate 0 1 0 105 rotate 1 0 0 -10 scale 0.27 0.27 0.27 include leaf.sc pop
  surface 0.3 0.22 0.12  0.9 0 0  1 1
  push translate 0 0.5 0 scale 0.018 0.5 0.018 sphere 0 0 0 1 pop
pop
