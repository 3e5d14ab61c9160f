# Sourced by the bench scripts that time whole processes themselves (speed_goals.sh,
# after_povray_pairs.sh); the sourcing script defines die().

# Wall seconds of one command (its words as given), its output thrown away.
seconds() {
  local start
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || die "failed: $*"
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f\n", b - a }'
}

# The median of the numbers on standard input, one a line.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
