// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's mean-curvature-flow skeleton (extract_mean_curvature_flow_skeleton,
// CGAL 5.5, default parameters) of a closed triangle mesh, as the anchor the
// curve skeleton is compared with (Benchmarks/curve_skeleton_report.py).
// Writes JSON: the skeleton's vertices, edges, each vertex's corresponding
// surface vertices, and the wall time of the extraction.
//
//   medialaxis-mcf-skeleton mesh.off out.json
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Mesh>;
using Skeleton = Skeletonization::Skeleton;
}

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: medialaxis-mcf-skeleton mesh.off out.json\n";
    return 2;
  }
  Mesh mesh;
  std::ifstream input(argv[1]);
  if (!input || !CGAL::IO::read_OFF(input, mesh) || mesh.is_empty() ||
    !CGAL::is_triangle_mesh(mesh) || !CGAL::is_closed(mesh))
  {
    std::cerr << argv[1] << ": not a closed triangle mesh in OFF\n";
    return 1;
  }
  Skeleton skeleton;
  const auto start = std::chrono::steady_clock::now();
  try
  {
    CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
  }
  catch (const std::exception& error)
  {
    std::cerr << argv[1] << ": the skeleton failed: " << error.what() << "\n";
    return 1;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::ofstream out(argv[2]);
  out.precision(17);
  out << "{\"seconds\": " << seconds << ",\n\"nodes\": [";
  bool first = true;
  for (auto v : CGAL::make_range(vertices(skeleton)))
  {
    const auto& p = skeleton[v].point;
    out << (first ? "" : ",\n") << "{\"position\": [" << p.x() << ", " << p.y() << ", " << p.z()
        << "], \"surface\": [";
    bool firstIndex = true;
    for (auto s : skeleton[v].vertices)
    {
      out << (firstIndex ? "" : ", ") << static_cast<std::size_t>(s);
      firstIndex = false;
    }
    out << "]}";
    first = false;
  }
  out << "],\n\"edges\": [";
  first = true;
  for (auto e : CGAL::make_range(edges(skeleton)))
  {
    out << (first ? "" : ", ") << "[" << source(e, skeleton) << ", " << target(e, skeleton) << "]";
    first = false;
  }
  out << "]}\n";
  std::printf("%s: %zu nodes, %zu edges, %.2f s\n", argv[1], num_vertices(skeleton),
    num_edges(skeleton), seconds);
  return out ? 0 : 1;
}
