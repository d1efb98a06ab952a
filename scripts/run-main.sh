#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job on a default input: sets up what is missing, then checks and
# prepares a generated filleted part and writes the result to output/.
#   scripts/run-main.sh [surface file]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${MEDIALAXIS_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh" --library
out="$root/output"
"$build/vtk/bin/PrepareSurfaceExample" --output "$out" "$@"
echo "results are in $out"
