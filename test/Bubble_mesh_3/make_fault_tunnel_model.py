#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a faulted layered model with a tunnel as a multi-body OBJ: three
layers offset by a normal fault (65 degrees, throw 40: the horizons end on the
fault at different heights on either side), a circular tunnel (radius 25)
through the hanging wall that a horizon cuts in two, and a small fault that
ends inside the middle footwall layer. The surfaces are meshed by Gmsh's OCC
kernel (python3-gmsh), finer on the tunnel's curvature, as a modelling tool
would export them.

usage: make_fault_tunnel_model.py OUT.obj [--edge H]
  --edge H  largest triangle edge (default 40); the box is 1000 x 600 x 400
"""
import argparse
import math

import gmsh

from make_pinch_out_model import write_multibody_obj


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--edge", type=float, default=40.)
    a = parser.parse_args()
    if not a.edge > 0.:
        parser.error("needs edge > 0")
    y = 600.
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    cot = 1. / math.tan(math.radians(65.))

    def fault_x(z):
        return 400. + z * cot

    foot, hang = [0., 130., 260., 400.], [0., 90., 220., 400.]

    def prism(section):  # a polygon in the xz-plane, extruded along y
        p = [occ.addPoint(x, 0, z) for x, z in section]
        loop = occ.addCurveLoop([occ.addLine(p[i], p[(i + 1) % len(p)]) for i in range(len(p))])
        return [e for e in occ.extrude([(2, occ.addPlaneSurface([loop]))], 0, y, 0) if e[0] == 3][0][1]

    bodies = []
    for i in range(3):
        z0, z1 = foot[i], foot[i + 1]
        bodies.append(prism([(0, z0), (fault_x(z0), z0), (fault_x(z1), z1), (0, z1)]))
        z0, z1 = hang[i], hang[i + 1]
        bodies.append(prism([(fault_x(z0), z0), (1000, z0), (1000, z1), (fault_x(z1), z1)]))
    tunnel = occ.addCylinder(760, 0, 215, 0, y, 0, 25)
    small_fault = occ.addRectangle(100, y / 3, 140, 110, y / 3)
    occ.rotate([(2, small_fault)], 100, y / 3, 140, 0, 1, 0, -1.3)  # steep, 140 to 247 high: inside foot_1
    occ.fragment([(3, b) for b in bodies] + [(3, tunnel)], [(2, small_fault)])
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 8)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 16)
    gmsh.model.mesh.generate(2)

    def body_name(x, z, volume):
        if volume < 0.01 * 1000. * y * 400.:
            return "tunnel_" + ("top" if z > 215 else "bottom")
        side, tops = ("foot", foot) if x < fault_x(z) else ("hang", hang)
        return "%s_%d" % (side, sum(1 for h in tops[1:3] if z > h))

    write_multibody_obj(a.out, "make_fault_tunnel_model.py --edge %g" % a.edge, body_name, "small_fault", "foot_1")
    gmsh.finalize()


if __name__ == "__main__":
    main()
