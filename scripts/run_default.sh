#!/usr/bin/env bash
# README command 1: install what is missing, build, and mesh the bundled default model.
# Usage: scripts/run_default.sh [extra bubble_mesh_3 options]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install_deps.sh"
bash "$root/scripts/build.sh" -DBUBBLE_MESH_3_BUILD_TESTS=OFF
mkdir -p "$root/out"
exec "$root/build/tools/bubble_mesh_3" "$root/examples/Bubble_mesh_3/data/layered_model.obj" "$@"
