4 6 4 # tetrahedron of spheres, MATFP-style trailing flags
v 0 0 0 0.25 1
v 1 0 0 0.125 0
v 0 1 0 1e-3 0
v 0 0 1 0 1
e 0 1 1
e 1 2 0
e 2 0 0
e 0 3 0
e 1 3 0
e 2 3 0

f 0 1 2 0
f 0 1 3 0
f 1 2 3 0
f 0 2 3 0
