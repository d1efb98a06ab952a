// SPDX-License-Identifier: GPL-3.0-or-later
// Plain C++ polygon and triangle meshes (no VTK), the currency of the surface
// readers and of surface preparation.
#ifndef medialaxis_PolygonMesh_h
#define medialaxis_PolygonMesh_h

#include "Geometry/Types.h"

#include <array>
#include <vector>

namespace medialaxis
{
/// Polygons of any size in compressed form: polygon p uses
/// Connectivity[Offsets[p] .. Offsets[p + 1]).
struct PolygonMesh
{
  std::vector<Point3> Points;
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> Connectivity;

  std::size_t NumberOfPolygons() const { return this->Offsets.size() - 1; }
  void AddPolygon(const Index* ids, std::size_t n)
  {
    this->Connectivity.insert(this->Connectivity.end(), ids, ids + n);
    this->Offsets.push_back(static_cast<Index>(this->Connectivity.size()));
  }
};

using Triangle = std::array<Index, 3>;

struct TriangleMesh
{
  std::vector<Point3> Points;
  std::vector<Triangle> Triangles;
};
}

#endif
