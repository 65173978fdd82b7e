# One leaf, length 1 along +y from its stalk at the origin, lying in the x-y
# plane and folded slightly along the midrib (two planar halves, fronts toward +z).
polygon 5  0 0 0  0.2 0.18 0.07  0.28 0.42 0.098  0.22 0.7 0.077  0 1 0
polygon 5  0 0 0  0 1 0  -0.22 0.7 0.077  -0.28 0.42 0.098  -0.2 0.18 0.07
