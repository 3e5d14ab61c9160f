#!/usr/bin/env bash
# Spreads an animation over a Slurm cluster as a job array: each array task renders a chunk of
# consecutive frames with +SF/+EF, so every frame is an independent job with deterministic
# output (the same bytes whichever node renders it). Tasks pass +C, so a resubmitted or
# requeued task skips the frames that are already complete. See docs/render-farm.md.
#
#   bash scripts/render-farm-slurm.sh submit ANIMATION.ini [FRAMES_PER_TASK] [-- SBATCH_OPTIONS...]
#       works out the frames (convray --list-frames), then submits the array with sbatch.
#   (inside Slurm) the same script runs once per array task.
#
# Environment: CONVRAY (the binary; default build/convray of this checkout), CONVRAY_ARGS
# (extra arguments for every frame, e.g. "+W1920 +H1080 +A0.3"). The output folder must be
# on a file system every node sees.
#SBATCH --job-name=convray
#SBATCH --cpus-per-task=4
#SBATCH --output=convray-%A_%a.log
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
convray="${CONVRAY:-$here/build/convray}"
read -r -a extra <<< "${CONVRAY_ARGS:-}"

# The frame numbers of the animation, one per line.
frame_numbers() { "$convray" "$1" "${extra[@]}" --list-frames | cut -f1; }

if [ "${1:-}" = submit ]; then
  shift
  [ $# -ge 1 ] || { echo "usage: $0 submit ANIMATION.ini [FRAMES_PER_TASK] [-- SBATCH_OPTIONS...]" >&2; exit 2; }
  animation="$1"; shift
  per_task=1
  if [ $# -ge 1 ] && [ "$1" != -- ]; then per_task="$1"; shift; fi
  [ "${1:-}" = -- ] && shift
  [[ "$per_task" =~ ^[1-9][0-9]*$ ]] || { echo "$0: FRAMES_PER_TASK must be a whole number >= 1" >&2; exit 2; }
  count=$(frame_numbers "$animation" | wc -l)
  tasks=$(( (count + per_task - 1) / per_task ))
  echo "==> $animation: $count frames, $tasks array tasks of up to $per_task frames"
  exec sbatch --array="0-$((tasks - 1))" "$@" "$0" task "$animation" "$per_task"
fi

[ "${1:-}" = task ] || { echo "usage: $0 submit ANIMATION.ini [FRAMES_PER_TASK] [-- SBATCH_OPTIONS...]" >&2; exit 2; }
animation="$2"; per_task="$3"
task="${SLURM_ARRAY_TASK_ID:?not inside a Slurm array task}"
mapfile -t frames < <(frame_numbers "$animation")
first_index=$(( task * per_task ))
(( first_index < ${#frames[@]} )) || { echo "task $task: no frames left"; exit 0; }
last_index=$(( first_index + per_task - 1 ))
(( last_index < ${#frames[@]} )) || last_index=$(( ${#frames[@]} - 1 ))
threads="${SLURM_CPUS_PER_TASK:-0}"
thread_switch=()
[ "$threads" -gt 0 ] && thread_switch=("+WT$threads")
exec "$convray" "$animation" "${extra[@]}" "${thread_switch[@]}" \
  "+SF${frames[$first_index]}" "+EF${frames[$last_index]}" +C
