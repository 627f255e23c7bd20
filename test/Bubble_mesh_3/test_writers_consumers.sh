#!/bin/bash
# Copyright (c) 2026 Bubble_mesh_3 contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Real consumers read the mesh writers' files: Gmsh's python API opens the
# .msh (physical groups, names, element counts, Jacobians) and the .mesh, VTK
# reads the .vtu (region/patch arrays, names), TetGen rebuilds and checks the
# mesh from .node/.ele/.face, and CalculiX solves the .inp under gravity.
# Usage: test_writers_consumers.sh BUILD_DIR
# It runs test_writers itself into its own folder (CTest may run both at
# once). A check whose program is missing is skipped with a message.

set -u
build=${1:?usage: test_writers_consumers.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
exe="$build/test/Bubble_mesh_3/test_writers"
out="$build/test_writers_consumers_out"

if [ ! -x "$exe" ]; then
  echo "FAIL: $exe is not built (cmake --build $build --target test_writers)"
  exit 1
fi
rm -rf "$out"
mkdir -p "$out"
if ! "$exe" "$out" > "$out/test_writers.log" 2>&1; then
  cat "$out/test_writers.log"
  echo "FAIL: $exe $out"
  exit 1
fi
echo "test_writers wrote the box mesh in every format to $out"

# Debian's python modules live with the system python, not with a pyenv one
python=/usr/bin/python3
[ -x "$python" ] || python=$(command -v python3 || true)
if [ -z "$python" ]; then
  echo "SKIP: no python3, so no consumer check"
  exit 0
fi

passed=0 failed=0 skipped=0
for check in gmsh vtk tetgen ccx; do
  echo "--- $check"
  "$python" "$here/check_consumers.py" "$check" "$out"
  case $? in
    0) passed=$((passed + 1)) ;;
    77) skipped=$((skipped + 1)) ;;
    *) failed=$((failed + 1)); echo "FAIL: $check" ;;
  esac
done
echo "consumer checks: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
