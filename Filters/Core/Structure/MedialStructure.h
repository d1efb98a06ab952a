// SPDX-License-Identifier: GPL-3.0-or-later
// The structure of a medial mesh as data: what each vertex is (sheet, seam,
// junction, rim, feature, fillet, curve, isolated), which triangles form one
// sheet, and the seams where three or more sheets meet.
#ifndef medialaxis_MedialStructure_h
#define medialaxis_MedialStructure_h

#include "Mesh/MedialMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace medialaxis
{
/// In the order of precedence of the rules (MedialStructure.cxx).
enum class MedialVertexType : std::uint8_t
{
  Sheet = 0,    // inside a sheet: two sides of the surface touch its ball
  Seam = 1,     // on a curve where three or more sheets meet
  Junction = 2, // where seams meet, or a curve meets a sheet
  Rim = 3,      // on the free boundary of a sheet, radius > 0
  Feature = 4,  // radius 0, on a sharp edge of the surface
  Fillet = 5,   // on a fillet centre line
  Curve = 6,    // on edges only (a tube's axis)
  Isolated = 7  // on no edge and no triangle
};
constexpr int NumberOfMedialVertexTypes = 8;
const char* MedialVertexTypeName(MedialVertexType type);

struct MedialStructureOptions
{
  /// Per vertex, optional (empty: a radius of 0 marks a feature vertex).
  std::vector<std::uint8_t> FeatureVertex;
  /// Per vertex, optional: on a fillet centre line (FilletDetector.h).
  std::vector<std::uint8_t> FilletVertex;
  /// Per vertex, optional: the connected pieces of its Atlas' cells
  /// (TangentComponents.h). Where given, sheet, seam, junction and rim
  /// vertices are compared with them (2, 3, 4 or more, 1), and with
  /// ByTangentComponents they decide between those four types, as MATFP
  /// classifies its spheres.
  std::vector<int> TangentComponents;
  bool ByTangentComponents = false;
  /// Sheets with less than this fraction of the mesh's total area, hanging
  /// on other sheets by edges of three or more faces, are flaps (discrete
  /// debris along rims and at junctions): they join the largest sheet they
  /// touch and do not count on those edges. 0 keeps every sheet.
  double MinimumSheetFraction = 0.001;
};

struct MedialSheet
{
  std::size_t Triangles = 0;
  double Area = 0.0;
  double MeanRadius = 0.0; // area-weighted, the radius linear on each triangle
  double MinimumRadius = 0.0;
  double MaximumRadius = 0.0;
};

struct MedialStructure
{
  std::vector<MedialVertexType> VertexType;
  /// Per face, its sheet: faces joined across edges of exactly two faces,
  /// unless both ends of the edge are feature vertices, and flaps joined to
  /// their host (MinimumSheetFraction). Sheets are numbered in the order of
  /// their first face.
  std::vector<Index> FaceSheet;
  std::vector<MedialSheet> Sheets;
  /// The edges of three or more faces (not counting flaps') of two sheets
  /// or more (a sheet meeting only itself is folded), sorted by (min, max)
  /// vertex id, and
  /// the seam of each: chains of them joined at vertices on exactly two
  /// (junctions end them), numbered in the order of their first edge.
  std::vector<std::array<Index, 2>> SeamEdges;
  std::vector<Index> SeamOfEdge;
  std::size_t NumberOfSeams = 0;
  std::array<std::size_t, NumberOfMedialVertexTypes> TypeCounts{};
  /// With TangentComponents: the sheet, seam, junction and rim vertices (by
  /// either rule) compared, and those where the two rules differ.
  std::size_t ComparedVertices = 0;
  std::size_t Disagreements = 0;
};

/// The type MATFP gives a sphere of radius > 0 whose tangent contacts form
/// `components` connected pieces: 1 rim, 2 sheet, 3 seam, 4 or more junction.
MedialVertexType TypeFromTangentComponents(int components);

/// Classifies a valid medial mesh (ValidateMedialMesh); option vectors of
/// the wrong size are ignored.
MedialStructure ClassifyMedialStructure(
  const MedialMesh& mesh, const MedialStructureOptions& options = MedialStructureOptions());
}

#endif
