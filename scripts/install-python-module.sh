#!/usr/bin/env bash
# Makes `import convray` work (docs/python.md): writes convray.pth, naming this build's
# build/python folder, into the site-packages of Debian's python3 (whose NumPy scripts/setup.sh
# installs) and of the python3 first on PATH when that is another one of the same version.
# Nothing is copied: a rebuild is seen at once; remove the .pth file(s) to undo.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
folder="$PWD/build/python"
if ! ls "$folder"/convray.*.so >/dev/null 2>&1; then
  echo "==> note: build/python has no convray module (pybind11-dev missing?); import convray skipped"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
declare -A done_sites=()
for python in /usr/bin/python3 "$(command -v python3 || true)"; do
  [ -x "$python" ] || continue
  # Only an interpreter that can load the module built here (same version and ABI).
  suffix=$("$python" -c 'import importlib.machinery as m; print(m.EXTENSION_SUFFIXES[0])')
  [ -e "$folder/convray$suffix" ] || continue
  site=$("$python" -c 'import site; print(site.getsitepackages()[0])')
  [ -n "${done_sites[$site]:-}" ] && continue
  done_sites[$site]=1
  $sudo mkdir -p "$site"
  echo "$folder" | $sudo tee "$site/convray.pth" >/dev/null
  if "$python" -c 'import convray' 2>/dev/null; then
    echo "==> import convray: $python (through $site/convray.pth)"
  else
    echo "==> warning: $python cannot import convray through $site/convray.pth"
  fi
done
