#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the seed corpus of FuzzSurfacePipeline (see its input layout):
small closed meshes, some with the flags for CAD mode, raw doubles and
orientation left unfixed. Rerun after changing the layout."""
import os
import struct

CUBE_TRIANGLES = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
                  (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]


def cube(offset=(0, 0, 0), scale=1.0, inward=False):
    pts = [(offset[0] + scale * (i & 1), offset[1] + scale * ((i >> 1) & 1),
            offset[2] + scale * ((i >> 2) & 1)) for i in range(8)]
    tris = [(a, c, b) if inward else (a, b, c) for a, b, c in CUBE_TRIANGLES]
    return pts, tris


def tetrahedron():
    return [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def octahedron():
    pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    tris = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return pts, tris


def append(a, b):
    base = len(a[0])
    return a[0] + b[0], a[1] + [(x + base, y + base, z + base) for x, y, z in b[1]]


def encode(mesh, flags=0):
    pts, tris = mesh
    assert len(pts) <= 32 and len(tris) <= 64
    out = bytearray([flags, len(pts)])
    for p in pts:
        for c in p:
            if flags & 1:
                out += struct.pack('<d', c)
            else:
                v = round(c * 64)
                assert -32768 <= v < 32768
                out += struct.pack('<h', v)
    out.append(len(tris))
    for t in tris:
        out += bytes(t)
    return bytes(out)


SEEDS = {
    'tetrahedron': encode(tetrahedron()),
    'cube': encode(cube(scale=4)),
    'cube_cad': encode(cube(scale=4), flags=2),
    'octahedron': encode(octahedron()),
    'cube_inward': encode(cube(scale=2, inward=True)),
    'cube_inward_unfixed': encode(cube(scale=2, inward=True), flags=4),
    'nested_cubes': encode(append(cube(scale=8), cube((2, 2, 2), 4))),
    'two_cubes': encode(append(cube(scale=2), cube((5, 0, 0), 3))),
    'cube_far_raw': encode(cube((1e6, 1e6, 1e6), 1.0), flags=1),
    'cube_tiny_raw': encode(cube(scale=1e-30), flags=1),
    'cube_huge_raw': encode(cube(scale=1e30), flags=3),
    # Bit 3: adaptive sampling (thickness rays, sizing field).
    'nested_cubes_adaptive': encode(append(cube(scale=8), cube((2, 2, 2), 4)), flags=8),
    'cube_tiny_raw_adaptive': encode(cube(scale=1e-30), flags=9),
    'cube_huge_raw_adaptive': encode(cube(scale=1e30), flags=11),
    # Bit 4: crossing shells resolved into their union (else refused).
    'overlapping_cubes': encode(append(cube(scale=4), cube((2, 2, 2), 4))),
    'overlapping_cubes_repair': encode(append(cube(scale=4), cube((2, 2, 2), 4)), flags=16),
    'overlapping_cubes_repair_cad': encode(append(cube(scale=4), cube((2, 1, 1), 2)), flags=18),
}

if __name__ == '__main__':
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'corpus', 'FuzzSurfacePipeline')
    os.makedirs(folder, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(folder, name), 'wb') as f:
            f.write(data)
