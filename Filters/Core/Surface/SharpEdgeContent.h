// SPDX-License-Identifier: GPL-3.0-or-later
// How much of a surface's structure is sharp edges: picks the CAD or the
// organic preset for a mesh nobody has labelled.
#ifndef medialaxis_SharpEdgeContent_h
#define medialaxis_SharpEdgeContent_h

#include "Mesh/PolygonMesh.h"

namespace medialaxis
{
struct SharpEdgeContent
{
  double SharpLength = 0.0;  // total length of the sharp edges (convex and concave)
  double CreaseLength = 0.0; // of those, in creases: chains at least CreaseFraction long
  double Area = 0.0;
  double CreaseFraction = 0.0; // a chain's shortest length for a crease, / sqrt(Area)
  int Creases = 0;             // chains of sharp edges that count as creases
  /// Dimensionless: CreaseLength / sqrt(Area). A cube's twelve edges give
  /// 12 / sqrt(6) = 4.9; a cylinder as tall as wide gives 2 pi / sqrt(1.5 pi)
  /// = 2.9; a smooth or noisy organic surface gives about 0.
  double Ratio() const;
};

/// Measures the sharp edges of a closed triangle mesh. An edge is sharp when
/// its two triangles' normals differ by more than `featureAngle` (radians),
/// both raw and after `normalFiltering` iterations of bilateral normal
/// filtering (BilateralFaceNormals), so that scan noise is not counted. The
/// sharp edges are joined into chains where exactly two meet at a vertex, the
/// line turns there by less than 30 degrees and the angle between the
/// normals changes by less than 15 degrees (a machined edge keeps its
/// angle; a coarse tessellation's ridges come and go); only chains at least
/// `creaseFraction` * sqrt(area) long count as creases: what is left of
/// noise after filtering branches and zig-zags into short pieces, and a
/// coarse tessellation's sharp bits (a tentacle's tip) are short, while the
/// edges of a machined part run on smoothly along whole faces. Deterministic.
SharpEdgeContent MeasureSharpEdgeContent(const TriangleMesh& mesh, double featureAngle,
  int normalFiltering = 3, double creaseFraction = 0.05);

/// The preset rule of `medial-axis --preset auto`: the CAD preset when the
/// creases add up to at least `minimumRatio` * sqrt(area), i.e. about the
/// edges of one face of a box (a cube has 4.9, one square face 4/sqrt(6) =
/// 1.6); a single rim on an otherwise smooth shape stays organic.
bool LooksLikeCad(const SharpEdgeContent& content, double minimumRatio = 1.5);
}

#endif
