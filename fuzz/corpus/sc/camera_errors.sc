eye 0 0 5
lookat 0 0 5
up 0 0 1
