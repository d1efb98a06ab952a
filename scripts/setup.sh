#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian 12 packages MedialAxis needs (only those missing) and
# configures and builds it. Idempotent and non-interactive.
#
#   scripts/setup.sh            library + Python wrapping + tests, and the ParaView plugin
#   scripts/setup.sh --library  library + Python wrapping + tests only
#   scripts/setup.sh --robustness  also the sanitizer and fuzzing builds
#
# Build folders: $MEDIALAXIS_BUILD_DIR (default: build/ in the source tree),
# with vtk/ (Debian's VTK 9.1) and paraview/ (ParaView 5.11's VTK, the plugin);
# with --robustness also asan/ (library + C++ tests with AddressSanitizer and
# UndefinedBehaviorSanitizer) and fuzz/ (libFuzzer targets, clang).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${MEDIALAXIS_BUILD_DIR:-$root/build}
with_paraview=1
with_robustness=0
for arg in "$@"; do
  case "$arg" in
    --library) with_paraview=0 ;;
    --robustness) with_robustness=1 ;;
    -h|--help) sed -n '3,13p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

# python3-networkx: medialaxis.skeleton_graph returns curve skeletons as networkx graphs.
packages=(cmake ninja-build g++ ccache pkg-config libvtk9-dev python3-vtk9 libcgal-dev
  libeigen3-dev libtbb-dev liblbfgspp-dev libnanoflann-dev libgtest-dev xvfb xauth
  python3-networkx)
if [ "$with_paraview" = 1 ]; then
  # Never python3-paraview: it conflicts with python3-vtk9 (see make-paraview-sdk.sh).
  # mpiexec and mpi4py: medial-axis-batch runs pvbatch on MPI ranks.
  # libqt5svg5: the GUI's toolbar icons (its picture, docs/images/paraview-gui.png).
  packages+=(paraview paraview-dev openmpi-bin python3-mpi4py libqt5svg5)
fi
if [ "$with_robustness" = 1 ]; then
  packages+=(clang-14 libclang-rt-14-dev) # libFuzzer and clang's sanitizer runtimes
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null || { echo "setup.sh: run as root or install sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=sudo
  fi
  echo "== installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

echo "== building the library (VTK 9.1) in $build/vtk"
cmake -S "$root" -B "$build/vtk" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" >/dev/null
cmake --build "$build/vtk"

if [ "$with_paraview" = 1 ]; then
  sdk="$build/paraview-sdk"
  pv_dir="$sdk/lib/x86_64-linux-gnu/cmake/paraview-5.11"
  if [ ! -f "$pv_dir/paraview-config.cmake" ] || [ ! -d "$sdk/lib/python3/dist-packages/paraview" ]; then
    echo "== preparing a ParaView SDK overlay in $sdk"
    sh "$root/scripts/make-paraview-sdk.sh" "$sdk" >/dev/null 2>&1 || {
      # The package lists may be missing or stale: refresh once and retry.
      if [ "$(id -u)" = 0 ]; then apt-get update -qq; else sudo apt-get update -qq; fi
      sh "$root/scripts/make-paraview-sdk.sh" "$sdk" >/dev/null
    }
  fi
  echo "== building the ParaView plugin in $build/paraview"
  cmake -S "$root" -B "$build/paraview" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DMEDIALAXIS_PARAVIEW_PLUGIN=ON -DParaView_DIR="$pv_dir" \
    -DMEDIALAXIS_PARAVIEW_PYTHONPATH="$sdk/lib/python3/dist-packages" \
    -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" >/dev/null
  cmake --build "$build/paraview"
fi
if [ "$with_robustness" = 1 ]; then
  # No Python wrapping, examples or benchmarks: the C++ tests are what runs here.
  echo "== building the library and C++ tests with ASan + UBSan in $build/asan"
  # Line tables only (-g1): the sanitizers' reports name files and lines, and
  # the CGAL-heavy units compile faster and link smaller than with full -g.
  cmake -S "$root" -B "$build/asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DMEDIALAXIS_SANITIZE=ON \
    -DMEDIALAXIS_WRAP_PYTHON=OFF -DMEDIALAXIS_BUILD_EXAMPLES=OFF -DMEDIALAXIS_BUILD_BENCHMARKS=OFF \
    -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" >/dev/null
  cmake --build "$build/asan"
  # -O1 with assertions (no NDEBUG) and line tables: faster to build, checks
  # stay on.
  echo "== building the fuzz targets in $build/fuzz"
  cmake -S "$root" -B "$build/fuzz" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DMEDIALAXIS_FUZZ=ON "${launcher[@]}" >/dev/null
  cmake --build "$build/fuzz"
fi
echo "== setup done"
