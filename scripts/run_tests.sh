#!/usr/bin/env bash
# README command 2: install what is missing (with the test peers), build everything, run all tests.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install_deps.sh" --tests
bash "$root/scripts/build.sh" -DBUBBLE_MESH_3_BUILD_TESTS=ON -DBUBBLE_MESH_3_BUILD_EXAMPLES=ON
cd "$root/build"
ctest --output-on-failure -j "${BUBBLE_MESH_3_JOBS:-$(nproc)}" --timeout 900
