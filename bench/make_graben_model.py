#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a graben with blind faults, a thin layer and a lens as a multi-body
OBJ: in a 3000 x 2000 x 1000 box, three undulating horizons dipping 4.6
degrees (the upper two a thin layer apart), two normal faults dipping 60
degrees towards each other that cut the middle layers and end inside the
bottom and top bodies at both ends, and a lens (a flattened ellipsoid) inside
the middle layer. The surfaces are meshed by Gmsh's OCC kernel
(python3-gmsh), as a modelling tool would export them: where a fault or a
horizon meets the wall y = 0, Gmsh writes some of the cut points up to 4e-11
off the wall's plane.

usage: make_graben_model.py OUT.obj [--edge H] [--thickness T]
  --edge H       largest triangle edge (default 60)
  --thickness T  thickness of the thin layer (default 8)
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test", "Bubble_mesh_3"))
from make_pinch_out_model import write_bodies_and_free_surfaces  # noqa: E402

X, Y, Z = 3000., 2000., 1000.
BASES = (250., 450.)  # the lower two horizons at x = 0; the third is the thin layer's top


def horizon_z(base, x, y):
    return base + 0.08 * x + 30. * math.sin(y / 400.)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--edge", type=float, default=60.)
    parser.add_argument("--thickness", type=float, default=8.)
    a = parser.parse_args()
    if not (a.edge > 0. and 0. < a.thickness < 100.):
        parser.error("needs edge > 0 and 0 < thickness < 100")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    box = occ.addBox(0, 0, 0, X, Y, Z)

    def horizon(base):  # a B-spline through a grid wider than the box
        nu, nv = 8, 6
        grid = []
        for j in range(nv):
            for i in range(nu):
                x, y = -100. + (X + 200.) * i / (nu - 1), -100. + (Y + 200.) * j / (nv - 1)
                grid.append(occ.addPoint(x, y, horizon_z(base, x, y)))
        return occ.addBSplineSurface(grid, nu)

    tools = [(2, horizon(b)) for b in BASES + (BASES[1] + a.thickness,)]
    for x0, turn in ((1000., 120.), (2000., 60.)):  # 700 wide down the dip, from z = 120 up and outwards to 726
        f = occ.addRectangle(x0, -50., 120., 700., Y + 100.)
        occ.rotate([(2, f)], x0, 0., 120., 0, 1, 0, -math.radians(turn))
        tools.append((2, f))
    lens = occ.addSphere(600., 1000., 400., 100.)
    occ.dilate([(3, lens)], 600., 1000., 400., 2.0, 1.2, 0.4)
    occ.fragment([(3, box), (3, lens)], tools)
    occ.synchronize()
    bounding = set()
    for _, v in gmsh.model.getEntities(3):
        bounding.update(abs(s) for _, s in gmsh.model.getBoundary([(3, v)], oriented=False))
    for _, s in gmsh.model.getEntities(2):  # the horizons' and faults' rims outside the box
        b = occ.getBoundingBox(2, s)
        inside = b[0] > -1e-6 and b[1] > -1e-6 and b[2] > -1e-6 and b[3] < X + 1e-6 and b[4] < Y + 1e-6 and b[5] < Z + 1e-6
        if s not in bounding and not inside:
            occ.remove([(2, s)], recursive=True)
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 6)
    gmsh.model.mesh.generate(2)

    mean_wave = 30. * 400. * (1. - math.cos(Y / 400.)) / Y  # the horizons' mean lift over y

    def body_name(x, z, volume):
        if volume < 1e7 and abs(x - 600.) < 100. and abs(z - 400.) < 30.:
            return "lens"
        # a body's centre lies mid-way between its horizons (the B-splines only approach
        # horizon_z, by metres: a thin layer's centre is not told apart from its horizons)
        middle, thin = sum(BASES) / 2., BASES[1] + a.thickness / 2.
        between = (BASES[0], (middle + thin) / 2., thin + 50.)
        layer = sum(1 for b in between if z > b + 0.08 * x + mean_wave)
        if layer in (1, 2):  # the faults cut these: west of both, the graben, east of both
            cot = 1. / math.tan(math.radians(60.))
            side = "w" if x < 1000. - (z - 120.) * cot else "e" if x > 2000. + (z - 120.) * cot else "g"
            return ("middle_", "thin_")[layer - 1] + side
        return ("bottom", None, None, "top")[layer]

    def faults(free):  # the blind ends: two below the lowest horizon, two above the thin layer
        return [(s, "fault_%d" % k, "bottom" if occ.getCenterOfMass(2, s)[2] < 300. else "top")
                for k, s in enumerate(free)]

    write_bodies_and_free_surfaces(a.out, "make_graben_model.py --edge %g --thickness %g" % (a.edge, a.thickness),
                                   body_name, faults)
    gmsh.finalize()


if __name__ == "__main__":
    main()
