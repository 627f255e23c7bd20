#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a salt dome piercing a layered box, as a multi-body OBJ: two tilted
horizons split a 1000 x 800 x 500 box into three layers, and an elongated salt
body (an ellipsoid cut at the box's floor) rises through both, so that the salt
is three bodies stacked along curved contacts, each horizon ending on the salt
in a closed curve. The surfaces are meshed by Gmsh's OCC kernel (python3-gmsh),
as a modelling tool would export them. A benchmark input for curved contacts
between bodies that no horizon separates from the box walls.

usage: make_salt_dome_model.py OUT.obj [--edge H] [--height Z]
  --edge H    largest triangle edge (default 40)
  --height Z  half height of the salt ellipsoid, centred at z = 120 (default 288;
              from 212 its top rises above the upper horizon, under 380 it stays
              under the box's top)
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "test", "Bubble_mesh_3"))
from make_pinch_out_model import write_closed_bodies  # noqa: E402

CENTRE, RADIUS = (450., 400., 120.), 180.


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--edge", type=float, default=40.)
    parser.add_argument("--height", type=float, default=288.)
    a = parser.parse_args()
    if not (a.edge > 0. and 212. <= a.height < 380.):
        parser.error("needs edge > 0 and 212 <= height < 380 (the dome pierces both horizons, under the top)")
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    box = occ.addBox(0, 0, 0, 1000, 800, 500)
    horizons = []
    for z, axis, angle in ((170., (0, 1, 0), 4.), (330., (1, 0, 0), -3.)):
        h = occ.addRectangle(-100, -100, 0, 1200, 1000)
        occ.rotate([(2, h)], 0, 0, 0, axis[0], axis[1], axis[2], math.radians(angle))
        occ.translate([(2, h)], 0, 0, z)
        horizons.append((2, h))
    salt = occ.addSphere(CENTRE[0], CENTRE[1], CENTRE[2], RADIUS)
    occ.dilate([(3, salt)], CENTRE[0], CENTRE[1], CENTRE[2], 1, 1, a.height / RADIUS)
    clip = occ.addBox(0, 0, 0, 1000, 800, 500)
    salt = occ.intersect([(3, salt)], [(3, clip)])[0][0][1]
    _, children = occ.fragment([(3, box)], horizons + [(3, salt)])
    occ.synchronize()
    salt = set(t for _, t in children[-1])
    # the three layers and the three salt bodies, each named by its place in z (the
    # horizons are tilted: a low dome's cap may lie under z = 330)
    names = {}
    for prefix, tags in (("salt_", [t for _, t in gmsh.model.getEntities(3) if t in salt]),
                         ("layer_", [t for _, t in gmsh.model.getEntities(3) if t not in salt])):
        if len(tags) != 3:
            raise SystemExit("make_salt_dome_model: %d %sbodies, 3 expected" % (len(tags), prefix))
        tags.sort(key=lambda t: occ.getCenterOfMass(3, t)[2])
        for t, level in zip(tags, ("lower", "middle", "upper")):
            x, _, z = occ.getCenterOfMass(3, t)
            names[(x, z)] = prefix + level
    # the horizons' parts outside the box bound nothing
    for _, s in gmsh.model.getEntities(2):
        if len(gmsh.model.getAdjacencies(2, s)[0]) == 0:
            gmsh.model.removeEntities([(2, s)], recursive=True)
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 3)
    gmsh.model.mesh.generate(2)

    def body_name(x, z, volume):
        del volume
        return names[(x, z)]
    write_closed_bodies(a.out, "make_salt_dome_model.py --edge %g --height %g" % (a.edge, a.height), body_name)
    gmsh.finalize()


if __name__ == "__main__":
    main()
