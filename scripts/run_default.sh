#!/usr/bin/env bash
# README command 1: install what is missing, build the programs, and mesh the bundled default model.
# Usage: scripts/run_default.sh [bubble_mesh_3 options]
# Without options it writes out/layered_model.{mesh,vtu,msh,inp} and the quality report
# (out/layered_model_quality.json and .svg) and a vertical section (out/layered_model_section.svg); with options it passes them on instead.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install_deps.sh"
# the programs only: tests and examples are the second command's business
bash "$root/scripts/build.sh" -DBUBBLE_MESH_3_BUILD_TESTS=OFF -DBUBBLE_MESH_3_BUILD_EXAMPLES=OFF
model="$root/examples/Bubble_mesh_3/data/layered_model.obj"
if [ "$#" -eq 0 ]; then
  out="$root/out"
  mkdir -p "$out"
  set -- -o "$out/layered_model.mesh" -o "$out/layered_model.vtu" -o "$out/layered_model.msh" \
         -o "$out/layered_model.inp" --quality-json "$out/layered_model_quality.json" \
         --quality-svg "$out/layered_model_quality.svg" --section-svg "$out/layered_model_section.svg"
fi
exec "$root/build/tools/bubble_mesh_3" "$model" "$@"
