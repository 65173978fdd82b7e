# Unit cube [-0.5, 0.5]^3, six squares counterclockwise seen from outside
# (outward normals), so it is a closed solid usable for glass. Place it with
# translate/rotate/scale before `include`.
polygon 4  0.5 -0.5 -0.5  0.5 0.5 -0.5  0.5 0.5 0.5  0.5 -0.5 0.5
polygon 4  -0.5 -0.5 0.5  -0.5 0.5 0.5  -0.5 0.5 -0.5  -0.5 -0.5 -0.5
polygon 4  -0.5 0.5 -0.5  -0.5 0.5 0.5  0.5 0.5 0.5  0.5 0.5 -0.5
polygon 4  0.5 -0.5 -0.5  0.5 -0.5 0.5  -0.5 -0.5 0.5  -0.5 -0.5 -0.5
polygon 4  -0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5
polygon 4  -0.5 0.5 -0.5  0.5 0.5 -0.5  0.5 -0.5 -0.5  -0.5 -0.5 -0.5
