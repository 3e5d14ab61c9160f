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
source "$(dirname "$0")/fuzz-lib.sh"
fuzz_help_or_seconds "$0" "$@"

seconds=${1:-600}
root=$fuzz_root
out=$root/fuzz-out/scene
fuzz_build "$out/logs" scene_fuzz
mkdir -p "$out/corpus"

# Seeds: real scenes, small enough to mutate quickly.
for f in /usr/share/povray-3.7/scenes/objects/*.pov /usr/share/povray-3.7/scenes/language/*/*.pov \
  "$root"/scenes/*.pov; do
  [ -f "$f" ] || continue
  [ "$(stat -c %s "$f")" -le 16384 ] || continue
  cp -n "$f" "$out/corpus/seed_$(basename "$(dirname "$f")")_$(basename "$f")" 2>/dev/null || true
done

fuzz_run scene_fuzz "$out/corpus" "$out/artifacts" "$out/logs/run.log" "$seconds" \
  -dict="$root/fuzz/scene.dict" -max_len=16384
fuzz_summary "scene parser" "$seconds" "$out/artifacts" "$out/logs/run.log"
[ "$fuzz_found" -eq 0 ]
