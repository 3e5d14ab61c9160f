#!/usr/bin/env bash
# scripts/render-farm-slurm.sh against Slurm itself: a single-node cluster on this machine
# (munged, slurmctld and slurmd on 127.0.0.1, every file in a temporary folder), then
#   1. an animation submitted as a job array: its frames are byte-identical to one process's;
#   2. an array task cancelled (scancel) while it renders a frame: no partial frame is left
#      under a frame's name, and the same submission again renders only what is missing (+C),
#      giving the same frames;
#   3. a still split into bands of rows (+SR/+ER), stitched by a job that waits for them: the
#      same pixels as one process rendering the whole picture (anti-aliased across the bands).
#
#   bash tests/slurm/render_farm_slurm_test.sh CONVRAY_BINARY
#
# Exit 0: passed; 77 (CTest's SKIP_RETURN_CODE): Slurm cannot run here, and why is printed
# (a missing package, daemons that do not start); anything else: failed.
set -euo pipefail

readonly SKIP=77
started=$SECONDS
convray="$(realpath "${1:?usage: $0 CONVRAY_BINARY}")"
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
farm="$source_dir/scripts/render-farm-slurm.sh"

say() { echo "[$(( SECONDS - started ))s] $*"; }
skip() { echo "SKIPPED: $*"; exit $SKIP; }
fail() { echo "FAILED: $*"; show_logs; exit 1; }

for tool in munged mungekey slurmctld slurmd sbatch squeue scancel scontrol sinfo oiiotool; do
  command -v "$tool" > /dev/null ||
    skip "$tool is not installed (Debian packages slurm-wlm, munge, openimageio-tools)"
done
[ -x "$convray" ] || fail "$convray is not an executable"

# Everything lives here; munged wants its socket's folder searchable by all.
tmp="$(mktemp -d /tmp/convray-slurm.XXXXXX)"
chmod 755 "$tmp"
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/logs" "$tmp/out"
export SLURM_CONF="$tmp/slurm.conf"
daemons=()  # the PIDs of what this test started, stopped in reverse order
slurm_up=""  # set once the node is idle: from then on there may be jobs to cancel

cleanup() {
  local status=$?
  if [ ${#daemons[@]} -gt 0 ]; then
    # Cancel this cluster's jobs (SLURM_CONF names it) and let slurmd end their steps first.
    if [ -n "$slurm_up" ]; then
      scancel --quiet --user="$(id -un)" 2> /dev/null || true
      for _ in $(seq 40); do [ -z "$(squeue -h 2> /dev/null)" ] && break; sleep 0.5; done
    fi
    for (( i = ${#daemons[@]} - 1; i >= 0; --i )); do
      kill "${daemons[$i]}" 2> /dev/null || true
      wait "${daemons[$i]}" 2> /dev/null || true
    done
    kill_orphaned_steps
  fi
  [ "${KEEP_SLURM_TEST_FOLDER:-}" ] && echo "kept $tmp" || rm -rf -- "$tmp"
  exit $status
}

# A job step whose slurmd is gone (the test interrupted mid-job) waits for it forever, ignoring
# SIGTERM: this cluster's steps are the slurmstepd processes whose environment names its
# slurm.conf, and they are killed by their process ids.
kill_orphaned_steps() {
  local environ pid
  for environ in /proc/[0-9]*/environ; do
    pid="${environ#/proc/}" pid="${pid%/environ}"
    [ "$(cat "/proc/$pid/comm" 2> /dev/null)" = slurmstepd ] || continue
    { tr '\0' '\n' < "$environ"; } 2> /dev/null | grep -qxF "SLURM_CONF=$SLURM_CONF" &&
      kill -KILL "$pid" 2> /dev/null || true
  done
}
trap cleanup EXIT
trap 'exit 143' TERM INT HUP  # a signal (CTest's timeout) also stops the daemons

show_logs() {
  local f
  for f in "$tmp"/logs/*.log; do [ -f "$f" ] && { echo "--- $f"; tail -n 20 "$f"; }; done
  for f in "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/munged.log; do
    [ -f "$f" ] && { echo "--- $f"; tail -n 15 "$f"; }
  done
  return 0
}

# A TCP port nothing listens on (a refused connection), for slurmctld and slurmd.
free_port() {
  local port
  for _ in $(seq 50); do
    port=$(( 20000 + RANDOM % 30000 ))
    (exec 3<> "/dev/tcp/127.0.0.1/$port") 2> /dev/null || { echo "$port"; return; }
  done
}

start_munge() {
  mungekey --create --keyfile="$tmp/munge.key" > /dev/null 2>&1 ||
    skip "mungekey could not create a key"
  chmod 400 "$tmp/munge.key"
  munged --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
    --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" \
    > "$tmp/munged.out" 2>&1 &
  daemons+=($!)
  for _ in $(seq 50); do [ -S "$tmp/munge.socket" ] && return; sleep 0.1; done
  skip "munged did not start: $(tail -n 3 "$tmp/munged.out" "$tmp/munged.log" 2> /dev/null)"
}

# The smallest configuration that runs batch jobs without systemd, cgroups or accounting.
write_slurm_conf() {
  local user ctld_port slurmd_port
  user="$(id -un)" ctld_port="$(free_port)" slurmd_port="$(free_port)"
  [ -n "$ctld_port" ] && [ -n "$slurmd_port" ] && [ "$ctld_port" != "$slurmd_port" ] ||
    skip "found no two free TCP ports on 127.0.0.1"
  cat > "$SLURM_CONF" << CONF
ClusterName=convraytest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=600
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
}

start_slurm() {
  node="$(hostname -s)"
  write_slurm_conf
  slurmctld -D -i -f "$SLURM_CONF" > "$tmp/slurmctld.out" 2>&1 &
  daemons+=($!)
  slurmd -D -f "$SLURM_CONF" -N "$node" > "$tmp/slurmd.out" 2>&1 &
  daemons+=($!)
  local pid state
  for _ in $(seq 120); do
    [ "$(sinfo -h -N -o %t 2> /dev/null | tr -d ' ')" = idle ] && { slurm_up=1; return; }
    for pid in "${daemons[@]}"; do kill -0 "$pid" 2> /dev/null || break 2; done  # one died
    sleep 0.5
  done
  state="$(sinfo -h -N -o %t 2>&1 | head -n 1)" || true
  skip "Slurm did not start (node state '$state'):" \
    "$(tail -n 3 "$tmp/slurmctld.out" "$tmp/slurmctld.log" "$tmp/slurmd.out" "$tmp/slurmd.log" 2> /dev/null)"
}

# Waits (at most $2 seconds) until job $1 (all its array tasks) has left the queue.
wait_for_job() {
  local job="$1" limit="$2" start=$SECONDS
  while [ -n "$(squeue -h -j "$job" -o %i 2> /dev/null)" ]; do
    (( SECONDS - start < limit )) || fail "job $job still queued after $limit s: $(squeue -j "$job")"
    sleep 0.5
  done
}

# The states of job $1's tasks, one word each (COMPLETED, CANCELLED, FAILED, ...), in order.
job_states() {
  scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort | uniq -c | xargs
}

expect_completed() {
  local states
  states="$(job_states "$1")"
  [[ "$states" =~ ^[0-9]+\ COMPLETED$ ]] || fail "job $1 did not complete: $states"
}

# The job id from render-farm-slurm.sh's output ("Submitted batch job N" or a bare number).
job_id() { grep -Eo '(^|job )[0-9]+$' | grep -Eo '[0-9]+' | tail -n 1; }

# Every file of folder $1 byte-identical to the same name in $2, and no other file (no
# temporary, no partial frame) in either.
expect_same_files() {
  local a="$1" b="$2"
  [ "$(ls -A "$a")" = "$(ls -A "$b")" ] ||
    fail "$a holds [$(ls -A "$a" | xargs)], $b holds [$(ls -A "$b" | xargs)]"
  local f
  for f in "$b"/*; do cmp "$a/${f##*/}" "$f" || fail "${f##*/} differs from one process's"; done
}

# --- the cluster --------------------------------------------------------------------------
start_munge
start_slurm
say "Slurm runs: node $node idle (slurmctld, slurmd, munged in $tmp)"
cd "$source_dir"  # the animation's INI names its scene and library from the checkout's root
export CONVRAY="$convray"

# --- 1. an animation as a job array ---------------------------------------------------------
# Frames of a second or more, so that a task can be cancelled in the middle of one (part 2).
animation=scenes/animations/metaballs.ini
settings="+W1280 +H960 +A0.3 +KFF4"
"$convray" "$animation" $settings "+O$tmp/single/" --quiet +WT2 ||
  fail "one process could not render the animation"
say "one process rendered $(ls "$tmp/single" | xargs)"
out=$(CONVRAY_ARGS="$settings +O$tmp/out/array/" bash "$farm" submit "$animation" 2 -- \
  --cpus-per-task=1 --output="$tmp/logs/array-%A_%a.log" 2>&1) || fail "submit: $out"
job=$(job_id <<< "$out")
wait_for_job "$job" 120
expect_completed "$job"
expect_same_files "$tmp/out/array" "$tmp/single"
say "1. job array $job: 2 tasks, 4 frames byte-identical to one process's"

# --- 2. a task cancelled mid-frame, then resubmitted ------------------------------------------
frames="$tmp/out/resumed"
submit_resumable() {
  CONVRAY_ARGS="$settings +O$frames/" bash "$farm" submit "$animation" 2 -- \
    --cpus-per-task=1 --output="$tmp/logs/resume-%A_%a.log" 2>&1
}
out=$(submit_resumable) || fail "submit: $out"
job=$(job_id <<< "$out")
# Task 1 renders frames 3 and 4: once frame 3 is written it is rendering frame 4.
for _ in $(seq 2400); do [ -f "$frames/metaballs3.png" ] && break; sleep 0.05; done
[ -f "$frames/metaballs3.png" ] || fail "task 1 never wrote its first frame"
scancel "${job}_1"
wait_for_job "$job" 120
states="$(job_states "$job")"
[[ "$states" == *CANCELLED* ]] || fail "task ${job}_1 was not cancelled: $states"
[ ! -e "$frames/metaballs4.png" ] || fail "frame 4 was complete before scancel came; slow it down"
# Nothing partial under a frame's name: what is there is complete, and is one process's frame.
for f in "$frames"/*; do cmp "$f" "$tmp/single/${f##*/}" || fail "${f##*/} is not a whole frame"; done
left=$(ls -A "$frames" | xargs)
[ "$left" = "metaballs1.png metaballs2.png metaballs3.png" ] ||
  fail "after scancel the folder holds [$left]"
say "2. task ${job}_1 cancelled while rendering frame 4 ($states): [$left] left, each whole"
before=$(stat -c '%n %i %Y' "$frames"/*)
out=$(submit_resumable) || fail "resubmit: $out"
job=$(job_id <<< "$out")
wait_for_job "$job" 120
expect_completed "$job"
expect_same_files "$frames" "$tmp/single"
[ "$(stat -c '%n %i %Y' "$frames"/metaballs[1-3].png)" = "$before" ] ||
  fail "the resubmission rendered complete frames again"
grep -q "metaballs3.png is complete; skipped (+C)" "$tmp/logs/resume-${job}_1.log" ||
  fail "task 1 of the resubmission did not say it skipped frame 3 (+C)"
say "2. resubmitted as job $job: frame 4 rendered, 1-3 kept (+C); all byte-identical"

# --- 3. a still split into bands of rows, stitched ------------------------------------------
scene=scenes/animations/metaballs.pov
still="+W320 +H241 +A0.3 +K0.5"
"$convray" "$scene" $still -o "$tmp/single-still.png" --quiet +WT2 ||
  fail "one process could not render the still"
out=$(CONVRAY_ARGS="$still" bash "$farm" submit-still "$scene" "$tmp/out/still.png" 3 -- \
  --cpus-per-task=1 --output="$tmp/logs/still-%A_%a.log" 2>&1) || fail "submit-still: $out"
array=$(grep -Eo 'array job [0-9]+' <<< "$out" | grep -Eo '[0-9]+')
stitch=$(job_id <<< "$out")
[ -n "$array" ] && [ -n "$stitch" ] || fail "submit-still said: $out"
wait_for_job "$stitch" 120
expect_completed "$array"
expect_completed "$stitch"
ls "$tmp"/out/still.part-{1,2,3}-of-3.png > /dev/null || fail "the parts are missing"
diff_report=$(oiiotool "$tmp/out/still.png" "$tmp/single-still.png" --diff 2>&1) ||
  fail "the stitched still differs from one process's: $diff_report"
say "3. still: 3 bands (array $array) stitched by job $stitch: every pixel as one process's"
say "PASSED"
