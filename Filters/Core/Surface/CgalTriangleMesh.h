// SPDX-License-Identifier: GPL-3.0-or-later
// A CGAL Surface_mesh of triangles back to the library's TriangleMesh, for
// the translation units that use CGAL's mesh processing (include it only
// there: it needs CGAL's headers).
#ifndef medialaxis_CgalTriangleMesh_h
#define medialaxis_CgalTriangleMesh_h

#include "Mesh/PolygonMesh.h"

#include <CGAL/boost/graph/iterator.h>

#include <vector>

namespace medialaxis
{
/// Points in the order `mesh` keeps them, then its faces; `faces` (if
/// given) receives the face of each triangle. False when a face is not a
/// triangle.
template <typename SurfaceMesh>
bool ToTriangleMesh(const SurfaceMesh& mesh, TriangleMesh& out,
  std::vector<typename SurfaceMesh::Face_index>* faces = nullptr)
{
  out = TriangleMesh();
  std::vector<Index> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  for (auto v : mesh.vertices())
  {
    index[v] = static_cast<Index>(out.Points.size());
    const auto& p = mesh.point(v);
    out.Points.push_back({ p.x(), p.y(), p.z() });
  }
  for (auto f : mesh.faces())
  {
    Triangle t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      if (k < 3)
      {
        t[k] = index[v];
      }
      ++k;
    }
    if (k != 3)
    {
      return false;
    }
    out.Triangles.push_back(t);
    if (faces)
    {
      faces->push_back(f);
    }
  }
  return true;
}
}

#endif
