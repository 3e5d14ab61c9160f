#!/usr/bin/env bash
# Fuzzes the render command's switches and INI files with libFuzzer under AddressSanitizer
# and UndefinedBehaviorSanitizer (fuzz/options_fuzz.cpp).
#
#   scripts/fuzz-options.sh [SECONDS]        (default 600; JOBS=N build jobs, default 2)
#
# Builds with clang into build-fuzz/, seeds the corpus with our INI files (scenes/**/*.ini)
# and a few command lines, and keeps corpus, logs and crash artifacts under
# fuzz-out/options (git-ignored). Exits non-zero if the run found a crash, leak, timeout or
# out-of-memory.
set -euo pipefail

case ${1:-} in -h | --help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
seconds=${1:-600}
[[ $seconds =~ ^[0-9]+$ ]] || { echo "usage: $0 [SECONDS]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
out=$root/fuzz-out/options
jobs=${JOBS:-2}

mkdir -p "$out/logs" "$out/corpus" "$out/artifacts"
CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCONVRAY_BUILD_FUZZ=ON -DCONVRAY_BUILD_TESTS=OFF -DCONVRAY_BUILD_BENCH=OFF >"$out/logs/configure.log" 2>&1 ||
  { cat "$out/logs/configure.log"; exit 2; }
cmake --build "$build" -j "$jobs" --target options_fuzz >"$out/logs/build.log" 2>&1 ||
  { tail -50 "$out/logs/build.log"; exit 2; }

# Seeds: switches (one per line), then a NUL and an INI file the switches name as @INI.
n=0
while IFS= read -r -d '' f; do
  n=$((n + 1))
  { printf 'scene.pov\n@INI\n+W64\n+H48\0'; cat "$f"; } >"$out/corpus/seed_ini_$n"
done < <(find "$root/scenes" -name '*.ini' -size -16k -print0)
printf 'scene.pov\n+W800\n+H600\n+A0.3\n-D\n+KFI1\n+KFF30\n+KC\n--video\nout.mp4' >"$out/corpus/seed_switches"
printf '+Iscene.pov\n+Oout.png\n+SF0.25\n+EF0.75\n--frame-step\n3\n--declare\nX=1.5' >"$out/corpus/seed_pov"
printf '@INI[Fast]\0[Fast]\nWidth=64\nHeight=48\nFinal_Frame=10\nInput_File_Name=s.pov\n' >"$out/corpus/seed_section"

before=$(find "$out/artifacts" -type f | wc -l)
status=0
"$build/fuzz/options_fuzz" "$out/corpus" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$out/artifacts/" >"$out/logs/run.log" 2>&1 ||
  status=$?
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/logs/run.log" | tail -1)
found=$(($(find "$out/artifacts" -type f | wc -l) - before))
if [ "$status" -ne 0 ] && [ "$found" -eq 0 ]; then found=1; fi
echo "options: $seconds s, ${executions:-?} executions, $found problems" \
  "$([ "$found" -gt 0 ] && echo "(artifacts: $out/artifacts, log: $out/logs/run.log)")"
[ "$found" -eq 0 ]
