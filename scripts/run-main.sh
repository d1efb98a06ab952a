#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job on a default input: sets up what is missing, then checks and
# prepares a generated filleted part (or the given surface), computes its
# Structural MAT step by step, and runs the medial-axis tool on it with the
# CAD settings for the MAT, its fillets and structure, the envelope, the reconstruction
# error, a JSON report and a picture. Everything goes to output/.
#   scripts/run-main.sh [surface file]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${MEDIALAXIS_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh" --library
out="$root/output"
"$build/vtk/bin/PrepareSurfaceExample" --output "$out" "$@"
# The prepared surface the example wrote (the newest *_prepared.vtp).
prepared=$(ls -t "$out"/*_prepared.vtp | head -n 1)
"$build/vtk/bin/medial-axis" --preset cad --fillets --structure --envelope --correspondence --error \
  --report "$out/medial-axis/report.json" --screenshot "$out/medial-axis/medial-axis.png" \
  "$prepared" "$out/medial-axis"
echo "results are in $out"
