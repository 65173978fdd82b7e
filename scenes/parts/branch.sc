# One branch segment: the sides of an octagonal frustum along +y, radius 1 at
# y = 0 and 0.85 at y = 1 (so a following segment scaled by 0.85 continues it
# seamlessly). Open at both ends: joints are covered by spheres in tree.sc.
# Faces run counterclockwise seen from outside.
polygon 4  1 0 0  0.85 1 0  0.601040764 1 0.601040764  0.7071067812 0 0.7071067812
polygon 4  0.7071067812 0 0.7071067812  0.601040764 1 0.601040764  0 1 0.85  0 0 1
polygon 4  0 0 1  0 1 0.85  -0.601040764 1 0.601040764  -0.7071067812 0 0.7071067812
polygon 4  -0.7071067812 0 0.7071067812  -0.601040764 1 0.601040764  -0.85 1 0  -1 0 0
polygon 4  -1 0 0  -0.85 1 0  -0.601040764 1 -0.601040764  -0.7071067812 0 -0.7071067812
polygon 4  -0.7071067812 0 -0.7071067812  -0.601040764 1 -0.601040764  0 1 -0.85  0 0 -1
polygon 4  0 0 -1  0 1 -0.85  0.601040764 1 -0.601040764  0.7071067812 0 -0.7071067812
polygon 4  0.7071067812 0 -0.7071067812  0.601040764 1 -0.601040764  0.85 1 0  1 0 0
