# Number syntax: hexadecimal, exponents, signs, tiny and huge values.
eye +0x1p3 0x1.8p0 .5e1
light 1e3 1E3 -1e-3 0x1p-2 1. .5
surface 1e-300 0.5 +0.5  0x0.8p0 0.25 0  1e2 1.0000000000000002
sphere -0 -0.0 0 1e-5
sphere 1e4 0 0 1e3
sphere 0 0 -1e6 4294967296e07
scale 1e-200 1e-200 1e-200
scale 1e200 1e200 1e200
sphere 0 0 0 1
translate 1e300 0 0
