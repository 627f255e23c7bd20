#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a thin layer across a box, as a multi-body OBJ: two horizontal
horizons a few metres apart split a 1000 x 800 x 600 box into three bodies,
so the layer's side walls are strips of needles. The surfaces are meshed by
Gmsh's OCC kernel (python3-gmsh), as a modelling tool would export them. A
benchmark input for the thin-layer rule of --remesh-surfaces: the layer's
horizons are re-meshed far finer than the box, and the bodies beside it must
grade from that size up to the target (bench/README.md, sessions 45 and 56).

usage: make_thin_layer_model.py OUT.obj [--edge H] [--thickness T]
  --edge H       largest triangle edge (default 60; the smallest is a quarter)
  --thickness T  the layer's thickness (default 2), its floor at z = 300
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test", "Bubble_mesh_3"))
from make_pinch_out_model import write_closed_bodies  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--edge", type=float, default=60.)
    parser.add_argument("--thickness", type=float, default=2.)
    a = parser.parse_args()
    if not (a.edge > 0. and 0. < a.thickness < 100.):
        parser.error("needs edge > 0 and 0 < thickness < 100")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    box = occ.addBox(0, 0, 0, 1000, 800, 600)
    horizons = [(2, occ.addRectangle(0, 0, z, 1000, 800)) for z in (300., 300. + a.thickness)]
    occ.fragment([(3, box)], horizons)
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 4)
    gmsh.model.mesh.generate(2)

    def body_name(x, z, volume):
        del x, volume
        return "lower" if z < 300. else "layer" if z < 300. + a.thickness else "upper"
    write_closed_bodies(a.out, "make_thin_layer_model.py --edge %g --thickness %g" % (a.edge, a.thickness), body_name)
    gmsh.finalize()


if __name__ == "__main__":
    main()
