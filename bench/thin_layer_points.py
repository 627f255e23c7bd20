#!/usr/bin/env python3
"""How many layers of points a thin region of a tetrahedral mesh has between its faces.

usage: bench/thin_layer_points.py MESH.mesh REGION [REGION ...]

Reads a Medit .mesh (as bubble_mesh_3 -o writes it) and, for each region
label given, counts the region's vertices that lie on no boundary face of the
region (faces of its tets that no other tet of the region shares) and divides
by half the number that do. For a slab-like layer whose two faces carry most
of its boundary points, that is about the number of layers of points inside:
0 means one tetrahedron across, 1 about two. Needs numpy (Debian's
/usr/bin/python3 with python3-numpy).
"""
import sys

import numpy as np


def read_tetrahedra(path):
    with open(path) as f:
        lines = f.read().split('\n')
    for i, line in enumerate(lines):
        if line.strip() == 'Tetrahedra':
            n = int(lines[i + 1])
            return np.loadtxt(lines[i + 2:i + 2 + n], dtype=np.int64, ndmin=2)
    sys.exit(f"{path}: no Tetrahedra section")


def main():
    if len(sys.argv) < 3 or sys.argv[1] in ('-h', '--help'):
        print(__doc__.strip())
        sys.exit(0 if len(sys.argv) > 1 and sys.argv[1] in ('-h', '--help') else 2)
    tets = read_tetrahedra(sys.argv[1])
    for arg in sys.argv[2:]:
        region = int(arg)
        t = tets[tets[:, 4] == region][:, :4]
        if len(t) == 0:
            print(f"region {region}: no tetrahedra")
            continue
        faces = np.sort(np.concatenate([t[:, [0, 1, 2]], t[:, [0, 1, 3]], t[:, [0, 2, 3]], t[:, [1, 2, 3]]]), axis=1)
        unique, count = np.unique(faces, axis=0, return_counts=True)
        boundary = len(np.unique(unique[count == 1]))
        inside = len(np.unique(t)) - boundary
        print(f"region {region}: {len(t)} tets, {boundary} vertices on its boundary, {inside} inside: "
              f"{inside / (boundary / 2):.2f} inside per point of one face")


if __name__ == '__main__':
    main()
