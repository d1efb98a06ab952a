// SPDX-License-Identifier: GPL-3.0-or-later
// The library's only translation unit with CGAL's Delaunay triangulation and
// AABB tree (Voronoi/SurfaceQueries.h): they take long to compile, so they
// are kept together here.
#include "Voronoi/VoronoiMedialAxis.h"

#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Support/DisjointSets.h"
#include "Support/HeapRelease.h"
#include "Surface/SurfacePreparation.h"
#include "Voronoi/DelaunayCells.h"
#include "Voronoi/MedialComplexCleanup.h"
#include "Voronoi/MedialTopologyRepair.h"
#include "Voronoi/SurfaceQueries.h"
#include "Voronoi/ThinPartRepair.h"

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
namespace
{
using cgal_surface::K;
using cgal_surface::KPoint;
using cgal_surface::SurfaceQueries;
using cgal_surface::ToKernel;
using cgal_surface::ToPoint;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
using CellBase =
  CGAL::Triangulation_cell_base_with_info_3<Index, K, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;

// The circumcentre of a Delaunay cell. CGAL's inexact construction divides
// by a determinant that must not be zero; a sliver that is flat to double
// precision (four sites of a planar face, rounded slightly off it) makes it
// exactly zero, so those few are constructed exactly. Exact predicates keep
// finite cells of a 3D triangulation from being truly flat.
Point3 Circumcentre(const KPoint& p, const KPoint& q, const KPoint& r, const KPoint& s)
{
  double nx, ny, nz, den;
  CGAL::determinants_for_circumcenterC3(p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), r.x(), r.y(),
    r.z(), s.x(), s.y(), s.z(), nx, ny, nz, den);
  if (den != 0.0)
  {
    return ToPoint(CGAL::circumcenter(p, q, r, s));
  }
  using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  const CGAL::Cartesian_converter<K, Exact> toExact;
  const Exact::Point_3 c = CGAL::circumcenter(toExact(p), toExact(q), toExact(r), toExact(s));
  return { CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()) };
}

// A lower bound of the distance from a cell's computed circumcentre to every
// site, from its empty circumsphere: the distance to its nearest corner, less
// a margin far above the centre's rounding error; -1 (unknown) for cells so
// flat that the centre may be far off (volume against the product of three
// edges below 1e-6).
double EmptyBallRadius(const Point3& centre, const std::array<Point3, 4>& corners)
{
  const Point3 a = corners[1] - corners[0], b = corners[2] - corners[0],
               c = corners[3] - corners[0];
  const double volume = std::abs(Dot(a, Cross(b, c)));
  if (!(volume >= 1e-6 * Norm(a) * Norm(b) * Norm(c)))
  {
    return -1.0;
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const Point3& corner : corners)
  {
    nearest = std::min(nearest, Norm(centre - corner));
  }
  return nearest * (1.0 - 1e-8);
}

double BoundingDiagonal(const TriangleMesh& surface)
{
  const auto [lo, hi] = BoundingBox(surface.Points);
  return Norm(hi - lo);
}
}

VoronoiMedialAxisResult ComputeVoronoiMedialAxis(const TriangleMesh& surface,
  const std::vector<Point3>& sites, const std::vector<Index>& siteTrianglesIn,
  const std::vector<std::uint8_t>& concaveFeature, const VoronoiMedialAxisOptions& options)
{
  VoronoiMedialAxisResult result;
  if (sites.size() < 4 || surface.Triangles.empty())
  {
    return result;
  }
  auto report = [&options](double f) { return !options.Progress || options.Progress(f); };
  auto abort = []()
  {
    VoronoiMedialAxisResult empty;
    empty.Aborted = true;
    return empty;
  };
  SurfaceQueries queries(surface);

  // 1. Delaunay triangulation of the sites (CGAL sorts the range spatially,
  // with a locally seeded shuffle). Meanwhile the other thread builds the
  // surface's AABB tree, needed for the inside and distance tests below.
  tbb::task_group background;
  background.run([&queries] { queries.Build(); });
  std::vector<std::pair<KPoint, Index>> input;
  input.reserve(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
  {
    input.emplace_back(ToKernel(sites[i]), static_cast<Index>(i));
  }
  Delaunay delaunay(input.begin(), input.end());
  std::vector<std::pair<KPoint, Index>>().swap(input);
  background.wait();
  if (!report(0.35))
  {
    return abort();
  }

  // 2. Circumcentres of the finite cells, and which of them lie inside.
  // Cells are numbered by their sorted site ids, not by CGAL's storage
  // order (which can depend on memory addresses): the output is then the
  // same in every run.
  std::vector<std::pair<std::array<Index, 4>, Delaunay::Cell_handle>> keyed;
  keyed.reserve(delaunay.number_of_finite_cells());
  for (auto c = delaunay.finite_cells_begin(); c != delaunay.finite_cells_end(); ++c)
  {
    std::array<Index, 4> key{ c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
      c->vertex(3)->info() };
    std::sort(key.begin(), key.end());
    keyed.emplace_back(key, c);
  }
  // Keys are unique (one per cell): the parallel sort is deterministic.
  tbb::parallel_sort(
    keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Delaunay::Cell_handle> cells;
  cells.reserve(keyed.size());
  for (auto& [key, c] : keyed)
  {
    c->info() = static_cast<Index>(cells.size());
    cells.push_back(c);
  }
  decltype(keyed)().swap(keyed);
  for (auto c = delaunay.all_cells_begin(); c != delaunay.all_cells_end(); ++c)
  {
    if (delaunay.is_infinite(c))
    {
      c->info() = -1;
    }
  }
  const std::size_t nc = cells.size();
  result.DelaunayCells = nc;
  // Flat copies of the cells' sites and neighbours (-1: infinite cell):
  // every later pass walks these arrays instead of CGAL's handles.
  std::vector<std::array<Index, 4>> cellSites(nc), cellNeighbours(nc);
  std::vector<Point3> centre(nc);
  std::vector<double> emptyRadius(nc);
  std::vector<char> inside(nc, 0), ambiguous(nc, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nc, 4096),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t c = r.begin(); c != r.end(); ++c)
      {
        const auto& cell = cells[c];
        for (int k = 0; k < 4; ++k)
        {
          cellSites[c][k] = cell->vertex(k)->info();
          cellNeighbours[c][k] = cell->neighbor(k)->info();
        }
        centre[c] = Circumcentre(cell->vertex(0)->point(), cell->vertex(1)->point(),
          cell->vertex(2)->point(), cell->vertex(3)->point());
        emptyRadius[c] = EmptyBallRadius(centre[c],
          { ToPoint(cell->vertex(0)->point()), ToPoint(cell->vertex(1)->point()),
            ToPoint(cell->vertex(2)->point()), ToPoint(cell->vertex(3)->point()) });
      }
    });
  std::vector<Delaunay::Cell_handle>().swap(cells);
  // Every later pass works on the flat arrays: the triangulation (27 MB at
  // 50,000 samples) goes before the medial mesh is built beside them.
  delaunay.clear();
  ReleaseFreeHeapPages();
  // Each site's triangle (given, or the nearest) and its normal.
  std::vector<Index> siteTriangle = siteTrianglesIn;
  const Index nt = static_cast<Index>(surface.Triangles.size());
  bool valid = siteTriangle.size() == sites.size();
  for (std::size_t i = 0; valid && i < siteTriangle.size(); ++i)
  {
    valid = siteTriangle[i] >= 0 && siteTriangle[i] < nt;
  }
  if (!valid)
  {
    siteTriangle.resize(sites.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sites.size(), 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          siteTriangle[i] = queries.NearestTriangle(sites[i]);
        }
      });
  }
  // Each site's normal, and whether it lies strictly inside its triangle.
  std::vector<Point3> normal(sites.size());
  std::vector<char> interiorSite(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
  {
    const Triangle& t = surface.Triangles[siteTriangle[i]];
    const Point3 &a = surface.Points[t[0]], &b = surface.Points[t[1]], &c = surface.Points[t[2]];
    const Point3 n = Cross(b - a, c - a);
    const double area2 = Dot(n, n);
    const double w0 = Dot(Cross(c - b, sites[i] - b), n) / area2;
    const double w1 = Dot(Cross(a - c, sites[i] - c), n) / area2;
    const double w2 = Dot(Cross(b - a, sites[i] - a), n) / area2;
    normal[i] = Normalized(n);
    interiorSite[i] = std::min({ w0, w1, w2 }) > 1e-9 && area2 > 0.0 ? 1 : 0;
  }
  // A circumcentre clearly in front of the tangent planes of its four sites
  // is outside, and a large ball clearly behind them is inside. Every other
  // one is decided exactly, by the closest surface point and its
  // pseudo-normal; that includes all small balls: in thin parts a small
  // ball's centre can be behind all four tangent planes and still outside,
  // past another part of the surface.
  constexpr double clearCosine = 0.1;
  const std::pair<Point3, Point3> box = BoundingBox(surface.Points);
  const Point3 &lo = box.first, &hi = box.second; // no structured bindings: captured below
  const double smallRadius =
    4.0 * std::sqrt(2.0 * SurfaceArea(surface) / (std::sqrt(3.0) * sites.size()));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nc, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t c = r.begin(); c != r.end(); ++c)
      {
        const Point3& x = centre[c];
        // Outside the surface's bounding box is outside. That also keeps the
        // far circumcentres of slivers (up to overflow) away from the
        // distance computations below, which would overflow on them.
        if (!(x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] &&
              x[2] <= hi[2]))
        {
          continue;
        }
        int behind = 0, front = 0;
        for (int k = 0; k < 4; ++k)
        {
          const Index s = cellSites[c][k];
          const Point3 d = centre[c] - sites[s];
          const double along = Dot(d, normal[s]), length = Norm(d);
          behind += along < -clearCosine * length ? 1 : 0;
          front += along > clearCosine * length ? 1 : 0;
        }
        if (front == 4)
        {
          continue;
        }
        const Index s0 = cellSites[c][0];
        if (behind == 4 && Norm(centre[c] - sites[s0]) >= smallRadius)
        {
          inside[c] = 1;
          continue;
        }
        // Walk from the site whose tangent plane is the least grazing
        // towards the circumcentre: if the open segment meets no triangle,
        // the circumcentre is on the same side as the site's own triangle
        // says. (Sites on a triangle's boundary are left to the exact test.)
        int best = 0;
        double bestCosine = 0.0;
        for (int k = 0; k < 4; ++k)
        {
          const Index s = cellSites[c][k];
          const Point3 d = centre[c] - sites[s];
          const double cosine = Dot(d, normal[s]) / Norm(d);
          if (std::fabs(cosine) > std::fabs(bestCosine))
          {
            bestCosine = cosine;
            best = k;
          }
        }
        const Index s = cellSites[c][best];
        if (std::fabs(bestCosine) > clearCosine && interiorSite[s] &&
          !queries.Crosses(centre[c], sites[s] + 1e-6 * (centre[c] - sites[s])))
        {
          inside[c] = bestCosine < 0.0 ? 1 : 0;
          continue;
        }
        ambiguous[c] = 1;
        inside[c] = queries.InsideByPseudoNormal(centre[c], sites[s], siteTriangle[s]) ? 1 : 0;
      }
    });
  for (char a : ambiguous)
  {
    result.AmbiguousInsideTests += a;
  }

  // 2b. A thin part sampled more sparsely than its thickness has Delaunay
  // cells spanning it from one side to the other (sites facing away from
  // each other across the solid) whose circumcentres lie far outside: a cell
  // with three sites on one side and one on the other is nearly flat.
  // Dropping them leaves holes in the part's medial sheet (paper 000, Fig.
  // 19). Such a cell stays, its vertex moved to the mean of the midpoints of
  // its facing pairs (on the part's mid-surface), its radius the distance to
  // the surface there.
  std::vector<char> spanning(nc, 0);
  if (options.RepairThinParts)
  {
    std::vector<Point3> repairedCentre(nc);
    constexpr double facingCosine = -0.5;                     // normals more than 120 degrees apart
    const double thinLimit2 = std::pow(0.5 * smallRadius, 2); // two sample spacings
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nc, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t c = r.begin(); c != r.end(); ++c)
        {
          if (inside[c])
          {
            continue;
          }
          // Facing pairs must face each other through the solid: no surface
          // between them, and the middle of them all inside.
          Point3 sum{ 0.0, 0.0, 0.0 };
          int pairs = 0;
          bool through = true;
          for (int i = 0; through && i < 4; ++i)
          {
            for (int j = i + 1; through && j < 4; ++j)
            {
              const Index a = cellSites[c][i], b = cellSites[c][j];
              if (Dot(normal[a], normal[b]) < facingCosine)
              {
                // Parts thicker than two spacings are sampled finely enough.
                const Point3 ab = sites[b] - sites[a];
                through = Dot(ab, ab) <= thinLimit2 &&
                  !queries.Crosses(sites[a] + 1e-6 * ab, sites[b] - 1e-6 * ab);
                sum = sum + 0.5 * (sites[a] + sites[b]);
                ++pairs;
              }
            }
          }
          if (pairs == 0 || !through)
          {
            continue;
          }
          // Halfway to the cell's centroid: two cells with the same facing
          // pairs would otherwise get the same vertex.
          const Point3 centroid = 0.25 *
            (sites[cellSites[c][0]] + sites[cellSites[c][1]] + sites[cellSites[c][2]] +
              sites[cellSites[c][3]]);
          const Point3 middle = 0.5 * ((1.0 / pairs) * sum + centroid);
          const Index s0 = cellSites[c][0];
          through = queries.InsideByPseudoNormal(middle, sites[s0], siteTriangle[s0]);
          if (through)
          {
            spanning[c] = 1;
            repairedCentre[c] = middle;
          }
        }
      });
    KeepSpanningCellsThatAddNoLoopOrVoid(cellSites, cellNeighbours, sites.size(), inside, spanning);
    for (std::size_t c = 0; c < nc; ++c)
    {
      if (spanning[c])
      {
        inside[c] = 1;
        centre[c] = repairedCentre[c];
        emptyRadius[c] = -1.0; // moved off its circumcentre
        ++result.SpanningCells;
      }
    }
  }
  // 2c. A solid's medial axis encloses no void, but the Voronoi complex can,
  // around a pocket of cells whose circumcentres fell outside. One face on
  // each void's boundary is left out, which opens it and changes nothing else.
  std::vector<std::array<Index, 2>> voidFaces;
  {
    std::vector<double> radius(nc);
    for (std::size_t c = 0; c < nc; ++c)
    {
      radius[c] = Norm(centre[c] - sites[cellSites[c][0]]);
    }
    voidFaces = FacesOpeningVoids(cellSites, cellNeighbours, sites.size(), inside, radius);
    result.OpenedVoids = voidFaces.size();
  }
  if (!report(0.7))
  {
    return abort();
  }

  // 3. Weld circumcentres of adjacent inside cells that coincide; remember
  // the adjacent inside pairs, the future medial edges.
  const double diagonal = BoundingDiagonal(surface);
  const double weld2 = std::pow(options.RelativeWeldTolerance * diagonal, 2);
  DisjointSets groups(nc);
  std::vector<std::array<Index, 2>> adjacentInside;
  adjacentInside.reserve(2 * nc);
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (!inside[c])
    {
      continue;
    }
    for (Index n : cellNeighbours[c])
    {
      if (n > static_cast<Index>(c) && inside[n])
      {
        adjacentInside.push_back({ static_cast<Index>(c), n });
        if (Distance2(centre[c], centre[n]) <= weld2)
        {
          groups.Union(static_cast<Index>(c), n);
        }
      }
    }
  }
  // Medial vertex ids in cell order; Atlas = union of the group's sites.
  std::vector<Index> vertexOf(nc, -1);
  std::vector<Point3> centreSum;
  std::vector<Index> groupSize;
  std::vector<char> spanningGroup;
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (!inside[c])
    {
      continue;
    }
    ++result.InsideCells;
    const Index root = groups.Find(static_cast<Index>(c));
    if (vertexOf[root] < 0)
    {
      vertexOf[root] = static_cast<Index>(groupSize.size());
      centreSum.push_back({ 0.0, 0.0, 0.0 });
      groupSize.push_back(0);
      spanningGroup.push_back(0);
    }
    const Index v = vertexOf[root];
    vertexOf[c] = v;
    centreSum[v] = centreSum[v] + centre[c];
    ++groupSize[v];
    spanningGroup[v] = spanningGroup[v] || spanning[c];
  }
  const std::size_t nv = groupSize.size();
  result.WeldedCells = result.InsideCells - nv;
  MedialMesh& mesh = result.Mesh;
  mesh.Centers.resize(nv);
  mesh.Radii.resize(nv);
  // Each vertex's sites: the four of each of its cells, sorted and made
  // unique in place, the vertices in parallel (a list per vertex, 170,000
  // of them at 50,000 samples, was most of this step's time).
  std::vector<Index> firstCell(nv + 1, 0);
  for (std::size_t v = 0; v < nv; ++v)
  {
    firstCell[v + 1] = firstCell[v] + groupSize[v];
  }
  std::vector<Index> rows(4 * static_cast<std::size_t>(firstCell[nv]));
  {
    std::vector<Index> cursor(firstCell.begin(), firstCell.end() - 1);
    for (std::size_t c = 0; c < nc; ++c)
    {
      if (inside[c])
      {
        std::copy(
          cellSites[c].begin(), cellSites[c].end(), rows.begin() + 4 * cursor[vertexOf[c]]++);
      }
    }
  }
  std::vector<Index> atlasCount(nv);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t v = r.begin(); v != r.end(); ++v)
      {
        const auto first = rows.begin() + 4 * firstCell[v],
                   last = rows.begin() + 4 * firstCell[v + 1];
        std::sort(first, last);
        atlasCount[v] = static_cast<Index>(std::unique(first, last) - first);
      }
    });
  const std::size_t atlasBase = result.AtlasSites.size();
  const std::size_t offsetBase = result.AtlasOffsets.size();
  result.AtlasOffsets.resize(offsetBase + nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    result.AtlasOffsets[offsetBase + v] =
      (v == 0 ? static_cast<Index>(atlasBase) : result.AtlasOffsets[offsetBase + v - 1]) +
      atlasCount[v];
  }
  result.AtlasSites.resize(static_cast<std::size_t>(result.AtlasOffsets.back()));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 1024),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t v = r.begin(); v != r.end(); ++v)
      {
        const auto first = rows.begin() + 4 * firstCell[v];
        const auto last = first + atlasCount[v];
        std::copy(first, last,
          result.AtlasSites.begin() + result.AtlasOffsets[offsetBase + v] - atlasCount[v]);
        mesh.Centers[v] = (1.0 / static_cast<double>(groupSize[v])) * centreSum[v];
        double radius = 0.0;
        for (auto s = first; s != last; ++s)
        {
          radius += Norm(mesh.Centers[v] - sites[*s]);
        }
        // A spanning cell's vertex is not equidistant from its sites: its
        // ball is the largest inside the surface.
        mesh.Radii[v] = spanningGroup[v] ? queries.Distance(mesh.Centers[v])
                                         : radius / static_cast<double>(atlasCount[v]);
      }
    });
  std::vector<Index>().swap(rows);
  // No site is nearer a vertex than any of its cells' empty balls reach past
  // the distance the welding moved it from their centres.
  result.SiteClearance.assign(nv, std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < nc; ++c)
  {
    if (inside[c])
    {
      double& clearance = result.SiteClearance[vertexOf[c]];
      clearance = emptyRadius[c] < 0.0 || clearance < 0.0
        ? -1.0
        : std::min(clearance, emptyRadius[c] - Norm(mesh.Centers[vertexOf[c]] - centre[c]));
    }
  }
  std::vector<double>().swap(emptyRadius);

  // 4. Edges: Voronoi edges (duals of Delaunay facets) between inside cells.
  mesh.Edges.reserve(adjacentInside.size());
  for (const auto& [a, b] : adjacentInside)
  {
    if (vertexOf[a] != vertexOf[b])
    {
      mesh.Edges.push_back(
        { std::min(vertexOf[a], vertexOf[b]), std::max(vertexOf[a], vertexOf[b]) });
    }
  }
  decltype(adjacentInside)().swap(adjacentInside);
  tbb::parallel_sort(mesh.Edges.begin(), mesh.Edges.end());
  mesh.Edges.erase(std::unique(mesh.Edges.begin(), mesh.Edges.end()), mesh.Edges.end());
  if (!report(0.8))
  {
    return abort();
  }

  // 5. Faces: the Voronoi face dual to each Delaunay edge whose cells are all
  // finite and inside, fan-triangulated.
  const bool filtering = options.ConcaveFiltering && concaveFeature.size() == sites.size();
  // Collect the complete faces first, keyed by their site pair, so that the
  // output order does not depend on CGAL's edge order.
  struct Face
  {
    std::array<Index, 2> Sites;
    std::size_t First, Size; // in `polygons`
  };
  std::vector<Face> complete;
  std::vector<Index> polygons, polygon;
  // Each Delaunay edge is circulated once over the flat cell arrays: the
  // cells around it are marked (6 local edges per cell) as they are visited.
  std::vector<std::uint8_t> edgeDone(nc, 0);
  for (std::size_t start = 0; start < nc; ++start)
  {
    if (!inside[start])
    {
      continue;
    }
    for (int e = 0; e < 6; ++e)
    {
      if (edgeDone[start] & (1u << e))
      {
        continue;
      }
      const Index u = cellSites[start][edgeEnds[e][0]], v = cellSites[start][edgeEnds[e][1]];
      int other[2], n = 0;
      for (int k = 0; k < 4; ++k)
      {
        if (k != edgeEnds[e][0] && k != edgeEnds[e][1])
        {
          other[n++] = k;
        }
      }
      Index current = static_cast<Index>(start);
      Index exitSite = cellSites[start][other[0]];
      bool allInside = true;
      polygon.clear();
      for (;;)
      {
        edgeDone[current] |= static_cast<std::uint8_t>(
          1u << LocalEdge(LocalIndex(cellSites, current, u), LocalIndex(cellSites, current, v)));
        const Index vertex = vertexOf[current];
        if (polygon.empty() || polygon.back() != vertex)
        {
          polygon.push_back(vertex);
        }
        const int exitLocal = LocalIndex(cellSites, current, exitSite);
        const int iu = LocalIndex(cellSites, current, u), iv = LocalIndex(cellSites, current, v);
        const int keep = 6 - exitLocal - iu - iv; // the fourth local index
        const Index next = cellNeighbours[current][exitLocal];
        if (next < 0 || !inside[next])
        {
          allInside = false;
          break;
        }
        exitSite = cellSites[current][keep];
        current = next;
        if (current == static_cast<Index>(start))
        {
          break;
        }
      }
      if (!allInside)
      {
        continue;
      }
      while (polygon.size() > 1 && polygon.back() == polygon.front())
      {
        polygon.pop_back();
      }
      if (polygon.size() < 3)
      {
        continue; // collapsed by welding
      }
      CanonicalCycle(polygon); // the output order must not depend on CGAL's
      const std::array<Index, 2> key{ std::min(u, v), std::max(u, v) };
      if (std::binary_search(voidFaces.begin(), voidFaces.end(), key))
      {
        continue;
      }
      complete.push_back({ key, polygons.size(), polygon.size() });
      polygons.insert(polygons.end(), polygon.begin(), polygon.end());
    }
  }
  // The cells are done with: their arrays (34 MB at 50,000 samples) go
  // before the faces are triangulated and the topology repaired.
  decltype(cellSites)().swap(cellSites);
  decltype(cellNeighbours)().swap(cellNeighbours);
  decltype(centre)().swap(centre);
  decltype(vertexOf)().swap(vertexOf);
  decltype(edgeDone)().swap(edgeDone);
  decltype(inside)().swap(inside);
  ReleaseFreeHeapPages();
  decltype(ambiguous)().swap(ambiguous);
  // One face per Delaunay edge: unique keys, a deterministic parallel sort.
  tbb::parallel_sort(complete.begin(), complete.end(),
    [](const Face& a, const Face& b) { return a.Sites < b.Sites; });

  std::vector<char> filtered; // per triangle: its face fails the concave test
  {
    std::size_t triangles = 0;
    for (const Face& face : complete)
    {
      triangles += face.Size >= 3 ? face.Size - 2 : 0;
    }
    mesh.Faces.reserve(mesh.Faces.size() + triangles);
    result.FaceSitePair.reserve(result.FaceSitePair.size() + triangles);
    filtered.reserve(triangles);
  }
  // The concave test of each face (a distance query for faces between two
  // concave-feature sites), in parallel.
  std::vector<char> spuriousFace(complete.size(), 0);
  if (filtering)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, complete.size(), 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t f = r.begin(); f != r.end(); ++f)
        {
          const Index s1 = complete[f].Sites[0], s2 = complete[f].Sites[1];
          if (concaveFeature[s1] && concaveFeature[s2])
          {
            const Point3 middle = 0.5 * (sites[s1] + sites[s2]);
            spuriousFace[f] = queries.Distance(middle) <
                options.ConcaveFilterAlpha * 0.5 * Norm(sites[s1] - sites[s2])
              ? 1
              : 0;
          }
        }
      });
  }
  for (std::size_t f = 0; f < complete.size(); ++f)
  {
    const Face& face = complete[f];
    const bool spurious = spuriousFace[f] != 0;
    const Index* p = polygons.data() + face.First;
    for (std::size_t k = 1; k + 1 < face.Size; ++k)
    {
      const std::array<Index, 3> tri{ p[0], p[k], p[k + 1] };
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      {
        continue; // a welded vertex met twice in the cycle
      }
      mesh.Faces.push_back(tri);
      result.FaceSitePair.push_back(face.Sites);
      filtered.push_back(spurious ? 1 : 0);
    }
  }
  std::vector<Face>().swap(complete);
  std::vector<Index>().swap(polygons);
  // Welding can make two faces share a triangle: keep the first.
  {
    std::vector<std::pair<std::array<Index, 3>, std::size_t>> sorted(mesh.Faces.size());
    for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
    {
      std::array<Index, 3> key = mesh.Faces[f];
      std::sort(key.begin(), key.end());
      sorted[f] = { key, f };
    }
    tbb::parallel_sort(sorted.begin(), sorted.end());
    std::vector<char> keep(mesh.Faces.size(), 1);
    for (std::size_t i = 1; i < sorted.size(); ++i)
    {
      if (sorted[i].first == sorted[i - 1].first)
      {
        keep[sorted[i].second] = 0;
      }
    }
    std::size_t out = 0;
    for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
    {
      if (keep[f])
      {
        mesh.Faces[out] = mesh.Faces[f];
        result.FaceSitePair[out] = result.FaceSitePair[f];
        filtered[out] = filtered[f];
        ++out;
      }
    }
    mesh.Faces.resize(out);
    result.FaceSitePair.resize(out);
    filtered.resize(out);
  }

  // 6. Concave filtering by collapses only (no holes), then pockets: tiny
  // pieces cut off from the rest, spurious in a connected solid.
  result.FilteredFaces = CollapseFlaggedTriangles(result, filtered);
  result.DroppedPockets =
    DropSmallComponents(result, std::max<std::size_t>(2, result.Mesh.Centers.size() / 1000));
  ReleaseFreeHeapPages();
  // 7. What the sampling still got wrong about the solid's topology.
  if (options.RepairTopology)
  {
    // A surface point lies within CoveringRadius of a site: a vertex is at
    // least its distance to the nearest site less that from the surface.
    // Its clearance bounds that distance without a search where known.
    std::unique_ptr<KdTree> siteTree;
    std::function<double(Index)> lowerBound;
    if (options.CoveringRadius > 0.0)
    {
      siteTree = std::make_unique<KdTree>(sites);
      lowerBound = [&siteTree, &sites, &options, &result](Index v)
      {
        const double clearance = result.SiteClearance[v];
        const Point3& p = result.Mesh.Centers[v];
        return (clearance >= 0.0 ? clearance : Norm(p - sites[siteTree->Nearest(p)])) -
          options.CoveringRadius;
      };
    }
    const TopologyRepairQueries surfaceQueries{ [&queries](const Point3& p)
      { return queries.Inside(p); },
      [&queries](const Point3& p) { return queries.Distance(p); },
      [&queries](const Point3& a, const Point3& b) { return queries.Crosses(a, b); }, lowerBound };
    const TopologyRepairCounts repaired =
      RepairMedialTopology(result, ComputeSurfaceTopology(surface), surfaceQueries);
    result.EdgesAcrossSurface = repaired.EdgesAcrossSurface;
    result.JoinedPieces = repaired.JoinedPieces;
    result.CutLoops = repaired.CutLoops;
    result.FilledHoles = repaired.FilledHoles;
    result.MissingLoops = repaired.MissingLoops;
  }
  report(1.0);
  ReleaseFreeHeapPages();
  return result;
}
}
