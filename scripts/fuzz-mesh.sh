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
source "$(dirname "$0")/fuzz-lib.sh"
fuzz_help_or_seconds "$0" "$@"

seconds=${1:-600}
shift || true
formats=("$@")
if [ ${#formats[@]} -eq 0 ]; then formats=(obj ply stl off gz); fi

root=$fuzz_root
build=$fuzz_build_dir
out=$root/fuzz-out
targets=(mesh_fuzz_seeds)
for format in "${formats[@]}"; do targets+=("mesh_fuzz_$format"); done
fuzz_build "$out/logs" "${targets[@]}"

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
  mkdir -p "$corpus"
  cp -n "$out/seeds/$format"/* "$corpus"/ 2>/dev/null || true
  fuzz_run "mesh_fuzz_$format" "$corpus" "$artifacts" "$log" "$seconds" -max_len="$(max_len_of "$format")"
  printf '%-6s %8s %12s %8s  %s\n' "$format" "$seconds" "${fuzz_executions:-?}" "$fuzz_found" \
    "$([ "$fuzz_found" -gt 0 ] && echo "$artifacts (log: $log)")"
  if [ "$fuzz_found" -gt 0 ]; then failed=1; fi
done
exit $failed
