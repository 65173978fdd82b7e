surface 1 1 1 0 0 9 4
1e55
sphere 0 0 0 4