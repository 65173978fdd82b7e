eye 0 0 5
lookat 0 0 0
up 0 0 -1e-300
sphere 0 0 0 1
