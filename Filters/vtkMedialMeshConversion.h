// SPDX-License-Identifier: GPL-3.0-or-later
// Conversion between the plain medial mesh and its vtkPolyData form
// (the data contract of docs/architecture.md), and the one validation every medial-mesh
// consumer calls. Private to the module: not wrapped.
#ifndef vtkMedialMeshConversion_h
#define vtkMedialMeshConversion_h

#include "Mesh/MedialMesh.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace medialaxis
{
/// Name of the point-data array that holds sphere radii.
constexpr const char* RadiusArrayName = "Radius";

/// Fills `output` with points, a `Radius` point-data array (active scalars),
/// triangles for faces, line cells for edges that bound no face and vertex
/// cells for isolated vertices.
void MedialMeshToPolyData(const MedialMesh& mesh, vtkPolyData* output);

/// Reads a medial mesh from poly data and validates it. Returns an empty
/// string on success, otherwise a message naming the defect (e.g. missing
/// `Radius` array, a polygon that is not a triangle, duplicate triangles).
std::string PolyDataToMedialMesh(vtkPolyData* input, MedialMesh& mesh);

/// Stores each vertex's Atlas (the surface sites it corresponds to): field
/// data `AtlasSites` (all lists concatenated in vertex order) and
/// `AtlasOffsets` (vertex v owns AtlasSites[AtlasOffsets[v] ..
/// AtlasOffsets[v + 1])), and point data `AtlasCount` for display.
void AddAtlasArrays(
  vtkPolyData* output, const std::vector<Index>& offsets, const std::vector<Index>& sites);

/// Reads the Atlas arrays back; returns an error message ("" on success).
std::string GetAtlasArrays(
  vtkPolyData* input, std::vector<Index>& offsets, std::vector<Index>& sites);

/// Adds cell data `StabilityRatio` to the poly data made from `mesh` by
/// MedialMeshToPolyData: per line its edge's ratio (Q-MAT's Gamma), per
/// triangle the smallest of its edges', 1 for isolated vertices.
void AddStabilityRatios(const MedialMesh& mesh, vtkPolyData* output);

/// `rvdOut` = the restricted Voronoi diagram `rvdIn` (cell data `SiteId`)
/// plus cell data `MedialVertexId`: a medial vertex whose Atlas holds the
/// polygon's site, -1 if none (colour the surface by it to see the
/// correspondence).
void AddCorrespondence(vtkPolyData* rvdIn, const std::vector<Index>& atlasOffsets,
  const std::vector<Index>& atlasSites, std::size_t numberOfSites, vtkPolyData* rvdOut);

/// Adds a one-value field-data array (a count or statistic for reports).
void AddFieldValue(vtkPolyData* output, const char* name, long long value);

/// Adds a one-value double field-data array (a measured quantity).
void AddFieldDouble(vtkPolyData* output, const char* name, double value);

/// The first value of a field-data array (as the two above add), 0 if absent.
double GetFieldValue(vtkPolyData* data, const char* name);

/// Adds a double field-data array of the given values (one per sheet, wall...).
void AddFieldArray(vtkPolyData* output, const char* name, const std::vector<double>& values);

/// Adds a double field-data array with one tuple per item: `get(item)`.
template <typename Item, typename Get>
void AddFieldPerItem(vtkPolyData* output, const char* name, const std::vector<Item>& items, Get get)
{
  std::vector<double> values;
  values.reserve(items.size());
  for (const Item& item : items)
  {
    values.push_back(static_cast<double>(get(item)));
  }
  AddFieldArray(output, name, values);
}

/// The shared validity check for medial meshes given as poly data.
inline std::string ValidateMedialPolyData(vtkPolyData* input)
{
  MedialMesh unused;
  return PolyDataToMedialMesh(input, unused);
}
}

#endif
