#!/usr/bin/env bash
# The manual builds with Doxygen without a single warning (scripts/build_docs.sh fails on any).
# Usage: bash test_docs.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../build}"
bash "$here/../../scripts/build_docs.sh" "$build/doc"
# every example the manual lists exists, and every example is listed
for f in "$here"/../../examples/Bubble_mesh_3/*.cpp; do
  name="$(basename "$f")"
  grep -q "Bubble_mesh_3/$name" "$here/../../doc/Bubble_mesh_3/examples.txt" \
    || { echo "test_docs: examples/Bubble_mesh_3/$name is not listed in doc/Bubble_mesh_3/examples.txt" >&2; exit 1; }
done
echo "test_docs: ok"
