# Shared by scripts/fuzz-*.sh (sourced, not run): the help switch, the clang build of the fuzz
# targets in build-fuzz/ (AddressSanitizer and UndefinedBehaviorSanitizer, fuzz/CMakeLists.txt),
# and one libFuzzer run with its summary.

fuzz_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fuzz_build_dir=$fuzz_root/build-fuzz

# -h or --help as the first argument: print the calling script's header comment and exit; a
# first argument that is not a whole number of seconds is an error, not a run.
fuzz_help_or_seconds() {
  local script=$1 first=${2:-}
  case $first in -h | --help) sed -n '2,/^set /p' "$script" | sed '$d; s/^# \{0,1\}//'; exit 0 ;; esac
  [[ -z $first || $first =~ ^[0-9]+$ ]] || { echo "usage: $script [SECONDS] ... (-h for help)" >&2; exit 2; }
}

# fuzz_build LOG_DIR TARGET...: configures build-fuzz/ with clang and builds the targets.
fuzz_build() {
  local logs=$1
  shift
  mkdir -p "$logs"
  CC=${CC:-clang} CXX=${CXX:-clang++} cmake -S "$fuzz_root" -B "$fuzz_build_dir" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCONVRAY_BUILD_FUZZ=ON -DCONVRAY_BUILD_TESTS=OFF \
    -DCONVRAY_BUILD_BENCH=OFF >"$logs/configure.log" 2>&1 || { cat "$logs/configure.log"; exit 2; }
  cmake --build "$fuzz_build_dir" -j "${JOBS:-2}" --target "$@" >"$logs/build.log" 2>&1 ||
    { tail -50 "$logs/build.log"; exit 2; }
}

# fuzz_run TARGET CORPUS ARTIFACTS LOG SECONDS [LIBFUZZER OPTIONS...]: one run of
# build-fuzz/fuzz/TARGET; sets fuzz_executions and fuzz_found (the artifacts it left, or 1 when it
# died without one).
fuzz_run() {
  local target=$1 corpus=$2 artifacts=$3 log=$4 seconds=$5
  shift 5
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  local before status=0
  before=$(find "$artifacts" -type f | wc -l)
  "$fuzz_build_dir/fuzz/$target" "$corpus" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" "$@" >"$log" 2>&1 ||
    status=$?
  fuzz_executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  fuzz_found=$(($(find "$artifacts" -type f | wc -l) - before))
  if [ "$status" -ne 0 ] && [ "$fuzz_found" -eq 0 ]; then fuzz_found=1; fi
}

# The one-line summary of fuzz_run: NAME: S s, N executions, K problems (and where to look).
fuzz_summary() {
  local name=$1 seconds=$2 artifacts=$3 log=$4
  echo "$name: $seconds s, ${fuzz_executions:-?} executions, $fuzz_found problems" \
    "$([ "$fuzz_found" -gt 0 ] && echo "(artifacts: $artifacts, log: $log)")"
}
