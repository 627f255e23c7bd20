#!/usr/bin/env bash
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# test_quality_cli.sh BUILD_DIR
# bubble_mesh_3_quality reads every format it claims and gives the same numbers
# on the same mesh written in each (our own small mesh, and what Gmsh and TetGen
# write when they are installed); bad or missing files give an error that names
# the file (and the line), and a non-zero exit.
set -u
BUILD=${1:?usage: test_quality_cli.sh BUILD_DIR}
Q="$BUILD/tools/bubble_mesh_3_quality"
if [ ! -x "$Q" ]; then echo "FAIL: $Q is not built"; exit 1; fi
T=$(mktemp -d "${TMPDIR:-/tmp}/bm3_quality.XXXXXX")
trap 'rm -rf "$T"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

# the JSON numbers that do not depend on the element order or the names
# (the worst-tet list keeps file indices, and only Gmsh files name regions)
numbers() { grep -v '"name"' "$1" | sed '/"worst_tetrahedra"/,$d'; }
# the same without what comes from boundary triangles (legacy .vtk from TetGen has none)
volume_numbers() {
  numbers "$1" | grep -v -e '"boundary_triangles"' -e '"surface_angle_source"' |
    sed 's/, "share_under_10_not_at_small_surface_angle": [^}]*//'
}

# ---------------------------------------------------------------------------
# The unit cube cut into 12 tets from an off-centre point c = (0.5, 0.45, 0.52):
# each face in two triangles, each triangle with c. Region 1 holds the tets whose
# centroid has x < 1/2 (the x=0 face, and one half of each y and z face), region 2
# the rest. By hand: region 1 = 1/6 (pyramid on x=0, height 1/2) + half of the
# pyramids on y=0, y=1, z=0, z=1, (0.45 + 0.55 + 0.52 + 0.48)/6 = 1/3: 0.5, region 2 0.5.
# 18 boundary triangles: the 12 of the hull (patch = face 1-6) and 6 between regions (7).
# The same mesh in every format: numbers printed with 17 digits in all of them.
cat > "$T/cube.mesh" <<'EOF'
MeshVersionFormatted 1
# a comment
Dimension 3
Vertices
9
0 0 0 0
1 0 0 0
0 1 0 0
1 1 0 0
0 0 1 0
1 0 1 0
0 1 1 0
1 1 1 0
0.5 0.45000000000000001 0.52000000000000002 0
Triangles
18
1 3 7 1
1 7 5 1
2 4 8 2
2 8 6 2
1 2 6 3
1 6 5 3
3 4 8 4
3 8 7 4
1 2 4 5
1 4 3 5
5 6 8 6
5 8 7 6
1 4 9 7
1 6 9 7
3 4 9 7
3 8 9 7
5 6 9 7
5 8 9 7
Tetrahedra
12
1 3 7 9 1
1 7 5 9 1
4 2 8 9 2
8 2 6 9 2
2 1 6 9 2
6 1 5 9 1
3 4 8 9 2
3 8 7 9 1
1 2 4 9 2
1 4 3 9 1
6 5 8 9 2
8 5 7 9 1
End
EOF
cat > "$T/cube41.msh" <<'EOF'
$MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
3 1 "left"
3 2 "right"
$EndPhysicalNames
$Entities
0 0 7 2
1 0 0 0 1 1 1 1 1 0
2 0 0 0 1 1 1 1 2 0
3 0 0 0 1 1 1 1 3 0
4 0 0 0 1 1 1 1 4 0
5 0 0 0 1 1 1 1 5 0
6 0 0 0 1 1 1 1 6 0
7 0 0 0 1 1 1 1 7 0
11 0 0 0 1 1 1 1 1 0
12 0 0 0 1 1 1 1 2 0
$EndEntities
$Nodes
1 9 101 109
3 11 0 9
101
102
103
104
105
106
107
108
109
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
0.5 0.45000000000000001 0.52000000000000002
$EndNodes
$Elements
9 30 1 30
2 1 2 2
1 101 103 107
2 101 107 105
2 2 2 2
3 102 104 108
4 102 108 106
2 3 2 2
5 101 102 106
6 101 106 105
2 4 2 2
7 103 104 108
8 103 108 107
2 5 2 2
9 101 102 104
10 101 104 103
2 6 2 2
11 105 106 108
12 105 108 107
2 7 2 6
13 101 104 109
14 101 106 109
15 103 104 109
16 103 108 109
17 105 106 109
18 105 108 109
3 11 4 6
19 101 103 107 109
20 101 107 105 109
21 106 101 105 109
22 103 108 107 109
23 101 104 103 109
24 108 105 107 109
3 12 4 6
25 104 102 108 109
26 108 102 106 109
27 102 101 106 109
28 103 104 108 109
29 101 102 104 109
30 106 105 108 109
$EndElements
EOF
cat > "$T/cube22.msh" <<'EOF'
$MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
9
1 0 0 0
2 1 0 0
3 0 1 0
4 1 1 0
5 0 0 1
6 1 0 1
7 0 1 1
8 1 1 1
9 0.5 0.45000000000000001 0.52000000000000002
$EndNodes
$Elements
30
1 2 2 1 1 1 3 7
2 2 2 1 1 1 7 5
3 2 2 2 2 2 4 8
4 2 2 2 2 2 8 6
5 2 2 3 3 1 2 6
6 2 2 3 3 1 6 5
7 2 2 4 4 3 4 8
8 2 2 4 4 3 8 7
9 2 2 5 5 1 2 4
10 2 2 5 5 1 4 3
11 2 2 6 6 5 6 8
12 2 2 6 6 5 8 7
13 2 2 7 7 1 4 9
14 2 2 7 7 1 6 9
15 2 2 7 7 3 4 9
16 2 2 7 7 3 8 9
17 2 2 7 7 5 6 9
18 2 2 7 7 5 8 9
19 4 2 1 11 1 3 7 9
20 4 2 1 11 1 7 5 9
21 4 2 2 12 4 2 8 9
22 4 2 2 12 8 2 6 9
23 4 2 2 12 2 1 6 9
24 4 2 1 11 6 1 5 9
25 4 2 2 12 3 4 8 9
26 4 2 1 11 3 8 7 9
27 4 2 2 12 1 2 4 9
28 4 2 1 11 1 4 3 9
29 4 2 2 12 6 5 8 9
30 4 2 1 11 8 5 7 9
$EndElements
EOF
cat > "$T/cube.node" <<'EOF'
# cube and centre, numbered from 0
9 3 0 0
0 0 0 0
1 1 0 0
2 0 1 0
3 1 1 0
4 0 0 1
5 1 0 1
6 0 1 1
7 1 1 1
8 0.5 0.45000000000000001 0.52000000000000002
EOF
cat > "$T/cube.ele" <<'EOF'
12 4 1
0 0 2 6 8 1
1 0 6 4 8 1
2 3 1 7 8 2
3 7 1 5 8 2
4 1 0 5 8 2
5 5 0 4 8 1
6 2 3 7 8 2
7 2 7 6 8 1
8 0 1 3 8 2
9 0 3 2 8 1
10 5 4 7 8 2
11 7 4 6 8 1
EOF
cat > "$T/cube.face" <<'EOF'
18 1
0 0 2 6 1
1 0 6 4 1
2 1 3 7 2
3 1 7 5 2
4 0 1 5 3
5 0 5 4 3
6 2 3 7 4
7 2 7 6 4
8 0 1 3 5
9 0 3 2 5
10 4 5 7 6
11 4 7 6 6
12 0 3 8 7
13 0 5 8 7
14 2 3 8 7
15 2 7 8 7
16 4 5 8 7
17 4 7 8 7
EOF
cat > "$T/cube_ascii.vtu" <<'EOF'
<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
  <Piece NumberOfPoints="9" NumberOfCells="30">
    <Points>
      <DataArray type="Float64" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1 0.5 0.45000000000000001 0.52000000000000002
      </DataArray>
    </Points>
    <Cells>
      <DataArray type="Int64" Name="connectivity" format="ascii">
0 2 6 0 6 4 1 3 7 1 7 5 0 1 5 0 5 4 2 3 7 2 7 6 0 1 3 0 3 2 4 5 7 4 7 6 0 3 8 0 5 8 2 3 8 2 7 8 4 5 8 4 7 8 0 2 6 8 0 6 4 8 3 1 7 8 7 1 5 8 1 0 5 8 5 0 4 8 2 3 7 8 2 7 6 8 0 1 3 8 0 3 2 8 5 4 7 8 7 4 6 8
      </DataArray>
      <DataArray type="Int64" Name="offsets" format="ascii">
3 6 9 12 15 18 21 24 27 30 33 36 39 42 45 48 51 54 58 62 66 70 74 78 82 86 90 94 98 102
      </DataArray>
      <DataArray type="UInt8" Name="types" format="ascii">
5 5 5 5 5 5 5 5 5 5 5 5 5 5 5 5 5 5 10 10 10 10 10 10 10 10 10 10 10 10
      </DataArray>
    </Cells>
    <CellData Scalars="MeshDomain">
      <DataArray type="Float64" Name="quality" format="ascii">
0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
      </DataArray>
      <DataArray type="Int32" Name="MeshDomain" format="ascii">
1 1 2 2 3 3 4 4 5 5 6 6 7 7 7 7 7 7 1 1 2 2 2 1 2 1 2 1 2 1
      </DataArray>
    </CellData>
  </Piece>
  </UnstructuredGrid>
</VTKFile>
EOF
cat > "$T/cube_base64.vtu" <<'EOF'
<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian" header_type="UInt32">
<UnstructuredGrid>
<Piece NumberOfPoints="9" NumberOfCells="30">
<Points>
<DataArray type="Float64" NumberOfComponents="3" format="binary">2AAAAA==AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA8D8AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAADwPwAAAAAAAAAAAAAAAAAA8D8AAAAAAADwPwAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAPA/AAAAAAAA8D8AAAAAAAAAAAAAAAAAAPA/AAAAAAAAAAAAAAAAAADwPwAAAAAAAPA/AAAAAAAA8D8AAAAAAADwPwAAAAAAAPA/AAAAAAAA4D/NzMzMzMzcP6RwPQrXo+A/</DataArray>
</Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="binary">MAMAAA==AAAAAAAAAAACAAAAAAAAAAYAAAAAAAAAAAAAAAAAAAAGAAAAAAAAAAQAAAAAAAAAAQAAAAAAAAADAAAAAAAAAAcAAAAAAAAAAQAAAAAAAAAHAAAAAAAAAAUAAAAAAAAAAAAAAAAAAAABAAAAAAAAAAUAAAAAAAAAAAAAAAAAAAAFAAAAAAAAAAQAAAAAAAAAAgAAAAAAAAADAAAAAAAAAAcAAAAAAAAAAgAAAAAAAAAHAAAAAAAAAAYAAAAAAAAAAAAAAAAAAAABAAAAAAAAAAMAAAAAAAAAAAAAAAAAAAADAAAAAAAAAAIAAAAAAAAABAAAAAAAAAAFAAAAAAAAAAcAAAAAAAAABAAAAAAAAAAHAAAAAAAAAAYAAAAAAAAAAAAAAAAAAAADAAAAAAAAAAgAAAAAAAAAAAAAAAAAAAAFAAAAAAAAAAgAAAAAAAAAAgAAAAAAAAADAAAAAAAAAAgAAAAAAAAAAgAAAAAAAAAHAAAAAAAAAAgAAAAAAAAABAAAAAAAAAAFAAAAAAAAAAgAAAAAAAAABAAAAAAAAAAHAAAAAAAAAAgAAAAAAAAAAAAAAAAAAAACAAAAAAAAAAYAAAAAAAAACAAAAAAAAAAAAAAAAAAAAAYAAAAAAAAABAAAAAAAAAAIAAAAAAAAAAMAAAAAAAAAAQAAAAAAAAAHAAAAAAAAAAgAAAAAAAAABwAAAAAAAAABAAAAAAAAAAUAAAAAAAAACAAAAAAAAAABAAAAAAAAAAAAAAAAAAAABQAAAAAAAAAIAAAAAAAAAAUAAAAAAAAAAAAAAAAAAAAEAAAAAAAAAAgAAAAAAAAAAgAAAAAAAAADAAAAAAAAAAcAAAAAAAAACAAAAAAAAAACAAAAAAAAAAcAAAAAAAAABgAAAAAAAAAIAAAAAAAAAAAAAAAAAAAAAQAAAAAAAAADAAAAAAAAAAgAAAAAAAAAAAAAAAAAAAADAAAAAAAAAAIAAAAAAAAACAAAAAAAAAAFAAAAAAAAAAQAAAAAAAAABwAAAAAAAAAIAAAAAAAAAAcAAAAAAAAABAAAAAAAAAAGAAAAAAAAAAgAAAAAAAAA</DataArray>
<DataArray type="Int64" Name="offsets" format="binary">8AAAAA==AwAAAAAAAAAGAAAAAAAAAAkAAAAAAAAADAAAAAAAAAAPAAAAAAAAABIAAAAAAAAAFQAAAAAAAAAYAAAAAAAAABsAAAAAAAAAHgAAAAAAAAAhAAAAAAAAACQAAAAAAAAAJwAAAAAAAAAqAAAAAAAAAC0AAAAAAAAAMAAAAAAAAAAzAAAAAAAAADYAAAAAAAAAOgAAAAAAAAA+AAAAAAAAAEIAAAAAAAAARgAAAAAAAABKAAAAAAAAAE4AAAAAAAAAUgAAAAAAAABWAAAAAAAAAFoAAAAAAAAAXgAAAAAAAABiAAAAAAAAAGYAAAAAAAAA</DataArray>
<DataArray type="UInt8" Name="types" format="binary">HgAAAA==BQUFBQUFBQUFBQUFBQUFBQUFCgoKCgoKCgoKCgoK</DataArray>
</Cells>
<CellData>
<DataArray type="Int32" Name="MeshDomain" format="binary">eAAAAA==AQAAAAEAAAACAAAAAgAAAAMAAAADAAAABAAAAAQAAAAFAAAABQAAAAYAAAAGAAAABwAAAAcAAAAHAAAABwAAAAcAAAAHAAAAAQAAAAEAAAACAAAAAgAAAAIAAAABAAAAAgAAAAEAAAACAAAAAQAAAAIAAAABAAAA</DataArray>
</CellData>
</Piece>
</UnstructuredGrid>
</VTKFile>
EOF
cat > "$T/cube.vtk" <<'EOF'
# vtk DataFile Version 2.0
cube and centre
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 9 double
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
0.5 0.45000000000000001 0.52000000000000002
CELLS 30 132
3 0 2 6
3 0 6 4
3 1 3 7
3 1 7 5
3 0 1 5
3 0 5 4
3 2 3 7
3 2 7 6
3 0 1 3
3 0 3 2
3 4 5 7
3 4 7 6
3 0 3 8
3 0 5 8
3 2 3 8
3 2 7 8
3 4 5 8
3 4 7 8
4 0 2 6 8
4 0 6 4 8
4 3 1 7 8
4 7 1 5 8
4 1 0 5 8
4 5 0 4 8
4 2 3 7 8
4 2 7 6 8
4 0 1 3 8
4 0 3 2 8
4 5 4 7 8
4 7 4 6 8
CELL_TYPES 30
5
5
5
5
5
5
5
5
5
5
5
5
5
5
5
5
5
5
10
10
10
10
10
10
10
10
10
10
10
10
CELL_DATA 30
SCALARS cell_scalars int 1
LOOKUP_TABLE default
1
1
2
2
3
3
4
4
5
5
6
6
7
7
7
7
7
7
1
1
2
2
2
1
2
1
2
1
2
1
EOF
base64 -d > "$T/cube_raw.vtu" <<'EOF'
PD94bWwgdmVyc2lvbj0iMS4wIj8+CjxWVEtGaWxlIHR5cGU9IlVuc3RydWN0dXJlZEdyaWQiIHZl
cnNpb249IjAuMSIgYnl0ZV9vcmRlcj0iTGl0dGxlRW5kaWFuIiBoZWFkZXJfdHlwZT0iVUludDY0
Ij4KPFVuc3RydWN0dXJlZEdyaWQ+CjxQaWVjZSBOdW1iZXJPZlBvaW50cz0iOSIgTnVtYmVyT2ZD
ZWxscz0iMzAiPgo8UG9pbnRzPgo8RGF0YUFycmF5IHR5cGU9IkZsb2F0NjQiIE51bWJlck9mQ29t
cG9uZW50cz0iMyIgZm9ybWF0PSJhcHBlbmRlZCIgb2Zmc2V0PSIwIi8+CjwvUG9pbnRzPgo8Q2Vs
bHM+CjxEYXRhQXJyYXkgdHlwZT0iSW50NjQiIE5hbWU9ImNvbm5lY3Rpdml0eSIgZm9ybWF0PSJh
cHBlbmRlZCIgb2Zmc2V0PSIyMjQiLz4KPERhdGFBcnJheSB0eXBlPSJJbnQ2NCIgTmFtZT0ib2Zm
c2V0cyIgZm9ybWF0PSJhcHBlbmRlZCIgb2Zmc2V0PSIxMDQ4Ii8+CjxEYXRhQXJyYXkgdHlwZT0i
VUludDgiIE5hbWU9InR5cGVzIiBmb3JtYXQ9ImFwcGVuZGVkIiBvZmZzZXQ9IjEyOTYiLz4KPC9D
ZWxscz4KPENlbGxEYXRhPgo8RGF0YUFycmF5IHR5cGU9IkludDMyIiBOYW1lPSJNZXNoRG9tYWlu
IiBmb3JtYXQ9ImFwcGVuZGVkIiBvZmZzZXQ9IjEzMzQiLz4KPC9DZWxsRGF0YT4KPC9QaWVjZT4K
PC9VbnN0cnVjdHVyZWRHcmlkPgo8QXBwZW5kZWREYXRhIGVuY29kaW5nPSJyYXciPgpf2AAAAAAA
AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAADwPwAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA
AAAAAAAAAPA/AAAAAAAAAAAAAAAAAADwPwAAAAAAAPA/AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA
AAAAAAAA8D8AAAAAAADwPwAAAAAAAAAAAAAAAAAA8D8AAAAAAAAAAAAAAAAAAPA/AAAAAAAA8D8A
AAAAAADwPwAAAAAAAPA/AAAAAAAA8D8AAAAAAADgP83MzMzMzNw/pHA9Ctej4D8wAwAAAAAAAAAA
AAAAAAAAAgAAAAAAAAAGAAAAAAAAAAAAAAAAAAAABgAAAAAAAAAEAAAAAAAAAAEAAAAAAAAAAwAA
AAAAAAAHAAAAAAAAAAEAAAAAAAAABwAAAAAAAAAFAAAAAAAAAAAAAAAAAAAAAQAAAAAAAAAFAAAA
AAAAAAAAAAAAAAAABQAAAAAAAAAEAAAAAAAAAAIAAAAAAAAAAwAAAAAAAAAHAAAAAAAAAAIAAAAA
AAAABwAAAAAAAAAGAAAAAAAAAAAAAAAAAAAAAQAAAAAAAAADAAAAAAAAAAAAAAAAAAAAAwAAAAAA
AAACAAAAAAAAAAQAAAAAAAAABQAAAAAAAAAHAAAAAAAAAAQAAAAAAAAABwAAAAAAAAAGAAAAAAAA
AAAAAAAAAAAAAwAAAAAAAAAIAAAAAAAAAAAAAAAAAAAABQAAAAAAAAAIAAAAAAAAAAIAAAAAAAAA
AwAAAAAAAAAIAAAAAAAAAAIAAAAAAAAABwAAAAAAAAAIAAAAAAAAAAQAAAAAAAAABQAAAAAAAAAI
AAAAAAAAAAQAAAAAAAAABwAAAAAAAAAIAAAAAAAAAAAAAAAAAAAAAgAAAAAAAAAGAAAAAAAAAAgA
AAAAAAAAAAAAAAAAAAAGAAAAAAAAAAQAAAAAAAAACAAAAAAAAAADAAAAAAAAAAEAAAAAAAAABwAA
AAAAAAAIAAAAAAAAAAcAAAAAAAAAAQAAAAAAAAAFAAAAAAAAAAgAAAAAAAAAAQAAAAAAAAAAAAAA
AAAAAAUAAAAAAAAACAAAAAAAAAAFAAAAAAAAAAAAAAAAAAAABAAAAAAAAAAIAAAAAAAAAAIAAAAA
AAAAAwAAAAAAAAAHAAAAAAAAAAgAAAAAAAAAAgAAAAAAAAAHAAAAAAAAAAYAAAAAAAAACAAAAAAA
AAAAAAAAAAAAAAEAAAAAAAAAAwAAAAAAAAAIAAAAAAAAAAAAAAAAAAAAAwAAAAAAAAACAAAAAAAA
AAgAAAAAAAAABQAAAAAAAAAEAAAAAAAAAAcAAAAAAAAACAAAAAAAAAAHAAAAAAAAAAQAAAAAAAAA
BgAAAAAAAAAIAAAAAAAAAPAAAAAAAAAAAwAAAAAAAAAGAAAAAAAAAAkAAAAAAAAADAAAAAAAAAAP
AAAAAAAAABIAAAAAAAAAFQAAAAAAAAAYAAAAAAAAABsAAAAAAAAAHgAAAAAAAAAhAAAAAAAAACQA
AAAAAAAAJwAAAAAAAAAqAAAAAAAAAC0AAAAAAAAAMAAAAAAAAAAzAAAAAAAAADYAAAAAAAAAOgAA
AAAAAAA+AAAAAAAAAEIAAAAAAAAARgAAAAAAAABKAAAAAAAAAE4AAAAAAAAAUgAAAAAAAABWAAAA
AAAAAFoAAAAAAAAAXgAAAAAAAABiAAAAAAAAAGYAAAAAAAAAHgAAAAAAAAAFBQUFBQUFBQUFBQUF
BQUFBQUKCgoKCgoKCgoKCgp4AAAAAAAAAAEAAAABAAAAAgAAAAIAAAADAAAAAwAAAAQAAAAEAAAA
BQAAAAUAAAAGAAAABgAAAAcAAAAHAAAABwAAAAcAAAAHAAAABwAAAAEAAAABAAAAAgAAAAIAAAAC
AAAAAQAAAAIAAAABAAAAAgAAAAEAAAACAAAAAQAAAAo8L0FwcGVuZGVkRGF0YT4KPC9WVEtGaWxl
Pgo=
EOF

formats="cube.mesh cube41.msh cube22.msh cube.node cube.ele cube_ascii.vtu cube_base64.vtu cube_raw.vtu cube.vtk"
for f in $formats; do
  if "$Q" "$T/$f" --json "$T/$f.json" > "$T/$f.txt" 2> "$T/$f.err"; then
    ok "read $f"
  else
    fail "reading $f: $(cat "$T/$f.err")"
  fi
done
ref="$T/cube.mesh.json"
if [ -s "$ref" ]; then
  # hand values (see above)
  grep -q '"tetrahedra": 12,' "$ref" && grep -q '"vertices": 9,' "$ref" && grep -q '"volume": 1,' "$ref" ||
    fail "cube.mesh: expected 12 tets, 9 vertices, volume 1"
  [ "$(grep -c '"tetrahedra": 6,' "$ref")" = 2 ] || fail "cube.mesh: expected two regions of 6 tets"
  [ "$(grep -c '"volume": 0.5,' "$ref")" = 2 ] || fail "cube.mesh: expected two regions of volume 0.5"
  grep -q '"boundary_triangles": 18,' "$ref" || fail "cube.mesh: expected 18 boundary triangles"
  echo "cube.mesh: $(grep -m1 '"dihedral_angle": {' "$ref" | sed 's/^ *//')"
  for f in $formats; do
    [ -s "$T/$f.json" ] || continue
    if cmp -s <(numbers "$ref") <(numbers "$T/$f.json"); then
      ok "$f gives the same numbers as cube.mesh"
    else
      fail "$f differs from cube.mesh:"
      diff <(numbers "$ref") <(numbers "$T/$f.json") | head -10
    fi
  done
fi

# ---------------------------------------------------------------------------
# What the peers write: Gmsh (.msh 4.1, 2.2, .vtk, .mesh: one mesh saved in each; Medit
# refs are physical tags only with SaveElementTagType 2) and TetGen (.node/.ele/.face, .vtk)
if command -v gmsh > /dev/null 2>&1; then
  cat > "$T/two.geo" <<'EOF'
SetFactory("OpenCASCADE");
Box(1) = {0,0,0, 1,1,0.5};
Box(2) = {0,0,0.5, 1,1,0.5};
Coherence;
Physical Volume("lower", 11) = {1};
Physical Volume("upper", 12) = {2};
Physical Surface("middle", 21) = {6};
Mesh.CharacteristicLengthMax = 0.4;
EOF
  (
    cd "$T" &&
      gmsh -3 two.geo -o g41.msh -format msh41 &&
      gmsh g41.msh -0 -o g22.msh -format msh22 &&
      gmsh g41.msh -0 -o g.vtk &&
      gmsh g41.msh -0 -o g.mesh -setnumber Mesh.SaveElementTagType 2
  ) > "$T/gmsh.log" 2>&1 || fail "gmsh failed: $(tail -3 "$T/gmsh.log")"
  for f in g41.msh g22.msh g.vtk g.mesh; do
    "$Q" "$T/$f" --json "$T/$f.json" > /dev/null 2> "$T/$f.err" || fail "reading Gmsh's $f: $(cat "$T/$f.err")"
  done
  if [ -s "$T/g41.msh.json" ]; then
    grep -q '"name": "lower"' "$T/g41.msh.json" || fail "g41.msh: the physical name 'lower' is missing"
    echo "gmsh g41.msh: $(grep -m1 '"tetrahedra"' "$T/g41.msh.json" | sed 's/^ *//') $(grep -m1 '"volume"' "$T/g41.msh.json" | sed 's/^ *//')"
    for f in g22.msh g.vtk g.mesh; do
      [ -s "$T/$f.json" ] || continue
      if cmp -s <(numbers "$T/g41.msh.json") <(numbers "$T/$f.json"); then
        ok "Gmsh's $f gives the same numbers as its .msh 4.1"
      else
        fail "Gmsh's $f differs from its .msh 4.1:"
        diff <(numbers "$T/g41.msh.json") <(numbers "$T/$f.json") | head -10
      fi
    done
  fi
else
  echo "SKIP: gmsh not installed"
fi

if command -v tetgen > /dev/null 2>&1; then
  cat > "$T/box.poly" <<'EOF'
# a unit box, region attribute 7
8 3 0 0
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 0 0 1
6 1 0 1
7 1 1 1
8 0 1 1
6 1
1 0 1
4 1 2 3 4
1 0 2
4 5 6 7 8
1 0 3
4 1 2 6 5
1 0 4
4 2 3 7 6
1 0 5
4 3 4 8 7
1 0 6
4 4 1 5 8
0
1
1 0.5 0.5 0.5 7 -1
EOF
  (cd "$T" && tetgen -pqAka0.01 box.poly) > "$T/tetgen.log" 2>&1 || fail "tetgen failed: $(tail -3 "$T/tetgen.log")"
  for f in box.1.ele box.1.vtk; do
    "$Q" "$T/$f" --json "$T/$f.json" > /dev/null 2> "$T/$f.err" || fail "reading TetGen's $f: $(cat "$T/$f.err")"
  done
  if [ -s "$T/box.1.ele.json" ] && [ -s "$T/box.1.vtk.json" ]; then
    grep -q '"region": 7,' "$T/box.1.ele.json" || fail "box.1.ele: region attribute 7 missing"
    grep -q '"volume": 1,' "$T/box.1.ele.json" || fail "box.1.ele: volume of the unit box is not 1"
    echo "tetgen box.1.ele: $(grep -m1 '"tetrahedra"' "$T/box.1.ele.json" | sed 's/^ *//')"
    if cmp -s <(volume_numbers "$T/box.1.ele.json") <(volume_numbers "$T/box.1.vtk.json"); then
      ok "TetGen's .vtk gives the same numbers as its .node/.ele"
    else
      fail "TetGen's .vtk differs from its .node/.ele:"
      diff <(volume_numbers "$T/box.1.ele.json") <(volume_numbers "$T/box.1.vtk.json") | head -10
    fi
  fi
else
  echo "SKIP: tetgen not installed"
fi

# ---------------------------------------------------------------------------
# Several meshes: the side-by-side table, JSON and SVG
if "$Q" "$T/cube.mesh" "$T/cube_raw.vtu" --names medit,vtu --json "$T/two.json" --svg "$T/two.svg" > "$T/two.txt" 2>&1; then
  grep -q 'Mesh quality comparison' "$T/two.txt" && grep -q 'medit' "$T/two.txt" && grep -q 'vtu' "$T/two.txt" ||
    fail "two meshes: no side-by-side table"
  [ "$(grep -c '"aspect_ratio_definition"' "$T/two.json")" = 2 ] && grep -q '"meshes"' "$T/two.json" ||
    fail "two meshes: JSON should hold two reports"
  grep -q '</svg>' "$T/two.svg" && grep -q 'medit (12 tets)' "$T/two.svg" || fail "two meshes: SVG incomplete"
  if command -v xmllint > /dev/null 2>&1; then
    xmllint --noout "$T/two.svg" || fail "the SVG is not well-formed XML"
  fi
  ok "two meshes side by side"
else
  fail "two meshes: $(cat "$T/two.txt")"
fi
"$Q" "$T/cube.mesh" --svg "$T/one.svg" > /dev/null 2>&1 && grep -q 'region 2 (6 tets)' "$T/one.svg" ||
  fail "one mesh: the SVG has no curve per region"
if command -v jq > /dev/null 2>&1; then
  jq -e '.meshes | length == 2' "$T/two.json" > /dev/null || fail "two.json is not valid JSON with two meshes"
  jq -e '.regions | length == 2' "$ref" > /dev/null || fail "cube.mesh.json is not valid JSON with two regions"
fi

# ---------------------------------------------------------------------------
# Errors: located, non-zero exit
expect_error() { # expect_error NAME STATUS PATTERN ARGS...: exit status and a message matching PATTERN
  local name=$1 status=$2 pattern=$3
  shift 3
  "$Q" "$@" > "$T/err.out" 2> "$T/err.txt"
  local s=$?
  if [ "$s" != "$status" ]; then
    fail "$name: exit status $s, expected $status ($(cat "$T/err.txt"))"
  elif ! grep -q -e "$pattern" "$T/err.txt"; then
    fail "$name: message '$(cat "$T/err.txt")' does not match '$pattern'"
  else
    ok "$name: $(head -1 "$T/err.txt")"
  fi
}
sed '9s/.*/0 0 1x 0/' "$T/cube.mesh" > "$T/bad.mesh"
expect_error "bad number in .mesh" 1 "bad.mesh:9: .*'1x' is not a number" "$T/bad.mesh"
sed 's/^Tetrahedra$/Hexahedra/' "$T/cube.mesh" > "$T/hex.mesh"
expect_error "hexahedra in .mesh" 1 "hex.mesh:[0-9]*: Hexahedra: only tetrahedral" "$T/hex.mesh"
head -n 24 "$T/cube41.msh" > "$T/trunc.msh"
expect_error "truncated .msh" 1 "trunc.msh:2[45]: unexpected end of file" "$T/trunc.msh"
cp "$T/cube.node" "$T/badidx.node"
sed '3s/.*/1 0 6 42 8 1/' "$T/cube.ele" > "$T/badidx.ele"
expect_error "index out of range in .ele" 1 "badidx.ele:3: tetrahedron refers to vertex 42" "$T/badidx.ele"
sed 's/^0 2 6 /0 two 6 /' "$T/cube_ascii.vtu" > "$T/bad.vtu"
expect_error "bad number in .vtu" 1 "bad.vtu:[0-9]*: .*'two' is not an integer" "$T/bad.vtu"
head -c 1500 "$T/cube_raw.vtu" > "$T/trunc_raw.vtu"
expect_error "truncated raw .vtu" 1 "trunc_raw.vtu" "$T/trunc_raw.vtu"
expect_error "missing file" 1 "cannot open '$T/missing.mesh'" "$T/missing.mesh"
cp "$T/cube.node" "$T/only.node"
expect_error "missing .ele beside .node" 1 "cannot open '$T/only.ele'" "$T/only.node"
expect_error "unknown format" 1 "unknown mesh format" "$T/cube.obj"
expect_error "no argument" 2 "no mesh file"
expect_error "unknown option" 2 "unknown option '--frobnicate'" "$T/cube.mesh" --frobnicate
expect_error "names count" 2 "names for 1 meshes" "$T/cube.mesh" --names a,b
"$Q" --help | grep -q '^Usage: bubble_mesh_3_quality' || fail "--help"

# Sections of the cube: the default plane is y = 1/2 (x and y extents equal), which cuts the
# 10 tets that have a vertex on y = 1 (c has y = 0.45: the two on the face y = 0 stay below);
# 5 of them in each region. Two meshes: two pictures one above the other.
count() { grep -o "$2" "$1" | wc -l; }
if "$Q" "$T/cube.mesh" --section-svg "$T/sec.svg" > /dev/null 2> "$T/err.txt"; then
  cells=$(count "$T/sec.svg" 'class="cell"')
  regions=$(grep -o 'class="cell" fill="[^"]*"' "$T/sec.svg" | sort -u | wc -l)
  if [ "$cells" -eq 10 ] && [ "$regions" -eq 2 ] && grep -q 'section y = 0.5 (x to the right, z up)' "$T/sec.svg"; then
    ok "section of the cube: $cells cut cells in $regions regions"
  else
    fail "section of the cube: $cells cut cells in $regions regions (10 in 2 expected)"
  fi
else
  fail "section of the cube: $(cat "$T/err.txt")"
fi
# z = 1/4 cuts the 2 tets on the face z = 0 and the 8 on the side faces, in each mesh
if "$Q" "$T/cube.mesh" "$T/cube.node" --names a,b --section-svg "$T/two.svg" --section z=0.25 > /dev/null 2> "$T/err.txt" &&
   [ "$(count "$T/two.svg" '<svg ')" -eq 3 ] && [ "$(count "$T/two.svg" 'class="cell"')" -eq 20 ] &&
   grep -q '>b: section z = 0.25 (seen from above' "$T/two.svg"; then
  ok "two sections one above the other, 10 cut cells each"
else
  fail "two sections: $(cat "$T/err.txt") $(count "$T/two.svg" '<svg ') svg elements, $(count "$T/two.svg" 'class="cell"') cells"
fi
expect_error "section plane outside the mesh" 2 "misses the model: its x runs from 0 to 1" \
  "$T/cube.mesh" --section-svg "$T/miss.svg" --section x=5
[ -e "$T/miss.svg" ] && fail "a section plane outside the mesh wrote its file"
expect_error "bad section plane" 2 "x=V, y=V or z=V" "$T/cube.mesh" --section-svg "$T/b.svg" --section q=1
expect_error "section plane without a file" 2 "give both" "$T/cube.mesh" --section y=0.5

if [ "$failures" -ne 0 ]; then
  echo "test_quality_cli: $failures failure(s)"
  exit 1
fi
echo "test_quality_cli: all checks passed"
