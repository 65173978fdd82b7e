# Triangles with surface coordinates: flat, smooth, mirrored, in a mesh block
# wound inward (turned over at end), and the forms inside csg (errors).
surface 0.8 0.6 0.4  1 0 0  1 1
triangle_uv -1 -1 0  0 0   1 -1 0  1 0   1 1 0  1 1
ptriangle_uv -1 -1 1  0 0 1  0 0   1 1 1  0 0 1  1 1   -1 1 1  0.2 0 1  0 1
push
  scale -1 1 1
  triangle_uv 0 0 0  0.1 0.2   2 0 0  0.7 0.3   0 3 0  0.4 0.9
pop
mesh
  triangle_uv 0 0 0  0 0      1 0 0  0.5 0    0 1 0  0 0.5
  triangle_uv 0 0 0  0 0      0 0 1  0.25 0.125  1 0 0  0.5 0
  ptriangle_uv 0 0 0  -1 -1 -1  0 0   0 1 0  0 1 0  0 0.5   0 0 1  0 0 1  0.25 0.125
  triangle_uv 1 0 0  0.5 0    0 0 1  0.25 0.125  0 1 0  0 0.5
end
csg union
  sphere 0 0 0 1
  triangle_uv 0 0 0 0 0  1 0 0 1 0  0 1 0 0 1
  mesh
    triangle_uv 0 0 0 0 0  0 1 0 0 1  1 0 0 1 0
  end
end
triangle_uv 0 0 0 0 0  1 0 0 1
