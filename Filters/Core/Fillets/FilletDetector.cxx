// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fillets/FilletDetector.h"

#include "Fillets/CentreLineGraph.h"
#include "Fillets/CircleFit.h"
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
constexpr double Pi = 3.14159265358979323846;

// Compressed lists: item i owns Items[Offsets[i] .. Offsets[i + 1]).
struct Lists
{
  std::vector<Index> Offsets;
  std::vector<Index> Items;
};

// The surface triangles each site's restricted cell touches, each once.
Lists TrianglesOfSites(std::size_t sites, const std::vector<Index>& polygonSite,
  const std::vector<Index>& polygonTriangle)
{
  std::vector<std::pair<Index, Index>> pairs(polygonSite.size());
  for (std::size_t p = 0; p < pairs.size(); ++p)
  {
    pairs[p] = { polygonSite[p], polygonTriangle[p] };
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  Lists lists;
  lists.Offsets.assign(sites + 1, 0);
  for (const auto& pair : pairs)
  {
    ++lists.Offsets[pair.first + 1];
  }
  for (std::size_t s = 0; s < sites; ++s)
  {
    lists.Offsets[s + 1] += lists.Offsets[s];
  }
  lists.Items.reserve(pairs.size());
  for (const auto& pair : pairs)
  {
    lists.Items.push_back(pair.second);
  }
  return lists;
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

// One piece of a centre line's envelope, with the radius that scales the
// tolerance of points near it.
struct EnvelopePiece
{
  ConePrimitive Cone;     // a ball when both ends coincide
  Point3 Lo, Hi;          // bounding box, grown by the tolerance
  bool Extension = false; // extrapolated past an end of the line
};

// Where an open centre line ends and heads: its centres and radii near one
// end fitted by least squares against arc length, over about three radii
// (at least three vertices), because the last medial edges zig-zag and the
// circle fits at the very end see less of the fillet.
struct LineEnd
{
  bool Valid = false;
  Point3 Centre;    // the fitted line at the end
  double Radius;    // the fitted radius there
  Point3 Direction; // unit, outwards
  double Slope;     // change of radius per length outwards, within +-0.45
};

LineEnd FitLineEnd(const std::vector<Point3>& centres, const std::vector<double>& radii, bool back)
{
  const std::size_t n = centres.size();
  auto vertex = [&](std::size_t k) { return back ? n - 1 - k : k; };
  const double endRadius = radii[vertex(0)];
  std::vector<double> arc{ 0.0 };
  while (arc.size() < n && (arc.size() < 3 || arc.back() <= 3.0 * endRadius))
  {
    const std::size_t k = arc.size();
    arc.push_back(arc.back() + Norm(centres[vertex(k)] - centres[vertex(k - 1)]));
  }
  const double count = static_cast<double>(arc.size());
  double sMean = 0.0, rMean = 0.0;
  Point3 cMean{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 0; k < arc.size(); ++k)
  {
    sMean += arc[k] / count;
    rMean += radii[vertex(k)] / count;
    cMean = cMean + (1.0 / count) * centres[vertex(k)];
  }
  double sVariance = 0.0, rCovariance = 0.0;
  Point3 cCovariance{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 0; k < arc.size(); ++k)
  {
    const double ds = arc[k] - sMean;
    sVariance += ds * ds;
    rCovariance += ds * (radii[vertex(k)] - rMean);
    cCovariance = cCovariance + ds * (centres[vertex(k)] - cMean);
  }
  LineEnd end;
  if (!(sVariance > 0.0))
  {
    return end;
  }
  const Point3 inwards = (1.0 / sVariance) * cCovariance; // d centre / d arc
  const double speed = Norm(inwards);
  if (!(speed > 0.0))
  {
    return end;
  }
  end.Valid = true;
  end.Centre = cMean - sMean * inwards;
  end.Radius =
    std::clamp(rMean - sMean * rCovariance / sVariance, 0.5 * endRadius, 1.5 * endRadius);
  end.Direction = (-1.0 / speed) * inwards;
  end.Slope = std::clamp(-rCovariance / sVariance / speed, -0.45, 0.45);
  return end;
}

class CentreLineEnvelope
{
public:
  /// `reach` bounds the tolerances Matches will be asked for. Past the
  /// ends of an open line the envelope is extrapolated, not fitted to the
  /// surface: points there match within at least `extensionTolerance`.
  CentreLineEnvelope(const std::vector<Point3>& centres, const std::vector<double>& radii,
    bool closed, double reach, double cosNormal, double extensionTolerance)
    : Reach(reach)
    , CosNormal(cosNormal)
    , ExtensionTolerance(extensionTolerance)
  {
    const std::size_t n = centres.size();
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i)
    {
      const std::size_t j = (i + 1) % n;
      this->Add(centres[i], radii[i], centres[j], radii[j]);
    }
    if (!closed)
    {
      // The ball rolls on up to one radius past the true end of the line,
      // which the medial line may fall short of by about another radius:
      // e.g. to a sharp cap edge across the fillet. Past that there is no
      // surface with the normals of the envelope.
      for (int end = 0; end < 2; ++end)
      {
        const LineEnd fit = FitLineEnd(centres, radii, end == 1);
        if (!fit.Valid)
        {
          continue;
        }
        const std::size_t last = end ? n - 1 : 0;
        const double reach = 2.0 * fit.Radius;
        this->Add(centres[last], radii[last], fit.Centre, fit.Radius, true);
        this->Add(fit.Centre, fit.Radius, fit.Centre + reach * fit.Direction,
          fit.Radius * (1.0 + 2.0 * fit.Slope), true);
      }
    }
  }

  // Whether p lies on the envelope, within `tolerance` times the local
  // radius, with the surface normal `normal`.
  bool Matches(const Point3& p, const Point3& normal, double tolerance) const
  {
    for (const EnvelopePiece& piece : this->Pieces)
    {
      if (p[0] < piece.Lo[0] || p[1] < piece.Lo[1] || p[2] < piece.Lo[2] || p[0] > piece.Hi[0] ||
        p[1] > piece.Hi[1] || p[2] > piece.Hi[2])
      {
        continue;
      }
      const ConePrimitive& cone = piece.Cone;
      const double t =
        cone.Length > 0.0 ? std::clamp(Dot(p - cone.C[0], cone.Axis) / cone.Length, 0.0, 1.0) : 0.0;
      const double radius = (1.0 - t) * cone.R[0] + t * cone.R[1];
      const PrimitiveDistance d = ConeDistance(cone, p);
      // Past the end, the extrapolation is less certain the farther it goes.
      const double tol = piece.Extension && this->ExtensionTolerance > tolerance ? tolerance +
          (this->ExtensionTolerance - tolerance) * std::min(1.0, t * cone.Length / radius)
                                                                                 : tolerance;
      if (std::abs(d.Distance) <= tol * radius && Dot(d.Normal, normal) >= this->CosNormal)
      {
        return true;
      }
    }
    return false;
  }

private:
  void Add(const Point3& c0, double r0, const Point3& c1, double r1, bool extension = false)
  {
    EnvelopePiece piece;
    piece.Extension = extension;
    piece.Cone = MakeCone(c0, r0, c1, r1);
    const double reach = std::max(r0, r1) * (1.0 + this->Reach);
    for (int k = 0; k < 3; ++k)
    {
      piece.Lo[k] = std::min(c0[k], c1[k]) - reach;
      piece.Hi[k] = std::max(c0[k], c1[k]) + reach;
    }
    this->Pieces.push_back(piece);
  }

  std::vector<EnvelopePiece> Pieces;
  double Reach;
  double CosNormal;
  double ExtensionTolerance;
};

// The point of a polyline nearest to p (closed: the last vertex joins the
// first): on segment Segment (vertex Segment to the next), at Along in
// [0, 1] (Unclamped before clamping), the first such in case of ties.
struct PolylineFoot
{
  std::size_t Segment = 0;
  double Along = 0.0, Unclamped = 0.0;
  Point3 Foot;
};

PolylineFoot NearestOnPolyline(const std::vector<Point3>& line, bool closed, const Point3& p)
{
  const std::size_t n = line.size();
  const std::size_t segments = closed ? n : (n > 0 ? n - 1 : 0);
  PolylineFoot nearest;
  nearest.Foot = n > 0 ? line[0] : p;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < segments; ++i)
  {
    const Point3 &a = line[i], &b = line[(i + 1) % n];
    const Point3 ab = b - a;
    const double length2 = Dot(ab, ab);
    const double u = length2 > 0.0 ? Dot(p - a, ab) / length2 : 0.0;
    const double along = std::clamp(u, 0.0, 1.0);
    const Point3 q = a + along * ab;
    const double d = Norm(p - q);
    if (d < best)
    {
      best = d;
      nearest = { i, along, u, q };
    }
  }
  return nearest;
}

// Moves each centre-line vertex to the centre of the circle fitted to the
// fillet's cross-section there (the surface points nearest to it, projected
// on the plane across the line), and takes that circle's radius.
// With `fromLine`, each point is measured from its closest point on the
// current line instead of from the vertex: on a curved line, sections then
// do not smear, provided the line is already close to the true one.
void RefineCentreLine(
  Fillet& fillet, const std::vector<Point3>& points, double inlier, bool fromLine)
{
  const std::size_t n = fillet.Centres.size();
  std::vector<Point3> centres = fillet.Centres;
  std::vector<std::uint8_t> fitted(n, 0);
  // Each point goes to the vertex nearest to its closest point on the line.
  std::vector<std::vector<Point3>> nearest(n);
  for (const Point3& p : points)
  {
    const PolylineFoot nearestPoint = NearestOnPolyline(centres, fillet.Closed, p);
    const std::size_t bestVertex =
      nearestPoint.Along < 0.5 ? nearestPoint.Segment : (nearestPoint.Segment + 1) % n;
    // Stored relative to the vertex, or to the foot moved to the vertex.
    nearest[bestVertex].push_back(fromLine ? centres[bestVertex] + (p - nearestPoint.Foot) : p);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    // Tangent over about one radius on each side: short medial edges zig-zag.
    std::size_t previous = i, next = i;
    for (std::size_t k = 1; k < n; ++k)
    {
      if (!fillet.Closed && k > i)
      {
        break;
      }
      previous = (i + n - k) % n;
      if (Norm(centres[previous] - centres[i]) >= fillet.Radii[i])
      {
        break;
      }
    }
    for (std::size_t k = 1; k < n; ++k)
    {
      if (!fillet.Closed && i + k >= n)
      {
        break;
      }
      next = (i + k) % n;
      if (Norm(centres[next] - centres[i]) >= fillet.Radii[i])
      {
        break;
      }
    }
    const Point3 tangent = Normalized(centres[next] - centres[previous]);
    if (nearest[i].size() < 6 || Norm(tangent) == 0.0)
    {
      continue;
    }
    // A frame across the line.
    const Point3 helper = std::abs(tangent[0]) < 0.9 ? Point3{ 1, 0, 0 } : Point3{ 0, 1, 0 };
    const Point3 e1 = Normalized(Cross(tangent, helper)), e2 = Cross(tangent, e1);
    // A thin slice across the line: the points nearest to the vertex's plane
    // (at most a quarter radius away). Farther along, the curvature of the
    // line, an error of the tangent or a changing radius would smear the
    // section.
    std::vector<std::pair<double, Point3>> slice;
    for (const Point3& p : nearest[i])
    {
      const Point3 d = p - centres[i];
      const double s = Dot(d, tangent);
      if (std::abs(s) <= 0.25 * fillet.Radii[i])
      {
        slice.push_back({ s, d });
      }
    }
    constexpr std::size_t SlicePoints = 24;
    if (slice.size() > SlicePoints)
    {
      std::nth_element(slice.begin(), slice.begin() + SlicePoints, slice.end(),
        [](const auto& a, const auto& b)
        {
          return std::abs(a.first) < std::abs(b.first) ||
            (std::abs(a.first) == std::abs(b.first) && a.first < b.first);
        });
      slice.resize(SlicePoints);
    }
    std::vector<std::array<double, 2>> section;
    double along = 0.0;
    for (const auto& [s, d] : slice)
    {
      section.push_back({ Dot(d, e1), Dot(d, e2) });
      along += s;
    }
    // The section lies where its points are along the line (interior
    // vertices; the ends keep the line's extent).
    const bool end = !fillet.Closed && (i == 0 || i + 1 == n);
    along = slice.empty() || end ? 0.0 : along / static_cast<double>(slice.size());
    const FittedCircle circle = FitCircleRobust(section, inlier);
    const double r = fillet.Radii[i];
    // Junctions (corner balls, several fillets) have no single section.
    if (circle.Valid && circle.InlierFraction >= 0.5 && std::hypot(circle.X, circle.Y) < 0.5 * r &&
      std::abs(circle.Radius - r) < 0.5 * r)
    {
      fillet.Centres[i] = centres[i] + circle.X * e1 + circle.Y * e2 + along * tangent;
      fillet.Radii[i] = circle.Radius;
      fitted[i] = 1;
    }
  }
  // A fit whose radius stands out from its neighbours' (an odd section, e.g.
  // where fins cross the line) does not count.
  std::vector<std::uint8_t> trusted = fitted;
  for (std::size_t i = 0; i < n; ++i)
  {
    std::vector<double> window;
    for (long k = -2; k <= 2; ++k)
    {
      const long j = static_cast<long>(i) + k;
      const std::size_t w = fillet.Closed
        ? static_cast<std::size_t>((j + 2 * static_cast<long>(n)) % static_cast<long>(n))
        : static_cast<std::size_t>(j);
      if ((fillet.Closed || (j >= 0 && j < static_cast<long>(n))) && fitted[w])
      {
        window.push_back(fillet.Radii[w]);
      }
    }
    if (fitted[i] && window.size() >= 3)
    {
      std::nth_element(window.begin(), window.begin() + window.size() / 2, window.end());
      const double median = window[window.size() / 2];
      trusted[i] = std::abs(fillet.Radii[i] - median) <= 4.0 * inlier * median;
    }
  }
  // Vertices without a trusted fit take the displacement and radius of the
  // trusted ones on both sides, weighted by distance along the line.
  std::vector<Point3> offset(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    offset[i] = fillet.Centres[i] - centres[i];
  }
  const std::vector<double> radii = fillet.Radii;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (trusted[i])
    {
      continue;
    }
    long before = -1, after = -1;
    double toBefore = 0.0, toAfter = 0.0;
    for (std::size_t k = 1; k < n && before < 0; ++k)
    {
      if (!fillet.Closed && k > i)
      {
        break;
      }
      const std::size_t j = (i + n - k) % n;
      toBefore += Norm(centres[(j + 1) % n] - centres[j]);
      before = trusted[j] ? static_cast<long>(j) : -1;
    }
    for (std::size_t k = 1; k < n && after < 0; ++k)
    {
      if (!fillet.Closed && i + k >= n)
      {
        break;
      }
      const std::size_t j = (i + k) % n;
      toAfter += Norm(centres[j] - centres[(j + n - 1) % n]);
      after = trusted[j] ? static_cast<long>(j) : -1;
    }
    if (before < 0 && after < 0)
    {
      fillet.Centres[i] = centres[i];
      continue;
    }
    if (!fillet.Closed && (before < 0 || after < 0))
    {
      // Past the last trusted fit towards an end of the line: continue the
      // trend of the last two (a radius changing along the line keeps
      // changing), or copy the last one when there is no second.
      const long step = before < 0 ? 1 : -1;
      const long first = before < 0 ? after : before;
      long second = -1;
      double between = 0.0;
      for (long j = first + step; j >= 0 && j < static_cast<long>(n); j += step)
      {
        between += Norm(centres[j] - centres[j - step]);
        if (trusted[j])
        {
          second = j;
          break;
        }
      }
      const double distance = before < 0 ? toAfter : toBefore;
      // At most as far again as the two fits are apart, and the radius
      // within half and one and a half times the last fit's.
      const double u = second >= 0 && between > 0.0 ? std::min(distance / between, 1.0) : 0.0;
      const std::size_t f = static_cast<std::size_t>(first);
      const std::size_t g = static_cast<std::size_t>(second >= 0 ? second : first);
      if (second >= 0)
      {
        const Point3 fittedF = centres[f] + offset[f], fittedG = centres[g] + offset[g];
        fillet.Centres[i] = fittedF + u * (fittedF - fittedG);
      }
      else
      {
        fillet.Centres[i] = centres[i] + offset[f];
      }
      fillet.Radii[i] =
        std::clamp(radii[f] + u * (radii[f] - radii[g]), 0.5 * radii[f], 1.5 * radii[f]);
      continue;
    }
    const double w = before < 0 ? 1.0 : (after < 0 ? 0.0 : toBefore / (toBefore + toAfter));
    const std::size_t b =
      before < 0 ? static_cast<std::size_t>(after) : static_cast<std::size_t>(before);
    const std::size_t a =
      after < 0 ? static_cast<std::size_t>(before) : static_cast<std::size_t>(after);
    fillet.Centres[i] = centres[i] + (1.0 - w) * offset[b] + w * offset[a];
    fillet.Radii[i] = (1.0 - w) * radii[b] + w * radii[a];
  }
  // Where the radius changes along the line (slope r' = dr/ds), a ball
  // touches the fillet along a circle that is not its great circle: radius
  // r sqrt(1 - r'^2), centre r r' behind the ball's centre along the line.
  // The fits found those circles; turn them into balls.
  const std::vector<Point3> circleCentres = fillet.Centres;
  const std::vector<double> circleRadii = fillet.Radii;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t before = fillet.Closed ? (i + n - 1) % n : (i > 0 ? i - 1 : i);
    const std::size_t after = fillet.Closed ? (i + 1) % n : (i + 1 < n ? i + 1 : i);
    const Point3 step = circleCentres[after] - circleCentres[before];
    const double length = Norm(step);
    if (length == 0.0)
    {
      continue;
    }
    const double slope = std::clamp((circleRadii[after] - circleRadii[before]) / length, -0.9, 0.9);
    const double r = circleRadii[i] / std::sqrt(1.0 - slope * slope);
    fillet.Radii[i] = r;
    fillet.Centres[i] = circleCentres[i] + (slope * r / length) * step;
  }
}

// Medial edges on exactly one medial triangle, sorted.
std::vector<std::array<Index, 2>> BoundaryEdges(const MedialMesh& medial)
{
  std::vector<std::array<Index, 2>> uses;
  uses.reserve(3 * medial.Faces.size());
  for (const auto& f : medial.Faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index a = f[k], b = f[(k + 1) % 3];
      uses.push_back({ std::min(a, b), std::max(a, b) });
    }
  }
  std::sort(uses.begin(), uses.end());
  std::vector<std::array<Index, 2>> boundary;
  for (std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i;
    while (j < uses.size() && uses[j] == uses[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      boundary.push_back(uses[i]);
    }
    i = j;
  }
  return boundary;
}

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
  std::sort(around.begin(), around.end());
  double largestGap = 2.0 * Pi - (around.back() - around.front());
  for (std::size_t i = 1; i < around.size(); ++i)
  {
    largestGap = std::max(largestGap, around[i] - around[i - 1]);
  }
  return 2.0 * Pi - largestGap >= options.MinimumArcAngle ? EdgeVerdict::Accepted
                                                          : EdgeVerdict::Rejected;
}

// The last medial edges of an open line may turn back on it (the ends of
// medial sheets zig-zag); such an end vertex is no further along the line.
void TrimFoldedEnds(Fillet& chain)
{
  if (chain.Closed)
  {
    return;
  }
  auto folds = [&chain](std::size_t a, std::size_t b, std::size_t c)
  { return Dot(chain.Centres[c] - chain.Centres[b], chain.Centres[b] - chain.Centres[a]) < 0.0; };
  while (chain.Vertices.size() >= 3 &&
    folds(chain.Vertices.size() - 3, chain.Vertices.size() - 2, chain.Vertices.size() - 1))
  {
    chain.Vertices.pop_back();
    chain.Centres.pop_back();
    chain.Radii.pop_back();
  }
  while (chain.Vertices.size() >= 3 && folds(2, 1, 0))
  {
    chain.Vertices.erase(chain.Vertices.begin());
    chain.Centres.erase(chain.Centres.begin());
    chain.Radii.erase(chain.Radii.begin());
  }
}

// Whether the point nearest to p on an open polyline is one of its ends.
bool PastAnEnd(const std::vector<Point3>& line, const Point3& p)
{
  const PolylineFoot nearest = NearestOnPolyline(line, false, p);
  return (nearest.Segment == 0 && nearest.Unclamped < 0.0) ||
    (nearest.Segment + 2 == line.size() && nearest.Unclamped > 1.0);
}

void Measure(Fillet& chain)
{
  const std::size_t n = chain.Centres.size();
  const std::size_t segments = chain.Closed ? n : n - 1;
  double weighted = 0.0;
  chain.Length = 0.0;
  chain.MinimumRadius = *std::min_element(chain.Radii.begin(), chain.Radii.end());
  chain.MaximumRadius = *std::max_element(chain.Radii.begin(), chain.Radii.end());
  for (std::size_t i = 0; i < segments; ++i)
  {
    const std::size_t j = (i + 1) % n;
    const double length = Norm(chain.Centres[j] - chain.Centres[i]);
    chain.Length += length;
    weighted += 0.5 * length * (chain.Radii[i] + chain.Radii[j]);
  }
  chain.MeanRadius = chain.Length > 0.0 ? weighted / chain.Length : chain.MaximumRadius;
  chain.RadiusVariation =
    chain.MeanRadius > 0.0 ? (chain.MaximumRadius - chain.MinimumRadius) / chain.MeanRadius : 0.0;
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
  const std::vector<std::array<Index, 2>> boundary = BoundaryEdges(medial);
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
    Measure(chain);
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
      [&](Index t)
      {
        const Triangle& tri = surface.Triangles[t];
        const Point3& n = triangles[t].Normal;
        const double tol = options.RadiusTolerance;
        return loose.Matches(triangles[t].Centroid, n, tol) &&
          loose.Matches(surface.Points[tri[0]], n, tol) &&
          loose.Matches(surface.Points[tri[1]], n, tol) &&
          loose.Matches(surface.Points[tri[2]], n, tol);
      });
    std::vector<Index> cornerIds;
    for (Index t : found)
    {
      cornerIds.insert(cornerIds.end(), surface.Triangles[t].begin(), surface.Triangles[t].end());
    }
    std::sort(cornerIds.begin(), cornerIds.end());
    cornerIds.erase(std::unique(cornerIds.begin(), cornerIds.end()), cornerIds.end());
    std::vector<Point3> corners;
    for (Index v : cornerIds)
    {
      corners.push_back(surface.Points[v]);
    }
    RefineCentreLine(fillet, corners, 0.25 * options.FaceTolerance, false);
    RefineCentreLine(fillet, corners, 0.25 * options.FaceTolerance, true);
    TrimFoldedEnds(fillet);
    Measure(fillet);

    const CentreLineEnvelope tight(
      fillet.Centres, fillet.Radii, fillet.Closed, reach, cosNormal, options.RadiusTolerance);
    seeds.insert(seeds.end(), found.begin(), found.end());
    for (Index t : grow(seeds,
           [&](Index t)
           {
             const Triangle& tri = surface.Triangles[t];
             const Point3& n = triangles[t].Normal;
             return tight.Matches(triangles[t].Centroid, n, options.RadiusTolerance) &&
               tight.Matches(surface.Points[tri[0]], n, options.FaceTolerance) &&
               tight.Matches(surface.Points[tri[1]], n, options.FaceTolerance) &&
               tight.Matches(surface.Points[tri[2]], n, options.FaceTolerance);
           }))
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
  // pass on the faces found past its ends alone.
  std::vector<int> renumber(result.Fillets.size(), -1);
  std::vector<Fillet> kept;
  for (std::size_t f = 0; f < result.Fillets.size(); ++f)
  {
    const Fillet& fillet = result.Fillets[f];
    const double expected = fillet.Length * fillet.MeanRadius * options.MinimumArcAngle;
    if (fillet.MinimumRadius > 0.0 && areaAlongLine[f] >= 0.5 * expected)
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
