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
source "$(dirname "$0")/fuzz-lib.sh"
fuzz_help_or_seconds "$0" "$@"

seconds=${1:-600}
root=$fuzz_root
out=$root/fuzz-out/options
fuzz_build "$out/logs" options_fuzz
mkdir -p "$out/corpus"

# Seeds: switches (one per line), then a NUL and an INI file the switches name as @INI.
n=0
while IFS= read -r -d '' f; do
  n=$((n + 1))
  { printf 'scene.pov\n@INI\n+W64\n+H48\0'; cat "$f"; } >"$out/corpus/seed_ini_$n"
done < <(find "$root/scenes" -name '*.ini' -size -16k -print0)
printf 'scene.pov\n+W800\n+H600\n+A0.3\n-D\n+KFI1\n+KFF30\n+KC\n--video\nout.mp4' >"$out/corpus/seed_switches"
printf '+Iscene.pov\n+Oout.png\n+SF0.25\n+EF0.75\n--frame-step\n3\n--declare\nX=1.5' >"$out/corpus/seed_pov"
printf 'scene.pov\n+W64\n+H48\n+SR0.25\n+ER30\n+SC2\n--end-column\n1\n@INI\0Start_Row=3\nEnd_Column=0.5\n' >"$out/corpus/seed_partial"
printf '@INI[Fast]\0[Fast]\nWidth=64\nHeight=48\nFinal_Frame=10\nInput_File_Name=s.pov\n' >"$out/corpus/seed_section"

fuzz_run options_fuzz "$out/corpus" "$out/artifacts" "$out/logs/run.log" "$seconds" -max_len=4096
fuzz_summary options "$seconds" "$out/artifacts" "$out/logs/run.log"
[ "$fuzz_found" -eq 0 ]
