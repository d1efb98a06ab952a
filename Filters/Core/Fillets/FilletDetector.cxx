// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fillets/FilletDetector.h"

#include "Fillets/CentreLine.h"
#include "Fillets/CentreLineGraph.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialPrimitives.h"
#include "Mesh/TriangleAdjacency.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace medialaxis
{
namespace
{
// Faces around more of the ball's circle than this wrap a tube (step 4).
constexpr double MaximumFilletArc = 1.25 * Pi;

// Compressed lists: item i owns Items[Offsets[i] .. Offsets[i + 1]).
struct Lists
{
  std::vector<Index> Offsets;
  std::vector<Index> Items;
};

// Groups (key, item) pairs by key, each pair once, items in increasing order.
Lists GroupPairs(std::size_t keys, std::vector<std::pair<Index, Index>> pairs)
{
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  Lists lists;
  lists.Offsets.assign(keys + 1, 0);
  for (const auto& pair : pairs)
  {
    ++lists.Offsets[pair.first + 1];
  }
  for (std::size_t k = 0; k < keys; ++k)
  {
    lists.Offsets[k + 1] += lists.Offsets[k];
  }
  lists.Items.reserve(pairs.size());
  for (const auto& pair : pairs)
  {
    lists.Items.push_back(pair.second);
  }
  return lists;
}

// The surface triangles each site's restricted cell touches, each once.
Lists TrianglesOfSites(std::size_t sites, const std::vector<Index>& polygonSite,
  const std::vector<Index>& polygonTriangle)
{
  std::vector<std::pair<Index, Index>> pairs(polygonSite.size());
  for (std::size_t p = 0; p < pairs.size(); ++p)
  {
    pairs[p] = { polygonSite[p], polygonTriangle[p] };
  }
  return GroupPairs(sites, std::move(pairs));
}

// The triangles around each surface vertex.
Lists TrianglesOfVertices(const TriangleMesh& surface)
{
  std::vector<std::pair<Index, Index>> pairs;
  pairs.reserve(3 * surface.Triangles.size());
  for (std::size_t t = 0; t < surface.Triangles.size(); ++t)
  {
    for (Index v : surface.Triangles[t])
    {
      pairs.emplace_back(v, static_cast<Index>(t));
    }
  }
  return GroupPairs(surface.Points.size(), std::move(pairs));
}

// The surface triangles the Atlases of medial vertices [first, last) touch,
// each once, in increasing order, into `triangles`.
void AtlasTriangles(const Index* first, const Index* last, const std::vector<Index>& atlasOffsets,
  const std::vector<Index>& atlasSites, const Lists& siteTriangles, std::vector<Index>& triangles)
{
  triangles.clear();
  for (const Index* v = first; v != last; ++v)
  {
    for (Index k = atlasOffsets[*v]; k < atlasOffsets[*v + 1]; ++k)
    {
      const Index site = atlasSites[k];
      triangles.insert(triangles.end(), siteTriangles.Items.begin() + siteTriangles.Offsets[site],
        siteTriangles.Items.begin() + siteTriangles.Offsets[site + 1]);
    }
  }
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
}

struct SurfaceTriangle
{
  Point3 Centroid;
  Point3 Normal;
  double Area;
};

// The corners of the given triangles, each once.
std::vector<Point3> CornerPoints(const TriangleMesh& surface, const std::vector<Index>& triangles)
{
  std::vector<Index> ids;
  for (Index t : triangles)
  {
    ids.insert(ids.end(), surface.Triangles[t].begin(), surface.Triangles[t].end());
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<Point3> corners;
  corners.reserve(ids.size());
  for (Index v : ids)
  {
    corners.push_back(surface.Points[v]);
  }
  return corners;
}

// A fillet's faces end where its ball leaves the surface. At a surface
// vertex on them the envelope's normal lies between the normals of the
// triangles around the vertex, across the arc; at a vertex past a tangent
// line, on the face beyond (which stays near the envelope for a while), all
// of them are turned one way from it, towards the fillet, by about the
// angle the vertex lies past the line. `tolerance` is the sine of the angle
// the envelope's normal may be off.
bool WithinArc(const CentreLineEnvelope::Match& match, Index vertex, const Lists& vertexTriangles,
  const std::vector<SurfaceTriangle>& triangles, double tolerance)
{
  const Point3 across = Cross(match.LineDirection, match.Normal);
  const double length = Norm(across);
  if (!(length > 0.0))
  {
    return true; // on a ball, no one direction across
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Index k = vertexTriangles.Offsets[vertex]; k < vertexTriangles.Offsets[vertex + 1]; ++k)
  {
    const double s = Dot(triangles[vertexTriangles.Items[k]].Normal, across) / length;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return lo <= tolerance && hi >= -tolerance;
}

// Where a triangle is tested against a medial edge: corners, edge midpoints
// and centroid, so that edges shorter than the triangles still see some.
constexpr int PointsPerTriangle = 7;
void TrianglePoints(const TriangleMesh& surface, Index t, Point3 (&points)[PointsPerTriangle])
{
  const Triangle& tri = surface.Triangles[t];
  const Point3 &a = surface.Points[tri[0]], &b = surface.Points[tri[1]],
               &c = surface.Points[tri[2]];
  points[0] = a;
  points[1] = b;
  points[2] = c;
  points[3] = 0.5 * (a + b);
  points[4] = 0.5 * (b + c);
  points[5] = 0.5 * (c + a);
  points[6] = (1.0 / 3.0) * (a + b + c);
}

enum class EdgeVerdict : std::uint8_t
{
  Rejected = 0,
  Accepted = 1,
  Undecided = 2, // too short for any surface point to fall within its span
};

// Whether medial edge (a, b) is a fillet centre-line edge: most of the
// surface within its span, among the triangles of both spheres' Atlas, lies
// on its envelope.
EdgeVerdict JudgeEdge(Index a, Index b, const MedialMesh& medial,
  const std::vector<Index>& atlasOffsets, const std::vector<Index>& atlasSites,
  const Lists& siteTriangles, const TriangleMesh& surface,
  const std::vector<SurfaceTriangle>& triangles, double minimumRadius, double cosNormal,
  const FilletDetectorOptions& options, std::vector<Index>& scratch)
{
  const double ra = medial.Radii[a], rb = medial.Radii[b];
  if (std::min(ra, rb) < minimumRadius)
  {
    return EdgeVerdict::Rejected;
  }
  const ConePrimitive cone = MakeCone(medial.Centers[a], ra, medial.Centers[b], rb);
  if (cone.Nested || !(cone.Length > 0.0))
  {
    return EdgeVerdict::Rejected;
  }
  const Index ends[2] = { a, b };
  AtlasTriangles(ends, ends + 2, atlasOffsets, atlasSites, siteTriangles, scratch);
  double inSpan = 0.0, matching = 0.0;
  std::vector<double> around; // angles of the matching normals around the axis
  Point3 points[PointsPerTriangle];
  for (Index t : scratch)
  {
    const SurfaceTriangle& tri = triangles[t];
    TrianglePoints(surface, t, points);
    for (const Point3& p : points)
    {
      const double u = Dot(p - cone.C[0], cone.Axis) / cone.Length;
      if (u < 0.0 || u > 1.0)
      {
        continue;
      }
      inSpan += tri.Area;
      const PrimitiveDistance d = ConeDistance(cone, p);
      const double radius = (1.0 - u) * ra + u * rb;
      if (std::abs(d.Distance) <= options.RadiusTolerance * radius &&
        Dot(d.Normal, tri.Normal) >= cosNormal)
      {
        matching += tri.Area;
        around.push_back(std::atan2(Dot(tri.Normal, cone.Perp2), Dot(tri.Normal, cone.Perp1)));
      }
    }
  }
  if (inSpan == 0.0)
  {
    return EdgeVerdict::Undecided;
  }
  if (matching < options.MinimumConsistentFraction * inSpan)
  {
    return EdgeVerdict::Rejected;
  }
  // A rolling ball touches an arc of the surface; a ball on an ordinary
  // sheet boundary touches a flat face along the edge: one normal direction.
  // A ball touching two faces that meet at a sharp edge has two directions:
  // the surface does not follow it between them, and most of its arc is one
  // gap. A fillet's faces cover their arc throughout.
  std::sort(around.begin(), around.end());
  double largestGap = 2.0 * Pi - (around.back() - around.front()), secondGap = 0.0;
  for (std::size_t i = 1; i < around.size(); ++i)
  {
    const double gap = around[i] - around[i - 1];
    secondGap = std::max(secondGap, std::min(gap, largestGap));
    largestGap = std::max(largestGap, gap);
  }
  const double arc = 2.0 * Pi - largestGap;
  return arc >= options.MinimumArcAngle && secondGap <= 0.5 * arc ? EdgeVerdict::Accepted
                                                                  : EdgeVerdict::Rejected;
}

void CheckInput(const TriangleMesh& surface, const MedialMesh& medial,
  const std::vector<Index>& atlasOffsets, const std::vector<Index>& atlasSites,
  const std::vector<Index>& polygonSite, const std::vector<Index>& polygonTriangle,
  std::size_t& sites)
{
  if (atlasOffsets.size() != medial.NumberOfVertices() + 1 || atlasOffsets.front() != 0 ||
    atlasOffsets.back() != static_cast<Index>(atlasSites.size()))
  {
    throw std::invalid_argument("the Atlas offsets do not match the medial mesh's " +
      std::to_string(medial.NumberOfVertices()) + " vertices");
  }
  if (polygonSite.size() != polygonTriangle.size())
  {
    throw std::invalid_argument("the restricted Voronoi diagram needs one site and one triangle "
                                "per polygon");
  }
  sites = 0;
  for (std::size_t p = 0; p < polygonSite.size(); ++p)
  {
    if (polygonSite[p] < 0 || polygonTriangle[p] < 0 ||
      polygonTriangle[p] >= static_cast<Index>(surface.Triangles.size()))
    {
      throw std::invalid_argument("restricted Voronoi polygon " + std::to_string(p) +
        " refers to triangle " + std::to_string(polygonTriangle[p]) + ", but the surface has " +
        std::to_string(surface.Triangles.size()) +
        " triangles: the diagram was computed on another surface");
    }
    sites = std::max(sites, static_cast<std::size_t>(polygonSite[p]) + 1);
  }
  for (Index s : atlasSites)
  {
    if (s < 0 || static_cast<std::size_t>(s) >= sites)
    {
      throw std::invalid_argument("Atlas site " + std::to_string(s) +
        " has no polygon in the restricted Voronoi diagram (" + std::to_string(sites) + " sites)");
    }
  }
}
}

FilletDetectionResult DetectFillets(const TriangleMesh& surface, const MedialMesh& medial,
  const std::vector<Index>& atlasOffsets, const std::vector<Index>& atlasSites,
  const std::vector<Index>& polygonSite, const std::vector<Index>& polygonTriangle,
  const FilletDetectorOptions& options)
{
  std::size_t sites = 0;
  CheckInput(surface, medial, atlasOffsets, atlasSites, polygonSite, polygonTriangle, sites);
  FilletDetectionResult result;
  result.TriangleFillet.assign(surface.Triangles.size(), -1);
  if (surface.Points.empty() || medial.NumberOfVertices() == 0)
  {
    return result;
  }
  const auto [lo, hi] = BoundingBox(surface.Points);
  result.Diagonal = Norm(hi - lo);
  const double cosNormal = std::cos(options.NormalTolerance);

  std::vector<SurfaceTriangle> triangles(surface.Triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = surface.Triangles[t];
    const Point3 &a = surface.Points[tri[0]], &b = surface.Points[tri[1]],
                 &c = surface.Points[tri[2]];
    const Point3 n = Cross(b - a, c - a);
    triangles[t] = { (1.0 / 3.0) * (a + b + c), Normalized(n), 0.5 * Norm(n) };
  }
  const Lists siteTriangles = TrianglesOfSites(sites, polygonSite, polygonTriangle);

  // 1. Centre-line edges among the medial boundary edges.
  const std::vector<std::array<Index, 2>> boundary = SheetBoundaryEdges(medial);
  result.BoundaryEdges = boundary.size();
  std::vector<EdgeVerdict> verdict(boundary.size(), EdgeVerdict::Rejected);
  const double minimumRadius = options.MinimumRadius * result.Diagonal;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, boundary.size(), 64),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      std::vector<Index> scratch;
      for (std::size_t e = range.begin(); e != range.end(); ++e)
      {
        verdict[e] = JudgeEdge(boundary[e][0], boundary[e][1], medial, atlasOffsets, atlasSites,
          siteTriangles, surface, triangles, minimumRadius, cosNormal, options, scratch);
      }
    });
  // Gaps of one edge in a centre line: an edge too short to judge, or a
  // rejected one between two ends of accepted edges, joins them.
  std::vector<int> acceptedDegree(medial.NumberOfVertices(), 0);
  for (std::size_t e = 0; e < boundary.size(); ++e)
  {
    if (verdict[e] == EdgeVerdict::Accepted)
    {
      ++acceptedDegree[boundary[e][0]];
      ++acceptedDegree[boundary[e][1]];
    }
  }
  std::vector<std::array<Index, 2>> centreLineEdges;
  for (std::size_t e = 0; e < boundary.size(); ++e)
  {
    const int da = acceptedDegree[boundary[e][0]], db = acceptedDegree[boundary[e][1]];
    const bool radiusOk =
      std::min(medial.Radii[boundary[e][0]], medial.Radii[boundary[e][1]]) >= minimumRadius;
    const bool bridge = radiusOk &&
      ((verdict[e] == EdgeVerdict::Undecided && da > 0 && db > 0) ||
        (verdict[e] == EdgeVerdict::Rejected && da == 1 && db == 1));
    if (verdict[e] == EdgeVerdict::Accepted || bridge)
    {
      centreLineEdges.push_back(boundary[e]);
    }
  }
  result.CentreLineEdges = centreLineEdges.size();

  // 2. Polylines, without the short ones.
  CentreLineGraphOptions graphOptions;
  graphOptions.SplitAngle = options.SplitAngle;
  for (const CentreLine& line :
    TraceCentreLines(centreLineEdges, medial.Centers, medial.Radii, graphOptions))
  {
    Fillet chain;
    chain.Vertices = line.Vertices;
    chain.Closed = line.Closed;
    for (Index v : chain.Vertices)
    {
      chain.Centres.push_back(medial.Centers[v]);
      chain.Radii.push_back(medial.Radii[v]);
    }
    MeasureFillet(chain);
    if (chain.Length >= options.MinimumLength * result.Diagonal)
    {
      result.Fillets.push_back(std::move(chain));
    }
  }

  // 3. Fillet faces, grown over the surface from the Atlas triangles of each
  // centre line through neighbouring triangles on its envelope: first
  // loosely, to refine the line by circle fits to the faces found, then
  // tightly along the refined line. A triangle claimed by an earlier fillet
  // (where fillets meet at a corner ball) keeps that fillet.
  const TriangleAdjacency adjacency = ComputeTriangleAdjacency(surface, 0.0);
  std::vector<int> stamp(surface.Triangles.size(), -1);
  int stamps = 0;
  auto grow = [&](const std::vector<Index>& seeds, const std::function<bool(Index)>& accept)
  {
    const int mark = stamps++;
    std::vector<Index> region;
    std::deque<Index> front;
    auto visit = [&](Index t)
    {
      if (stamp[t] == mark || result.TriangleFillet[t] >= 0)
      {
        return;
      }
      stamp[t] = mark;
      if (accept(t))
      {
        region.push_back(t);
        front.push_back(t);
      }
    };
    for (Index t : seeds)
    {
      visit(t);
    }
    while (!front.empty())
    {
      const Index t = front.front();
      front.pop_front();
      for (Index neighbour : adjacency.Neighbour[t])
      {
        if (neighbour >= 0)
        {
          visit(neighbour);
        }
      }
    }
    return region;
  };
  // A triangle is on a fillet's faces when its centroid and corners lie on
  // the envelope, the corners within its arc (the angle they may be off it
  // twice the envelope's tolerance there: a centre off by that much turns
  // the normals by about as much).
  const Lists vertexTriangles = TrianglesOfVertices(surface);
  auto onFaces = [&](const CentreLineEnvelope& envelope, Index t, double centroidTolerance,
                   double cornerTolerance)
  {
    const Point3& n = triangles[t].Normal;
    if (!envelope.Matches(triangles[t].Centroid, n, centroidTolerance))
    {
      return false;
    }
    for (Index v : surface.Triangles[t])
    {
      const auto match = envelope.Find(surface.Points[v], n, cornerTolerance);
      if (!match || !WithinArc(*match, v, vertexTriangles, triangles, 2.0 * match->Tolerance))
      {
        return false;
      }
    }
    return true;
  };
  const double reach = std::max(options.RadiusTolerance, options.FaceTolerance);
  std::vector<double> areaAlongLine(result.Fillets.size(), 0.0);
  for (std::size_t f = 0; f < result.Fillets.size(); ++f)
  {
    Fillet& fillet = result.Fillets[f];
    std::vector<Index> seeds;
    AtlasTriangles(fillet.Vertices.data(), fillet.Vertices.data() + fillet.Vertices.size(),
      atlasOffsets, atlasSites, siteTriangles, seeds);

    const CentreLineEnvelope loose(
      fillet.Centres, fillet.Radii, fillet.Closed, reach, cosNormal, options.RadiusTolerance);
    const std::vector<Index> found = grow(seeds,
      [&](Index t) { return onFaces(loose, t, options.RadiusTolerance, options.RadiusTolerance); });
    const std::vector<Point3> corners = CornerPoints(surface, found);
    RefineCentreLine(fillet, corners, 0.25 * options.FaceTolerance, false);
    RefineCentreLine(fillet, corners, 0.25 * options.FaceTolerance, true);
    TrimFoldedEnds(fillet);
    MeasureFillet(fillet);

    const CentreLineEnvelope tight(
      fillet.Centres, fillet.Radii, fillet.Closed, reach, cosNormal, options.RadiusTolerance);
    seeds.insert(seeds.end(), found.begin(), found.end());
    const std::vector<Index> faces = grow(seeds,
      [&](Index t) { return onFaces(tight, t, options.RadiusTolerance, options.FaceTolerance); });
    fillet.ArcAngle = FacesArc(fillet, CornerPoints(surface, faces));
    for (Index t : faces)
    {
      result.TriangleFillet[t] = static_cast<int>(f);
      ++fillet.SurfaceTriangles;
      fillet.SurfaceArea += triangles[t].Area;
      if (fillet.Closed || !PastAnEnd(fillet.Centres, triangles[t].Centroid))
      {
        areaAlongLine[f] += triangles[t].Area;
      }
    }
  }
  // 4. A rolling ball leaves faces about as wide as its arc along the whole
  // line; a line with much less (a sheet boundary near some curved face) is
  // no fillet. Only the faces along the line count: a short line must not
  // pass on the faces found past its ends alone. And a ball between two
  // faces touches at most half its circle (the full-round end of a rib):
  // faces around more than five eighths of it wrap a tube (a cup's handle,
  // a pipe), whose centre line is a curve skeleton, not a fillet's.
  std::vector<int> renumber(result.Fillets.size(), -1);
  std::vector<Fillet> kept;
  for (std::size_t f = 0; f < result.Fillets.size(); ++f)
  {
    const Fillet& fillet = result.Fillets[f];
    const double expected = fillet.Length * fillet.MeanRadius * options.MinimumArcAngle;
    if (fillet.MinimumRadius > 0.0 && areaAlongLine[f] >= 0.5 * expected &&
      fillet.ArcAngle <= MaximumFilletArc)
    {
      renumber[f] = static_cast<int>(kept.size());
      kept.push_back(fillet);
    }
  }
  for (int& f : result.TriangleFillet)
  {
    f = f >= 0 ? renumber[f] : -1;
  }
  result.Fillets.swap(kept);
  return result;
}
}
