#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a three-body model as a multi-body OBJ: a lower and an upper body, a
wedge-shaped layer between them that pinches out at a small angle, and a steep
fault that ends inside the lower body. The surfaces are meshed by Gmsh's OCC
kernel (python3-gmsh), as a modelling tool would export them.

usage: make_pinch_out_model.py OUT.obj [--slope S] [--edge H] [--width Y]
  --slope S  rise of the wedge's top over its length (default 0.03: 1.72 degrees)
  --edge H   largest triangle edge (default 40)
  --width Y  extent of the box along y (default 600)
The box is 1000 x Y x 400; the wedge runs from x = 0 (thickness 600 S) to x = 600.
"""
import argparse
import math
from collections import defaultdict, deque

import gmsh


def oriented(triangles, coords):
    """The triangles of one closed body turned consistently, then outward."""
    tris = [list(t) for t in triangles]
    by_edge = defaultdict(list)
    for i, t in enumerate(tris):
        for k in range(3):
            by_edge[frozenset((t[k], t[(k + 1) % 3]))].append(i)
    seen = [False] * len(tris)
    for start in range(len(tris)):
        if seen[start]:
            continue
        seen[start] = True
        queue = deque([start])
        while queue:
            t = tris[queue.popleft()]
            for k in range(3):
                a, b = t[k], t[(k + 1) % 3]
                for j in by_edge[frozenset((a, b))]:
                    if seen[j]:
                        continue
                    u = tris[j]
                    # a neighbour turned the same way runs the shared edge b -> a
                    if any(u[m] == a and u[(m + 1) % 3] == b for m in range(3)):
                        u.reverse()
                    seen[j] = True
                    queue.append(j)
    volume = 0.
    for a, b, c in tris:
        p, q, r = coords[a - 1], coords[b - 1], coords[c - 1]
        volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                   + p[2] * (q[0] * r[1] - q[1] * r[0]))
    return [tuple(t[::-1]) for t in tris] if volume < 0 else [tuple(t) for t in tris]


def gmsh_surface_mesh():
    """Gmsh's current mesh as OBJ wants it: the node coordinates (numbered from
    1 in that order) and a function giving a surface's triangles in that numbering."""
    tags, flat, _ = gmsh.model.mesh.getNodes()
    index = {int(t): i + 1 for i, t in enumerate(tags)}
    coords = [tuple(flat[3 * i:3 * i + 3]) for i in range(len(tags))]

    def triangles(surface):
        _, _, nodes = gmsh.model.mesh.getElements(2, surface)
        n = nodes[0]
        return [tuple(index[int(n[k + m])] for m in range(3)) for k in range(0, len(n), 3)]

    return coords, triangles


def write_bodies_and_free_surfaces(path, made_by, body_name, free_groups):
    """Writes Gmsh's current surface mesh as a multi-body OBJ: each volume as a
    closed body named body_name(x, z, volume) of its centre of mass, and the
    surfaces that bound no volume (faults ending inside a body), in Gmsh's
    order, as the groups free_groups(tags) gives: (tag, group name, body it lies in)."""
    occ = gmsh.model.occ
    coords, triangles = gmsh_surface_mesh()
    lines = ["# made by " + made_by]
    lines += ["v %.12g %.12g %.12g" % p for p in coords]
    bounding = set()
    for _, body in gmsh.model.getEntities(3):
        x, _, z = occ.getCenterOfMass(3, body)
        lines.append("o " + body_name(x, z, occ.getMass(3, body)))
        tris = []
        for _, s in gmsh.model.getBoundary([(3, body)], oriented=False, recursive=False):
            bounding.add(abs(s))
            tris += triangles(abs(s))
        lines += ["f %d %d %d" % t for t in oriented(tris, coords)]
    for s, name, inside in free_groups([s for _, s in gmsh.model.getEntities(2) if s not in bounding]):
        lines += ["g " + name, "#@inside " + inside, "#@patch " + name]
        lines += ["f %d %d %d" % t for t in triangles(s)]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def write_multibody_obj(path, made_by, body_name, free_name, free_inside):
    """write_bodies_and_free_surfaces() for a model with one surface that bounds no
    volume: group free_name inside body free_inside."""
    def one(free):
        if len(free) != 1:
            raise SystemExit("%s: the %s should be one surface inside the %s body, got %d"
                             % (made_by.split()[0], free_name, free_inside, len(free)))
        return [(free[0], free_name, free_inside)]
    write_bodies_and_free_surfaces(path, made_by, body_name, one)


def write_closed_bodies(path, made_by, body_name):
    """write_bodies_and_free_surfaces() for a model whose every surface bounds a
    volume (no fault ends inside a body)."""
    def none(free):
        if free:
            raise SystemExit("%s: %d surfaces bound no body" % (made_by.split()[0], len(free)))
        return []
    write_bodies_and_free_surfaces(path, made_by, body_name, none)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--slope", type=float, default=0.03)
    parser.add_argument("--edge", type=float, default=40.)
    parser.add_argument("--width", type=float, default=600.)
    a = parser.parse_args()
    if not (0. < a.slope < 0.3 and a.edge > 0. and a.width > 0.):
        parser.error("needs 0 < slope < 0.3, edge > 0 and width > 0")
    y = a.width
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    occ = gmsh.model.occ
    lower = occ.addBox(0, 0, 0, 1000, y, 200)
    upper = occ.addBox(0, 0, 200, 1000, y, 200)
    corners = [occ.addPoint(0, 0, 200), occ.addPoint(600, 0, 200), occ.addPoint(0, 0, 200 + 600 * a.slope)]
    loop = occ.addCurveLoop([occ.addLine(corners[i], corners[(i + 1) % 3]) for i in range(3)])
    wedge = [e for e in occ.extrude([(2, occ.addPlaneSurface([loop]))], 0, y, 0) if e[0] == 3][0][1]
    upper_parts, _ = occ.cut([(3, upper)], [(3, wedge)], removeTool=False)
    fault = occ.addRectangle(0, y / 4, 40, 120, y / 2)
    occ.rotate([(2, fault)], 0, y / 4, 40, 0, 1, 0, -1.2)  # steep, 40 to 150 high: inside the lower body
    occ.translate([(2, fault)], 300, 0, 0)
    occ.fragment([(3, lower), (3, wedge)] + upper_parts, [(2, fault)])
    occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", a.edge)
    gmsh.option.setNumber("Mesh.MeshSizeMin", a.edge / 4)
    gmsh.model.mesh.generate(2)

    write_multibody_obj(a.out, "make_pinch_out_model.py --slope %g --edge %g --width %g (%.3f degrees)"
                        % (a.slope, a.edge, a.width, math.degrees(math.atan(a.slope))),
                        lambda x, z, mass: "wedge" if abs(z - 200) < 40 and x < 400 else ("lower" if z < 200 else "upper"),
                        "fault", "lower")
    gmsh.finalize()


if __name__ == "__main__":
    main()
