#!/usr/bin/env bash
# Regenerates the pictures of docs/kernels.md with convray itself: the paper's Fig. 6 (one
# triangle) and Fig. 9 (a polygon soup), each under the Cauchy kernel (left) and the quartic
# kernel (right), plus a close-up of the Cauchy surface's truncation ledges.
# Usage: bash scripts/make-kernel-images.sh   (after a build; make-docs-images.sh calls it)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=./build/convray
out=docs/images/kernels
mkdir -p $out
$convray scenes/kernels/triangle.pov +W640 +H320 +A0.3 --quiet -o $out/triangle.png
$convray scenes/kernels/model.pov +W480 +H240 --quiet -o $out/model.png
$convray scenes/kernels/model-closeup.pov +W320 +H240 --quiet -o $out/model-closeup.png
echo "pictures written to $out/"
