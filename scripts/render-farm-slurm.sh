#!/usr/bin/env bash
# Spreads convray renders over a Slurm cluster (docs/render-farm.md):
#
#   bash scripts/render-farm-slurm.sh submit ANIMATION.ini [FRAMES_PER_TASK] [-- SBATCH_OPTIONS...]
#       an animation as a job array: each array task renders a chunk of consecutive frames with
#       +SF/+EF, so every frame is an independent job with deterministic output (the same bytes
#       whichever node renders it). Tasks pass +C, so a resubmitted or requeued task skips the
#       frames that are already complete. The frames come from convray --list-frames.
#   bash scripts/render-farm-slurm.sh submit-still SCENE OUTPUT PARTS [-- SBATCH_OPTIONS...]
#       one large still split into PARTS bands of rows (POV-Ray's +SR/+ER): an array of PARTS
#       tasks writes OUTPUT's parts beside it (out/big.png: out/big.part-01-of-08.png, ...),
#       then a job that waits for them all (afterok) stitches them into OUTPUT with
#       scripts/stitch-parts.sh. Parts pass +C too; the parts stay for the user to remove.
#   (inside Slurm) the same script runs once per array task, and as the stitching job.
#
# Environment: CONVRAY (the binary; default build/convray of this checkout), CONVRAY_ARGS
# (extra arguments for every render, e.g. "+W1920 +H1080 +A0.3"). The output folder must be
# on a file system every node sees, and so must this checkout: Slurm runs a copy of this
# script from its spool folder, so `submit` passes the binary's and the scripts' absolute
# paths on to the jobs in the environment (sbatch exports it by default).
#SBATCH --job-name=convray
#SBATCH --cpus-per-task=4
#SBATCH --output=convray-%A_%a.log
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Inside a job, the copy in Slurm's spool has no checkout beside it: the submitter's paths.
convray="${CONVRAY:-$here/build/convray}"
case "$convray" in
  /*) ;;
  */*) convray="$PWD/$convray" ;;
  *) convray="$(command -v "$convray" || echo "$convray")" ;;
esac
export CONVRAY="$convray" CONVRAY_FARM_SCRIPTS="${CONVRAY_FARM_SCRIPTS:-$here/scripts}"
read -r -a extra <<< "${CONVRAY_ARGS:-}"
usage() {
  echo "usage: $0 submit ANIMATION.ini [FRAMES_PER_TASK] [-- SBATCH_OPTIONS...]" >&2
  echo "       $0 submit-still SCENE OUTPUT PARTS [-- SBATCH_OPTIONS...]" >&2
  exit 2
}

# The frame numbers of the animation, one per line.
frame_numbers() { "$convray" "$1" "${extra[@]}" --list-frames | cut -f1; }

# Part K (1-based) of OUTPUT's N: out/big.png -> out/big.part-03-of-08.png.
part_name() {
  local output="$1" k="$2" n="$3" digits=${#3}
  printf '%s.part-%0*d-of-%s.%s' "${output%.*}" "$digits" "$k" "$n" "${output##*.}"
}

submit_animation() {
  [ $# -ge 1 ] || usage
  local animation="$1"; shift
  local per_task=1
  if [ $# -ge 1 ] && [ "$1" != -- ]; then per_task="$1"; shift; fi
  [ "${1:-}" = -- ] && shift
  [[ "$per_task" =~ ^[1-9][0-9]*$ ]] || { echo "$0: FRAMES_PER_TASK must be a whole number >= 1" >&2; exit 2; }
  local count tasks
  count=$(frame_numbers "$animation" | wc -l)
  tasks=$(( (count + per_task - 1) / per_task ))
  echo "==> $animation: $count frames, $tasks array tasks of up to $per_task frames"
  exec sbatch --array="0-$((tasks - 1))" "$@" "$0" task "$animation" "$per_task"
}

animation_task() {
  local animation="$1" per_task="$2" task="${SLURM_ARRAY_TASK_ID:?not inside a Slurm array task}"
  local frames
  mapfile -t frames < <(frame_numbers "$animation")
  local first_index=$(( task * per_task ))
  (( first_index < ${#frames[@]} )) || { echo "task $task: no frames left"; exit 0; }
  local last_index=$(( first_index + per_task - 1 ))
  (( last_index < ${#frames[@]} )) || last_index=$(( ${#frames[@]} - 1 ))
  exec "$convray" "$animation" "${extra[@]}" $(thread_switch) \
    "+SF${frames[$first_index]}" "+EF${frames[$last_index]}" +C
}

# +WTn from the CPUs Slurm gave the task, if it says.
thread_switch() { [ "${SLURM_CPUS_PER_TASK:-0}" -gt 0 ] && echo "+WT$SLURM_CPUS_PER_TASK" || true; }

submit_still() {
  [ $# -ge 3 ] || usage
  local scene="$1" output="$2" parts="$3"; shift 3
  [ "${1:-}" = -- ] && shift
  [[ "$parts" =~ ^[1-9][0-9]*$ ]] || { echo "$0: PARTS must be a whole number >= 1" >&2; exit 2; }
  [[ "${output##*/}" == *.* ]] || { echo "$0: OUTPUT needs an extension (.png, .tif, .exr)" >&2; exit 2; }
  local array
  array=$(sbatch --parsable --array="0-$((parts - 1))" "$@" "$0" still-task "$scene" "$output" "$parts")
  array="${array%%;*}"  # "ID;CLUSTER" on federated clusters
  echo "==> $scene: $parts bands of rows, array job $array; then stitched into $output"
  sbatch --dependency="afterok:$array" --kill-on-invalid-dep=yes --cpus-per-task=1 --job-name=convray-stitch "$@" \
    "$0" stitch "$output" "$parts"
}

# Band K of N: rows from fraction K/N to (K+1)/N, written with the same digits on either side of
# a boundary, so that neighbouring bands meet without a gap or an overlap (partial_image.hpp).
still_task() {
  local scene="$1" output="$2" parts="$3" task="${SLURM_ARRAY_TASK_ID:?not inside a Slurm array task}"
  local start end
  start=$(awk -v k="$task" -v n="$parts" 'BEGIN { printf "%.9f", k / n }')
  end=$(awk -v k="$task" -v n="$parts" 'BEGIN { printf "%.9f", (k + 1) / n }')
  exec "$convray" "$scene" "${extra[@]}" $(thread_switch) "+SR$start" "+ER$end" +C \
    -o "$(part_name "$output" $((task + 1)) "$parts")"
}

stitch() {
  local output="$1" parts="$2" k names=()
  for (( k = 1; k <= parts; ++k )); do names+=("$(part_name "$output" "$k" "$parts")"); done
  exec bash "$CONVRAY_FARM_SCRIPTS/stitch-parts.sh" "$output" "${names[@]}"
}

command="${1:-}"; [ $# -ge 1 ] && shift
case "$command" in
  submit) submit_animation "$@" ;;
  submit-still) submit_still "$@" ;;
  task) [ $# -eq 2 ] || usage; animation_task "$@" ;;
  still-task) [ $# -eq 3 ] || usage; still_task "$@" ;;
  stitch) [ $# -eq 2 ] || usage; stitch "$@" ;;
  *) usage ;;
esac
