#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets up what is missing, builds both builds and runs every test of each
# (C++, Python, examples; pvbatch with the ParaView plugin), then the C++
# tests again under AddressSanitizer + UndefinedBehaviorSanitizer and a
# bounded fuzzing run of each libFuzzer target. Exits non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${MEDIALAXIS_BUILD_DIR:-$root/build}
"$root/scripts/setup.sh" --robustness
status=0
echo "== tests of the library build (VTK 9.1)"
ctest --test-dir "$build/vtk" --output-on-failure -j2 || status=1
echo "== tests of the ParaView plugin build"
ctest --test-dir "$build/paraview" --output-on-failure || status=1
echo "== C++ tests with AddressSanitizer + UndefinedBehaviorSanitizer"
ctest --test-dir "$build/asan" --output-on-failure -j2 || status=1
echo "== fuzz targets: corpus replay and a bounded run each"
ctest --test-dir "$build/fuzz" --output-on-failure -j2 || status=1
exit $status
