#!/usr/bin/env bash
# Fuzzes the scene parser with libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer
# (fuzz/scene_fuzz.cpp).
#
#   scripts/fuzz-scene.sh [SECONDS]        (default 600)
#
# Builds with clang into build-fuzz/, seeds the corpus with POV-Ray's sample scenes (Debian
# povray-examples), our scenes/ and the language tests' snippets, gives libFuzzer a dictionary
# of the language's keywords (fuzz/scene.dict), and keeps corpus, logs and crash artifacts
# under fuzz-out/scene (git-ignored) so later runs continue where earlier ones stopped.
# Exits non-zero if the run found a crash, leak, timeout or out-of-memory.
set -euo pipefail

seconds=${1:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
out=$root/fuzz-out/scene
jobs=${JOBS:-2}

mkdir -p "$out/logs" "$out/corpus" "$out/artifacts"
CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCONVRAY_BUILD_FUZZ=ON -DCONVRAY_BUILD_TESTS=OFF -DCONVRAY_BUILD_BENCH=OFF >"$out/logs/configure.log" 2>&1 ||
  { cat "$out/logs/configure.log"; exit 2; }
cmake --build "$build" -j "$jobs" --target scene_fuzz >"$out/logs/build.log" 2>&1 ||
  { tail -50 "$out/logs/build.log"; exit 2; }

# Seeds: real scenes, small enough to mutate quickly.
for f in /usr/share/povray-3.7/scenes/objects/*.pov /usr/share/povray-3.7/scenes/language/*/*.pov \
  "$root"/scenes/*.pov; do
  [ -f "$f" ] || continue
  [ "$(stat -c %s "$f")" -le 16384 ] || continue
  cp -n "$f" "$out/corpus/seed_$(basename "$(dirname "$f")")_$(basename "$f")" 2>/dev/null || true
done

before=$(find "$out/artifacts" -type f | wc -l)
status=0
"$build/fuzz/scene_fuzz" "$out/corpus" -dict="$root/fuzz/scene.dict" -max_total_time="$seconds" \
  -max_len=16384 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$out/artifacts/" >"$out/logs/run.log" 2>&1 || status=$?
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/logs/run.log" | tail -1)
found=$(($(find "$out/artifacts" -type f | wc -l) - before))
if [ "$status" -ne 0 ] && [ "$found" -eq 0 ]; then found=1; fi
echo "scene parser: $seconds s, ${executions:-?} executions, $found problems" \
  "$([ "$found" -gt 0 ] && echo "(artifacts: $out/artifacts, log: $out/logs/run.log)")"
[ "$found" -eq 0 ]
