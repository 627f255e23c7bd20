#!/usr/bin/env bash
# Installs the Debian 12 packages Bubble_mesh_3 needs to build, test and benchmark.
# Idempotent: packages already present are skipped, so a second run costs nothing.
# Usage: scripts/install_deps.sh [--tests] [--bench]
set -euo pipefail

build_pkgs=(cmake g++ make ccache libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev
            libopenmesh-dev libtbb-dev)
test_pkgs=(python3 gmsh python3-gmsh python3-vtk9 calculix-ccx doxygen tetgen)
bench_pkgs=(tetgen gmsh clang libclang-rt-14-dev python3-numpy)

want=("${build_pkgs[@]}")
for arg in "$@"; do
  case "$arg" in
    --tests) want+=("${test_pkgs[@]}") ;;
    --bench) want+=("${bench_pkgs[@]}") ;;
    *) echo "install_deps.sh: unknown option '$arg' (use --tests, --bench)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi
echo "install_deps.sh: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
