// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/RestrictedVoronoi.h"

#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Support/DisjointSets.h"
#include "Support/HeapRelease.h"
#include "Surface/FeatureNormals.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace medialaxis
{
namespace
{
// Nearest neighbours cached per site; sites whose cell needs more are
// extended on the fly (thread-locally).
constexpr std::size_t CachedNeighbours = 20;
// Triangles are processed in fixed blocks so that the output order never
// depends on how threads share the work.
constexpr std::size_t BlockSize = 128;

// A polygon vertex and the label of the edge that starts at it: a site id
// (>= 0) for a bisector edge, or -(k + 1) for part of triangle edge k.
struct LabelledVertex
{
  Point3 P;
  Index Label;
};
using Polygon = std::vector<LabelledVertex>;

// Keeps the part of `poly` closer to site i than to site j (Sutherland-Hodgman);
// false when all of it is.
bool ClipByBisector(const Point3& si, const Point3& sj, Index j, Polygon& poly, Polygon& scratch)
{
  const Point3 normal = sj - si;
  const Point3 middle = 0.5 * (si + sj);
  const std::size_t n = poly.size();
  double f[64];
  std::vector<double> fLarge;
  double* side = f;
  if (n > 64)
  {
    fLarge.resize(n);
    side = fLarge.data();
  }
  bool anyOut = false, anyIn = false;
  for (std::size_t k = 0; k < n; ++k)
  {
    side[k] = Dot(poly[k].P - middle, normal);
    (side[k] > 0.0 ? anyOut : anyIn) = true;
  }
  if (!anyOut)
  {
    return false;
  }
  if (!anyIn)
  {
    poly.clear();
    return true;
  }
  scratch.clear();
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t k1 = (k + 1) % n;
    const bool inA = side[k] <= 0.0, inB = side[k1] <= 0.0;
    if (inA)
    {
      scratch.push_back(poly[k]);
    }
    if (inA != inB)
    {
      const double t = side[k] / (side[k] - side[k1]);
      const Point3 p = poly[k].P + t * (poly[k1].P - poly[k].P);
      // Leaving the cell: the edge from p runs along the bisector with j.
      scratch.push_back({ p, inA ? j : poly[k].Label });
    }
  }
  poly.swap(scratch);
  return true;
}

double PolygonArea2(const Polygon& poly, Point3* weightedCentroid)
{
  // Twice the area, by a fan from vertex 0; also the area-weighted centroid sum.
  double twiceArea = 0.0;
  Point3 sum{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
  {
    const double a = Norm(Cross(poly[k].P - poly[0].P, poly[k + 1].P - poly[0].P));
    twiceArea += a;
    sum = sum + (a / 3.0) * (poly[0].P + poly[k].P + poly[k + 1].P);
  }
  if (weightedCentroid)
  {
    *weightedCentroid = sum;
  }
  return twiceArea;
}

struct BlockOutput
{
  std::vector<Point3> Vertices;
  std::vector<Index> Sizes;
  std::vector<Index> Sites;
  std::vector<Index> Triangles;
  std::vector<std::uint8_t> EdgeMask; // bit k: touches triangle edge k along a segment
  std::vector<double> TwiceArea;
  std::vector<Point3> WeightedCentroid; // sum of (twice-area x centroid)
  std::vector<double> Reach;            // farthest vertex from the site

  void Clear()
  {
    this->Vertices.clear();
    this->Sizes.clear();
    this->Sites.clear();
    this->Triangles.clear();
    this->EdgeMask.clear();
    this->TwiceArea.clear();
    this->WeightedCentroid.clear();
    this->Reach.clear();
  }
};

struct ThreadState
{
  std::vector<int> Stamp; // Stamp[site] == triangle + 1: already queued for that triangle
  std::vector<Index> Queue;
  Polygon Poly, Scratch;
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2;
  // A block is clipped here, then copied out at its exact size: grown by
  // doubling in place, the blocks held twice the room they needed (135 MB
  // for 98 MB of polygons on a 268,686-triangle mesh at 50,000 samples).
  BlockOutput Block;
};

class RvdBuilder
{
public:
  RvdBuilder(const TriangleMesh& surface, const std::vector<Point3>& sites)
    : Surface(surface)
    , Sites(sites)
    , Tree(sites)
  {
  }

  void CacheNeighbours()
  {
    const std::size_t ns = this->Sites.size();
    const std::size_t k = std::min(CachedNeighbours + 1, ns);
    this->NeighbourCount = k;
    this->NeighbourIds.resize(ns * k);
    this->NeighbourD2.resize(ns * k);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ns, 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        std::vector<std::uint32_t> ids;
        std::vector<double> d2;
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          this->Tree.Nearest(this->Sites[i], k, ids, d2);
          std::copy(ids.begin(), ids.end(), this->NeighbourIds.begin() + i * k);
          std::copy(d2.begin(), d2.end(), this->NeighbourD2.begin() + i * k);
        }
      });
  }

  // Clips state.Poly (the triangle) to the Voronoi cell of site i.
  void ClipToCell(Index i, ThreadState& state) const
  {
    const Point3& si = this->Sites[i];
    const std::size_t ns = this->Sites.size();
    const std::uint32_t* ids = &this->NeighbourIds[i * this->NeighbourCount];
    const double* d2 = &this->NeighbourD2[i * this->NeighbourCount];
    std::size_t count = this->NeighbourCount;
    std::size_t position = 0;
    bool extended = false;
    double radius2 = -1.0; // of the polygon as it is; < 0: to be measured
    while (!state.Poly.empty())
    {
      if (position == count)
      {
        if (count >= ns)
        {
          return; // every other site has been used
        }
        // Rare: a cell larger than the cached neighbourhood.
        const std::size_t more = std::min(ns, (extended ? count : this->NeighbourCount) * 2);
        this->Tree.Nearest(si, more, state.Ids, state.D2);
        ids = state.Ids.data();
        d2 = state.D2.data();
        count = state.Ids.size();
        extended = true;
      }
      const Index j = ids[position];
      const double dj2 = d2[position];
      ++position;
      if (j == i)
      {
        continue;
      }
      if (radius2 < 0.0)
      {
        radius2 = 0.0;
        for (const auto& v : state.Poly)
        {
          radius2 = std::max(radius2, Distance2(v.P, si));
        }
      }
      if (dj2 > 4.0 * radius2)
      {
        return; // security radius: no farther site can cut the polygon
      }
      if (dj2 == 0.0)
      {
        // Coincident sites: the lower id owns the region.
        if (j < i)
        {
          state.Poly.clear();
        }
        continue;
      }
      if (ClipByBisector(si, this->Sites[j], j, state.Poly, state.Scratch))
      {
        radius2 = -1.0;
      }
    }
  }

  void ProcessTriangle(Index t, ThreadState& state, BlockOutput& out) const
  {
    const Triangle& tri = this->Surface.Triangles[t];
    const Point3 a = this->Surface.Points[tri[0]], b = this->Surface.Points[tri[1]],
                 c = this->Surface.Points[tri[2]];
    const double triangleTwiceArea = Norm(Cross(b - a, c - a));
    const Index seed = this->Tree.Nearest((1.0 / 3.0) * (a + b + c));
    state.Queue.clear();
    state.Queue.push_back(seed);
    state.Stamp[seed] = static_cast<int>(t) + 1;
    for (std::size_t head = 0; head < state.Queue.size(); ++head)
    {
      const Index i = state.Queue[head];
      state.Poly.assign({ { a, -1 }, { b, -2 }, { c, -3 } });
      this->ClipToCell(i, state);
      if (state.Poly.size() < 3)
      {
        continue;
      }
      std::uint8_t mask = 0;
      const std::size_t n = state.Poly.size();
      for (std::size_t k = 0; k < n; ++k)
      {
        const Index label = state.Poly[k].Label;
        if (label >= 0)
        {
          if (state.Stamp[label] != static_cast<int>(t) + 1)
          {
            state.Stamp[label] = static_cast<int>(t) + 1;
            state.Queue.push_back(label);
          }
        }
        else if (Distance2(state.Poly[k].P, state.Poly[(k + 1) % n].P) > 0.0)
        {
          mask |= static_cast<std::uint8_t>(1u << (-label - 1));
        }
      }
      Point3 weighted;
      const double twiceArea = PolygonArea2(state.Poly, &weighted);
      if (!(twiceArea > 1e-14 * triangleTwiceArea))
      {
        continue; // a sliver from round-off at a cell corner
      }
      double reach2 = 0.0;
      for (const auto& v : state.Poly)
      {
        out.Vertices.push_back(v.P);
        reach2 = std::max(reach2, Distance2(v.P, this->Sites[i]));
      }
      // The root of the largest square is the largest root (a correctly
      // rounded root is monotone): the same value as the largest distance.
      out.Reach.push_back(std::sqrt(reach2));
      out.Sizes.push_back(static_cast<Index>(n));
      out.Sites.push_back(i);
      out.Triangles.push_back(t);
      out.EdgeMask.push_back(mask);
      out.TwiceArea.push_back(twiceArea);
      out.WeightedCentroid.push_back(weighted);
    }
  }

  const TriangleMesh& Surface;
  const std::vector<Point3>& Sites;
  KdTree Tree;
  std::size_t NeighbourCount = 0;
  std::vector<std::uint32_t> NeighbourIds;
  std::vector<double> NeighbourD2;
};

}

RestrictedVoronoiDiagram ComputeRestrictedVoronoi(const TriangleMesh& surface,
  const std::vector<Point3>& sites, const RestrictedVoronoiOptions& options)
{
  RestrictedVoronoiDiagram rvd;
  const std::size_t ns = sites.size();
  const std::size_t nt = surface.Triangles.size();
  if (ns == 0 || nt == 0)
  {
    return rvd;
  }
  auto report = [&options](double fraction)
  { return !options.Progress || options.Progress(fraction); };

  RvdBuilder builder(surface, sites);
  builder.CacheNeighbours();
  if (!report(0.1))
  {
    rvd.Aborted = true;
    return rvd;
  }

  const std::size_t blocks = (nt + BlockSize - 1) / BlockSize;
  std::vector<BlockOutput> outputs(blocks);
  tbb::enumerable_thread_specific<ThreadState> states(
    [ns]
    {
      ThreadState s;
      s.Stamp.assign(ns, 0);
      return s;
    });
  // Each batch is appended in block (= triangle) order as soon as it is
  // done, and its blocks freed: the workers then hold one batch at a time,
  // not every block beside the result (with a heap per thread, that was
  // 145 MB more on a 268,686-triangle surface at 50,000 samples).
  rvd.CellArea.assign(ns, 0.0);
  rvd.CellRadius.assign(ns, 0.0);
  std::vector<Point3> weighted(ns, Point3{ 0.0, 0.0, 0.0 });
  std::vector<std::uint8_t> edgeMask;
  auto append = [&](BlockOutput& o)
  {
    rvd.Vertices.insert(rvd.Vertices.end(), o.Vertices.begin(), o.Vertices.end());
    for (std::size_t p = 0; p < o.Sites.size(); ++p)
    {
      rvd.Offsets.push_back(rvd.Offsets.back() + o.Sizes[p]);
      rvd.PolygonSite.push_back(o.Sites[p]);
      rvd.PolygonTriangle.push_back(o.Triangles[p]);
      edgeMask.push_back(o.EdgeMask[p]);
      rvd.CellArea[o.Sites[p]] += 0.5 * o.TwiceArea[p];
      double& reach = rvd.CellRadius[o.Sites[p]];
      reach = std::max(reach, o.Reach[p]);
      weighted[o.Sites[p]] = weighted[o.Sites[p]] + o.WeightedCentroid[p];
    }
    o = BlockOutput();
  };
  // Batches between which progress is reported and abort is honoured.
  const std::size_t batches = std::min<std::size_t>(20, blocks);
  for (std::size_t batch = 0; batch < batches; ++batch)
  {
    const std::size_t first = blocks * batch / batches, last = blocks * (batch + 1) / batches;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 1),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        ThreadState& state = states.local();
        for (std::size_t block = r.begin(); block != r.end(); ++block)
        {
          const std::size_t t1 = std::min(nt, (block + 1) * BlockSize);
          state.Block.Clear();
          for (std::size_t t = block * BlockSize; t < t1; ++t)
          {
            builder.ProcessTriangle(static_cast<Index>(t), state, state.Block);
          }
          outputs[block] = state.Block; // copies allocate the exact size
        }
      });
    if (batch == 0)
    {
      // Room for all, extrapolated from the first batch with 5% to spare
      // (more grows the arrays as usual).
      std::size_t np = 0, nvert = 0;
      for (std::size_t b = first; b < last; ++b)
      {
        np += outputs[b].Sites.size();
        nvert += outputs[b].Vertices.size();
      }
      const double scale = 1.05 * static_cast<double>(blocks) / static_cast<double>(last);
      np = static_cast<std::size_t>(scale * static_cast<double>(np)) + 16;
      nvert = static_cast<std::size_t>(scale * static_cast<double>(nvert)) + 64;
      rvd.Vertices.reserve(nvert);
      rvd.Offsets.reserve(np + 1);
      rvd.PolygonSite.reserve(np);
      rvd.PolygonTriangle.reserve(np);
      edgeMask.reserve(np);
    }
    for (std::size_t b = first; b < last; ++b)
    {
      append(outputs[b]);
    }
    if (!report(0.1 + 0.8 * (batch + 1) / batches))
    {
      rvd = RestrictedVoronoiDiagram();
      rvd.Aborted = true;
      return rvd;
    }
  }
  std::vector<BlockOutput>().swap(outputs);
  // An estimate far above the count (triangles much larger in the first
  // batch than elsewhere) would otherwise stay reserved to the end.
  auto fit = [](auto& array)
  {
    if (array.capacity() > array.size() + array.size() / 10)
    {
      array.shrink_to_fit();
    }
  };
  fit(rvd.Vertices);
  fit(rvd.Offsets);
  fit(rvd.PolygonSite);
  fit(rvd.PolygonTriangle);
  const std::size_t np = rvd.PolygonSite.size();
  rvd.CellCentroid.resize(ns);
  for (std::size_t i = 0; i < ns; ++i)
  {
    rvd.CellCentroid[i] = rvd.CellArea[i] > 0.0 ? (0.5 / rvd.CellArea[i]) * weighted[i] : sites[i];
  }

  // Feature flags and connected pieces of every cell.
  const TriangleAdjacency adjacency =
    FeatureAdjacency(surface, options.FeatureAngle, options.FeatureNormalFiltering);
  std::vector<Index> firstPolygon(nt + 1, 0);
  for (Index t : rvd.PolygonTriangle)
  {
    ++firstPolygon[t + 1];
  }
  std::partial_sum(firstPolygon.begin(), firstPolygon.end(), firstPolygon.begin());
  rvd.ConvexFeature.assign(ns, 0);
  rvd.ConcaveFeature.assign(ns, 0);
  DisjointSets pieces(np);
  for (std::size_t p = 0; p < np; ++p)
  {
    const Index t = rvd.PolygonTriangle[p], site = rvd.PolygonSite[p];
    for (int k = 0; k < 3; ++k)
    {
      if (!(edgeMask[p] & (1u << k)))
      {
        continue;
      }
      const EdgeFeature feature = adjacency.Feature[t][k];
      if (feature == EdgeFeature::Convex)
      {
        rvd.ConvexFeature[site] = 1;
      }
      else if (feature == EdgeFeature::Concave)
      {
        rvd.ConcaveFeature[site] = 1;
      }
      const Index across = adjacency.Neighbour[t][k];
      if (across < 0)
      {
        continue;
      }
      for (Index q = firstPolygon[across]; q < firstPolygon[across + 1]; ++q)
      {
        if (rvd.PolygonSite[q] == site)
        {
          pieces.Union(static_cast<Index>(p), q);
        }
      }
    }
  }
  rvd.CellComponents.assign(ns, 0);
  for (std::size_t p = 0; p < np; ++p)
  {
    if (pieces.Find(static_cast<Index>(p)) == static_cast<Index>(p))
    {
      ++rvd.CellComponents[rvd.PolygonSite[p]];
    }
  }
  report(1.0);
  ReleaseFreeHeapPages();
  return rvd;
}
}
