#!/usr/bin/env bash
# Configures and builds Bubble_mesh_3 in ./build (Release, -O2). Extra arguments go to cmake.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
jobs="${BUBBLE_MESH_3_JOBS:-$(nproc)}"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "$@" >"$root/build.configure.log" 2>&1 || {
  cat "$root/build.configure.log" >&2; echo "build.sh: cmake configure failed" >&2; exit 1; }
cmake --build "$root/build" -j "$jobs"
