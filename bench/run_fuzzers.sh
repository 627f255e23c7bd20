#!/usr/bin/env bash
# Fuzz the geological model readers with libFuzzer + AddressSanitizer + UBSan.
#   bench/run_fuzzers.sh [SECONDS_PER_READER]   (default 60)
# Builds bench/fuzz/fuzz_read_{ml,ts,obj}.cpp with clang++ against include/,
# seeds a corpus per reader from the hand-written test files and, when
# ../shared/data/geomodels exists, from the real models (their first 64 KiB,
# the largest input fuzzed), runs each fuzzer for SECONDS_PER_READER and prints
# executions and findings. Work files go to ${FUZZ_DIR:-/tmp/bubble_mesh_3_fuzz}.
# Exit status: 0 if no finding, 1 otherwise. Not part of the test command.
set -euo pipefail
seconds="${1:-60}"
here="$(cd "$(dirname "$0")/.." && pwd)"
work="${FUZZ_DIR:-/tmp/bubble_mesh_3_fuzz}"
shared="${BUBBLE_MESH_3_SHARED_DATA_DIR:-$here/../shared/data/geomodels}"
max_len=65536
mkdir -p "$work"
command -v clang++ >/dev/null || { echo "run_fuzzers.sh: clang++ is needed (Debian: apt-get install clang)"; exit 2; }

findings=0
for fmt in ml ts obj; do
  exe="$work/fuzz_read_$fmt"
  echo "== building $exe"
  clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$here/include" "$here/bench/fuzz/fuzz_read_$fmt.cpp" -o "$exe" -lgmp -lmpfr

  corpus="$work/corpus_$fmt"
  artifacts="$work/findings_$fmt/"
  mkdir -p "$corpus" "$artifacts"
  for f in "$here"/test/Bubble_mesh_3/data/io/*; do
    cp "$f" "$corpus/seed_$(basename "$f")"
  done
  if [ -d "$shared" ]; then
    for f in "$shared"/*.ml; do
      head -c "$max_len" "$f" > "$corpus/seed_head_$(basename "$f")"
    done
  else
    echo "   (no real models in $shared: seeding with the test files only)"
  fi
  if [ "$fmt" = obj ]; then
    # OBJ seeds: a few small bodies written by hand
    printf 'o A\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\no F\n#@inside A\n#@patch fault\nv .1 .1 .1\nv .2 .1 .1\nv .1 .2 .1\nf -3 -2 -1\n' > "$corpus/seed_tet.obj"
    printf 'g A\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\ng B\nv 0 0 -1\nf 1 2 3 4\nf 6 2 1\nf 6 3 2\nf 6 4 3\nf 6 1 4\n' > "$corpus/seed_pyramids.obj"
  fi

  dict="$here/bench/fuzz/gocad.dict"
  [ "$fmt" = obj ] && dict="$here/bench/fuzz/obj.dict"
  log="$work/fuzz_read_$fmt.log"
  echo "== fuzzing $fmt for $seconds s (log: $log)"
  set +e
  "$exe" "$corpus" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -dict="$dict" -artifact_prefix="$artifacts" > "$log" 2>&1
  status=$?
  set -e
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  [ -z "$runs" ] && runs=$(grep -o '#[0-9]*' "$log" | tail -1 | tr -d '#')
  found=$(find "$artifacts" -type f | wc -l)
  echo "   $fmt: ${runs:-?} executions, corpus $(ls "$corpus" | wc -l) files, exit status $status, $found finding(s) in $artifacts"
  if [ "$found" -gt 0 ] || [ "$status" -ne 0 ]; then
    findings=$((findings + 1))
    grep -m5 -E 'ERROR|SUMMARY|runtime error|round trip|terminate' "$log" | sed 's/^/   /' || true
  fi
done
[ "$findings" -eq 0 ] && echo "no findings" || { echo "findings in $findings reader(s)"; exit 1; }
