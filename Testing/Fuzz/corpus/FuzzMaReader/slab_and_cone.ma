# A small medial mesh for the reader tests: one slab (triangle) with a cone
# (edge 2-3) hanging off it, and one isolated sphere (vertex 4).
5 4 1
v 0 0 0 0.5
v 1 0 0 0.4
v 0 1 0 0.3
v 0 2 0 0.2
v 5 5 5 1.0
e 0 1
e 1 2
e 2 0
e 2 3
f 0 1 2
