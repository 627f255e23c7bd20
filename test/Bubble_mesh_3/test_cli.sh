#!/usr/bin/env bash
# Tests of the bubble_mesh_3 program as a user runs it: help, exit codes, messages,
# no half-written outputs. Usage: test_cli.sh BUILD_DIR
set -u
build="$1"
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$build/tools/bubble_mesh_3"
model="$root/examples/Bubble_mesh_3/data/layered_model.obj"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
pass=0; fail=0
check() { # check NAME CONDITION...
  local name="$1"; shift
  if "$@"; then pass=$((pass+1)); echo "ok   $name"; else fail=$((fail+1)); echo "FAIL $name"; fi
}
run() { # run ARGS... : sets rc, out, err
  "$exe" "$@" >"$tmp/out" 2>"$tmp/err"; rc=$?
  out="$(cat "$tmp/out")"; err="$(cat "$tmp/err")"
}
contains() { case "$1" in *"$2"*) return 0;; *) echo "  expected '$2' in: $1" | head -5; return 1;; esac; }
# meshed_volumes SUMMARY_JSON QUALITY_JSON [TOLERANCE [SKIP]]: "N regions, all meshed with their
# volumes" when every region of --check --summary-json (but SKIP: "all but SKIP") has tetrahedra whose
# volume is its own within TOLERANCE (relative, default 1e-9), else the wrong ones
meshed_volumes() {
  /usr/bin/python3 - "$@" <<'PY'
import json, sys
model = {r["name"]: r["volume"] for r in json.load(open(sys.argv[1]))["regions"]}
mesh = {r["name"]: (r["tetrahedra"], r["volume"]) for r in json.load(open(sys.argv[2]))["regions"]}
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-9
skip = sys.argv[4] if len(sys.argv) > 4 else None
bad = [n for n, v in model.items() if n not in mesh or mesh[n][0] == 0 or (n != skip and abs(mesh[n][1] - v) > tol * v)]
which = "all but %s" % skip if skip else "all"
print("%d regions, %s" % (len(model), which + " meshed with their volumes" if not bad else "wrong: " + " ".join(bad)))
PY
}

run --help
check "--help exits 0" test "$rc" -eq 0
check "--help shows usage" contains "$out" "Usage: bubble_mesh_3 INPUT"
check "--help lists --check" contains "$out" "--check"
check "--help lists --remesh-surfaces" contains "$out" "--remesh-surfaces"
check "--help explains relative --size" contains "$out" "e.g. 2%"

run
check "no input exits 2" test "$rc" -eq 2
check "no input says so" contains "$err" "no input file"

# a needle-shaped body: --check says its triangles are poor and points to --remesh-surfaces
cat > "$tmp/needle.obj" <<'OBJ'
o Needle
v 0 0 0
v 1000 0 0
v 0 1 0
v 0 0 1
f 1 3 2
f 1 2 4
f 2 3 4
f 1 4 3
OBJ
run "$tmp/needle.obj" --check
check "needle body --check exits 0" test "$rc" -eq 0
check "poor input angles point to --remesh-surfaces" contains "$out" "try --remesh-surfaces"

# a unit box of 12 triangles around a small sphere of 32 (an ore lens): the
# sphere's edge is the median input edge, and the box walls refined to it by
# default make the whole box that fine; the program says so, and --size caps
# the walls' edges (the surfaces kept)
python3 - "$tmp/lens.obj" 1 <<'PY'
import sys, math
# a unit box of 12 triangles holding a small sphere of 128 triangles: the sphere's edge is the model's median
V=[]; idx={}
def v(p):
    k=tuple(round(c, 12) for c in p)
    if k not in idx: idx[k]=len(V)+1; V.append(k)
    return idx[k]
def oriented(a, b, c, n):
    pa, pb, pc = V[a-1], V[b-1], V[c-1]
    u=[pb[i]-pa[i] for i in range(3)]; w=[pc[i]-pa[i] for i in range(3)]
    cr=[u[1]*w[2]-u[2]*w[1], u[2]*w[0]-u[0]*w[2], u[0]*w[1]-u[1]*w[0]]
    return (a, b, c) if sum(cr[i]*n[i] for i in range(3)) > 0 else (a, c, b)
box=[]
for ax in range(3):
    for side in (0, 1):
        u, w = (ax+1) % 3, (ax+2) % 3
        q=[]
        for k in range(4):
            c=[0, 0, 0]; c[ax]=side; c[u]=1 if k in (1, 2) else 0; c[w]=1 if k >= 2 else 0
            q.append(v(c))
        n=[0, 0, 0]; n[ax]=2*side-1
        box += [oriented(q[0], q[1], q[2], n), oriented(q[0], q[2], q[3], n)]
def unit(a): l=math.sqrt(sum(x*x for x in a)); return tuple(x/l for x in a)
e=[(1,0,0),(-1,0,0),(0,1,0),(0,-1,0),(0,0,1),(0,0,-1)]
F=[(e[i], e[j], e[k]) for i in range(2) for j in range(2, 4) for k in range(4, 6)]
for level in range(int(sys.argv[2]) if len(sys.argv) > 2 else 2):
    G=[]
    for a, b, c in F:
        ab, bc, ca = unit([a[i]+b[i] for i in range(3)]), unit([b[i]+c[i] for i in range(3)]), unit([c[i]+a[i] for i in range(3)])
        G += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    F=G
sphere=[]
for f in F:
    t=[v((0.3+0.1*p[0], 0.5+0.1*p[1], 0.5+0.1*p[2])) for p in f]
    sphere.append(oriented(t[0], t[1], t[2], [f[0][i]+f[1][i]+f[2][i] for i in range(3)]))
with open(sys.argv[1], 'w') as o:
    for p in V: o.write('v %r %r %r\n' % p)
    o.write('o host\n')
    for f in box: o.write('f %d %d %d\n' % f)
    for f in sphere: o.write('f %d %d %d\n' % (f[0], f[2], f[1]))
    o.write('o lens\n')
    for f in sphere: o.write('f %d %d %d\n' % f)
PY
run "$tmp/lens.obj" --no-sliver-removal --threads 2 -o "$tmp/lens_median.mesh"
check "fine body in a coarse box meshes" test "$rc" -eq 0
check "walls refined to a small median: the note names --size" contains "$out" "--size S above it keeps them coarser"
tets_median="$(sed -n 's/^mesh: \([0-9]*\) tetrahedra.*/\1/p' <<<"$out")"
run "$tmp/lens.obj" --size 0.3 --no-sliver-removal --threads 2 -o "$tmp/lens_size.mesh"
check "--size with the surfaces kept meshes" test "$rc" -eq 0
tets_size="$(sed -n 's/^mesh: \([0-9]*\) tetrahedra.*/\1/p' <<<"$out")"
check "--size above the median: no note, a coarser box ($tets_size against $tets_median tetrahedra)" \
  test -n "$tets_size" -a -n "$tets_median" -a "$((tets_size * 4))" -lt "${tets_median:-0}"
check "--size: no note when given" test "$(grep -c 'keeps them coarser' <<<"$out")" -eq 0
run "$tmp/lens.obj" --size 0.3 --keep-input-triangles -o "$tmp/lens_kept.mesh"
check "--size with --keep-input-triangles exits 2" test "$rc" -eq 2
check "--size with --keep-input-triangles says why" contains "$err" "it does nothing with --keep-input-triangles"
check "no output after a usage error" test ! -e "$tmp/lens_kept.mesh"
# a re-meshing size in the wrong unit (0.001 for a model 1 km wide): refused before any work,
# not hours of meshing and an out-of-memory kill
run "$model" --remesh-surfaces --size 0.001 -o "$tmp/tiny.mesh"
check "a re-meshing size far too small exits 2" test "$rc" -eq 2
check "a re-meshing size far too small: the message gives the count and asks for a larger --size" \
  contains "$err" "million tetrahedra (about"
check "a re-meshing size far too small: no output" test ! -e "$tmp/tiny.mesh"

# a layer pinching out at 1.72 degrees and a fault ending inside the body below, as Gmsh
# meshes them: re-meshed with the thickness rule, the surfaces crowd the pinch-out and the
# surface recovery gives up there; the program re-meshes them with fewer edges across and says so
if /usr/bin/python3 -c "import gmsh" 2>/dev/null; then
  /usr/bin/python3 "$here/make_pinch_out_model.py" "$tmp/pinch.obj"
  run "$tmp/pinch.obj" --check
  check "pinch-out model: --check warns of the 1.72-degree contact" contains "$out" "meet at 1.72 deg"
  run "$tmp/pinch.obj" --remesh-surfaces --population-rounds 0 --threads 2 -o "$tmp/pinch.mesh"
  check "pinch-out model re-meshed exits 0" test "$rc" -eq 0
  check "pinch-out model re-meshed writes its mesh" test -s "$tmp/pinch.mesh"
  check "the new surfaces' triangles and edges are told before the volume stages run" \
    test -n "$(sed -n '/^  surfaces re-meshed: [0-9]* triangles, edges from [0-9.]* (across thin layers and at fault tips) to the target /,$p' <<<"$out" | grep '^\[.* s\] surface bubbles\.\.\.')"
  check "pinch-out model re-meshed: every region has tetrahedra" \
    test "$(grep -cE '^  [123] (lower|upper|wedge) +[1-9]' <<<"$out")" -eq 3
  if grep -q "note: the surface recovery failed on the re-meshed surfaces" <<<"$out"; then
    echo "  pinch-out model: re-meshed again with --layer-elements $(sed -n 's/.*re-meshed again with --layer-elements \([0-9.]*\).*/\1/p' <<<"$out")"
    check "the note names the --layer-elements used" contains "$out" "they were re-meshed again with --layer-elements"
  else
    echo "  pinch-out model: the first re-meshed surfaces were recovered"
  fi
  # a fault with throw (horizons ending on it at other heights on either side), a tunnel
  # a horizon cuts in two, and a small fault ending inside a layer: every region meshed,
  # each with the volume the model gives it (the surfaces kept exactly, the tunnel too)
  /usr/bin/python3 "$here/make_fault_tunnel_model.py" "$tmp/tunnel.obj"
  run "$tmp/tunnel.obj" --check --summary-json "$tmp/tunnel_summary.json"
  check "fault-and-tunnel model: --check exits 0" test "$rc" -eq 0
  check "fault-and-tunnel model: the small fault lies inside foot_1" contains "$out" "'small_fault' in region 3 'foot_1'"
  check "--check lists the surfaces' names, parts folded" \
    contains "$out" "surfaces (the names --surface-size-factor takes): 'foot_0/foot', 'foot_0/hang' (2 parts), "
  run "$tmp/tunnel.obj" --threads 2 -o "$tmp/tunnel.mesh" --quality-json "$tmp/tunnel_quality.json"
  check "fault-and-tunnel model meshes" test "$rc" -eq 0
  volumes="$(meshed_volumes "$tmp/tunnel_summary.json" "$tmp/tunnel_quality.json")"
  echo "  fault-and-tunnel model: $volumes"
  check "fault-and-tunnel model: 8 regions, each meshed with its volume" test "$volumes" = "8 regions, all meshed with their volumes"
  # re-meshed without the balance, the tunnel's 16 facets become fewer chords: the program says which
  # volumes changed. This run is also the unfactored side of the size-factor pair below, so it has 2 edges across
  # thin layers, where that pair's figures were measured (at the default 1.63 the run without
  # factors already has 26,868 tetrahedra in foot_0, 19,575 at 2, and the factor gives 1.49
  # times as many)
  run "$tmp/tunnel.obj" --remesh-surfaces --population-rounds 0 --threads 2 -o "$tmp/tunnel_remeshed.mesh" \
      --quality-json "$tmp/tunnel_remeshed_q.json" --layer-elements 2 --no-balance-volumes
  check "fault-and-tunnel model re-meshed exits 0" test "$rc" -eq 0
  check "re-meshed: the note names the tunnel whose volume changed" contains "$out" "note: re-meshing changed the volume of region 6 'tunnel_bottom' by -"
  # every new triangle cuts into the tunnel: slides along its facets cannot give the volume back,
  # so the balance (the default) re-meshes the tunnel's surfaces again with their creases kept
  run "$tmp/tunnel.obj" --remesh-surfaces --population-rounds 0 --threads 2 -o "$tmp/tunnel_balanced.mesh"
  check "fault-and-tunnel model re-meshed with the balance (the default) exits 0" test "$rc" -eq 0
  check "re-meshed with the balance (the default): the tunnel's surfaces keep their creases" \
    contains "$out" "surfaces of convex, coarsely faceted bodies re-meshed with every crease kept"
  tunnel_change="$(sed -n 's/.*largest region volume change \([0-9.e+-]*\).*/\1/p' <<<"$out" | head -1)"
  echo "  fault-and-tunnel model with the balance: largest region volume change $tunnel_change"
  check "re-meshed with the balance (the default): every region keeps its volume within 1e-6" \
    /usr/bin/python3 -c "import sys; assert float(sys.argv[1]) < 1e-6" "$tunnel_change"
  check "re-meshed with the balance (the default): no note says a volume changed" bash -c '! grep -q "changed the volume" <<<"$1"' _ "$out"
  # between the kept creases the tunnel lies flat, where slides change no volume: the balance
  # moves no point (before session 58's guards it slid 24 points for nothing)
  check "re-meshed with the balance (the default): no point slides on the faceted tunnel" bash -c '! grep -q "points slid along" <<<"$1"' _ "$out"
  # a region and a surface asked finer: more tetrahedra in the region (4.6 times with population
  # control, 2.3 without), more triangles on foot_2's outer walls (4.0 times; a surface whose
  # sizes the thin-layer rule sets, as the small fault's, gains only where the target binds)
  run "$tmp/tunnel.obj" --remesh-surfaces --population-rounds 0 --threads 2 -o "$tmp/tunnel_factors.mesh" \
      --quality-json "$tmp/tunnel_factors_q.json" --region-size-factor foot_0=0.5 --surface-size-factor foot_2/outside=0.5 \
      --layer-elements 2 --no-balance-volumes
  check "re-meshed with size factors exits 0" test "$rc" -eq 0
  check "size factors are listed" contains "$out" "size factor 0.5 in region 1 'foot_0'"
  check "region foot_0 at 0.5: over 1.5 times the tetrahedra, the other regions' volumes unchanged; foot_2/outside at 0.5: over twice the triangles" \
    /usr/bin/python3 - "$tmp/tunnel_remeshed_q.json" "$tmp/tunnel_factors_q.json" "$tmp/tunnel_remeshed.mesh" "$tmp/tunnel_factors.mesh" <<'PY'
import json, re, sys
a = {r["name"]: r for r in json.load(open(sys.argv[1]))["regions"]}
b = {r["name"]: r for r in json.load(open(sys.argv[2]))["regions"]}
assert b["foot_0"]["tetrahedra"] > 1.5 * a["foot_0"]["tetrahedra"], (a["foot_0"]["tetrahedra"], b["foot_0"]["tetrahedra"])
for n in a: assert abs(a[n]["volume"] - b[n]["volume"]) <= 1e-9 * a[n]["volume"], n
def wall_triangles(mesh):
    text = open(mesh).read()
    ref = re.search(r'# patch \d+ ref (\d+) "foot_2/outside"', text).group(1)
    block = text.split("\nTriangles\n", 1)[1].split("\n")
    n = int(block[0])
    return sum(1 for line in block[1:n + 1] if line.split()[3] == ref)
fa, fb = wall_triangles(sys.argv[3]), wall_triangles(sys.argv[4])
print("  foot_0: %d -> %d tetrahedra; foot_2/outside: %d -> %d triangles" % (a["foot_0"]["tetrahedra"], b["foot_0"]["tetrahedra"], fa, fb))
assert fb > 2 * fa, (fa, fb)
PY
  run "$tmp/tunnel.obj" --check --region-size-factor granite=0.5
  check "--region-size-factor naming no region exits 2" test "$rc" -eq 2
  check "--region-size-factor naming no region lists the regions" contains "$err" "has no region 'granite'; its regions are 1 'foot_0', 2 'hang_0'"
  run "$tmp/tunnel.obj" --check --remesh-surfaces --surface-size-factor granite=0.5
  check "--surface-size-factor naming no surface exits 2" test "$rc" -eq 2
  check "--surface-size-factor naming no surface lists the surfaces" contains "$err" "has no surface 'granite'; its surfaces are"
  run "$tmp/tunnel.obj" --surface-size-factor small_fault=0.5
  check "--surface-size-factor without --remesh-surfaces exits 2" test "$rc" -eq 2
  run "$tmp/tunnel.obj" --region-size-factor foot_0=0
  check "--region-size-factor 0 exits 2 with the range" contains "$err" "takes a factor from 0.05 to 20"
  # edges turning by half the default curvature angle follow the tunnel's bends closer: under 1 %
  run "$tmp/tunnel.obj" --remesh-surfaces --curvature-angle 11.25 --population-rounds 0 --threads 2 -o "$tmp/tunnel_curved.mesh"
  check "re-meshed with --curvature-angle 11.25 exits 0" test "$rc" -eq 0
  check "--curvature-angle 11.25: no region's volume changes by over 1 %" test "$(grep -c 'changed the volume' <<<"$out")" -eq 0
  run "$tmp/tunnel.obj" --feature-angle 20
  check "--feature-angle without --remesh-surfaces exits 2" test "$rc" -eq 2
  check "--feature-angle without --remesh-surfaces says so" contains "$err" "--feature-angle is a rule of --remesh-surfaces"
  run "$tmp/tunnel.obj" --remesh-surfaces --feature-angle 0
  check "--feature-angle 0 exits 2 with the range" contains "$err" "--feature-angle takes degrees above 0 and under 180"
  run "$tmp/tunnel.obj" --curvature-angle 11.25
  check "--curvature-angle without --remesh-surfaces exits 2" test "$rc" -eq 2
  check "--curvature-angle without --remesh-surfaces says so" contains "$err" "--curvature-angle is a rule of --remesh-surfaces"
  # a folded horizon (an anticline) re-meshed coarse: its chords change the two bodies' volumes
  # (2.3e-4 here) until the balance (the default) slides the new points along it, and the tetrahedra have each
  # body's input volume (at 8 % of the diagonal nearly every new point is within two edges of a curve
  # and stays: nothing is balanced)
  /usr/bin/python3 "$root/bench/make_crossing_faults_model.py" "$tmp/fold.obj" --edge 80 >/dev/null
  run "$tmp/fold.obj" --check --summary-json "$tmp/fold_summary.json"
  run "$tmp/fold.obj" --remesh-surfaces --size 4% --layer-elements 0 --population-rounds 0 --threads 2 \
      -o "$tmp/fold.mesh" --quality-json "$tmp/fold_q.json"
  check "folded model re-meshed exits 0" test "$rc" -eq 0
  check "folded model re-meshed: the chords changed a volume by over 1e-5, and points slid" /usr/bin/python3 - "$out" <<'PY'
import re, sys
m = re.search(r"largest region volume change (\S+) \((\S+) before (\d+) points slid along the input surfaces\)", sys.argv[1])
print("  folded model: volume change %s after, %s before %s points slid" % m.groups())
sys.exit(0 if float(m.group(2)) > 1e-5 and float(m.group(1)) < 1e-9 and int(m.group(3)) > 0 else 1)
PY
  check "folded model re-meshed: each region meshed with its input volume (1e-9)" \
    test "$(meshed_volumes "$tmp/fold_summary.json" "$tmp/fold_q.json")" = "2 regions, all meshed with their volumes"
  # a graben whose faults end inside the bodies at both ends, a thin layer and a lens, as Gmsh
  # writes them: 9 cut points on the wall y = 0 lie up to 3.6e-11 off its plane. Before they were
  # given the wall's coordinate back, the surface recovery failed on that wall
  /usr/bin/python3 "$root/bench/make_graben_model.py" "$tmp/graben.obj" --edge 200
  run "$tmp/graben.obj" --check --summary-json "$tmp/graben_summary.json"
  check "graben model: --check exits 0" test "$rc" -eq 0
  check "graben model: --check says meshing puts 9 points back on their wall" \
    contains "$out" "note: 9 points lie a hair off the axis plane of a box wall they are on"
  run "$tmp/graben.obj" --threads 2 -o "$tmp/graben.mesh" --quality-json "$tmp/graben_quality.json"
  check "graben model with points a hair off a wall meshes" test "$rc" -eq 0
  check "graben model: the note says the points were put back on the wall" \
    contains "$out" "points lay a hair off the axis plane of a box wall they are on"
  volumes="$(meshed_volumes "$tmp/graben_summary.json" "$tmp/graben_quality.json")"
  echo "  graben model: $volumes"
  check "graben model: 9 regions, each meshed with its volume" test "$volumes" = "9 regions, all meshed with their volumes"
  # re-meshed with the balance: the lens (46 coarse triangles, every new point near a curve or a
  # needle) can have none of its points moved and keeps what its chords cut off (-1.4 %). Before, it
  # held back every step, and all 9 regions kept their chords' errors (5.6e-6 to 1.5e-4); now the other
  # 8 share what the lens lost (the walls are flat: their total cannot change), 5.7e-7 each
  run "$tmp/graben.obj" --remesh-surfaces --size 400 --layer-elements 1 --population-rounds 0 \
      --threads 2 -o "$tmp/graben_balanced.mesh" --quality-json "$tmp/graben_balanced_q.json"
  check "graben model re-meshed with the balance exits 0" test "$rc" -eq 0
  check "graben model re-meshed with the balance: only the lens is left out of it" \
    contains "$out" "(1 region left out of the volume balance; the others changed by at most"
  volumes="$(meshed_volumes "$tmp/graben_summary.json" "$tmp/graben_balanced_q.json" 1e-6 lens)"
  echo "  graben model re-meshed with the balance: $volumes"
  check "graben model re-meshed with the balance: every region but the lens meshed with its volume (1e-6)" \
    test "$volumes" = "9 regions, all but lens meshed with their volumes"
else
  echo "SKIP: python3-gmsh is not installed (scripts/install_deps.sh --tests installs it)"
fi

# a GOCAD box of two layers whose contact is listed with the layers on the wrong sides (its
# triangles face the upper layer, the file puts the lower one there): mended from the geometry
python3 - "$tmp/split.ml" <<'PY'
import sys
h=0.75
P=[(x,y,z) for z in (0,h,2) for y in (0,2) for x in (0,2)]
def i(x,y,z): return P.index((x,y,z))
def quad(q, n):  # two triangles over corners q (around), normal along n
    u=[q[1][k]-q[0][k] for k in range(3)]; w=[q[2][k]-q[0][k] for k in range(3)]
    c=[u[1]*w[2]-u[2]*w[1],u[2]*w[0]-u[0]*w[2],u[0]*w[1]-u[1]*w[0]]
    if sum(c[k]*n[k] for k in range(3))<0: q=q[::-1]
    a,b,cc,d=[i(*p) for p in q]
    return [(a,b,cc),(a,cc,d)]
def walls(z0,z1):
    return (quad([(0,0,z0),(2,0,z0),(2,0,z1),(0,0,z1)],(0,-1,0))+quad([(0,2,z0),(2,2,z0),(2,2,z1),(0,2,z1)],(0,1,0))+
            quad([(0,0,z0),(0,2,z0),(0,2,z1),(0,0,z1)],(-1,0,0))+quad([(2,0,z0),(2,2,z0),(2,2,z1),(2,0,z1)],(1,0,0)))
sq=lambda z:[(0,0,z),(2,0,z),(2,2,z),(0,2,z)]
parts={'lower_skin':quad(sq(0),(0,0,-1))+walls(0,h),'upper_skin':quad(sq(2),(0,0,1))+walls(h,2),'contact':quad(sq(h),(0,0,1))}
names=['lower_skin','upper_skin','contact']
o=open(sys.argv[1],'w')
o.write('GOCAD Model3d 1\nHEADER {\nname: split box\n}\n')
for n in names: o.write('TSURF %s\n'%n)
for k,n in enumerate(names):
    o.write('TFACE %d boundary %s\n'%(k+1,n))
    for v in parts[n][0]: o.write('  %g %g %g\n'%P[v])
o.write('REGION 4 Universe\n +1 +2 0\nREGION 5 Lower\n -1 +3 0\nREGION 6 Upper\n -2 -3 0\nEND\n')
for n in names:
    o.write('GOCAD TSurf 1\nHEADER {\nname: %s\n}\nTFACE\n'%n)
    used=sorted({v for t in parts[n] for v in t})
    for v in used: o.write('VRTX %d %g %g %g\n'%((v+1,)+P[v]))
    for t in parts[n]: o.write('TRGL %d %d %d\n'%tuple(v+1 for v in t))
    o.write('END\n')
PY
run "$tmp/split.ml" -o "$tmp/split.mesh" --summary-json "$tmp/split.json"
check "contact listed on the wrong sides: meshed" test "$rc" -eq 0 -a -s "$tmp/split.mesh"
check "contact listed on the wrong sides: a note names it" contains "$out" "wrong sides of 1 patch ('contact'), against their triangles"
check "contact listed on the wrong sides: layer volumes from the geometry" python3 - "$tmp/split.json" <<'PY'
import json,sys
r={x['name']:x['volume'] for x in json.load(open(sys.argv[1]))['regions']}
sys.exit(0 if abs(r['Lower']-3)<1e-12 and abs(r['Upper']-5)<1e-12 else 1)
PY

# the same box with every sign the other way round, as a wrong ZPOSITIVE makes it
sed -e 's/^ +1 +2 0$/ -1 -2 0/' -e 's/^ -1 +3 0$/ +1 +3 0/' -e 's/^ -2 -3 0$/ +2 -3 0/' "$tmp/split.ml" > "$tmp/split_all.ml"
run "$tmp/split_all.ml" --check
check "every sign wrong: valid after mending" test "$rc" -eq 0
check "every sign wrong: ZPOSITIVE named" contains "$out" "the file's ZPOSITIVE (Elevation or Depth) is likely the wrong one"

# the contact listed as +3 by both layers: its sides come from the geometry
sed -e 's/^ -2 -3 0$/ -2 +3 0/' "$tmp/split.ml" > "$tmp/split_same.ml"
run "$tmp/split_same.ml" --check --summary-json "$tmp/split_same.json"
check "same sign in both regions: valid after mending" test "$rc" -eq 0
check "same sign in both regions: a note says so" contains "$out" "is listed with the same sign in both its regions"
check "same sign in both regions: layer volumes from the geometry" python3 - "$tmp/split_same.json" <<'PY'
import json,sys
r={x['name']:x['volume'] for x in json.load(open(sys.argv[1]))['regions']}
sys.exit(0 if abs(r['Lower']-3)<1e-12 and abs(r['Upper']-5)<1e-12 else 1)
PY

# a TSurf file of open surfaces (a box's walls and a fault inside it): --regions says which
# regions each object separates; without it the error points there
ts="$root/test/Bubble_mesh_3/data/io/box_and_fault.ts"
run "$ts" --check
check "open TSurf objects without --regions: invalid input" test "$rc" -eq 1
check "open TSurf objects without --regions: hint names --regions" contains "$err" "give --regions FILE"
printf '# object positive negative\nbox outside rock\nfault rock rock\n' > "$tmp/regions.txt"
run "$ts" --regions "$tmp/regions.txt" -o "$tmp/bf.mesh" --summary-json "$tmp/bf.json"
check "--regions: meshed" test "$rc" -eq 0 -a -s "$tmp/bf.mesh"
check "--regions: one region 'rock' with the fault inside it" python3 - "$tmp/bf.json" <<'PY'
import json,sys
s=json.load(open(sys.argv[1]))
r=s['regions']
sys.exit(0 if len(r)==1 and r[0]['name']=='rock' and abs(r[0]['volume']-1)<1e-12 else 1)
PY
printf 'box rock outside\nfault rock rock\n' > "$tmp/regions_swapped.txt"
run "$ts" --regions "$tmp/regions_swapped.txt" --check
check "--regions with the box's sides swapped: mended" test "$rc" -eq 0
check "--regions with the box's sides swapped: the note names the regions file" contains "$out" "the regions file '$tmp/regions_swapped.txt' puts the regions on the wrong sides of 1 patch ('box')"
run "$model" --regions "$tmp/regions.txt" --check
check "--regions on an OBJ input is a usage error" test "$rc" -eq 2

# one body as STL (a scanner's or surface modeller's export): meshed, named after the file
python3 - "$tmp/Dam.stl" <<'PY'
import sys
P=[(0,0,0),(40,0,0),(40,20,0),(0,20,0),(10,0,10),(30,0,10),(30,20,10),(10,20,10)]
Q=[(0,3,2,1),(4,5,6,7),(0,1,5,4),(1,2,6,5),(2,3,7,6),(3,0,4,7)]  # outward
with open(sys.argv[1],'w') as o:
    o.write('solid dam\n')
    for q in Q:
        for t in ((q[0],q[1],q[2]),(q[0],q[2],q[3])):
            o.write(' facet normal 0 0 0\n  outer loop\n')
            for v in t: o.write('   vertex %g %g %g\n'%P[v])
            o.write('  endloop\n endfacet\n')
    o.write('endsolid dam\n')
PY
run "$tmp/Dam.stl" -o "$tmp/dam.mesh" --summary-json "$tmp/dam.json"
check "STL body: meshed" test "$rc" -eq 0 -a -s "$tmp/dam.mesh"
check "STL body: one region named after the file, its volume" python3 - "$tmp/dam.json" <<'PY'
import json,sys
r=json.load(open(sys.argv[1]))['regions']
sys.exit(0 if len(r)==1 and r[0]['name']=='Dam' and abs(r[0]['volume']-6000)<1e-9 else 1)
PY

# surfaces re-meshed first: a unit cube whose bottom face has a needle along its diagonal
# (a point 0.001 off it); the bundled model's volume mesh would take minutes re-meshed
python3 - "$tmp/cube.obj" <<'PY'
import sys
v=[(x,y,z) for z in (0,1) for y in (0,1) for x in (0,1)]
def vid(x,y,z): return v.index((x,y,z))+1
f=[]
def face(quad, n):  # quad of (x,y,z) corners around, n the outward normal
    a,b,c,d=[vid(*p) for p in quad]
    u=[quad[1][i]-quad[0][i] for i in range(3)]; w=[quad[2][i]-quad[0][i] for i in range(3)]
    cr=[u[1]*w[2]-u[2]*w[1],u[2]*w[0]-u[0]*w[2],u[0]*w[1]-u[1]*w[0]]
    if sum(cr[i]*n[i] for i in range(3))<0: a,b,c,d=d,c,b,a
    f.extend([(a,b,c),(a,c,d)])
face([(0,0,1),(1,0,1),(1,1,1),(0,1,1)],(0,0,1))
face([(0,0,0),(1,0,0),(1,0,1),(0,0,1)],(0,-1,0))
face([(0,1,0),(1,1,0),(1,1,1),(0,1,1)],(0,1,0))
face([(0,0,0),(0,1,0),(0,1,1),(0,0,1)],(-1,0,0))
face([(1,0,0),(1,1,0),(1,1,1),(1,0,1)],(1,0,0))
v.append((0.5,0.499,0)); c=len(v)
a,b,cc,d=vid(0,0,0),vid(1,0,0),vid(1,1,0),vid(0,1,0)
f.append((a,d,cc))  # upper-left half, clockwise seen from above: normal -z
f.extend([(a,c,b),(b,c,cc),(cc,c,a)])      # lower-right half as a fan around the point near the diagonal
with open(sys.argv[1],'w') as o:
    o.write('o Cube\n')
    for p in v: o.write('v %g %g %g\n'%p)
    for t in f: o.write('f %d %d %d\n'%t)
PY
run "$tmp/cube.obj" --remesh-surfaces --size 25% -o "$tmp/r.mesh" --quality-json "$tmp/qr.json" --threads 2
check "--remesh-surfaces exits 0" test "$rc" -eq 0
check "needle cube: input angles point to --remesh-surfaces" contains "$out" "try --remesh-surfaces"
check "progress line for the surface remeshing" contains "$out" "surface remeshing..."
check "summary gives the remeshing figures" contains "$out" "surface remeshing: 14 -> "
check "summary counts re-meshed triangles kept whole" contains "$out" "re-meshed triangles kept whole"
check "summary gives the remeshing time" contains "$out" "time: surface remeshing "
check "re-meshed: no triangle under 25 degrees, volume kept, region named" python3 -c "
import json,re
q=json.load(open('$tmp/qr.json'))
assert any(r.get('name') == 'Cube' for r in q['regions']), q['regions']
assert abs(q['all']['volume'] - 1.) <= 1e-9, q['all']['volume']
# a facet on a re-meshed triangle that an input corner forces thin counts with the corner's angle
assert q['surface_angle_source'] == 'boundary facets, or the input corner forcing them', q['surface_angle_source']
m=re.search(r'min angle ([0-9.e+-]+) -> ([0-9.e+-]+) deg \((\d+) triangles under 25 deg', open('$tmp/out').read())
assert m, 'no remeshing line'
assert float(m.group(1)) < 1. and float(m.group(2)) >= 25. and int(m.group(3)) == 0, m.group(0)
"
run "$tmp/cube.obj" --remesh-surfaces --size 25% -o "$tmp/r1.mesh" --threads 1 -q
check "--remesh-surfaces: same mesh with 1 and 2 threads" cmp -s "$tmp/r1.mesh" "$tmp/r.mesh"

# --layer-elements: a slab 1 x 1 x 0.1 re-meshed at a size of 25 % of its diagonal (0.35);
# the thickness rule asks for N edges across the 0.1 between top and bottom, so the
# re-meshed surfaces must get finer with N: 0 (rule off) < 1 < 1.63 (the default)
python3 - "$tmp/slab.obj" <<'PY'
import sys
h=0.1
v=[(x,y,z) for z in (0,h) for y in (0,1) for x in (0,1)]
i=lambda x,y,z: v.index((x,y,z))+1
q=[[(0,0,0),(0,1,0),(1,1,0),(1,0,0)],[(0,0,h),(1,0,h),(1,1,h),(0,1,h)],
   [(0,0,0),(1,0,0),(1,0,h),(0,0,h)],[(1,0,0),(1,1,0),(1,1,h),(1,0,h)],
   [(1,1,0),(0,1,0),(0,1,h),(1,1,h)],[(0,1,0),(0,0,0),(0,0,h),(0,1,h)]]
with open(sys.argv[1],'w') as o:
    o.write('o Slab\n')
    for p in v: o.write('v %g %g %g\n'%p)
    for a,b,c,d in q: o.write('f %d %d %d\nf %d %d %d\n'%(i(*a),i(*b),i(*c),i(*a),i(*c),i(*d)))
PY
slab_triangles() { echo "$out" | sed -n 's/^surface remeshing: 12 -> \([0-9]*\) triangles.*/\1/p'; }
run "$tmp/slab.obj" --remesh-surfaces --size 25% --layer-elements 0 --no-sliver-removal --threads 2
check "--layer-elements 0 exits 0" test "$rc" -eq 0
check "--layer-elements 0: no thickness note" test -z "$(echo "$out" | grep 'note: thin layers')"
n0="$(slab_triangles)"
run "$tmp/slab.obj" --remesh-surfaces --size 25% --layer-elements 1 --no-sliver-removal --threads 2
n1="$(slab_triangles)"
run "$tmp/slab.obj" --remesh-surfaces --size 25% --no-sliver-removal --threads 2
n2="$(slab_triangles)"
check "thin slab: the note names the thickness rule's sizes" contains "$out" "note: thin layers or fault tips (thickness down to 0.1) make edges as short as 0.06135 there, under the target size"
check "thin slab: ... and --layer-elements" contains "$out" "--layer-elements (now 1.63)"
check "thin slab above the rule's floor: no flat-layer note" test -z "$(echo "$out" | grep 'note: edges stop at')"
# at twice the diagonal the floor (a tenth of it) is over twice the slab's thickness
run "$tmp/slab.obj" --remesh-surfaces --size 200% --no-sliver-removal --threads 2
check "thin slab well under the rule's floor: the note gives the floor" contains "$out" "note: edges stop at 0.28"
check "... and says the slab's tetrahedra are flat" contains "$out" "(here down to 0.1: a pinch-out's tip, or a layer thinner than that all along), its tetrahedra are flat"
# --min-size lowers the floor: at 0.1 the rule's 0.1 / 1.63 stops at 0.1, no longer 0.28
run "$tmp/slab.obj" --remesh-surfaces --size 200% --min-size 0.1 --no-sliver-removal --threads 2
check "--min-size 0.1 exits 0" test "$rc" -eq 0
check "--min-size 0.1: the thickness rule's edges stop at 0.1" contains "$out" "make edges as short as 0.1 there"
check "--min-size 0.1: no flat-layer note (the floor is the slab's thickness)" test -z "$(echo "$out" | grep 'note: edges stop at')"
check "--min-size 0.1, under the target: no note that the rule refines nothing" \
  test -z "$(echo "$out" | grep 'is not under the target size')"
run "$tmp/slab.obj" --remesh-surfaces --size 200% --min-size 3 --no-sliver-removal --threads 2
check "--min-size over the target size: the note says the rule refines nothing" \
  contains "$out" "note: --min-size 3 is not under the target size 2.835"
check "... and no note that edges stop at 3, over the target" test -z "$(echo "$out" | grep 'note: edges stop at')"
run "$tmp/slab.obj" --min-size 0.1
check "--min-size without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--min-size without --remesh-surfaces says so" contains "$err" "--remesh-surfaces"
run "$tmp/slab.obj" --remesh-surfaces --min-size 0
check "--min-size 0 exits 2" test "$rc" -eq 2
echo "  slab re-meshed triangles with 0 / 1 / 1.63 (default) edges across: $n0 / $n1 / $n2"
check "--layer-elements: finer with more edges across a thin layer" \
  test -n "$n0" -a -n "$n1" -a -n "$n2" -a "${n0:-0}" -lt "${n1:-0}" -a "${n1:-0}" -lt "${n2:-0}"
run "$tmp/slab.obj" --layer-elements 1
check "--layer-elements without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--layer-elements without --remesh-surfaces says so" contains "$err" "--remesh-surfaces"
run "$tmp/slab.obj" --remesh-surfaces --layer-elements -1
check "--layer-elements -1 exits 2" test "$rc" -eq 2
check "--help lists --layer-elements" bash -c "'$exe' --help | grep -q -- --layer-elements"

# --size-grading: the slab of 0.1 on a box 1 thick (their interface shared); the
# layer rule makes the slab fine, and the box's far faces get coarser the faster
# the sizes may grow: more triangles with 1.2 than with the default 1.5
python3 - "$tmp/slab_box.obj" <<'PY'
import sys
def box(name, z0, z1, o, base):
    v=[(x,y,z) for z in (z0,z1) for y in (0,1) for x in (0,1)]
    i=lambda x,y,z: base+v.index((x,y,z))+1
    q=[[(0,0,z0),(0,1,z0),(1,1,z0),(1,0,z0)],[(0,0,z1),(1,0,z1),(1,1,z1),(0,1,z1)],
       [(0,0,z0),(1,0,z0),(1,0,z1),(0,0,z1)],[(1,0,z0),(1,1,z0),(1,1,z1),(1,0,z1)],
       [(1,1,z0),(0,1,z0),(0,1,z1),(1,1,z1)],[(0,1,z0),(0,0,z0),(0,0,z1),(0,1,z1)]]
    o.write('o %s\n'%name)
    for p in v: o.write('v %g %g %g\n'%p)
    # each quad split on its diagonal through the corner of smallest (z, y, x)
    for quad in q:
        k=min(range(4), key=lambda t:(quad[t][2],quad[t][1],quad[t][0])); a,b,c,d=quad[k:]+quad[:k]
        o.write('f %d %d %d\nf %d %d %d\n'%(i(*a),i(*b),i(*c),i(*a),i(*c),i(*d)))
with open(sys.argv[1],'w') as o:
    box('Slab', 0., 0.1, o, 0)
    box('Box', 0.1, 1.1, o, 8)
PY
grading_triangles() { echo "$out" | sed -n 's/^surface remeshing: [0-9]* -> \([0-9]*\) triangles.*/\1/p'; }
run "$tmp/slab_box.obj" --remesh-surfaces --size 25% --no-sliver-removal --threads 2
check "--remesh-surfaces on the slab and box exits 0" test "$rc" -eq 0
g15="$(grading_triangles)"
grading_bubbles() { echo "$out" | sed -n 's/^mesh: .* surface points, \([0-9]*\) bubbles.*/\1/p'; }
b_default="$(grading_bubbles)"
run "$tmp/slab_box.obj" --remesh-surfaces --size 25% --size-grading 1.2 --no-sliver-removal --threads 2
g12="$(grading_triangles)"
echo "  slab and box re-meshed triangles with size grading 1.5 (default) / 1.2: $g15 / $g12"
check "--size-grading: more triangles with a slower grading" \
  test -n "$g15" -a -n "$g12" -a "${g15:-0}" -lt "${g12:-0}"
# --interior-grading: in the box beside the fine slab the bubbles grow away from
# it at most by the ratio given between touching ones: fewer of them with 3 (the
# default with the surfaces kept) than by default re-meshed, the same as the
# default with 1.25 given
run "$tmp/slab_box.obj" --remesh-surfaces --size 25% --interior-grading 1.25 --no-sliver-removal --threads 2
b125="$(grading_bubbles)"
run "$tmp/slab_box.obj" --remesh-surfaces --size 25% --interior-grading 3 --no-sliver-removal --threads 2
b3="$(grading_bubbles)"
echo "  slab and box bubbles with interior grading 1.25 (default re-meshed) / 3 / 1.25 given: $b_default / $b3 / $b125"
check "--interior-grading: fewer bubbles with 3 than by default re-meshed" \
  test -n "$b_default" -a -n "$b3" -a "${b3:-0}" -lt "${b_default:-0}"
check "--interior-grading 1.25 is the default re-meshed" test -n "$b125" -a "${b125:-x}" = "${b_default:-y}"
run "$tmp/slab_box.obj" --interior-grading 1
check "--interior-grading 1 exits 2" test "$rc" -eq 2
check "--interior-grading 1 says what it takes" contains "$err" "ratio above 1"
check "--help lists --interior-grading" bash -c "'$exe' --help | grep -q -- --interior-grading"
run "$tmp/slab_box.obj" --size-grading 1.2
check "--size-grading without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--size-grading without --remesh-surfaces says so" contains "$err" "--remesh-surfaces"
run "$tmp/slab_box.obj" --remesh-surfaces --size-grading 1
check "--size-grading 1 exits 2" test "$rc" -eq 2
check "--help lists --size-grading" bash -c "'$exe' --help | grep -q -- --size-grading"
run "$tmp/slab_box.obj" --refine-ribbons
check "--refine-ribbons without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--refine-ribbons without --remesh-surfaces says so" contains "$err" "--remesh-surfaces"
check "--help lists --refine-ribbons" bash -c "'$exe' --help | grep -q -- --refine-ribbons"
run "$tmp/slab_box.obj" --balance-volumes
check "--balance-volumes without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--balance-volumes without --remesh-surfaces says so" contains "$err" "--balance-volumes is a rule of --remesh-surfaces"
run "$tmp/slab_box.obj" --no-balance-volumes
check "--no-balance-volumes without --remesh-surfaces exits 2" test "$rc" -eq 2
check "--no-balance-volumes without --remesh-surfaces says so" contains "$err" "--no-balance-volumes is a rule of --remesh-surfaces"
check "--help lists --no-balance-volumes" bash -c "'$exe' --help | grep -q -- --no-balance-volumes"

# --population-rounds: with 0 no pass thins the initial bubbles (placed about 8 times
# too dense), so the bundled model keeps more of them than with population control
mesh_bubbles() { echo "$out" | sed -n 's/^mesh: .*, \([0-9]*\) bubbles.*/\1/p'; }
run "$model" --population-rounds 0 --no-sliver-removal --threads 2
check "--population-rounds 0 exits 0" test "$rc" -eq 0
b0="$(mesh_bubbles)"
run "$model" --no-sliver-removal --threads 2
b12="$(mesh_bubbles)"
echo "  bundled model's bubbles with 0 / 12 (default) population rounds: $b0 / $b12"
check "--population-rounds 0: the crowded start is kept" test -n "$b0" -a -n "$b12" -a "${b0:-0}" -gt "${b12:-0}"
run "$model" --population-rounds 2.5
check "--population-rounds 2.5 exits 2" test "$rc" -eq 2
check "--help lists --population-rounds" bash -c "'$exe' --help | grep -q -- --population-rounds"
# --population-tolerance: a looser one settles the regions after fewer rounds (the
# population it ends with differs); out of (0, 0.1] it is refused
run "$model" --population-tolerance 0.1 --no-sliver-removal --threads 2
check "--population-tolerance 0.1 exits 0" test "$rc" -eq 0
b_loose="$(mesh_bubbles)"
run "$model" --population-tolerance 0.0005 --no-sliver-removal --threads 2
b_strict="$(mesh_bubbles)"
echo "  bundled model's bubbles with population tolerance 0.1 / 0.005 (default) / 0.0005: $b_loose / $b12 / $b_strict"
check "--population-tolerance 0.1 and 0.0005 end with other populations" \
  test -n "$b_loose" -a -n "$b_strict" -a "${b_loose:-x}" != "${b_strict:-y}"
run "$model" --population-tolerance 0
check "--population-tolerance 0 exits 2" test "$rc" -eq 2
check "--population-tolerance 0 says what it takes" contains "$err" "above 0 and at most 0.1"
check "--help lists --population-tolerance" bash -c "'$exe' --help | grep -q -- --population-tolerance"

# by default each planar face is re-triangulated first: the bottom's needle goes, the cube stays the cube
run "$tmp/cube.obj" -o "$tmp/p.mesh" --quality-json "$tmp/qp.json" --threads 2
check "planar pieces: exits 0" test "$rc" -eq 0
check "planar pieces: summary line" contains "$out" "planar pieces: 6 of 6 re-triangulated"
check "a region with no room for bubbles is named, with the way to a finer mesh" contains "$out" "note: 1 of 1 regions got no bubble inside ('Cube')"
check "... which is --remesh-surfaces --size" contains "$out" "(--remesh-surfaces --size S, e.g. --size 2%"
run "$tmp/cube.obj" --planar-angle-bound 45
check "--planar-angle-bound 45 exits 2" test "$rc" -eq 2
check "--planar-angle-bound 45 named" contains "$err" "--planar-angle-bound"
run "$tmp/cube.obj" --keep-input-triangles -o "$tmp/k.mesh" --quality-json "$tmp/qk.json" --threads 2
check "--keep-input-triangles exits 0" test "$rc" -eq 0
check "--keep-input-triangles: no re-triangulation" test -z "$(echo "$out" | grep 'planar pieces')"
check "--help lists --keep-input-triangles" bash -c "'$exe' --help | grep -q -- --keep-input-triangles"
run "$tmp/cube.obj" --axis-planes-only --keep-input-triangles
check "--axis-planes-only --keep-input-triangles exits 2" test "$rc" -eq 2
check "--axis-planes-only --keep-input-triangles named" contains "$err" "--axis-planes-only"
run "$tmp/cube.obj" --axis-planes-only -o "$tmp/ax.mesh"
check "--axis-planes-only exits 0" test "$rc" -eq 0
check "--axis-planes-only: no tilted piece refined" contains "$out" "(0 tilted"
run "$tmp/cube.obj" --tilted-size-factor 1.5 --axis-planes-only
check "--tilted-size-factor --axis-planes-only exits 2" test "$rc" -eq 2
check "--tilted-size-factor --axis-planes-only named" contains "$err" "--tilted-size-factor"
run "$tmp/cube.obj" --tilted-size-factor 0.5
check "--tilted-size-factor 0.5 exits 2" test "$rc" -eq 2
check "--tilted-size-factor 0.5 named" contains "$err" "--tilted-size-factor must be in [1, 100]"
check "--help lists --tilted-size-factor" bash -c "'$exe' --help | grep -q -- --tilted-size-factor"
check "planar pieces re-triangulated: better smallest dihedral, same volume" python3 -c "
import json,sys
p=json.load(open('$tmp/qp.json'))['all']; k=json.load(open('$tmp/qk.json'))['all']
print('  smallest dihedral', k['dihedral_angle']['min'], '->', p['dihedral_angle']['min'], ', volume', k['volume'], p['volume'])
sys.exit(0 if p['dihedral_angle']['min'] > k['dihedral_angle']['min'] and abs(p['volume'] - 1) < 1e-12 and abs(k['volume'] - 1) < 1e-12 else 1)"

run "$model" --size 2% --planar-angle-bound 0 -o "$tmp/size_unused.mesh"
check "--size with no new points on planar pieces exits 2" test "$rc" -eq 2
check "--size with no new points on planar pieces says why" contains "$err" "it does nothing with --planar-angle-bound 0"
run "$model" --remesh-surfaces --size 0
check "--size 0 exits 2" test "$rc" -eq 2
run "$model" --remesh-surfaces --size abc%
check "--size abc% exits 2" test "$rc" -eq 2
check "--size abc% named" contains "$err" "--size"

run "$model" --force-law soft
check "--force-law soft exits 2" test "$rc" -eq 2
check "--force-law soft named" contains "$err" "--force-law takes cubic or repulsive, not 'soft'"
run "$model" --smooth 2.5
check "--smooth 2.5 exits 2" test "$rc" -eq 2
check "--smooth 2.5 named" contains "$err" "--smooth takes a number of passes"

run "$model" --no-such-option
check "unknown option exits 2" test "$rc" -eq 2
check "unknown option named" contains "$err" "--no-such-option"

run "$tmp/missing.obj" --check
check "missing file exits 1" test "$rc" -eq 1
check "missing file named" contains "$err" "missing.obj"

printf '\x00\x01\x02binary\xff\xfe' > "$tmp/binary.obj"
run "$tmp/binary.obj" --check --summary-json "$tmp/bin.json"
check "binary file exits 1" test "$rc" -eq 1
check "binary file named" contains "$err" "binary.obj"
check "no JSON written on failure" test ! -e "$tmp/bin.json"
check "no temporary left on failure" test ! -e "$tmp/bin.json.tmp"

: > "$tmp/empty.ml"
run "$tmp/empty.ml" --check
check "empty file exits 1" test "$rc" -eq 1
check "empty file named" contains "$err" "empty.ml"

run "$tmp/model.xyz" --check
check "unknown extension exits non-zero" test "$rc" -ne 0

# an open body: a tetrahedron with one face missing
cat > "$tmp/open.obj" <<'OBJ'
o Body
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
f 1 3 2
f 1 2 4
f 2 3 4
OBJ
run "$tmp/open.obj" --check
check "open body exits 1" test "$rc" -eq 1
check "open body names the region" contains "$err" "Body"

if [ -f "$model" ]; then
  run "$model" --check --summary-json "$tmp/summary.json"
  check "default model --check exits 0" test "$rc" -eq 0
  check "summary printed" contains "$out" "region"
  check "summary JSON written" test -s "$tmp/summary.json"
  if command -v python3 >/dev/null; then
    check "summary JSON parses and has regions" python3 -c "
import json,sys
d=json.load(open('$tmp/summary.json'))
regions=d['regions']
assert len(regions) >= 4, regions
assert all(r['volume'] > 0 for r in regions)
"
  fi
  # end to end: mesh the default model, several outputs, quality report
  run "$model" -o "$tmp/m.mesh" -o "$tmp/m.msh" -o "$tmp/m.vtu" --quality-json "$tmp/q.json" --quality-svg "$tmp/q.svg" \
      --section-svg "$tmp/s.svg" --threads 2
  check "meshing the default model exits 0" test "$rc" -eq 0
  check "progress line per stage" contains "$out" "tetrahedralization..."
  check "progress line per step of the sliver removal" contains "$out" "s] sliver removal: moving bubbles..."
  check "progress line per step of the tetrahedralization" contains "$out" "s] tetrahedralization: recovering the surfaces..."
  check "summary gives tetrahedra" contains "$out" "tetrahedra"
  check "summary gives triangles kept whole" contains "$out" "input triangles kept whole"
  check "summary reports sliver removal" contains "$out" "sliver removal: tetrahedra with a dihedral angle under 15"
  for f in m.mesh m.msh m.vtu q.json q.svg s.svg; do
    check "$f written" test -s "$tmp/$f"
    check "$f.tmp not left" test ! -e "$tmp/$f.tmp"
  done
  if command -v python3 >/dev/null; then
    check "quality JSON has every region" python3 -c "
import json
q=json.load(open('$tmp/q.json'))
s=json.load(open('$tmp/summary.json'))
regions=[r for r in q['regions'] if r.get('region') not in (None, 'all')]
names={r.get('name') for r in q['regions']}
for r in s['regions']:
    assert r['name'] in names, (r['name'], names)
"
  fi
  # the mesh file states one tetrahedron block whose count matches the summary
  tets=$(awk '/^Tetrahedra/{getline; print $1; exit}' "$tmp/m.mesh")
  check "Medit file has tetrahedra" test "${tets:-0}" -gt 0
  check "summary tet count = Medit count" contains "$out" "mesh: $tets tetrahedra"

  # the section: a vertical plane through the middle, cut cells of several regions named in the legend
  if command -v python3 >/dev/null; then
    check "section SVG cuts cells of several regions, legend names them, surfaces drawn" python3 -c "
import re,json
svg=open('$tmp/s.svg').read()
assert 'section y = 300 (x to the right, z up)' in svg, svg[:400]
fills=set(re.findall(r'class=\"cell\" fill=\"([^\"]+)\"', svg))
assert len(fills) >= 4, fills
assert svg.count('class=\"surface\"') > 10
names=[r['name'] for r in json.load(open('$tmp/summary.json'))['regions']]
assert sum(('>'+n+'<') in svg for n in names) >= 4, names
"
  fi
  run "$model" -q --section-svg "$tmp/top.svg" --section z=350 --no-sliver-removal
  check "--section z=350 exits 0" test "$rc" -eq 0
  check "--section z=350 is a map view" grep -q "section z = 350 (seen from above" "$tmp/top.svg"
  command -v python3 >/dev/null && check "section legend counts the outlined poor tetrahedra" python3 -c "
import re
svg=open('$tmp/top.svg').read()
m=re.search(r'tetrahedra under 10 deg \((\d+) cut\)', svg)
assert m, 'no legend entry for the poor tetrahedra'
assert int(m.group(1)) == svg.count('class=\"poor-cell\"'), (m.group(1), svg.count('class=\"poor-cell\"'))
"
  run "$model" -q --section-svg "$tmp/miss.svg" --section x=5000 -o "$tmp/miss.mesh"
  check "--section outside the model exits 2" test "$rc" -eq 2
  check "--section outside the model gives the model's range" contains "$err" "misses the model: its x runs from 0 to 1000"
  check "--section outside the model writes nothing" test ! -e "$tmp/miss.svg" -a ! -e "$tmp/miss.mesh"
  run "$model" --section w=3 --section-svg "$tmp/w.svg"
  check "--section w=3 exits 2" test "$rc" -eq 2
  check "--section w=3 says what it takes" contains "$err" "x=V, y=V or z=V"
  run "$model" --section y=10
  check "--section without --section-svg exits 2" test "$rc" -eq 2

  # a real consumer: CalculiX solves the bundled model's Abaqus deck under its own weight
  if [ -x /usr/bin/python3 ] && command -v ccx >/dev/null; then
    mkdir -p "$tmp/ccx"
    run "$model" -q -o "$tmp/ccx/model.inp"
    check "Abaqus output exits 0" test "$rc" -eq 0
    check "CalculiX solves the bundled model, largest displacement at the top" \
      /usr/bin/python3 "$here/check_consumers.py" ccx-model "$tmp/ccx/model.inp"
  else
    echo "SKIP: CalculiX check (needs /usr/bin/python3 and ccx: Debian calculix-ccx)"
  fi

  # same input, same mesh, whatever the thread count
  run "$model" -o "$tmp/one.mesh" --threads 1 -q
  check "one thread exits 0" test "$rc" -eq 0
  check "same mesh with 1 and 2 threads" cmp -s "$tmp/one.mesh" "$tmp/m.mesh"

  # the repulsive force law: bubbles placed otherwise, the same region volumes
  run "$model" -q -o "$tmp/rep.mesh" --force-law repulsive --quality-json "$tmp/q_rep.json"
  check "--force-law repulsive exits 0" test "$rc" -eq 0
  if command -v python3 >/dev/null; then
    check "--force-law repulsive: another mesh, same volume" python3 -c "
import json
a=json.load(open('$tmp/q.json')); b=json.load(open('$tmp/q_rep.json'))
assert open('$tmp/rep.mesh').read() != open('$tmp/m.mesh').read()
assert b['all']['tetrahedra'] > 0
assert abs(a['all']['volume'] - b['all']['volume']) <= 1e-9 * a['all']['volume']
"
  fi

  # smoothing: the same volume, a lower aspect-ratio median, a mean smallest
  # dihedral no worse (2.19 -> 2.15 and 44.3 -> 44.8 degrees when written)
  run "$model" -q -o "$tmp/smooth.mesh" --smooth 3 --quality-json "$tmp/q_smooth.json"
  check "--smooth 3 exits 0" test "$rc" -eq 0
  if command -v python3 >/dev/null; then
    check "--smooth 3: same volume, aspect-ratio median lower, mean smallest dihedral no worse" python3 -c "
import json
a=json.load(open('$tmp/q.json'))['all']; b=json.load(open('$tmp/q_smooth.json'))['all']
assert abs(a['volume'] - b['volume']) <= 1e-9 * a['volume']
assert b['aspect_ratio']['median'] < a['aspect_ratio']['median'], (a['aspect_ratio'], b['aspect_ratio'])
assert b['smallest_dihedral_angle']['mean'] >= a['smallest_dihedral_angle']['mean']
"
  fi

  # sliver removal moves bubbles only where it helps: switched off, the mesh is no better
  run "$model" -q --no-sliver-removal --quality-json "$tmp/q_raw.json"
  check "--no-sliver-removal exits 0" test "$rc" -eq 0
  if command -v python3 >/dev/null; then
    check "sliver removal: min dihedral not worse, fewer tets under 15 degrees" python3 -c "
import json
a=json.load(open('$tmp/q.json'))['all']; b=json.load(open('$tmp/q_raw.json'))['all']
assert a['tetrahedra'] > 0 and b['tetrahedra'] > 0
assert a['dihedral_angle']['min'] >= b['dihedral_angle']['min'], (a['dihedral_angle'], b['dihedral_angle'])
sa=a['smallest_dihedral_angle']; sb=b['smallest_dihedral_angle']
assert sa['share_under_15'] * a['tetrahedra'] < sb['share_under_15'] * b['tetrahedra'], (sa, sb)
assert abs(a['volume'] - b['volume']) <= 1e-9 * b['volume']
"
    # the default model's input triangles have no angle under 10 degrees: no
    # tetrahedron under 10 is left (session 51's two sat among four surface
    # points, which only a new vertex in the star of one of their edges reached)
    check "sliver removal: the default model has no tetrahedron under 10 degrees" python3 -c "
import json
s=json.load(open('$tmp/q.json'))['all']['smallest_dihedral_angle']
assert s['share_under_10'] == 0 and s['share_under_10_not_at_small_surface_angle'] == 0, s
"
  fi
  # a region asked finer with the surfaces kept: its bubbles only get smaller
  run "$model" -q --region-size-factor Layer_1_footwall=0.5 --region-size-factor 5=2 --quality-json "$tmp/q_factors.json"
  check "--region-size-factor with the surfaces kept exits 0" test "$rc" -eq 0
  if command -v python3 >/dev/null; then
    check "--region-size-factor: region 1 at 0.5 over twice the tetrahedra, region 5 at 2 fewer, volumes the same" python3 -c "
import json
a={r['name']: r for r in json.load(open('$tmp/q.json'))['regions']}
b={r['name']: r for r in json.load(open('$tmp/q_factors.json'))['regions']}
assert b['Layer_1_footwall']['tetrahedra'] > 2 * a['Layer_1_footwall']['tetrahedra'], (a['Layer_1_footwall'], b['Layer_1_footwall'])
assert b['Layer_4_footwall']['tetrahedra'] < a['Layer_4_footwall']['tetrahedra']
for n in a: assert abs(a[n]['volume'] - b[n]['volume']) <= 1e-9 * a[n]['volume'], n
"
  fi
  # Steiner points of the recovery: collapsed by default, kept on request;
  # the collapses make input triangles whole again
  run "$model" -q --keep-steiner-points --quality-json "$tmp/q_kept.json"
  check "--keep-steiner-points exits 0" test "$rc" -eq 0
  if command -v python3 >/dev/null; then
    # A collapse is kept only where it leaves no more cells under the sliver bound
    # (and none under the mesh's smallest angle): fewer tets under it in the end. The
    # flips and insertions after the collapses differ between the two runs, so their
    # smallest angles are not ordered (session 39: 9.275 collapsed, 9.340 kept)
    check "collapsed Steiner points: fewer, more triangles whole, same volume, no more tets under 15 degrees" python3 -c "
import json
qa=json.load(open('$tmp/q.json')); qb=json.load(open('$tmp/q_kept.json'))
a=qa['all']; b=qb['all']
assert qa['steiner_points'] < qb['steiner_points'], (qa['steiner_points'], qb['steiner_points'])
assert qa['input_triangles_kept_whole'] > qb['input_triangles_kept_whole']
assert abs(a['volume'] - b['volume']) <= 1e-9 * b['volume']
under = lambda r: round(r['smallest_dihedral_angle']['share_under_15'] * r['tetrahedra'])
print('  tets under 15 degrees:', under(a), 'collapsed,', under(b), 'kept; smallest dihedral',
      a['dihedral_angle']['min'], b['dihedral_angle']['min'])
assert under(a) <= under(b), (under(a), under(b))
"
  fi
  run "$model" --sliver-bound 80
  check "--sliver-bound out of range exits 2" test "$rc" -eq 2
  check "--sliver-bound out of range named" contains "$err" "--sliver-bound"

  # the model turned by 30 degrees about the vertical: its walls are planes only up
  # to the rounding of their points (internal/near_coplanarity.h); before, the
  # surface recovery split a wall edge without end and gave up after two minutes
  if command -v python3 >/dev/null; then
    python3 - "$model" "$tmp/turned.obj" <<'PY'
import sys, math
c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
with open(sys.argv[1]) as f, open(sys.argv[2], 'w') as out:
    for line in f:
        t = line.split()
        if t and t[0] == 'v':
            x, y, z = map(float, t[1:4])
            line = 'v %r %r %r\n' % (c * x - s * y, s * x + c * y, z)
        out.write(line)
PY
    if command -v timeout >/dev/null; then limit=(timeout 120); else limit=(); fi
    "${limit[@]}" "$exe" "$tmp/turned.obj" -q --quality-json "$tmp/q_turned.json" >"$tmp/out" 2>"$tmp/err"; rc=$?
    check "model turned by 30 degrees: meshed" test "$rc" -eq 0
    check "model turned by 30 degrees: same volume, smallest dihedral over 1 degree" python3 -c "
import json
a=json.load(open('$tmp/q.json'))['all']; b=json.load(open('$tmp/q_turned.json'))['all']
assert abs(a['volume'] - b['volume']) <= 1e-9 * a['volume'], (a['volume'], b['volume'])
assert b['dihedral_angle']['min'] > 1., b['dihedral_angle']
"
  fi

  # modelA2 turned by 30 degrees: its outer walls are fans of needles planar only
  # up to rounding, on the convex hull; the recovery fails there without guard
  # points mirrored beyond them (internal/outer_wall_guards.h), and is run again
  # with them. Before: a clear error after 256 stalled insertions (and earlier a hang).
  a2="$root/../shared/data/geomodels/modelA2.ml"
  if command -v python3 >/dev/null && [ -f "$a2" ]; then
    python3 - "$a2" "$tmp/A2turned.ml" <<'PY'
import sys, math, re
c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
number = re.compile(r'[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?$')
after = 0  # a TFACE line of the model section is followed by three points
with open(sys.argv[1]) as f, open(sys.argv[2], 'w') as out:
    for line in f:
        t = line.split()
        if t and t[0] in ('VRTX', 'PVRTX') and len(t) >= 5:
            x, y, z = map(float, t[2:5])
            line = ' '.join([t[0], t[1], repr(c * x - s * y), repr(s * x + c * y), repr(z)] + t[5:]) + '\n'
        elif t and t[0] == 'TFACE' and len(t) >= 3:
            after = 3
        elif after > 0 and len(t) == 3 and all(number.match(q) for q in t):
            x, y, z = map(float, t)
            line = '  %r %r %r\n' % (c * x - s * y, s * x + c * y, z)
            after -= 1
        else:
            after = 0
        out.write(line)
PY
    if command -v timeout >/dev/null; then limit=(timeout 400); else limit=(); fi
    "${limit[@]}" "$exe" "$tmp/A2turned.ml" --threads 2 --summary-json "$tmp/s_a2.json" \
      --quality-json "$tmp/q_a2.json" >"$tmp/out" 2>"$tmp/err"; rc=$?
    check "modelA2 turned by 30 degrees: meshed" test "$rc" -eq 0
    check "modelA2 turned by 30 degrees: guard points said" contains "$(cat "$tmp/out")" "guard points"
    check "modelA2 turned by 30 degrees: every region's volume, no tet inverted" python3 -c "
import json
s=json.load(open('$tmp/s_a2.json')); q=json.load(open('$tmp/q_a2.json'))
mesh={r['region']: r['volume'] for r in q['regions']}
for r in s['regions']:
    assert abs(mesh[r['index']] - r['volume']) <= 1e-9 * r['volume'], (r['index'], mesh[r['index']], r['volume'])
assert q['all']['negatively_oriented_tetrahedra'] == 0, q['all']
"
  else
    echo "SKIP: modelA2 turned ($a2 or python3 missing)"
  fi

  # a bad output name is refused before any work, nothing written
  run "$model" -o "$tmp/m.xyz"
  check "unknown output format exits 2" test "$rc" -eq 2
  check "unknown output format named" contains "$err" "m.xyz"
else
  echo "SKIP: bundled model $model not generated yet"
fi

echo "$pass passed, $fail failed"
test "$fail" -eq 0
