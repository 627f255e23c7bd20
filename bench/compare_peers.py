#!/usr/bin/env python3
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Peer comparison (issue 7, item 4): TetGen, Gmsh and bubble_mesh_3 on the same
geological models, on the same machine, in one run.

For each model: export_peer_inputs writes a TetGen PLC (.poly, facet marker =
patch + 1, one region seed per region) and a Gmsh discrete surface mesh; then
each mesher runs under a time limit and /usr/bin/time -v (wall time, peak
resident memory; a crash or an abort is a result, not a failure of this
script); every output mesh is measured by one tool, bubble_mesh_3_quality, and
export_peer_inputs --kept-whole counts the input triangles it keeps whole.
Writes a Markdown and a JSON table and one SVG of side-by-side histograms per
model. A benchmark, not a test.
"""

import argparse
import concurrent.futures
import glob
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
DEFAULT_MODEL = os.path.join(REPO, "examples", "Bubble_mesh_3", "data", "layered_model.obj")
SHARED_MODELS = os.path.join(REPO, "..", "shared", "data", "geomodels")
DEBIAN_PYTHON = "/usr/bin/python3"  # sees Debian's python3-gmsh (the pyenv python3 on PATH does not)
GNU_TIME = "/usr/bin/time"

# (name, kind, TetGen switches or bubble_mesh_3 extra arguments)
MESHERS = [
    ("tetgen -pA", "tetgen", "-pA"),
    ("tetgen -pq1.414/10 -A", "tetgen", "-pq1.414/10A"),
    ("tetgen -pYA", "tetgen", "-pYA"),
    ("gmsh Delaunay, surfaces kept", "gmsh", None),
    ("bubble_mesh_3", "bubble", []),
    ("bubble_mesh_3 --remesh-surfaces", "bubble", ["--remesh-surfaces"]),
    ("bubble_mesh_3 --keep-input-triangles", "bubble", ["--keep-input-triangles"]),
]
MESHER_KEYS = ["tetgen-pA", "tetgen-pq", "tetgen-pYA", "gmsh", "bubble", "bubble-remesh", "bubble-keep"]
# bubble-keep (planar pieces not re-triangulated) only when asked: it is the
# comparison of one choice of ours, and the default run has a time budget
DEFAULT_MESHERS = [k for k in MESHER_KEYS if k != "bubble-keep"]


def row_order(row):
    """a model's rows in the order of MESHERS"""
    return MESHER_KEYS.index(row["key"])


def fail(msg):
    sys.stderr.write("compare_peers: error: %s\n" % msg)
    sys.exit(1)


# ---------------------------------------------------------------------------
# Gmsh worker: runs under Debian's python3 (python3-gmsh)

def gmsh_worker(surf_msh, regions_json, out_msh):
    """Opens the discrete surfaces, makes one volume per region from its shells
    (outer shell first), embeds the surfaces inside regions, and meshes the
    volumes with Gmsh's 3D Delaunay (Mesh.Algorithm3D = 1). The discrete
    surfaces have no parametrization: Gmsh keeps their triangles as they are."""
    import gmsh  # noqa: imported here: only Debian's python3 has it
    with open(regions_json) as f:
        info = json.load(f)
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 1)
        gmsh.open(surf_msh)
        for r in info["regions"]:
            loops = [gmsh.model.geo.addSurfaceLoop(shell) for shell in r["shells"]]
            gmsh.model.geo.addVolume(loops, r["index"])
        gmsh.model.geo.synchronize()
        for r in info["regions"]:
            if r["inside"]:
                gmsh.model.mesh.embed(2, r["inside"], 3, r["index"])
            gmsh.model.addPhysicalGroup(3, [r["index"]], r["index"])
            gmsh.model.setPhysicalName(3, r["index"], r["name"])
        present = set(tag for dim, tag in gmsh.model.getEntities(2))
        for p in info["patches"]:
            if p["tag"] in present:
                gmsh.model.addPhysicalGroup(2, [p["tag"]], p["tag"])
                gmsh.model.setPhysicalName(2, p["tag"], p["name"])
        gmsh.option.setNumber("Mesh.Algorithm3D", 1)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        start = time.perf_counter()
        gmsh.model.mesh.generate(3)
        print("gmsh_worker: generate(3) took %.3f s" % (time.perf_counter() - start))
        gmsh.write(out_msh)
    except Exception as e:  # Gmsh raises a plain Exception with its last error
        sys.stderr.write("gmsh_worker: error: %s\n" % e)
        return 1
    finally:
        gmsh.finalize()
    return 0


# ---------------------------------------------------------------------------
# running a program with a time limit, wall time and peak memory

def run(cmd, cwd, timeout, log_path, use_time=True):
    """Runs cmd in its own process group; returns a dict with status ('ok',
    'timeout', 'crash', 'error'), wall seconds, peak RSS (MiB or None), the
    exit code or signal, and a one-line reason."""
    time_file = log_path + ".time"
    full = ([GNU_TIME, "-v", "-o", time_file] if use_time else []) + cmd
    with open(log_path, "w") as log:
        log.write("$ cd %s && %s\n" % (shlex.quote(cwd), " ".join(shlex.quote(c) for c in cmd)))
        log.flush()
        start = time.perf_counter()
        proc = subprocess.Popen(full, cwd=cwd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            rc = proc.wait(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            rc = proc.wait()
            timed_out = True
        wall = time.perf_counter() - start
    res = {"status": "ok", "wall_s": wall, "cpu_s": None, "peak_mib": None, "returncode": rc, "reason": ""}
    signum = None
    if use_time and os.path.exists(time_file):
        with open(time_file) as f:
            text = f.read()
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            res["peak_mib"] = int(m.group(1)) / 1024.0
        # CPU time (user + system): on a loaded machine it says more than the wall time
        user = re.search(r"User time \(seconds\): ([0-9.]+)", text)
        system = re.search(r"System time \(seconds\): ([0-9.]+)", text)
        if user and system:
            res["cpu_s"] = float(user.group(1)) + float(system.group(1))
        m = re.search(r"Command terminated by signal (\d+)", text)
        if m:
            signum = int(m.group(1))
        m = re.search(r"Command exited with non-zero status (\d+)", text)
        if m:
            rc = int(m.group(1))
    elif rc < 0:
        signum = -rc
    if timed_out:
        res["status"] = "timeout"
        res["reason"] = "timeout after %g s (killed)" % timeout
        res["peak_mib"] = res["cpu_s"] = None  # the killed /usr/bin/time wrote nothing reliable
    elif signum is not None:
        try:
            name = signal.Signals(signum).name
        except ValueError:
            name = "signal %d" % signum
        res["status"] = "crash"
        res["reason"] = "%s%s" % (name, _last_error_line(log_path, ": "))
    elif rc != 0:
        res["status"] = "error"
        res["reason"] = "exit %d%s" % (rc, _last_error_line(log_path, ": "))
    return res


def _last_error_line(log_path, prefix):
    """The most telling line of a log: an assertion, an error, else the last line."""
    try:
        with open(log_path, errors="replace") as f:
            lines = [l.strip() for l in f if l.strip() and not l.startswith("$ ")]
    except OSError:
        return ""
    for pattern in (r"Assertion", r"[Ee]rror", r"[Ee]xception", r"what\(\)"):
        for l in reversed(lines):
            if re.search(pattern, l):
                l = re.sub(r"^.*?(tetgen\.cxx:\d+: )", r"\1", l)
                return prefix + l[:200]
    return prefix + lines[-1][:200] if lines else ""


def region_volume_error(region_volumes, quality_regions):
    """The largest relative error of a region's volume in the mesh (tets labelled with its index)
    against the model; 1 for a region the mesh does not have."""
    meshed = {q["region"]: q["volume"] for q in quality_regions if isinstance(q.get("region"), int)}
    worst = 0.0
    for index, volume in region_volumes.items():
        v = meshed.get(index)
        worst = max(worst, 1.0 if v is None else abs(v - volume) / volume)
    return worst


def _own_time(kind, log_path):
    """The meshing time a peer reports itself (TetGen: CPU seconds after reading its input; Gmsh:
    wall seconds of generate(3)), or None."""
    pattern = {"tetgen": r"Total running seconds:\s*([0-9.eE+-]+)",
               "gmsh": r"gmsh_worker: generate\(3\) took ([0-9.eE+-]+) s"}.get(kind)
    if not pattern:
        return None
    try:
        with open(log_path, errors="replace") as f:
            m = re.search(pattern, f.read())
    except OSError:
        return None
    return float(m.group(1)) if m else None


def _bubble_stages(log_path):
    """bubble_mesh_3's own summary: seconds per stage and the sliver removal's before -> after
    (cells under its bound, smallest dihedral), or {}."""
    try:
        with open(log_path, errors="replace") as f:
            text = f.read()
    except OSError:
        return {}
    out = {}
    m = re.search(r"^time: (.*)$", text, re.M)
    if m:
        for name, value in re.findall(r"([a-z ]+?) ([0-9.eE+-]+) s", m.group(1)):
            out["time_" + name.strip().replace(" ", "_") + "_s"] = float(value)
    m = re.search(r"sliver removal: tetrahedra with a dihedral angle under ([0-9.]+) degrees (\d+) -> (\d+), "
                  r"smallest dihedral ([0-9.eE+-]+) -> ([0-9.eE+-]+)", text)
    if m:
        out.update({"sliver_bound": float(m.group(1)), "slivers_before": int(m.group(2)),
                    "slivers_after": int(m.group(3)), "min_dihedral_before": float(m.group(4)),
                    "min_dihedral_after": float(m.group(5))})
    return out


# ---------------------------------------------------------------------------

def find_tools(build_dir):
    tools = {
        "bubble_mesh_3": os.path.join(build_dir, "tools", "bubble_mesh_3"),
        "quality": os.path.join(build_dir, "tools", "bubble_mesh_3_quality"),
        "export": os.path.join(build_dir, "bench", "export_peer_inputs"),
    }
    missing = [p for p in tools.values() if not os.access(p, os.X_OK)]
    if missing:
        fail("missing program(s): %s\nbuild them with:\n  cmake -S %s -B %s -DCMAKE_BUILD_TYPE=Release "
             "-DBUBBLE_MESH_3_BUILD_BENCH=ON\n  make -C %s bubble_mesh_3 bubble_mesh_3_quality export_peer_inputs"
             % (", ".join(missing), REPO, build_dir, build_dir))
    return tools


def peer_availability(tools):
    """mesher kind -> None if available, else why not."""
    avail = {}
    avail["tetgen"] = None if shutil.which("tetgen") else "tetgen not on PATH (Debian: apt-get install tetgen)"
    if not os.access(DEBIAN_PYTHON, os.X_OK):
        avail["gmsh"] = "%s not found" % DEBIAN_PYTHON
    else:
        ok = subprocess.run([DEBIAN_PYTHON, "-c", "import gmsh"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL).returncode == 0
        avail["gmsh"] = None if ok else "python3-gmsh not importable by %s (Debian: apt-get install python3-gmsh)" % DEBIAN_PYTHON
    try:
        help_text = subprocess.run([tools["bubble_mesh_3"], "--help"], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True, timeout=30).stdout
    except (OSError, subprocess.TimeoutExpired):
        help_text = ""
    if re.search(r"(^|\s)-o[\s,]", help_text):
        avail["bubble"] = None
        avail["bubble-remesh"] = None if "--remesh-surfaces" in help_text else \
            "not available (bubble_mesh_3 --help lists no --remesh-surfaces yet)"
        avail["bubble-keep"] = None if "--keep-input-triangles" in help_text else \
            "not available (bubble_mesh_3 --help lists no --keep-input-triangles yet)"
    else:
        avail["bubble"] = avail["bubble-remesh"] = avail["bubble-keep"] = \
            "not available (bubble_mesh_3 --help lists no -o: it cannot mesh yet)"
    return avail


def model_name(path):
    return os.path.splitext(os.path.basename(path))[0]


def mesher_output(kind, workdir, base):
    if kind == "tetgen":
        return os.path.join(workdir, base + ".1.ele")
    if kind == "gmsh":
        return os.path.join(workdir, base + ".msh")
    return os.path.join(workdir, base + ".mesh")


# How the runs are scheduled. By default every run uses one thread (TetGen and
# Gmsh's 3D Delaunay have only one; bubble_mesh_3 gets --threads 1) and --jobs of
# them run at a time, in the order of run_rank(): the two-thread runs of before
# session 55 used 1.2-1.8 cores, and two one-thread runs side by side take no
# longer each than one alone (modelA1 re-meshed: 91.0 s alone, 91.7 s beside
# another), so the whole run takes about the CPU time of its rows over --jobs
# (837 s for the default models in session 55). With --bubble-threads T > 1 our
# runs take T threads and run alone after the peers, in phases over all models
# (sessions 26-54): the peers --jobs at a time, then ours with the surfaces kept,
# then ours re-meshed, cheapest model first.
PEER_KEYS = ["tetgen-pq", "tetgen-pYA", "tetgen-pA", "gmsh"]
PHASES = [PEER_KEYS, ["bubble", "bubble-keep"], ["bubble-remesh"]]

# Rough one-thread seconds per unit of a model's size, its volume over the cube of
# its median input edge (about the number of bubbles at the median size; it
# predicted our re-meshed runs within a factor 1.6 on the models in ../shared, the
# input triangles within 5): only the order of the runs depends on them. TetGen's
# -pq and -pY may run until their time limit whatever the size (modelA2, modelA5),
# so they count as long as that limit and start early.
SECONDS_PER_SIZE = {"bubble-remesh": 1.2e-2, "bubble": 3e-3, "bubble-keep": 3e-3, "gmsh": 3e-4, "tetgen-pA": 1e-5}


def expected_cost(ctx, key, args):
    """A guess of a run's seconds, capped at its time limit, to start the costliest first."""
    limit = args.remesh_timeout if key == "bubble-remesh" else \
        (args.bubble_timeout if key.startswith("bubble") else args.timeout)
    if key in ("tetgen-pq", "tetgen-pYA"):
        return limit
    guess = SECONDS_PER_SIZE[key] * (ctx["size"] if ctx["size"] is not None else 1e5)
    return guess if limit is None else min(guess, limit)


def phase_order(phase, contexts, done):
    """The models in the order a phase of the --bubble-threads T > 1 schedule visits
    them. The peers go largest model first (by input triangles): the runs likely to
    take longest start first, so that the short ones fill the other core beside them.
    The re-meshed runs take 5-15 times the surfaces-kept run of the same model: they
    go cheapest first (by that run's time, else by input triangles), so that what is
    left of the budget is spent on the rows that can finish, not on a large model
    killed half-way while a small one is skipped."""
    order = list(range(len(contexts)))

    def triangles(i):
        return contexts[i]["triangles"] if contexts[i]["triangles"] is not None else float("inf")
    if phase is PEER_KEYS:
        return sorted(order, key=lambda i: -triangles(i))
    if "bubble-remesh" not in phase:
        return order

    def cost(i):
        kept = [r for r in done[i] if r["key"] == "bubble" and r["status"] == "ok" and r["time_s"] is not None]
        if kept:
            return (0, kept[0]["time_s"])
        return (1, triangles(i))
    return sorted(order, key=cost)


def phase_tasks(phase, contexts, done, selected):
    """(model, mesher) pairs of a phase in the order they start: the peers mesher by
    mesher (TetGen's quality refinement, the slowest, first), our runs model by model."""
    order = phase_order(phase, contexts, done)
    if phase is PEER_KEYS:
        return [(i, key) for key in phase if key in selected for i in order]
    return [(i, key) for i in order for key in phase if key in selected]


def run_rank(cost, size):
    """Where a run goes in the one-thread schedule: the short ones (guessed under 15 s, 20-30 s
    in all) first, so that a budget cut never takes their rows; then the costliest first (longest
    processing time first), so that the long runs overlap and short ones fill the end."""
    if cost < 15.0:
        return (0, cost, 0.0)
    return (1, -cost, -(size or 0.0))


def schedule(contexts, selected, args):
    """The runs as a list of (jobs at a time, [(model, mesher)] or a function of the rows
    done so far giving them): one batch of every run, costliest first, when our runs take one
    thread; else the phases."""
    if args.bubble_threads == 1:
        tasks = [(i, key) for i in range(len(contexts)) for key in MESHER_KEYS if key in selected]
        tasks.sort(key=lambda t: run_rank(expected_cost(contexts[t[0]], t[1], args), contexts[t[0]]["size"]))
        return [(args.jobs, tasks)]
    return [(args.jobs if phase is PEER_KEYS else 1,
             (lambda done, phase=phase: phase_tasks(phase, contexts, done, selected))) for phase in PHASES]


def prepare_model(model, args, tools, out_dir):
    """The model's own numbers (volumes, from bubble_mesh_3 --check) and the peers' inputs."""
    name = model_name(model)
    mdir = os.path.join(out_dir, name)
    os.makedirs(mdir, exist_ok=True)
    print("== %s: inputs" % model, flush=True)
    summary_path = os.path.join(mdir, "summary.json")
    r = run([tools["bubble_mesh_3"], os.path.abspath(model), "--check", "-q", "--summary-json", summary_path],
            mdir, args.timeout, os.path.join(mdir, "check.log"), use_time=False)
    region_volumes = None  # region index -> volume
    triangles = size = None
    if r["status"] == "ok":
        with open(summary_path) as f:
            s = json.load(f)
        region_volumes = {reg["index"]: reg["volume"] for reg in s.get("regions", []) if reg.get("volume")}
        triangles = s.get("number_of_triangles")
        edge = (s.get("edge_length") or {}).get("median")
        if s.get("volume") and edge:
            size = s["volume"] / edge ** 3
    else:
        print("   bubble_mesh_3 --check: %s %s" % (r["status"], r["reason"]))
    r = run([tools["export"], os.path.abspath(model), "--out-dir", mdir, "--name", name], mdir, args.timeout,
            os.path.join(mdir, "export.log"), use_time=False)
    if r["status"] != "ok":
        print("   export_peer_inputs: %s %s" % (r["status"], r["reason"]))
    return {"model": model, "name": name, "mdir": mdir, "region_volumes": region_volumes, "triangles": triangles,
            "size": size,
            "export_ok": os.path.exists(os.path.join(mdir, name + ".poly"))}


def run_row(ctx, key, args, tools, avail, deadline):
    """One mesher on one model: runs it (within the time left) and measures its mesh."""
    label, kind, extra = MESHERS[MESHER_KEYS.index(key)]
    name, mdir, model = ctx["name"], ctx["mdir"], ctx["model"]
    row = {"model": name, "mesher": label, "key": key, "status": "", "error": "", "tets": None,
           "vertices": None, "time_s": None, "cpu_s": None, "peak_mib": None, "min_dihedral": None,
           "share_under_10": None, "share_under_10_unexplained": None, "mean_smallest_dihedral": None, "aspect_ratio_median": None,
           "triangles": ctx["triangles"], "kept_whole": None, "volume_rel_error": None, "mesh": None, "own_time_s": None,
           "command": ""}
    tag = "   %-16s %-34s" % (name[:16], label)
    why_not = avail.get(kind if kind != "bubble" else key)
    if why_not:
        row["status"] = "not available"
        row["error"] = why_not
        print("%s %s" % (tag, why_not), flush=True)
        return row
    remaining = deadline - time.perf_counter()
    if remaining < 5.0:
        row["status"] = "skipped"
        row["error"] = "skipped: the time budget (--budget %g s) is used up" % args.budget
        print("%s %s" % (tag, row["error"]), flush=True)
        return row
    if key == "bubble-remesh" and args.remesh_timeout is None:
        run_timeout = remaining  # the last phase: nothing else waits for the time
    else:
        limit = args.remesh_timeout if key == "bubble-remesh" else (args.bubble_timeout if kind == "bubble" else args.timeout)
        run_timeout = min(limit, remaining)
    wdir = os.path.join(mdir, key)
    if os.path.isdir(wdir):
        shutil.rmtree(wdir)
    os.makedirs(wdir)
    out = mesher_output(kind, wdir, name)
    if kind == "tetgen":
        if not ctx["export_ok"]:
            row["status"], row["error"] = "error", "no TetGen input (export_peer_inputs failed)"
            return row
        os.symlink(os.path.join("..", name + ".poly"), os.path.join(wdir, name + ".poly"))
        cmd = ["tetgen", extra, name + ".poly"]
    elif kind == "gmsh":
        if not ctx["export_ok"]:
            row["status"], row["error"] = "error", "no Gmsh input (export_peer_inputs failed)"
            return row
        cmd = [DEBIAN_PYTHON, os.path.abspath(__file__), "--gmsh-worker",
               os.path.join(mdir, name + ".surf.msh"), os.path.join(mdir, name + ".regions.json"), out]
    else:
        cmd = [tools["bubble_mesh_3"], os.path.abspath(model), "-o", out, "--threads", str(args.bubble_threads)] + \
            extra + args.bubble_args
    row["command"] = " ".join(shlex.quote(c) for c in cmd)
    res = run(cmd, wdir, run_timeout, os.path.join(wdir, "run.log"))
    row["status"] = res["status"]
    row["error"] = res["reason"]
    row["time_s"] = res["wall_s"]
    row["cpu_s"] = res["cpu_s"]
    row["peak_mib"] = res["peak_mib"]
    row["own_time_s"] = _own_time(kind, os.path.join(wdir, "run.log"))
    if kind == "bubble":
        row["stages"] = _bubble_stages(os.path.join(wdir, "run.log"))
    if res["status"] == "ok" and not os.path.exists(out):
        row["status"], row["error"] = "error", "no output mesh %s" % out
    print("%s %-8s %7.2f s (CPU %s s) %s" % (tag, row["status"], res["wall_s"], fmt(res["cpu_s"], ".2f"), row["error"]),
          flush=True)
    if row["status"] != "ok":
        return row
    row["mesh"] = out
    qjson = os.path.join(wdir, "quality.json")
    q = run([tools["quality"], out, "--json", qjson], wdir, args.timeout, os.path.join(wdir, "quality.log"),
            use_time=False)
    if q["status"] == "ok":
        with open(qjson) as f:
            rep = json.load(f)
        a = rep["all"]
        row["tets"] = a["tetrahedra"]
        row["vertices"] = rep.get("points", a.get("vertices"))
        row["min_dihedral"] = a["dihedral_angle"]["min"]
        row["share_under_10"] = a["smallest_dihedral_angle"]["share_under_10"]
        row["share_under_10_unexplained"] = a["smallest_dihedral_angle"].get(
            "share_under_10_not_at_small_surface_angle")
        row["share_under_10_at_sharp_contact"] = a["smallest_dihedral_angle"].get(
            "share_under_10_at_sharp_contact")
        row["share_under_10_touching_nothing"] = a["smallest_dihedral_angle"].get(
            "share_under_10_not_touching_small_surface_angle")
        row["mean_smallest_dihedral"] = a["smallest_dihedral_angle"]["mean"]
        row["aspect_ratio_median"] = a["aspect_ratio"]["median"]
        if ctx["region_volumes"]:
            row["volume_rel_error"] = region_volume_error(ctx["region_volumes"], rep.get("regions", []))
    else:
        row["error"] = (row["error"] + "; " if row["error"] else "") + "quality: " + q["reason"]
    kjson = os.path.join(wdir, "kept_whole.json")
    k = run([tools["export"], os.path.abspath(model), "--kept-whole", out, "--json", kjson], wdir,
            args.timeout, os.path.join(wdir, "kept_whole.log"), use_time=False)
    if k["status"] == "ok":
        with open(kjson) as f:
            kw = json.load(f)
        row["kept_whole"] = kw["kept_whole"]
        row["triangles"] = kw["triangles"]
    return row


def draw_histograms(ctx, rows, args, tools, out_dir):
    """The side-by-side histograms of the model's measured meshes (and their sections through the
    middle of the model, one above the other, in NAME_sections.svg); the histograms' path, or None."""
    measured = sorted((r for r in rows if r["tets"] is not None), key=row_order)
    if not measured:
        return None
    svg = os.path.join(out_dir, ctx["name"] + ".svg")
    sections = os.path.join(out_dir, ctx["name"] + "_sections.svg")
    names = [r["mesher"].replace(",", "") for r in measured]
    s = run([tools["quality"]] + [r["mesh"] for r in measured] +
            ["--names", ",".join(names), "--svg", svg, "--section-svg", sections],
            ctx["mdir"], args.timeout, os.path.join(ctx["mdir"], "histograms.log"), use_time=False)
    if s["status"] != "ok":
        print("   histograms of %s: %s %s" % (ctx["name"], s["status"], s["reason"]))
        return None
    return svg


# ---------------------------------------------------------------------------
# tables

def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def unexplained_cell(r):
    """share under 10 degrees no surface angle explains, with the parts next to a sharp contact and
    with no vertex on a surface angle under 10 either"""
    u, s = r.get("share_under_10_unexplained"), r.get("share_under_10_at_sharp_contact")
    t = r.get("share_under_10_touching_nothing")
    if u is None:
        return "-"
    parts = ["%.2f" % (100.0 * x) for x in (s, t) if x is not None]
    return "%.2f" % (100.0 * u) + (" (%s)" % "; ".join(parts) if parts else "")


def markdown_table(rows):
    head = ("| model | mesher | tets | vertices | CPU (s) | wall (s) | peak memory (MiB) | min dihedral | % under 10 deg "
            "| % under 10 deg, no surface angle under 10 (of them: next to a sharp contact; with no vertex on one either) | mean smallest dihedral | AR median "
            "| input triangles kept whole | region volume error | error |")
    lines = [head, "|" + "---|" * 15]
    for r in rows:
        kept = "-"
        if r["kept_whole"] is not None and r["triangles"]:
            kept = "%d / %d (%.1f %%)" % (r["kept_whole"], r["triangles"], 100.0 * r["kept_whole"] / r["triangles"])
        err = ("crash: " + r["error"]) if r["status"] == "crash" else r["error"]
        err = err.replace("|", "\\|")
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["model"], r["mesher"], fmt(r["tets"], "d"), fmt(r["vertices"], "d"), fmt(r.get("cpu_s"), ".2f"),
            fmt(r["time_s"], ".2f"), fmt(r["peak_mib"], ".0f"), fmt(r["min_dihedral"], ".3g"),
            fmt(None if r["share_under_10"] is None else 100.0 * r["share_under_10"], ".2f"),
            unexplained_cell(r),
            fmt(r["mean_smallest_dihedral"], ".2f"), fmt(r["aspect_ratio_median"], ".2f"), kept,
            fmt(r["volume_rel_error"], ".1e"), err))
    return "\n".join(lines) + "\n"


def default_models():
    models = [DEFAULT_MODEL]
    shared = os.path.normpath(SHARED_MODELS)
    if os.path.isdir(shared):
        models += sorted(glob.glob(os.path.join(shared, "*.ml")))
    else:
        print("compare_peers: %s not found: only the bundled model" % shared)
    return models


def main():
    if len(sys.argv) >= 2 and sys.argv[1] == "--gmsh-worker":
        if len(sys.argv) != 5:
            fail("--gmsh-worker SURF.msh REGIONS.json OUT.msh")
        sys.exit(gmsh_worker(*sys.argv[2:5]))

    p = argparse.ArgumentParser(
        prog="compare_peers",
        description="Runs TetGen (-pA, -pq1.414/10 -A, -pYA), Gmsh's 3D Delaunay with the input surfaces kept, "
                    "and bubble_mesh_3 (surfaces kept, and --remesh-surfaces) on the same models, measures every "
                    "mesh with bubble_mesh_3_quality, and writes a Markdown + JSON table and side-by-side SVG "
                    "histograms per model.",
        epilog="Default models: the bundled examples/Bubble_mesh_3/data/layered_model.obj and every .ml in "
               "../shared/data/geomodels when present. Needs tetgen, /usr/bin/python3 with python3-gmsh, "
               "/usr/bin/time (Debian package 'time'), and the programs bubble_mesh_3, bubble_mesh_3_quality, "
               "export_peer_inputs in BUILD_DIR (cmake -DBUBBLE_MESH_3_BUILD_BENCH=ON). A mesher that is missing, "
               "crashes or times out is a row of the table, not a failure.")
    p.add_argument("models", nargs="*", metavar="MODEL", help=".ml, .ts or .obj geological models")
    p.add_argument("--build-dir", default=os.path.join(REPO, "build-bench"),
                   help="CMake build folder with the programs (default: %(default)s)")
    p.add_argument("--out", default=None, help="output folder (default: BUILD_DIR/compare_peers)")
    p.add_argument("--timeout", type=float, default=120.0,
                   help="time limit per peer run, and per measurement of a mesh, in seconds (default: %(default)s)")
    # The slowest peer run that finishes, TetGen -pq on CloudSpin, takes 91-108 s here;
    # those that reach the limit (TetGen -pq on modelA2, -pYA on modelA5) did not
    # finish in 420-500 s either
    p.add_argument("--bubble-timeout", type=float, default=200.0,
                   help="time limit per bubble_mesh_3 run with the surfaces kept, in seconds (default: %(default)s)")
    p.add_argument("--remesh-timeout", type=float, default=None,
                   help="time limit per bubble_mesh_3 --remesh-surfaces run in seconds (default: what is left "
                        "of the budget)")
    p.add_argument("--budget", type=float, default=870.0,
                   help="time budget of the whole run in seconds: a run gets at most what is left, and runs "
                        "are skipped (and say so) once it is used up (default: %(default)s)")
    p.add_argument("--meshers", default=",".join(DEFAULT_MESHERS),
                   help="comma-separated subset of: %s (default: all but bubble-keep)" % ",".join(MESHER_KEYS))
    p.add_argument("--jobs", "--peer-jobs", dest="jobs", type=int, default=min(2, os.cpu_count() or 1),
                   help="runs at a time, each on one thread (TetGen; Gmsh's 3D Delaunay; bubble_mesh_3 with "
                        "--threads 1), the short ones first, then the costliest; with --bubble-threads T > 1 only "
                        "the peers' runs go this many at a time, ours alone (default: %(default)s, at most 2 and "
                        "the number of CPUs)")
    p.add_argument("--bubble-threads", type=int, default=1,
                   help="threads of each bubble_mesh_3 run; above 1 our runs run alone, after the peers "
                        "(default: %(default)s, like the peers)")
    p.add_argument("--bubble-args", default="", help="extra arguments for bubble_mesh_3 (quoted, e.g. '--seed 1')")
    args = p.parse_args()
    args.bubble_args = shlex.split(args.bubble_args)
    if args.jobs < 1:
        fail("--jobs takes a number >= 1, got %d" % args.jobs)
    if args.bubble_threads < 1:
        fail("--bubble-threads takes a number >= 1, got %d" % args.bubble_threads)

    selected = [s.strip() for s in args.meshers.split(",") if s.strip()]
    bad = [s for s in selected if s not in MESHER_KEYS]
    if bad:
        fail("unknown mesher(s) %s; known: %s" % (", ".join(bad), ", ".join(MESHER_KEYS)))
    if not os.access(GNU_TIME, os.X_OK):
        fail("%s is missing: peak memory needs GNU time (Debian: apt-get install time)" % GNU_TIME)
    models = args.models or default_models()
    for m in models:
        if not os.path.isfile(m):
            fail("no such model file: %s" % m)
    build_dir = os.path.abspath(args.build_dir)
    tools = find_tools(build_dir)
    out_dir = os.path.abspath(args.out or os.path.join(build_dir, "compare_peers"))
    os.makedirs(out_dir, exist_ok=True)
    avail = peer_availability(tools)

    command = " ".join(shlex.quote(a) for a in ["bench/compare_peers"] + sys.argv[1:])
    print("reproduce with: %s" % command)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else None
    start = time.perf_counter()
    deadline = start + args.budget
    contexts = [prepare_model(m, args, tools, out_dir) for m in models]
    done = [[] for _ in models]  # rows per model
    # A model's histograms are drawn once its last row is measured, in the same pool
    # (behind the runs already queued: beside the last long runs); with our runs alone
    # (--bubble-threads T > 1), after all runs.
    drawn = {}  # model index -> future of its histograms' path
    for jobs, tasks in schedule(contexts, selected, args):
        if callable(tasks):
            tasks = tasks(done)
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            pending = {pool.submit(run_row, contexts[i], key, args, tools, avail, deadline): i for i, key in tasks}
            while pending:
                finished, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
                for f in finished:
                    i = pending.pop(f)
                    done[i].append(f.result())
                    if len(done[i]) == len(selected) and jobs > 1:
                        drawn[i] = pool.submit(draw_histograms, contexts[i], done[i], args, tools, out_dir)
    for model_rows in done:
        model_rows.sort(key=row_order)
    # drawing reads every mesh of a model on one thread (7 s for modelA2's three): --jobs models at a time
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for i, ctx in enumerate(contexts):
            if i not in drawn:
                drawn[i] = pool.submit(draw_histograms, ctx, done[i], args, tools, out_dir)
    rows, svgs = [], {}
    for i, ctx in enumerate(contexts):
        rows += done[i]
        svg = drawn[i].result()
        if svg:
            svgs[ctx["name"]] = svg
    total = time.perf_counter() - start
    load_end = os.getloadavg()[0] if hasattr(os, "getloadavg") else None

    info = {"command": command, "machine": os.uname().nodename, "cpus": os.cpu_count(),
            "load_average_at_start": load, "load_average_at_end": load_end, "timeout_s": args.timeout, "budget_s": args.budget, "total_s": total,
            "jobs": args.jobs, "bubble_threads": args.bubble_threads,
            "tetgen": shutil.which("tetgen"), "rows": rows, "histograms": svgs}
    with open(os.path.join(out_dir, "compare_peers.json"), "w") as f:
        json.dump(info, f, indent=1)
    md = ["# compare_peers\n", "Command: `%s` (total %.0f s, %s CPUs, load average %.1f at start and %.1f at the end, "
          "time limit %g s per run, budget %g s, %d runs at a time, bubble_mesh_3 on %d thread%s)\n" % (
              command, total, os.cpu_count(), load or 0.0, load_end or 0.0, args.timeout, args.budget,
              args.jobs, args.bubble_threads, "" if args.bubble_threads == 1 else "s"), "",
          markdown_table(rows), ""]
    for n, s in svgs.items():
        sections = s[:-len(".svg")] + "_sections.svg"
        md.append("Histograms of %s: %s%s\n" % (n, s, ("; sections: " + sections) if os.path.exists(sections) else ""))
    with open(os.path.join(out_dir, "compare_peers.md"), "w") as f:
        f.write("\n".join(md))
    print()
    print(markdown_table(rows))
    print("wrote %s, %s and %d SVG file(s); total %.0f s" % (
        os.path.join(out_dir, "compare_peers.md"), os.path.join(out_dir, "compare_peers.json"), len(svgs), total))
    print("reproduce with: %s" % command)


if __name__ == "__main__":
    main()
