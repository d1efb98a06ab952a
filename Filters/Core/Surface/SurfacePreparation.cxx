// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/SurfacePreparation.h"

#include "Geometry/Vec3.h"
#include "Surface/CoincidentPoints.h"
#include "Surface/ContactSeparation.h"
#include "Surface/DegenerateTriangles.h"
#include "Surface/SelfIntersection.h"
#include "Surface/SelfIntersectionRepair.h"
#include "Surface/ShellOrientation.h"
#include "Surface/SurfaceWrap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <unordered_map>

namespace medialaxis
{
namespace
{
// How the notes of a surface moved by the repair begin.
constexpr const char* WrappedNote = "self-intersections repaired by wrapping";
constexpr const char* PulledApartNote = "contact pulled apart: the surface passed through itself";

std::string Count(std::size_t n, const char* singular, const char* plural)
{
  return std::to_string(n) + ' ' + (n == 1 ? singular : plural);
}

// Generalised winding number of point p with respect to a set of triangles
// (sum of signed solid angles, Van Oosterom and Strackee).
double WindingNumber(const Point3& p, const std::vector<Point3>& points,
  const std::vector<Triangle>& triangles, const std::vector<Index>& subset)
{
  double total = 0.0;
  for (Index t : subset)
  {
    const Point3 a = (points[triangles[t][0]] - p);
    const Point3 b = (points[triangles[t][1]] - p);
    const Point3 c = (points[triangles[t][2]] - p);
    const double la = Norm(a), lb = Norm(b), lc = Norm(c);
    const double numerator = Dot(a, Cross(b, c));
    const double denominator = la * lb * lc + Dot(a, b) * lc + Dot(b, c) * la + Dot(c, a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * Pi);
}

double SignedVolumeOf(const std::vector<Point3>& points, const std::vector<Triangle>& triangles,
  const std::vector<Index>& subset)
{
  if (subset.empty())
  {
    return 0.0;
  }
  // Relative to one of the component's points, for accuracy far from the origin.
  const Point3 origin = points[triangles[subset[0]][0]];
  double sixVolume = 0.0;
  for (Index t : subset)
  {
    const Point3 a = (points[triangles[t][0]] - origin);
    const Point3 b = (points[triangles[t][1]] - origin);
    const Point3 c = (points[triangles[t][2]] - origin);
    sixVolume += Dot(a, Cross(b, c));
  }
  return sixVolume / 6.0;
}

// Whether triangles a and b are within `rings` vertex rings of each other on
// the surface (a breadth-first search over the vertex graph from a's
// corners). Crossings of such near neighbours are local folds of the mesh;
// crossings of triangles far apart on the surface mean it passes through
// itself.
bool AreSurfaceNeighbours(const std::vector<Triangle>& triangles,
  const std::vector<std::vector<Index>>& vertexTriangles, Index a, Index b, int rings)
{
  std::unordered_map<Index, int> depth;
  std::vector<Index> frontier(triangles[a].begin(), triangles[a].end());
  for (Index v : frontier)
  {
    depth.emplace(v, 0);
  }
  auto isCornerOfB = [&](Index v)
  { return v == triangles[b][0] || v == triangles[b][1] || v == triangles[b][2]; };
  for (int ring = 0; ring <= rings; ++ring)
  {
    std::vector<Index> next;
    for (Index v : frontier)
    {
      if (isCornerOfB(v))
      {
        return true;
      }
      for (Index t : vertexTriangles[v])
      {
        for (Index w : triangles[t])
        {
          if (depth.emplace(w, ring + 1).second)
          {
            next.push_back(w);
          }
        }
      }
    }
    frontier.swap(next);
  }
  return false;
}

std::string Percent(double fraction)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.2g%%", 100.0 * fraction);
  return text;
}

std::string Location(const TriangleCrossing& c)
{
  char text[96];
  std::snprintf(text, sizeof(text), "(%.6g, %.6g, %.6g)", 0.5 * (c.Lo[0] + c.Hi[0]),
    0.5 * (c.Lo[1] + c.Hi[1]), 0.5 * (c.Lo[2] + c.Hi[2]));
  return text;
}
}

double SignedVolume(const TriangleMesh& mesh)
{
  std::vector<Index> all(mesh.Triangles.size());
  std::iota(all.begin(), all.end(), Index(0));
  return SignedVolumeOf(mesh.Points, mesh.Triangles, all);
}

double SurfaceArea(const TriangleMesh& mesh)
{
  double twiceArea = 0.0;
  for (const Triangle& t : mesh.Triangles)
  {
    twiceArea +=
      Norm(Cross((mesh.Points[t[1]] - mesh.Points[t[0]]), (mesh.Points[t[2]] - mesh.Points[t[0]])));
  }
  return 0.5 * twiceArea;
}

namespace
{
// The bounding-box diagonal of the points the triangles use.
double UsedDiagonal(const TriangleMesh& mesh)
{
  Point3 lo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Triangle& t : mesh.Triangles)
  {
    for (Index v : t)
    {
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], mesh.Points[v][k]);
        hi[k] = std::max(hi[k], mesh.Points[v][k]);
      }
    }
  }
  return Norm(hi - lo);
}

// The input's notes and counts in the report of its repaired surface.
void KeepInputCounts(const SurfacePreparationReport& report, SurfacePreparationReport& repaired)
{
  repaired.Notes.insert(repaired.Notes.begin(), report.Notes.begin(), report.Notes.end());
  repaired.InputPoints = report.InputPoints;
  repaired.InputTriangles = report.InputTriangles;
  repaired.NonFinitePoints = report.NonFinitePoints;
  repaired.MergedPoints = report.MergedPoints;
  repaired.UnusedPoints = report.UnusedPoints;
  repaired.DegenerateTriangles = report.DegenerateTriangles;
  repaired.SplitNeighbours = report.SplitNeighbours;
  repaired.DuplicateTriangles = report.DuplicateTriangles;
  repaired.ReorientedTriangles = report.ReorientedTriangles;
  repaired.SelfIntersections = report.SelfIntersections;
  repaired.CrossingShells = report.CrossingShells;
  repaired.CrossingFarApart = report.CrossingFarApart;
  repaired.PassThroughExtent = report.PassThroughExtent;
  repaired.Crossings = report.Crossings;
  repaired.Repaired = true;
}

// The crossings found by `report` resolved: every shell turned outward on
// its own, the union's boundary prepared again; `repaired` receives its
// report, with the input's counts and notes. Where the crossings cannot be
// resolved exactly and `mayWrap`, the surface is wrapped instead (unless
// the inside itself is in doubt). Returns why the repair failed, or an
// empty string.
std::string RepairAndPrepare(const std::vector<Point3>& points, std::vector<Triangle> triangles,
  const std::vector<std::vector<Index>>& shells, const SurfacePreparationReport& report,
  TriangleMesh& output, const SurfacePreparationOptions& options, bool mayWrap,
  SurfacePreparationReport& repaired)
{
  for (const std::vector<Index>& shell : shells)
  {
    if (SignedVolumeOf(points, triangles, shell) < 0.0)
    {
      for (Index t : shell)
      {
        std::swap(triangles[t][1], triangles[t][2]);
      }
    }
  }
  TriangleMesh oriented{ points, std::move(triangles) };
  SelfIntersectionRepairResult repair = RepairSelfIntersections(oriented, report.Crossings);
  SurfaceWrapResult wrap;
  double diagonal = 0.0;
  if (!repair.Error.empty())
  {
    if (!mayWrap || repair.InsideInDoubt || !(options.WrapAlpha > 0.0))
    {
      return repair.Error;
    }
    diagonal = UsedDiagonal(oriented);
    const double alpha = options.WrapAlpha * diagonal;
    wrap = WrapSurface(oriented, alpha, alpha / 30.0);
    if (!wrap.Error.empty())
    {
      return repair.Error + "; wrapping it instead failed: " + wrap.Error;
    }
  }
  const bool wrapped = !repair.Error.empty();
  SurfacePreparationOptions again = options;
  again.RepairSelfIntersections = false;
  again.KnownCrossings = nullptr;
  repaired = PrepareSurface(wrapped ? wrap.Surface : repair.Surface, output, again);
  if (!repaired.Ok())
  {
    return "the repaired surface is not usable: " + repaired.Error;
  }
  // The input's counts and notes, then the repaired surface's facts.
  for (std::string& note : repaired.Notes)
  {
    note = "repaired surface: " + note;
  }
  const double inputArea = SurfaceArea(oriented);
  if (wrapped)
  {
    repaired.Notes.insert(repaired.Notes.begin(),
      std::string(WrappedNote) + ": resolving " + Count(report.SelfIntersections, "pair", "pairs") +
        " of crossing triangles exactly failed (" + repair.Error +
        "), so an alpha wrap (balls of " + Percent(wrap.Alpha / diagonal) + " of the diagonal, " +
        Percent(wrap.Offset / diagonal) + " outside) replaced the surface; it lies within " +
        Percent(wrap.LargestDeviation / diagonal) +
        " of the diagonal of the input and bridges details narrower than the balls");
  }
  else
  {
    repaired.Notes.insert(repaired.Notes.begin(),
      "self-intersections repaired: " + Count(report.SelfIntersections, "pair", "pairs") +
        " of crossing triangles resolved into the outer boundary of the solid, " +
        Percent(inputArea > 0.0 ? repair.RemovedArea / inputArea : 0.0) +
        " of the area (the parts inside) removed");
  }
  KeepInputCounts(report, repaired);
  repaired.RemovedArea = wrapped ? 0.0 : repair.RemovedArea;
  repaired.RepairMethod = wrapped ? "alpha wrap" : "resolved crossings";
  repaired.RepairDeviation = wrapped ? wrap.LargestDeviation / diagonal : 0.0;
  return {};
}

// A small contact pulled apart (ContactSeparation.h): the piercing vertices
// of the far-apart crossings moved back `options.ContactGap` of the diagonal
// behind the walls they poke through, the moved surface checked to cross
// itself no more (but in local folds) and prepared; `repaired` receives its
// report. Returns why it could not be done, or an empty string.
std::string SeparateAndPrepare(const std::vector<Point3>& points,
  const std::vector<Triangle>& triangles, const std::vector<std::vector<Index>>& shells,
  const std::vector<std::vector<Index>>& vertexTriangles,
  const std::vector<TriangleCrossing>& farApart, const SurfacePreparationReport& report,
  double diagonal, const SurfacePreparationOptions& options, TriangleMesh& output,
  SurfacePreparationReport& repaired)
{
  std::vector<signed char> outward(triangles.size(), 1);
  for (const std::vector<Index>& shell : shells)
  {
    if (SignedVolumeOf(points, triangles, shell) < 0.0)
    {
      for (Index t : shell)
      {
        outward[t] = -1;
      }
    }
  }
  const ContactSeparation separation =
    SeparatePiercingVertices(points, triangles, outward, farApart, options.ContactGap * diagonal);
  if (!separation.Error.empty())
  {
    return separation.Error;
  }
  const std::vector<TriangleCrossing> left = FindSelfIntersections(separation.Points, triangles);
  for (const TriangleCrossing& c : left)
  {
    if (!AreSurfaceNeighbours(triangles, vertexTriangles, c.A, c.B, options.LocalFoldRings))
    {
      return "the surface still passes through itself with the tips moved back";
    }
  }
  SurfacePreparationOptions again = options;
  again.RepairSelfIntersections = false;
  again.KnownCrossings = &left;
  repaired = PrepareSurface(TriangleMesh{ separation.Points, triangles }, output, again);
  if (!repaired.Ok())
  {
    return "the surface with the tips moved back is not usable: " + repaired.Error;
  }
  repaired.Notes.insert(repaired.Notes.begin(),
    std::string(PulledApartNote) + " near " + Location(farApart.front()) + " (" +
      Count(farApart.size(), "pair", "pairs") + " of triangles far apart): " +
      Count(separation.MovedVertices, "vertex poking", "vertices poking") +
      " through a wall moved back behind it, by at most " +
      Percent(separation.LargestMove / diagonal) + " of the diagonal");
  KeepInputCounts(report, repaired);
  repaired.RepairMethod = "pulled apart";
  repaired.RepairDeviation = separation.LargestMove / diagonal;
  return {};
}
}

bool IsMovedSurfaceNote(const std::string& note)
{
  return note.rfind(WrappedNote, 0) == 0 || note.rfind(PulledApartNote, 0) == 0;
}

SurfacePreparationReport PrepareSurface(
  const TriangleMesh& input, TriangleMesh& output, const SurfacePreparationOptions& options)
{
  SurfacePreparationReport report;
  report.InputPoints = input.Points.size();
  report.InputTriangles = input.Triangles.size();
  output = TriangleMesh();

  if (input.Triangles.empty())
  {
    report.Error = "surface is empty: it has no triangles";
    return report;
  }
  const Index np = static_cast<Index>(input.Points.size());
  std::vector<char> used(input.Points.size(), 0);
  for (const Triangle& t : input.Triangles)
  {
    for (Index v : t)
    {
      if (v < 0 || v >= np)
      {
        report.Error = "surface has a triangle referencing point " + std::to_string(v) +
          ", outside [0, " + std::to_string(np) + ")";
        return report;
      }
      used[v] = 1;
    }
  }

  // 1. Non-finite coordinates, and the bounding box of what is used.
  Point3 lo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (std::size_t i = 0; i < input.Points.size(); ++i)
  {
    if (!used[i])
    {
      continue;
    }
    const Point3& p = input.Points[i];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      ++report.NonFinitePoints;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  if (report.NonFinitePoints)
  {
    report.Error = "surface has " + Count(report.NonFinitePoints, "point", "points") +
      " with NaN or infinite coordinates";
    return report;
  }
  const double diagonal = Norm((hi - lo));
  double extent = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    extent = std::max({ extent, std::fabs(lo[k]), std::fabs(hi[k]) });
  }
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
  {
    report.Error = diagonal > 0.0 ? "surface is too large: its bounding box overflows"
                                  : "surface is degenerate: all its points coincide";
    return report;
  }

  // 2. Merge coincident points. A tolerance too small for the grid's integer
  // cells (points extremely far from the origin) falls back to exact merging.
  double tolerance = options.RelativeMergeTolerance * diagonal;
  if (tolerance > 0.0 && extent / tolerance > 1e15)
  {
    tolerance = 0.0;
  }
  const auto representative = MergeCoincidentPoints(input.Points, used, tolerance);
  for (std::size_t i = 0; i < representative.size(); ++i)
  {
    report.MergedPoints += (used[i] && representative[i] != static_cast<Index>(i)) ? 1 : 0;
  }

  // 3. Drop triangles with a repeated vertex, then zero-area needles.
  std::vector<Triangle> triangles;
  triangles.reserve(input.Triangles.size());
  for (const Triangle& t : input.Triangles)
  {
    const Triangle m{ representative[t[0]], representative[t[1]], representative[t[2]] };
    if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2])
    {
      ++report.DegenerateTriangles;
      continue;
    }
    triangles.push_back(m);
  }
  report.DegenerateTriangles += RemoveNeedles(input.Points, triangles, report.SplitNeighbours);

  // 4. Drop triangles whose vertex set repeats an earlier one.
  report.DuplicateTriangles = RemoveDuplicateTriangles(triangles);
  if (triangles.empty())
  {
    report.Error = "surface has no valid triangles: all " + std::to_string(report.InputTriangles) +
      " are degenerate or duplicates";
    return report;
  }

  // 5. Edge incidence: boundary and non-manifold edges.
  const std::size_t nt = triangles.size();
  EdgePairing edges = PairTriangleEdges(triangles);
  report.BoundaryEdges = edges.BoundaryEdges;
  report.NonManifoldEdges = edges.NonManifoldEdges;
  if (report.BoundaryEdges || report.NonManifoldEdges)
  {
    if (report.BoundaryEdges)
    {
      report.Error =
        "surface is not closed: " + Count(report.BoundaryEdges, "boundary edge", "boundary edges");
    }
    if (report.NonManifoldEdges)
    {
      report.Error += std::string(report.Error.empty() ? "surface is not manifold: " : "; and ") +
        Count(report.NonManifoldEdges, "edge is", "edges are") +
        " shared by more than two triangles";
    }
    return report;
  }

  // 6. Non-manifold vertices: the corners around a vertex must form one fan.
  report.NonManifoldVertices =
    CountNonManifoldVertices(triangles, edges.Adjacencies, input.Points.size());
  if (report.NonManifoldVertices)
  {
    report.Error = "surface is not manifold: " +
      Count(report.NonManifoldVertices, "vertex joins", "vertices join") +
      " several separate sheets of triangles";
    return report;
  }

  // 7. Consistent orientation per connected component (breadth-first).
  ShellOrientation shells = OrientShells(nt, edges.Adjacencies);
  // The edge list goes before the self-intersection test, whose own arrays
  // then take its room (57 MB with the half-edges on a 268,686-triangle
  // surface).
  decltype(edges.Adjacencies)().swap(edges.Adjacencies);
  const std::vector<Index>& component = shells.Component;
  const std::vector<std::vector<Index>>& members = shells.Members;
  report.ReorientedTriangles = shells.Flipped;
  if (shells.NonOrientable)
  {
    report.Error = "surface is not orientable (like a Moebius strip or Klein bottle)";
    return report;
  }
  if (report.ReorientedTriangles && !options.FixOrientation)
  {
    report.Error = "surface orientation is inconsistent: " +
      Count(report.ReorientedTriangles, "triangle disagrees", "triangles disagree") +
      " with its neighbours";
    return report;
  }
  for (std::size_t t = 0; t < nt; ++t)
  {
    if (shells.Flip[t])
    {
      std::swap(triangles[t][1], triangles[t][2]);
    }
  }
  report.Components = members.size();

  // 8. Self-intersection. Shells that cross each other, or a shell passing
  // through itself, bound no solid; the nesting test below would misread
  // them (overlapping spheres would become a sphere with a cavity). Scanned
  // and decimated meshes often have a few neighbouring triangles folded over
  // each other; those are local and only noted.
  report.Crossings = options.KnownCrossings ? *options.KnownCrossings
                                            : FindSelfIntersections(input.Points, triangles);
  report.SelfIntersectionTested = true;
  const std::vector<TriangleCrossing>& crossings = report.Crossings;
  report.SelfIntersections = crossings.size();
  if (!crossings.empty())
  {
    // The refusal in report.Error stands unless the crossings are resolved.
    auto refuseUnlessRepaired = [&]() -> SurfacePreparationReport
    {
      if (options.RepairSelfIntersections)
      {
        SurfacePreparationReport repaired;
        const std::string failed = RepairAndPrepare(
          input.Points, triangles, members, report, output, options, true, repaired);
        if (failed.empty())
        {
          return repaired;
        }
        report.Error += "; repairing it failed: " + failed;
      }
      return report;
    };
    const TriangleCrossing* betweenShells = nullptr;
    for (const TriangleCrossing& c : crossings)
    {
      if (component[c.A] != component[c.B])
      {
        betweenShells = betweenShells ? betweenShells : &c;
        ++report.CrossingShells;
      }
    }
    if (betweenShells)
    {
      report.Error = "surface intersects itself: " +
        Count(report.CrossingShells, "pair of triangles", "pairs of triangles") +
        " of separate shells cross, e.g. near " + Location(*betweenShells) +
        " (overlapping shells must be merged into one surface first)";
      return refuseUnlessRepaired();
    }
    std::vector<std::vector<Index>> vertexTriangles(input.Points.size());
    for (std::size_t t = 0; t < nt; ++t)
    {
      for (Index v : triangles[t])
      {
        vertexTriangles[v].push_back(static_cast<Index>(t));
      }
    }
    // Where the surface passes through itself: the box of all crossings of
    // triangles far apart on the surface.
    const TriangleCrossing* farApart = nullptr;
    std::vector<TriangleCrossing> farApartCrossings;
    Point3 lo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (const TriangleCrossing& c : crossings)
    {
      if (!AreSurfaceNeighbours(triangles, vertexTriangles, c.A, c.B, options.LocalFoldRings))
      {
        farApart = farApart ? farApart : &c;
        farApartCrossings.push_back(c);
        ++report.CrossingFarApart;
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], c.Lo[k]);
          hi[k] = std::max(hi[k], c.Hi[k]);
        }
      }
    }
    report.PassThroughExtent = farApart ? Norm(hi - lo) / diagonal : 0.0;
    // A vertex poking through a wall (by less than half its shortest edge)
    // is pulled apart: resolved exactly, the contact would leave a hole no
    // sampling could see.
    std::string notSeparated = "pulling apart is off";
    if (options.RepairSelfIntersections && farApart && options.ContactGap > 0.0)
    {
      SurfacePreparationReport repaired;
      notSeparated = SeparateAndPrepare(input.Points, triangles, members, vertexTriangles,
        farApartCrossings, report, diagonal, options, output, repaired);
      if (notSeparated.empty())
      {
        return repaired;
      }
    }
    if (report.PassThroughExtent > options.MaxPassThroughExtent)
    {
      report.Error = "surface intersects itself: " +
        Count(report.CrossingFarApart, "pair of triangles", "pairs of triangles") +
        " far apart on the surface cross, e.g. near " + Location(*farApart) +
        " (the surface passes through itself)";
      return refuseUnlessRepaired();
    }
    // Other small contacts are kept unless they can be resolved exactly:
    // wrapping the whole surface for one would cost more than it mends.
    // (Local folds are kept as they are: resolving them misclassifies the
    // patches.)
    if (options.RepairSelfIntersections && farApart)
    {
      SurfacePreparationReport repaired;
      const std::string failed = RepairAndPrepare(
        input.Points, triangles, members, report, output, options, false, repaired);
      if (failed.empty())
      {
        return repaired;
      }
      output = TriangleMesh();
      report.Notes.push_back("the crossings could not be repaired (pulling the contact apart: " +
        notSeparated + "; resolving it: " + failed + ")");
    }
    const std::size_t folds = crossings.size() - report.CrossingFarApart;
    if (folds)
    {
      report.Notes.push_back(Count(folds, "pair of neighbouring triangles overlaps",
                               "pairs of neighbouring triangles overlap") +
        " (local folds): kept");
    }
    if (farApart)
    {
      report.Notes.push_back("the surface touches or passes through itself near " +
        Location(*farApart) + " (" + Count(report.CrossingFarApart, "pair", "pairs") +
        " of triangles, within " + Percent(report.PassThroughExtent) +
        " of the diagonal): kept, the medial axis may be wrong there");
    }
  }

  // 9. Outward orientation: a shell nested inside an odd number of others
  // bounds a cavity and must face inward; every other shell faces outward.
  // The nesting test costs components x triangles, so it is skipped (every
  // shell made outward) for surfaces with very many components.
  constexpr std::size_t maxNestingComponents = 64;
  const bool testNesting = members.size() > 1 && members.size() <= maxNestingComponents;
  if (members.size() > maxNestingComponents)
  {
    report.Notes.push_back("nesting of shells not tested (" + std::to_string(members.size()) +
      " components): every shell oriented outward");
  }
  for (std::size_t c = 0; c < members.size(); ++c)
  {
    int depth = 0;
    if (testNesting)
    {
      const Point3& probe = input.Points[triangles[members[c][0]][0]];
      for (std::size_t other = 0; other < members.size(); ++other)
      {
        if (other != c &&
          std::fabs(WindingNumber(probe, input.Points, triangles, members[other])) > 0.5)
        {
          ++depth;
        }
      }
    }
    const double volume = SignedVolumeOf(input.Points, triangles, members[c]);
    const bool wantPositive = depth % 2 == 0;
    if ((volume < 0.0) == wantPositive && volume != 0.0)
    {
      if (!options.FixOrientation)
      {
        report.Error = "surface is oriented inward: normals point into the solid";
        return report;
      }
      for (Index t : members[c])
      {
        std::swap(triangles[t][1], triangles[t][2]);
      }
      ++report.InwardComponents;
    }
  }

  // 10. Compact: keep only the points that triangles use, in first-use order.
  std::vector<Index> newId(input.Points.size(), -1);
  output.Triangles.reserve(triangles.size());
  for (Triangle t : triangles)
  {
    for (Index& v : t)
    {
      if (newId[v] < 0)
      {
        newId[v] = static_cast<Index>(output.Points.size());
        output.Points.push_back(input.Points[v]);
      }
      v = newId[v];
    }
    output.Triangles.push_back(t);
  }
  std::size_t usedInput = 0;
  for (char u : used)
  {
    usedInput += u;
  }
  report.UnusedPoints = input.Points.size() - usedInput;

  report.Area = SurfaceArea(output);
  report.Volume = SignedVolume(output);
  if (!(report.Volume > 1e-12 * diagonal * diagonal * diagonal))
  {
    report.Error = "surface encloses no volume (a flat or doubly covered sheet)";
    return report;
  }

  auto note = [&report](std::size_t n, const char* singular, const char* plural, const char* what)
  {
    if (n)
    {
      report.Notes.push_back(Count(n, singular, plural) + ' ' + what);
    }
  };
  note(report.MergedPoints, "coincident point", "coincident points", "merged");
  note(report.UnusedPoints, "unused point", "unused points", "dropped");
  note(report.DegenerateTriangles, "degenerate triangle", "degenerate triangles", "dropped");
  note(report.DuplicateTriangles, "duplicate triangle", "duplicate triangles", "dropped");
  note(report.ReorientedTriangles, "triangle", "triangles", "flipped to agree with neighbours");
  note(report.InwardComponents, "inward shell", "inward shells", "flipped to face outward");
  if (report.Components > 1)
  {
    report.Notes.push_back(std::to_string(report.Components) + " separate shells");
  }
  return report;
}
}
