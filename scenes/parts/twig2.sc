# Twig variant 2: a thin brown stalk (an ellipsoid) along +y, length 1, with
# 9 leaves (parts/leaf.sc) in a spiral 137.5 degrees apart and one at the tip.
# 21 primitives. The leaves take the surface current where the twig is
# included (tools/tree_gen.cpp gives each twig its colour: this variant's
# green (0.32 0.56 0.14) or an autumn tint); the stalk sets its own.
push
  push translate 0 0.12 0 rotate 0 1 0 40 rotate 0 0 1 55 scale 0.289 0.289 0.289 include leaf.sc pop
  push translate 0 0.2263 0 rotate 0 1 0 177.5 rotate 0 0 1 53.12 scale 0.3145 0.3145 0.3145 include leaf.sc pop
  push translate 0 0.3325 0 rotate 0 1 0 315 rotate 0 0 1 51.25 scale 0.34 0.34 0.34 include leaf.sc pop
  push translate 0 0.4387 0 rotate 0 1 0 92.5 rotate 0 0 1 49.38 scale 0.3655 0.3655 0.3655 include leaf.sc pop
  push translate 0 0.545 0 rotate 0 1 0 230 rotate 0 0 1 47.5 scale 0.391 0.391 0.391 include leaf.sc pop
  push translate 0 0.6512 0 rotate 0 1 0 7.5 rotate 0 0 1 45.62 scale 0.3655 0.3655 0.3655 include leaf.sc pop
  push translate 0 0.7575 0 rotate 0 1 0 145 rotate 0 0 1 43.75 scale 0.34 0.34 0.34 include leaf.sc pop
  push translate 0 0.8638 0 rotate 0 1 0 282.5 rotate 0 0 1 41.88 scale 0.3145 0.3145 0.3145 include leaf.sc pop
  push translate 0 0.97 0 rotate 0 1 0 60 rotate 0 0 1 40 scale 0.289 0.289 0.289 include leaf.sc pop
  push translate 0 1 0 rotate 0 1 0 70 rotate 1 0 0 -10 scale 0.34 0.34 0.34 include leaf.sc pop
  surface 0.3 0.22 0.12  0.9 0 0  1 1
  push translate 0 0.5 0 scale 0.018 0.5 0.018 sphere 0 0 0 1 pop
pop
