# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Hands the files test_writers wrote to the programs that use them and checks
# what those programs make of them against box_expected.json:
#   check_consumers.py gmsh|vtk|tetgen|ccx DIR
# Exit status: 0 passed, 77 skipped (the program or module is missing), else failed.

import json
import math
import os
import shutil
import subprocess
import sys

SKIP = 77


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def load_expected(d):
    with open(os.path.join(d, "box_expected.json")) as f:
        return json.load(f)


def check_gmsh(d, exp):
    try:
        import gmsh
    except ImportError:
        print("SKIP: no gmsh python module (Debian: python3-gmsh)")
        return SKIP
    gmsh.initialize(["gmsh", "-v", "2"])
    try:
        # .msh: one named physical group per region and per patch
        gmsh.open(os.path.join(d, "box.msh"))
        groups = gmsh.model.getPhysicalGroups()
        want = [(2, int(k)) for k in exp["patches"]] + [(3, int(k)) for k in exp["regions"]]
        check(sorted(groups) == sorted(want), "physical groups %s, expected %s" % (groups, want))
        for dim, key, what, etype in ((3, "regions", "tets", 4), (2, "patches", "triangles", 2)):
            for tag, e in exp[key].items():
                name = gmsh.model.getPhysicalName(dim, int(tag))
                check(name == e["name"], "physical (%d,%s) is named %r, expected %r" % (dim, tag, name, e["name"]))
                n = 0
                for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, int(tag)):
                    types, tags, _ = gmsh.model.mesh.getElements(dim, ent)
                    check(list(types) in ([], [etype]), "element types %s in (%d,%d)" % (list(types), dim, ent))
                    n += sum(len(t) for t in tags)
                check(n == e[what], "group %r has %d elements, expected %d" % (name, n, e[what]))
                print("gmsh: .msh physical group (%d, %s) %r: %d %s" % (dim, tag, name, n, what))
        node_tags, _, _ = gmsh.model.mesh.getNodes()
        check(len(node_tags) == exp["points"], "%d nodes, expected %d" % (len(node_tags), exp["points"]))
        # Gmsh's own measure of orientation: the Jacobian determinant of every tet
        _, dets, _ = gmsh.model.mesh.getJacobians(4, [0.25, 0.25, 0.25])
        check(len(dets) == exp["tets"] and min(dets) > 0, "non-positive tet Jacobians in Gmsh")
        print("gmsh: %d nodes, %d tets all with positive Jacobian (min %.3g)" % (len(node_tags), len(dets), min(dets)))
        # .mesh: Gmsh makes an elementary entity per Medit reference
        gmsh.clear()
        gmsh.open(os.path.join(d, "box.mesh"))
        for dim, key, what in ((3, "regions", "tets"), (2, "patches", "triangles")):
            for tag, e in exp[key].items():
                types, tags, _ = gmsh.model.mesh.getElements(dim, int(tag))
                n = sum(len(t) for t in tags)
                check(n == e[what], ".mesh ref %s (dim %d): %d elements, expected %d" % (tag, dim, n, e[what]))
        print("gmsh: .mesh read with %d tets and %d triangles under their references" % (exp["tets"], exp["triangles"]))
    finally:
        gmsh.finalize()
    return 0


def check_vtk(d, exp):
    try:
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    except ImportError:
        try:
            from vtk import vtkXMLUnstructuredGridReader
        except ImportError:
            print("SKIP: no vtk python module (Debian: python3-vtk9)")
            return SKIP
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(d, "box.vtu"))
    r.Update()
    g = r.GetOutput()
    check(g.GetNumberOfPoints() == exp["points"], "vtk: %d points" % g.GetNumberOfPoints())
    check(g.GetNumberOfCells() == exp["tets"] + exp["triangles"], "vtk: %d cells" % g.GetNumberOfCells())
    region = g.GetCellData().GetArray("region")
    patch = g.GetCellData().GetArray("patch")
    check(region is not None and patch is not None, "vtk: no region or patch cell array")
    counts = {}
    for c in range(g.GetNumberOfCells()):
        key = (g.GetCellType(c), int(region.GetValue(c)), int(patch.GetValue(c)))
        counts[key] = counts.get(key, 0) + 1
    want = {}
    for tag, e in exp["regions"].items():
        want[(10, int(tag), -1)] = e["tets"]
    for tag, e in exp["patches"].items():
        want[(5, -1, int(tag))] = e["triangles"]
    check(counts == want, "vtk: (cell type, region, patch) counts %s, expected %s" % (counts, want))
    names = g.GetFieldData().GetAbstractArray("region_names")
    check(names is not None, "vtk: no region_names field data")
    for tag, e in exp["regions"].items():
        check(names.GetValue(int(tag)) == e["name"], "vtk: region_names[%s] = %r" % (tag, names.GetValue(int(tag))))
    # VTK's own cell measure: every tet has a positive signed volume
    from vtkmodules.vtkCommonDataModel import vtkTetra
    pts = g.GetPoints()
    smallest = min(vtkTetra.ComputeVolume(*[pts.GetPoint(g.GetCell(c).GetPointId(i)) for i in range(4)])
                   for c in range(g.GetNumberOfCells()) if g.GetCellType(c) == 10)
    check(smallest > 0, "vtk: a tet of non-positive volume")
    print("vtk: %d points, %d cells; region/patch arrays per cell match; names %s; smallest tet volume %.3g"
          % (g.GetNumberOfPoints(), g.GetNumberOfCells(),
             [names.GetValue(i) for i in range(names.GetNumberOfValues())], smallest))
    return 0


def program_and_copies(d, program, package, files):
    """the path of `program` and a folder of its own holding copies of `files`, or None"""
    path = shutil.which(program)
    if path is None:
        print("SKIP: no %s program (Debian: %s)" % (program, package))
        return None
    work = os.path.join(d, program)
    os.makedirs(work, exist_ok=True)
    for f in files:
        shutil.copy(os.path.join(d, f), work)
    return path, work


def check_tetgen(d, exp):
    found = program_and_copies(d, "tetgen", "tetgen", ["box.node", "box.ele", "box.face"])
    if found is None:
        return SKIP
    tetgen, work = found
    # -r: reconstruct the mesh from the files, -C: check it
    p = subprocess.run([tetgen, "-rCV", "box"], cwd=work, capture_output=True, text=True, timeout=120)
    out = p.stdout + p.stderr
    check(p.returncode == 0, "tetgen -rCV exited with %d:\n%s" % (p.returncode, out[-2000:]))
    check("the mesh appears to be consistent" in out, "tetgen does not find the mesh consistent:\n" + out[-2000:])
    check("Mesh boundaries connected correctly" in out, "tetgen: boundary not connected:\n" + out[-2000:])

    def last_column_counts(path):
        counts = {}
        with open(path) as f:
            lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
        for l in lines[1:]:
            counts[int(float(l[-1]))] = counts.get(int(float(l[-1])), 0) + 1
        return counts

    ele = last_column_counts(os.path.join(work, "box.1.ele"))
    face = last_column_counts(os.path.join(work, "box.1.face"))
    check(ele == {int(k): e["tets"] for k, e in exp["regions"].items()}, "tetgen: region attributes %s" % ele)
    check(face == {int(k): e["triangles"] for k, e in exp["patches"].items()}, "tetgen: face markers %s" % face)
    print("tetgen -rC: mesh consistent, boundary connected; regions %s, face markers %s kept" % (ele, face))
    return 0


def read_inp_nodes_and_elsets(path):
    """node coordinates and element-set names of an Abaqus file written by write_abaqus_inp"""
    nodes, elsets = {}, []
    with open(path) as f:
        block = None
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                words = [w.strip() for w in line.split(",")]
                block = words[0].upper()
                for w in words[1:]:
                    if block == "*ELEMENT" and w.upper().startswith("ELSET="):
                        elsets.append(w.split("=", 1)[1])
                continue
            if block == "*NODE":
                v = line.split(",")
                nodes[int(v[0])] = tuple(float(x) for x in v[1:4])
    return nodes, elsets


def solve_under_gravity(ccx, work, inp_name, materials):
    """Runs CalculiX on `inp_name` in `work` as a linear-elastic body under its own weight,
    fixed at its lowest nodes. `materials` maps each ELSET to (E, nu, rho). Checks a clean
    run and that the largest displacement is at the top, pointing down; returns
    (nodes, displacements, top node, base nodes)."""
    nodes, elsets = read_inp_nodes_and_elsets(os.path.join(work, inp_name))
    check(set(elsets) == set(materials), "ELSETs %s, materials for %s" % (sorted(elsets), sorted(materials)))
    zmin = min(p[2] for p in nodes.values())
    zmax = max(p[2] for p in nodes.values())
    base = sorted(n for n, p in nodes.items() if p[2] == zmin)
    # what the mesh writer leaves to users: materials, sections, supports, loads
    deck = ["*INCLUDE, INPUT=%s" % inp_name]
    for i, (elset, (e, nu, rho)) in enumerate(sorted(materials.items())):
        deck += ["*MATERIAL, NAME=ROCK%d" % (i + 1), "*ELASTIC", "%g, %g" % (e, nu), "*DENSITY", "%g" % rho]
        deck += ["*SOLID SECTION, ELSET=%s, MATERIAL=ROCK%d" % (elset, i + 1)]
    deck += ["*NSET, NSET=BASE"] + [", ".join(str(n) for n in base[i:i + 16]) for i in range(0, len(base), 16)]
    deck += ["*NSET, NSET=EVERY_NODE, GENERATE", "1, %d, 1" % max(nodes)]
    deck += ["*BOUNDARY", "BASE, 1, 3, 0.", "*STEP", "*STATIC", "*DLOAD"]
    deck += ["%s, GRAV, 9.81, 0., 0., -1." % elset for elset in sorted(materials)]
    deck += ["*NODE PRINT, NSET=EVERY_NODE", "U", "*END STEP"]
    with open(os.path.join(work, "gravity.inp"), "w") as f:
        f.write("\n".join(deck) + "\n")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    p = subprocess.run([ccx, "-i", "gravity"], cwd=work, capture_output=True, text=True, timeout=600, env=env)
    out = p.stdout + p.stderr
    check(p.returncode == 0, "ccx exited with %d:\n%s" % (p.returncode, out[-3000:]))
    check("*ERROR" not in out.upper(), "ccx reports errors:\n" + out[-3000:])
    check("*WARNING" not in out.upper(), "ccx warns:\n" + out[-3000:])
    check("Job finished" in out, "ccx did not finish:\n" + out[-3000:])
    u = {}
    with open(os.path.join(work, "gravity.dat")) as f:
        for line in f:
            v = line.split()
            if len(v) == 4 and v[0].isdigit():
                u[int(v[0])] = tuple(float(x) for x in v[1:])
    check(len(u) == len(nodes), "ccx printed %d displacements, expected %d" % (len(u), len(nodes)))
    mag = {n: math.sqrt(sum(c * c for c in x)) for n, x in u.items()}
    top = max(mag, key=lambda n: (mag[n], -n))
    check(max(mag[n] for n in base) == 0.0, "ccx: the base moves")
    check(nodes[top][2] == zmax, "ccx: largest displacement at z = %g, not at the top z = %g" % (nodes[top][2], zmax))
    check(u[top][2] < 0, "ccx: the top moves up under gravity")
    return nodes, u, mag, top, zmin, zmax


def check_ccx(d, exp):
    found = program_and_copies(d, "ccx", "calculix-ccx", ["box.inp"])
    if found is None:
        return SKIP
    ccx, work = found
    elsets = exp["abaqus_elsets"]
    rocks = {"1": (1.0e9, 0.25, 2500.0), "2": (5.0e8, 0.30, 2200.0)}
    nodes, u, mag, top, zmin, zmax = solve_under_gravity(
        ccx, work, "box.inp", {elset: rocks[r] for r, elset in elsets.items()})
    check(len(u) == exp["points"], "ccx printed %d displacements, expected %d" % (len(u), exp["points"]))
    # a column of the softer rock under its own weight settles rho g H^2 / (2 E) at the top
    estimate = 2200.0 * 9.81 * (zmax - zmin) ** 2 / (2 * 5.0e8)
    check(estimate / 3 < mag[top] < 3 * estimate, "ccx: top settles %g, expected about %g" % (mag[top], estimate))
    print("ccx: %d nodes solved, base fixed, largest displacement %.3g at node %d (z = %g, the top); "
          "a soft column would settle %.3g" % (len(u), mag[top], top, nodes[top][2], estimate))
    return 0


def check_ccx_model(inp):
    """CalculiX on a whole model's .inp (e.g. the bundled model meshed by bubble_mesh_3):
    one rock for every region, base fixed, own weight"""
    work = os.path.dirname(os.path.abspath(inp))
    ccx = shutil.which("ccx")
    if ccx is None:
        print("SKIP: no ccx program (Debian: calculix-ccx)")
        return SKIP
    _, elsets = read_inp_nodes_and_elsets(inp)
    rock = (2.0e10, 0.25, 2600.0)
    nodes, u, mag, top, zmin, zmax = solve_under_gravity(ccx, work, os.path.basename(inp),
                                                         {e: rock for e in elsets})
    # a column of rock under its own weight settles rho g H^2 / (2 E) at the top
    estimate = rock[2] * 9.81 * (zmax - zmin) ** 2 / (2 * rock[0])
    check(estimate / 3 < mag[top] < 3 * estimate, "ccx: top settles %g, expected about %g" % (mag[top], estimate))
    print("ccx: %d nodes, %d regions solved; base fixed; largest displacement %.3g at z = %g (the top); "
          "a rock column would settle %.3g" % (len(u), len(elsets), mag[top], nodes[top][2], estimate))
    return 0


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "ccx-model":
        return check_ccx_model(sys.argv[2])
    if len(sys.argv) != 3 or sys.argv[1] not in ("gmsh", "vtk", "tetgen", "ccx"):
        print("usage: check_consumers.py gmsh|vtk|tetgen|ccx DIR   or   check_consumers.py ccx-model FILE.inp")
        return 2
    d = sys.argv[2]
    exp = load_expected(d)
    return {"gmsh": check_gmsh, "vtk": check_vtk, "tetgen": check_tetgen, "ccx": check_ccx}[sys.argv[1]](d, exp)


if __name__ == "__main__":
    sys.exit(main())
