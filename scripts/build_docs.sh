#!/usr/bin/env bash
# Builds the HTML manual with Doxygen into build/doc and fails if Doxygen warns.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/doc}"
command -v doxygen >/dev/null || { echo "build_docs.sh: doxygen is not installed (scripts/install_deps.sh --tests)" >&2; exit 1; }
mkdir -p "$out"
sed -e "s|@ROOT@|$root|g" -e "s|@OUT@|$out|g" "$root/doc/Bubble_mesh_3/Doxyfile.in" > "$out/Doxyfile"
rm -f "$out/warnings.log"
(cd "$out" && doxygen Doxyfile)
if [ -s "$out/warnings.log" ]; then
  echo "build_docs.sh: doxygen warnings ($(wc -l < "$out/warnings.log") lines):" >&2
  cat "$out/warnings.log" >&2
  exit 1
fi
echo "manual: $out/html/index.html (no warnings)"
