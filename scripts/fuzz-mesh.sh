#!/usr/bin/env bash
# Fuzzes the mesh readers with libFuzzer (fuzz/mesh_fuzz.cpp), one format after the other.
#
#   scripts/fuzz-mesh.sh [SECONDS_PER_FORMAT] [FORMATS...]
#
# SECONDS_PER_FORMAT defaults to 600; FORMATS to "obj ply stl off gz" (also: any).
# Builds with clang into build-fuzz/, seeds each corpus from our own writers, and keeps
# corpora, logs and crash artifacts under fuzz-out/ (git-ignored), so later runs continue
# where earlier ones stopped. Prints one summary line per format and exits non-zero if any
# run found a crash, leak, timeout or out-of-memory.
set -euo pipefail

seconds=${1:-600}
shift || true
formats=("$@")
if [ ${#formats[@]} -eq 0 ]; then formats=(obj ply stl off gz); fi

root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
out=$root/fuzz-out
jobs=${JOBS:-2}

# Configure and build (only the fuzz targets and what they need).
mkdir -p "$out/logs"
CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCONVRAY_BUILD_FUZZ=ON -DCONVRAY_BUILD_TESTS=OFF -DCONVRAY_BUILD_BENCH=OFF >"$out/logs/configure.log" 2>&1 ||
  { cat "$out/logs/configure.log"; exit 2; }
targets=(mesh_fuzz_seeds)
for format in "${formats[@]}"; do targets+=("mesh_fuzz_$format"); done
cmake --build "$build" -j "$jobs" --target "${targets[@]}" >"$out/logs/build.log" 2>&1 ||
  { tail -50 "$out/logs/build.log"; exit 2; }

# Seed corpus: fresh every time, merged into the corpus the runs keep: our writers' files, and
# the variants of tests/data/meshes/ (one small file per way users' files are written).
rm -rf "$out/seeds"
"$build/fuzz/mesh_fuzz_seeds" "$out/seeds"
for format in obj ply stl off; do
  mkdir -p "$out/seeds/$format"
  cp "$root"/tests/data/meshes/*."$format" "$out/seeds/$format"/ 2>/dev/null || true
done

# The largest seed is a few KiB; room for growth, small enough to stay fast.
max_len_of() {
  case $1 in
    gz) echo 8192 ;;
    *) echo 16384 ;;
  esac
}

failed=0
printf '%-6s %8s %12s %8s  %s\n' format seconds executions crashes artifacts
for format in "${formats[@]}"; do
  corpus=$out/corpus/$format
  artifacts=$out/artifacts/$format
  log=$out/logs/$format.log
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  cp -n "$out/seeds/$format"/* "$corpus"/ 2>/dev/null || true
  before=$(find "$artifacts" -type f | wc -l)

  status=0
  "$build/fuzz/mesh_fuzz_$format" "$corpus" -max_total_time="$seconds" -max_len="$(max_len_of "$format")" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1 || status=$?

  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  found=$(($(find "$artifacts" -type f | wc -l) - before))
  if [ "$status" -ne 0 ] && [ "$found" -eq 0 ]; then found=1; fi  # died without an artifact
  printf '%-6s %8s %12s %8s  %s\n' "$format" "$seconds" "${executions:-?}" "$found" \
    "$([ "$found" -gt 0 ] && echo "$artifacts (log: $log)")"
  if [ "$found" -gt 0 ]; then failed=1; fi
done
exit $failed
