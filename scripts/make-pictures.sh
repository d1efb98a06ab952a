#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates the pictures in docs/images with the medial-axis tool: the MAT
# of an organic model (the Stanford Bunny from ../shared/data/meshes) and of
# a generated CAD-like part with its fillets highlighted (README), and the
# mid-surfaces of the thin-walled CAD meshes of ../shared/data/meshes
# (docs/benchmark-results.md), curve skeletons (docs/methods.md), and the plugin in the ParaView GUI
# (docs/paraview.md).
#   scripts/make-pictures.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${MEDIALAXIS_BUILD_DIR:-$root/build}
meshes=${MEDIALAXIS_MESH_DIR:-$root/../shared/data/meshes}
"$root/scripts/setup.sh" --library
tool="$build/vtk/bin/medial-axis"
images="$root/docs/images"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$images"
# The filleted part of the main job (3 x 2 x 1, fillet radius 0.2).
"$build/vtk/bin/PrepareSurfaceExample" --output "$work/part" --samples 1000 --target 100 >/dev/null
part=$(ls -t "$work"/part/*_prepared.vtp | head -n 1)
"$tool" --preset cad --fillets --quiet --screenshot "$images/cad-filleted-part.png" "$part" \
  "$work/cad"
"$tool" --preset organic --quiet --screenshot "$images/organic-bunny.png" "$meshes/bunny.obj" \
  "$work/organic"
for mesh in abc_00000125.obj abc_00000068.obj casting.off cup.off; do
  "$tool" --preset cad --mid-surface --quiet --screenshot "$images/mid-surface-${mesh%.*}.png" \
    "$meshes/$mesh" "$work/${mesh%.*}"
done
# Curve skeletons inside their surfaces (docs/methods.md): two organic shapes and the vessel.
for mesh in armadillo.off fertility.off vessel.off; do
  "$tool" --preset organic --curve-skeleton --quiet \
    --screenshot "$images/curve-skeleton-${mesh%.*}.png" "$meshes/$mesh" "$work/${mesh%.*}"
done
# The plugin in the real ParaView GUI (docs/paraview.md, README): the whole
# window, drawn under Xvfb.
"$root/scripts/setup.sh" >/dev/null # the plugin build and ParaView's Python modules
MEDIALAXIS_GUI_PICTURE="$images/paraview-gui.png" \
  PV_PLUGIN_PATH="$build/paraview/lib/paraview-plugins/MedialAxis" \
  PYTHONPATH="$build/paraview-sdk/lib/python3/dist-packages" \
  xvfb-run -a -s "-screen 0 1600x1000x24" paraview --dr \
  --script="$root/Examples/ParaView/gui_picture.py" >/dev/null
echo "pictures are in $images"
