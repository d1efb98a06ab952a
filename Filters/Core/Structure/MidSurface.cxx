// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/MidSurface.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Mesh/TriangleLocator.h"
#include "Structure/MidSurfaceFolds.h"
#include "Structure/WallProbe.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>

namespace medialaxis
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// Neighbouring triangles meeting at less than this tessellate one smooth side.
const double SmoothSideAngle = 20.0 * Pi / 180.0;
// A lateral face stands at least this steeply on the wall's mid-surface.
const double LateralFaceSine = std::sin(60.0 * Pi / 180.0);
// A junction's branches reach this many wall thicknesses (along the sheet)
// from the nearest centred point: the T's arcs about one, a rib's fillets
// about two. Farther, the sheet does not join two walls but a wall and
// something else (a tube, a block), and its triangles are dropped.
const double MaximumStraightening = 3.0;
// A straightened point lies at least this fraction of its thickness from
// the surface (a half on a wall and at its junctions).
const double MinimumClearance = 0.3;
// Rounds of untangling a fold may take.
const int FoldRounds = 30;
// Walls smaller than this share of the mid-surface are fragments.
const double MinimumWallFraction = 0.001;
// A wall bends by less than this from one triangle to the next.
const double SameWallCosine = std::cos(30.0 * Pi / 180.0);

// Slivers (height under 5% of their longest edge) tilt with the last digits
// of their points: their normals say nothing.
bool IsSliver(const std::vector<Point3>& points, const std::array<Index, 3>& t)
{
  double longest2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    longest2 = std::max(longest2, Distance2(points[t[k]], points[t[(k + 1) % 3]]));
  }
  return !(Norm(AreaNormal(points, t)) > 0.05 * longest2);
}

// Per vertex, the distinct sheets of its kept faces; a state per (vertex,
// sheet) for the search along each sheet.
struct SheetStates
{
  std::vector<Index> Offsets; // per vertex
  std::vector<Index> Sheet;   // per state
  std::vector<Index> Vertex;  // per state

  Index Find(Index v, Index sheet) const
  {
    for (Index s = this->Offsets[v]; s < this->Offsets[v + 1]; ++s)
    {
      if (this->Sheet[s] == sheet)
      {
        return s;
      }
    }
    return -1;
  }
};

SheetStates MakeSheetStates(
  const MedialMesh& mesh, const std::vector<Index>& kept, const std::vector<Index>& faceSheet)
{
  std::vector<std::vector<Index>> sheets(mesh.NumberOfVertices());
  for (Index f : kept)
  {
    for (Index v : mesh.Faces[f])
    {
      sheets[v].push_back(faceSheet[f]);
    }
  }
  SheetStates states;
  states.Offsets.push_back(0);
  for (std::size_t v = 0; v < sheets.size(); ++v)
  {
    std::sort(sheets[v].begin(), sheets[v].end());
    sheets[v].erase(std::unique(sheets[v].begin(), sheets[v].end()), sheets[v].end());
    for (Index s : sheets[v])
    {
      states.Sheet.push_back(s);
      states.Vertex.push_back(static_cast<Index>(v));
    }
    states.Offsets.push_back(static_cast<Index>(states.Sheet.size()));
  }
  return states;
}

// For every state, the nearest wall vertex along the edges of its sheet
// (Dijkstra from all wall vertices at once); -1 where none is reachable.
std::vector<Index> NearestWallVertex(const MedialMesh& mesh, const std::vector<Index>& kept,
  const std::vector<Index>& faceSheet, const SheetStates& states,
  const std::vector<std::uint8_t>& isWall, std::vector<double>& distance)
{
  const std::size_t ns = states.Sheet.size();
  std::vector<std::vector<std::pair<Index, double>>> next(ns);
  for (Index f : kept)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index a = states.Find(t[k], faceSheet[f]),
                  b = states.Find(t[(k + 1) % 3], faceSheet[f]);
      const double w = std::sqrt(Distance2(mesh.Centers[t[k]], mesh.Centers[t[(k + 1) % 3]]));
      next[a].emplace_back(b, w);
      next[b].emplace_back(a, w);
    }
  }
  distance.assign(ns, Infinity);
  std::vector<Index> source(ns, -1);
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t s = 0; s < ns; ++s)
  {
    if (isWall[states.Vertex[s]])
    {
      distance[s] = 0.0;
      source[s] = states.Vertex[s];
      queue.emplace(0.0, static_cast<Index>(s));
    }
  }
  while (!queue.empty())
  {
    const auto [d, s] = queue.top();
    queue.pop();
    if (d > distance[s])
    {
      continue;
    }
    for (const auto& [t, w] : next[s])
    {
      if (d + w < distance[t] || (d + w == distance[t] && source[s] < source[t]))
      {
        distance[t] = d + w;
        source[t] = source[s];
        queue.emplace(d + w, t);
      }
    }
  }
  return source;
}
}

MidSurface ExtractMidSurface(const MedialMesh& mesh, const MedialStructure& structure,
  const TriangleMesh& surface, const MidSurfaceOptions& options)
{
  MidSurface out;
  const WallSheets walls = FindWallSheets(mesh, structure, options.Walls);
  out.WallThickness = walls.WallThickness;
  out.WallSheets = walls.NumberOfWallSheets;
  const std::size_t nv = mesh.NumberOfVertices();
  std::vector<Index> kept;
  for (std::size_t f = 0; f < mesh.Faces.size() && f < structure.FaceSheet.size(); ++f)
  {
    const Index s = structure.FaceSheet[f];
    if (s >= 0 && walls.SheetIsWall[s])
    {
      kept.push_back(static_cast<Index>(f));
    }
  }
  if (kept.empty() || surface.Triangles.empty())
  {
    return out;
  }
  const TriangleLocator locator(surface);
  std::vector<Point3> surfaceNormal(surface.Triangles.size());
  for (std::size_t t = 0; t < surface.Triangles.size(); ++t)
  {
    surfaceNormal[t] = TriangleNormal(surface, static_cast<Index>(t));
  }
  const SheetStates states = MakeSheetStates(mesh, kept, structure.FaceSheet);

  // Vertex normals of the medial sheets (their faces' orientations aligned
  // with the first).
  std::vector<Point3> normal(nv, Point3{ 0, 0, 0 });
  std::vector<std::uint8_t> used(nv, 0);
  for (Index f : kept)
  {
    const Point3 n = AreaNormal(mesh.Centers, mesh.Faces[f]);
    for (Index v : mesh.Faces[f])
    {
      normal[v] = normal[v] + (Dot(normal[v], n) < 0.0 ? -1.0 : 1.0) * n;
      used[v] = 1;
    }
  }

  // Vertices of one sheet between two parallel sides: moved to the middle
  // between them. Elsewhere (where a side turns into a fillet, a rib or a
  // corner) the vertex is straightened onto the wall's plane below.
  std::vector<double> facetTurn(surface.Triangles.size(), 0.0);
  const TriangleAdjacency adjacency = ComputeTriangleAdjacency(surface, SmoothSideAngle);
  const auto centroid = [&](Index t)
  {
    const Triangle& tri = surface.Triangles[t];
    return (1.0 / 3.0) * (surface.Points[tri[0]] + surface.Points[tri[1]] + surface.Points[tri[2]]);
  };
  for (std::size_t t = 0; t < facetTurn.size(); ++t)
  {
    for (Index u : adjacency.Neighbour[t])
    {
      const double angle = u < 0
        ? Pi
        : std::acos(std::max(-1.0, std::min(1.0, Dot(surfaceNormal[t], surfaceNormal[u]))));
      if (angle < SmoothSideAngle && angle > std::fabs(facetTurn[t]))
      {
        // Convex where the neighbour falls below this triangle's plane.
        const bool convex =
          Dot(surfaceNormal[t], centroid(u) - centroid(static_cast<Index>(t))) < 0.0;
        facetTurn[t] = convex ? angle : -angle;
      }
    }
  }
  const WallProbe probe{ locator, surfaceNormal, facetTurn };
  const double probeReach = 1.5 * walls.WallThickness;
  std::vector<Point3> position = mesh.Centers;
  std::vector<double> thickness(nv);
  std::vector<std::uint8_t> isWall(nv, 0);
  std::vector<MidSurfacePointType> type(nv, MidSurfacePointType::Medial);
  for (std::size_t v = 0; v < nv; ++v)
  {
    thickness[v] = 2.0 * mesh.Radii[v];
    if (used[v] && states.Offsets[v + 1] - states.Offsets[v] == 1 && Norm(normal[v]) > 0.0 &&
      probe.Centre(mesh.Centers[v], Normalized(normal[v]),
        std::max(3.0 * mesh.Radii[v], probeReach), position[v], thickness[v]))
    {
      isWall[v] = 1;
      type[v] = MidSurfacePointType::Centred;
      ++out.CentredPoints;
    }
  }
  // The walls' normals again, from the centred vertices: the medial
  // triangles tilt with the noise of the discrete medial axis.
  std::vector<Point3> wallNormal(nv, Point3{ 0, 0, 0 });
  for (Index f : kept)
  {
    const auto& t = mesh.Faces[f];
    if (isWall[t[0]] && isWall[t[1]] && isWall[t[2]] && !IsSliver(position, t))
    {
      const Point3 n = AreaNormal(position, t);
      for (Index v : t)
      {
        wallNormal[v] = wallNormal[v] + (Dot(normal[v], n) < 0.0 ? -1.0 : 1.0) * n;
      }
    }
  }
  // A centred vertex on no triangle of centred vertices (at the edge of a
  // wall) takes its centred neighbours' normals, a ring at a time.
  std::vector<std::vector<Index>> neighbours(nv);
  for (Index f : kept)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  }
  for (int ring = 0; ring < 3; ++ring)
  {
    std::vector<Point3> filled = wallNormal;
    for (std::size_t v = 0; v < nv; ++v)
    {
      if (!isWall[v] || Norm(wallNormal[v]) > 0.0)
      {
        continue;
      }
      for (Index w : neighbours[v])
      {
        if (isWall[w] && Norm(wallNormal[w]) > 0.0)
        {
          const Point3 n = Normalized(wallNormal[w]);
          filled[v] = filled[v] + (Dot(normal[v], n) < 0.0 ? -1.0 : 1.0) * n;
        }
      }
    }
    wallNormal.swap(filled);
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    wallNormal[v] = Normalized(Norm(wallNormal[v]) > 0.0 ? wallNormal[v] : normal[v]);
  }

  // Every other vertex (branches towards junctions and rims) onto the plane
  // of the nearest wall vertex of each of its sheets, where those planes meet.
  std::vector<double> sourceDistance;
  const std::vector<Index> source =
    NearestWallVertex(mesh, kept, structure.FaceSheet, states, isWall, sourceDistance);
  std::vector<PlaneSet> planes(nv);
  std::vector<std::uint8_t> unplaced(nv, 0);
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (!used[v])
    {
      continue;
    }
    if (isWall[v])
    {
      planes[v].Add(position[v], wallNormal[v]);
      continue;
    }
    double sum = 0.0;
    int count = 0;
    for (Index s = states.Offsets[v]; s < states.Offsets[v + 1]; ++s)
    {
      const Index w = source[s];
      if (w >= 0 && sourceDistance[s] > MaximumStraightening * thickness[w])
      {
        unplaced[v] = 1; // not a junction's branch: where a tube or a block joins the wall
      }
      else if (w >= 0)
      {
        planes[v].Add(position[w], wallNormal[w]);
        sum += thickness[w];
        ++count;
      }
    }
    if (count == 0)
    {
      planes[v].Add(position[v], wallNormal[v]);
      continue;
    }
    position[v] = planes[v].Meet(mesh.Centers[v]);
    type[v] = planes[v].Normals.size() > 1 ? MidSurfacePointType::Junction
                                           : MidSurfacePointType::Straightened;
    thickness[v] = sum / count;
    if (type[v] == MidSurfacePointType::Straightened)
    {
      // Where a chord across the wall meets two parallel sides alike, its
      // middle corrects the plane's tilt; a junction keeps where its walls'
      // planes meet and their mean thickness.
      const Point3 n = Normalized(planes[v].Normals[0]);
      const auto chord = probe.Chord(position[v], n, probeReach);
      if (chord.Thickness > 0.0)
      {
        position[v] = position[v] + chord.Offset * n;
        thickness[v] = chord.Thickness;
      }
    }
    // A wall's middle is half a thickness from the surface, at a junction
    // too; a point much nearer has been laid on a plane that is not its
    // wall's (where a wall bends into a tube or a boss).
    const double clearance = locator.Distance(position[v]) / (sum / count);
    if (!(clearance >= MinimumClearance))
    {
      unplaced[v] = 1;
    }
  }

  // The kept faces on compact point ids, flat ones dropped.
  std::vector<Index> pointOf(nv, -1);
  std::vector<std::array<Index, 3>> faces;
  double scale = 0.0;
  for (const Point3& p : surface.Points)
  {
    scale = std::max(scale, Norm(p - surface.Points[0]));
  }
  for (Index f : kept)
  {
    const auto& t = mesh.Faces[f];
    if (!(Norm(AreaNormal(position, t)) > 1e-12 * scale * scale) || unplaced[t[0]] ||
      unplaced[t[1]] || unplaced[t[2]])
    {
      ++out.DroppedTriangles;
      continue;
    }
    std::array<Index, 3> face;
    for (int k = 0; k < 3; ++k)
    {
      if (pointOf[t[k]] < 0)
      {
        pointOf[t[k]] = static_cast<Index>(out.Mesh.Points.size());
        out.Mesh.Points.push_back(position[t[k]]);
        out.Thickness.push_back(thickness[t[k]]);
        out.MedialVertex.push_back(t[k]);
        out.PointType.push_back(type[t[k]]);
      }
      face[k] = pointOf[t[k]];
    }
    faces.push_back(face);
  }
  OrientConsistently(faces);
  const std::size_t medialPoints = out.Mesh.Points.size();
  std::vector<PlaneSet> pointPlanes(medialPoints);
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (pointOf[v] >= 0)
    {
      pointPlanes[pointOf[v]] = planes[v];
    }
  }
  std::vector<std::uint8_t> untangled;
  if (UntangleFolds(out.Mesh.Points, faces, pointPlanes, FoldRounds, untangled) > 0)
  {
    // The tips of the folds left go; what is still folded is counted.
    const std::vector<Index> tips = FoldedTips(out.Mesh.Points, faces);
    std::vector<std::uint8_t> drop(faces.size(), 0);
    for (Index f : tips)
    {
      drop[f] = 1;
    }
    std::size_t kept = 0;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      if (!drop[f])
      {
        faces[kept++] = faces[f];
      }
    }
    faces.resize(kept);
    out.DroppedTriangles += tips.size();
    out.FoldedEdges = FoldedTips(out.Mesh.Points, faces).size();
  }
  for (std::size_t p = 0; p < medialPoints; ++p)
  {
    // A point moved within its wall's tangent plane is centred again where
    // it landed: a curved wall falls away from the plane, and a tapered
    // wall's thickness changes along it.
    if (!untangled[p] || pointPlanes[p].Normals.size() != 1)
    {
      continue;
    }
    const Point3 n = Normalized(pointPlanes[p].Normals[0]);
    Point3 middle;
    double across = 0.0;
    if (probe.Centre(out.Mesh.Points[p], n, probeReach, middle, across))
    {
      out.Mesh.Points[p] = middle;
      out.Thickness[p] = across;
    }
    else
    {
      const auto chord = probe.Chord(out.Mesh.Points[p], n, probeReach);
      out.Thickness[p] = chord.Thickness > 0.0 ? chord.Thickness : out.Thickness[p];
    }
  }

  // Free boundaries out along the mid-surface to the lateral faces.
  const EdgeFaceMap edgeUses = EdgeFaces(faces);
  std::vector<std::array<Index, 3>> boundary; // a, b as in the face, then the face
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    const auto& t = faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index a = t[k], b = t[(k + 1) % 3];
      if (edgeUses.at({ std::min(a, b), std::max(a, b) }).size() == 1)
      {
        boundary.push_back({ a, b, static_cast<Index>(f) });
      }
    }
  }
  std::vector<Index> extended(medialPoints, -1);
  if (options.ExtendToLateralFaces)
  {
    std::vector<Point3> outward(medialPoints, Point3{ 0, 0, 0 });
    for (const auto& e : boundary)
    {
      const auto& points = out.Mesh.Points;
      const Point3 n = AreaNormal(points, faces[e[2]]);
      const Point3 d = Normalized(Cross(points[e[1]] - points[e[0]], n));
      outward[e[0]] = outward[e[0]] + d;
      outward[e[1]] = outward[e[1]] + d;
    }
    // The mid-surface so far: a boundary that faces another wall across a
    // gap (a notch of the discrete medial axis at a junction) is stitched
    // to it rather than run on to the surface.
    const TriangleMesh straightened{ out.Mesh.Points, faces };
    const TriangleLocator midLocator(straightened);
    for (std::size_t p = 0; p < medialPoints; ++p)
    {
      const PlaneSet& plane = pointPlanes[p];
      if (!(Norm(outward[p]) > 0.0) || plane.Normals.empty())
      {
        continue;
      }
      const Point3 origin = out.Mesh.Points[p];
      const double reach = out.Thickness[p];
      const Point3 along = plane.AlongAll(outward[p]);
      Point3 step{ 0, 0, 0 };
      if (Norm(along) > 1e-9 * Norm(outward[p]))
      {
        const Point3 dir = Normalized(along);
        // Another wall's triangle: the ray runs along its own wall's plane.
        const auto hit = midLocator.FirstHitIf(origin, dir, 1e-3 * reach, reach,
          [&](Index t)
          {
            const Point3 n = Normalized(AreaNormal(straightened.Points, straightened.Triangles[t]));
            for (const Point3& m : plane.Normals)
            {
              if (std::fabs(Dot(n, Normalized(m))) >= SamePlaneCosine)
              {
                return false;
              }
            }
            return true;
          });
        if (hit.Triangle >= 0)
        {
          step = hit.Distance * dir;
        }
      }
      if (!(Norm(step) > 0.0))
      {
        // The nearest lateral face (standing steeply on the wall's planes),
        // reached along the mid-surface and away from the wall.
        const auto lateral = [&](Index t)
        {
          for (const Point3& n : plane.Normals)
          {
            const double c = Dot(surfaceNormal[t], Normalized(n));
            if (std::sqrt(std::max(0.0, 1.0 - c * c)) < LateralFaceSine)
            {
              return false;
            }
          }
          return true;
        };
        const auto closest = locator.Closest(origin, lateral, reach);
        if (closest.Triangle >= 0)
        {
          const Point3 toFace = plane.AlongAll(closest.Point - origin);
          if (Dot(toFace, outward[p]) > 0.0)
          {
            step = toFace;
          }
        }
      }
      if (Norm(step) > 1e-3 * reach)
      {
        // The chord just inside the lateral face (further in where it slips
        // off the sides there): the thickness, and the middle of the face.
        const Point3 n = Normalized(plane.Normals[0]);
        WallProbe::ChordResult chord;
        for (double along : { 1.0 - 1e-3, 0.9, 0.5 })
        {
          chord = probe.Chord(origin + along * step, n, probeReach);
          if (chord.Thickness > 0.0)
          {
            break;
          }
        }
        extended[p] = static_cast<Index>(out.Mesh.Points.size());
        out.Mesh.Points.push_back(origin + step + chord.Offset * n);
        out.Thickness.push_back(chord.Thickness > 0.0 ? chord.Thickness : out.Thickness[p]);
        out.MedialVertex.push_back(-1);
        out.PointType.push_back(MidSurfacePointType::Lateral);
        ++out.ExtendedPoints;
      }
    }
    for (const auto& e : boundary)
    {
      // The strip's triangles use the edge b -> a, as a neighbour must.
      const Index a = e[0], b = e[1], ea = extended[a], eb = extended[b];
      const Point3 faceNormal = AreaNormal(out.Mesh.Points, faces[e[2]]);
      const auto add = [&](const std::array<Index, 3>& t)
      {
        // Not flat, and not turned over (where the extensions of a convex
        // corner's points cross).
        const Point3 n = AreaNormal(out.Mesh.Points, t);
        if (Norm(n) > 1e-12 * scale * scale && Dot(n, faceNormal) > 0.0)
        {
          faces.push_back(t);
        }
        else
        {
          ++out.DroppedTriangles;
        }
      };
      if (ea >= 0)
      {
        add({ b, a, ea });
      }
      if (eb >= 0)
      {
        add({ b, ea >= 0 ? ea : a, eb });
      }
    }
  }
  out.Mesh.Triangles = faces;

  // Walls: triangles joined where the surface bends gently, and at
  // junctions where one continues another's plane.
  EdgeFaceMap edgeFaces = EdgeFaces(faces);
  std::vector<Point3> unit(faces.size());
  std::vector<std::uint8_t> sliver(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    unit[f] = Normalized(AreaNormal(out.Mesh.Points, faces[f]));
    sliver[f] = IsSliver(out.Mesh.Points, faces[f]);
  }
  DisjointSets wallSets(faces.size());
  for (const auto& [edge, around] : edgeFaces)
  {
    if (around.size() == 1)
    {
      ++out.BoundaryEdges;
      continue;
    }
    out.JunctionEdges += around.size() > 2 ? 1 : 0;
    const double cosine = around.size() == 2 ? SameWallCosine : SamePlaneCosine;
    for (std::size_t i = 0; i < around.size(); ++i)
    {
      for (std::size_t j = i + 1; j < around.size(); ++j)
      {
        if (!sliver[around[i]] && !sliver[around[j]] &&
          std::fabs(Dot(unit[around[i]], unit[around[j]])) >= cosine)
        {
          wallSets.Union(around[i], around[j]);
        }
      }
    }
  }
  // A sliver joins one wall only (at a crease it must not join the walls on
  // its sides): its largest neighbour, preferring a proper triangle across
  // an edge of two, then any proper triangle, then another sliver.
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    if (!sliver[f])
    {
      continue;
    }
    Index best = -1;
    double bestScore = -1.0;
    for (int k = 0; k < 3; ++k)
    {
      const Index a = faces[f][k], b = faces[f][(k + 1) % 3];
      const auto& around = edgeFaces[{ std::min(a, b), std::max(a, b) }];
      for (Index g : around)
      {
        if (g == static_cast<Index>(f))
        {
          continue;
        }
        const double rank = sliver[g] ? 0.0 : (around.size() == 2 ? 2.0 : 1.0);
        const double score =
          rank + Norm(AreaNormal(out.Mesh.Points, faces[g])) / (scale * scale + 1e-300) * 1e-3;
        if (score > bestScore)
        {
          best = g;
          bestScore = score;
        }
      }
    }
    if (best >= 0)
    {
      wallSets.Union(static_cast<Index>(f), best);
    }
  }
  // Fragments (under MinimumWallFraction of the area: debris of the
  // discrete medial axis at junctions and of the stitching) join the
  // largest wall they touch (by a point at least), as flaps join their sheet.
  std::vector<double> faceArea(faces.size()), rootArea(faces.size(), 0.0);
  double totalArea = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    faceArea[f] = 0.5 * Norm(AreaNormal(out.Mesh.Points, faces[f]));
    totalArea += faceArea[f];
  }
  std::vector<std::vector<Index>> vertexFaces(out.Mesh.Points.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    for (Index v : faces[f])
    {
      vertexFaces[v].push_back(static_cast<Index>(f));
    }
  }
  for (int pass = 0; pass < 2; ++pass)
  {
    std::fill(rootArea.begin(), rootArea.end(), 0.0);
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      rootArea[wallSets.Find(static_cast<Index>(f))] += faceArea[f];
    }
    std::vector<Index> host(faces.size(), -1);
    for (const auto& around : vertexFaces)
    {
      for (Index f : around)
      {
        const Index r = wallSets.Find(f);
        if (rootArea[r] >= MinimumWallFraction * totalArea)
        {
          continue;
        }
        for (Index g : around)
        {
          const Index q = wallSets.Find(g);
          if (q != r && (host[r] < 0 || rootArea[q] > rootArea[host[r]]))
          {
            host[r] = q;
          }
        }
      }
    }
    for (std::size_t r = 0; r < faces.size(); ++r)
    {
      if (host[r] >= 0 && rootArea[host[r]] > rootArea[r])
      {
        wallSets.Union(static_cast<Index>(r), host[r]);
      }
    }
  }
  std::vector<Index> wallOfRoot(faces.size(), -1);
  out.WallOfTriangle.resize(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    const Index root = wallSets.Find(static_cast<Index>(f));
    if (wallOfRoot[root] < 0)
    {
      wallOfRoot[root] = static_cast<Index>(out.Walls.size());
      out.Walls.push_back({ 0.0, 0.0, Infinity, -Infinity });
    }
    out.WallOfTriangle[f] = wallOfRoot[root];
    MidSurfaceWall& wall = out.Walls[wallOfRoot[root]];
    const double area = faceArea[f];
    wall.Area += area;
    for (Index v : faces[f])
    {
      wall.MeanThickness += area * out.Thickness[v] / 3.0;
      wall.MinimumThickness = std::min(wall.MinimumThickness, out.Thickness[v]);
      wall.MaximumThickness = std::max(wall.MaximumThickness, out.Thickness[v]);
    }
  }
  for (MidSurfaceWall& wall : out.Walls)
  {
    wall.MeanThickness = wall.Area > 0.0 ? wall.MeanThickness / wall.Area : 0.0;
  }
  return out;
}
}
