# Twig variant 1: a thin brown stalk (an ellipsoid) along +y, length 1, with
# 11 leaves (parts/leaf.sc) in a spiral 137.5 degrees apart and one at the tip.
# 25 primitives. The leaves take the surface current where the twig is
# included (tools/tree_gen.cpp gives each twig its colour: this variant's
# green (0.22 0.5 0.12) or an autumn tint); the stalk sets its own.
push
  push translate 0 0.12 0 rotate 0 1 0 0 rotate 0 0 1 62 scale 0.255 0.255 0.255 include leaf.sc pop
  push translate 0 0.205 0 rotate 0 1 0 137.5 rotate 0 0 1 60.3 scale 0.273 0.273 0.273 include leaf.sc pop
  push translate 0 0.29 0 rotate 0 1 0 275 rotate 0 0 1 58.6 scale 0.291 0.291 0.291 include leaf.sc pop
  push translate 0 0.375 0 rotate 0 1 0 52.5 rotate 0 0 1 56.9 scale 0.309 0.309 0.309 include leaf.sc pop
  push translate 0 0.46 0 rotate 0 1 0 190 rotate 0 0 1 55.2 scale 0.327 0.327 0.327 include leaf.sc pop
  push translate 0 0.545 0 rotate 0 1 0 327.5 rotate 0 0 1 53.5 scale 0.345 0.345 0.345 include leaf.sc pop
  push translate 0 0.63 0 rotate 0 1 0 105 rotate 0 0 1 51.8 scale 0.327 0.327 0.327 include leaf.sc pop
  push translate 0 0.715 0 rotate 0 1 0 242.5 rotate 0 0 1 50.1 scale 0.309 0.309 0.309 include leaf.sc pop
  push translate 0 0.8 0 rotate 0 1 0 20 rotate 0 0 1 48.4 scale 0.291 0.291 0.291 include leaf.sc pop
  push translate 0 0.885 0 rotate 0 1 0 157.5 rotate 0 0 1 46.7 scale 0.273 0.273 0.273 include leaf.sc pop
  push translate 0 0.97 0 rotate 0 1 0 295 rotate 0 0 1 45 scale 0.255 0.255 0.255 include leaf.sc pop
  push translate 0 1 0 rotate 0 1 0 30 rotate 1 0 0 -10 scale 0.3 0.3 0.3 include leaf.sc pop
  surface 0.3 0.22 0.12  0.9 0 0  1 1
  push translate 0 0.5 0 scale 0.018 0.5 0.018 sphere 0 0 0 1 pop
pop
