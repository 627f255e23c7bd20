#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a folded two-body model with faults ending inside the bodies, as a
multi-body OBJ: an anticline horizon (a B-spline dome) splits a 1000 x 800 x 500
box; two steep faults cross each other (an X) and cut the horizon, so each ends
inside both bodies; and two parallel faults a few units apart touch the wall x = 0
and end inside the lower body. The surfaces are meshed by Gmsh's OCC kernel
(python3-gmsh), as a modelling tool would export them. A benchmark input: the
pair of close faults makes a strongly graded sizing field around them.

usage: make_crossing_faults_model.py OUT.obj [--edge H] [--gap G]
  --edge H  largest triangle edge (default 40)
  --gap G   distance between the two parallel faults (default 4)
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test", "Bubble_mesh_3"))
from make_pinch_out_model import write_bodies_and_free_surfaces  # noqa: E402


def horizon_z(x, y):
    return 300 + 90 * math.exp(-((x - 500) / 300) ** 2 - ((y - 400) / 350) ** 2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--edge", type=float, default=40.)
    parser.add_argument("--gap", type=float, default=4.)
    a = parser.parse_args()
    if not (a.edge > 0. and 0. < a.gap < 100.):
        parser.error("needs edge > 0 and 0 < gap < 100")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    box = occ.addBox(0, 0, 0, 1000, 800, 500)
    nu, nv = 9, 7
    grid = [occ.addPoint(-50 + 1100 * i / (nu - 1), -50 + 900 * j / (nv - 1),
                         horizon_z(-50 + 1100 * i / (nu - 1), -50 + 900 * j / (nv - 1)))
            for j in range(nv) for i in range(nu)]
    horizon = occ.addBSplineSurface(grid, nu)
    tools = [(2, horizon)]
    for turn in (35, -35):  # the X: vertical, 500 long, from z = 40 to 440
        f = occ.addRectangle(250, 150, 40, 500, 400)
        occ.rotate([(2, f)], 250, 150, 40, 1, 0, 0, math.pi / 2)
        occ.rotate([(2, f)], 500, 150, 110, 0, 0, 1, math.radians(turn))
        occ.translate([(2, f)], 0, 250, 0)
        tools.append((2, f))
    for y0 in (100., 100. + a.gap):  # the pair: dipping 80 degrees, from the wall x = 0
        f = occ.addRectangle(0, y0, 60, 300, 200)
        occ.rotate([(2, f)], 0, y0, 60, 1, 0, 0, math.radians(80))
        tools.append((2, f))
    occ.fragment([(3, box)], tools)
    occ.synchronize()
    bounding = set()
    for _, v in gmsh.model.getEntities(3):
        bounding.update(abs(s) for _, s in gmsh.model.getBoundary([(3, v)], oriented=False))
    for _, s in gmsh.model.getEntities(2):
        b = occ.getBoundingBox(2, s)
        if s not in bounding and not (b[0] > -1e-6 and b[1] > -1e-6 and b[3] < 1000 + 1e-6 and b[4] < 800 + 1e-6):
            occ.remove([(2, s)], recursive=True)  # the horizon's rim outside the box
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 4)
    gmsh.model.mesh.generate(2)

    def faults(free):  # each inside the body on its side of the horizon
        groups = []
        for k, s in enumerate(free):
            x, y, z = occ.getCenterOfMass(2, s)
            groups.append((s, "fault_%d" % k, "lower" if z < horizon_z(x, y) else "upper"))
        return groups
    write_bodies_and_free_surfaces(a.out, "make_crossing_faults_model.py --edge %g --gap %g" % (a.edge, a.gap),
                                   lambda x, z, volume: "lower" if z < 250 else "upper", faults)
    gmsh.finalize()


if __name__ == "__main__":
    main()
