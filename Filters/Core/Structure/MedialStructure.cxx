// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/MedialStructure.h"

#include "Geometry/Vec3.h"
#include "Support/DisjointSets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medialaxis
{
const char* MedialVertexTypeName(MedialVertexType type)
{
  switch (type)
  {
    case MedialVertexType::Sheet:
      return "sheet";
    case MedialVertexType::Seam:
      return "seam";
    case MedialVertexType::Junction:
      return "junction";
    case MedialVertexType::Rim:
      return "rim";
    case MedialVertexType::Feature:
      return "feature";
    case MedialVertexType::Fillet:
      return "fillet";
    case MedialVertexType::Curve:
      return "curve";
    case MedialVertexType::Isolated:
      return "isolated";
  }
  return "unknown";
}

MedialVertexType TypeFromTangentComponents(int components)
{
  return components <= 1 ? MedialVertexType::Rim
    : components == 2    ? MedialVertexType::Sheet
    : components == 3    ? MedialVertexType::Seam
                         : MedialVertexType::Junction;
}

namespace
{
bool StructuralType(MedialVertexType t)
{
  return t == MedialVertexType::Sheet || t == MedialVertexType::Seam ||
    t == MedialVertexType::Junction || t == MedialVertexType::Rim;
}

struct FaceEdge
{
  std::array<Index, 2> Key;
  Index Face;
  bool operator<(const FaceEdge& other) const
  {
    return this->Key != other.Key ? this->Key < other.Key : this->Face < other.Face;
  }
};

// Per vertex, how many of each kind of edge and how many faces meet there.
struct Incidence
{
  int Faces = 0;
  int SeamEdges = 0;
  int BoundaryEdges = 0;
  int CurveEdges = 0;
};

MedialVertexType TypeOf(const Incidence& in, bool feature, bool fillet)
{
  if (in.Faces == 0 && in.CurveEdges == 0)
  {
    return MedialVertexType::Isolated;
  }
  if (feature)
  {
    return MedialVertexType::Feature;
  }
  if (fillet)
  {
    return MedialVertexType::Fillet;
  }
  if (in.SeamEdges >= 3 || (in.CurveEdges > 0 && in.Faces > 0))
  {
    return MedialVertexType::Junction;
  }
  if (in.SeamEdges > 0)
  {
    return MedialVertexType::Seam;
  }
  if (in.Faces == 0)
  {
    return MedialVertexType::Curve;
  }
  return in.BoundaryEdges > 0 ? MedialVertexType::Rim : MedialVertexType::Sheet;
}

// Sheets: faces joined in `joined`.
void NumberSheets(const MedialMesh& mesh, const std::vector<double>& faceArea, DisjointSets& joined,
  MedialStructure& out)
{
  const std::size_t nf = mesh.Faces.size();
  out.FaceSheet.assign(nf, -1);
  std::vector<Index> sheetOfRoot(nf, -1);
  std::vector<double> weightedRadius;
  for (std::size_t f = 0; f < nf; ++f)
  {
    const Index root = joined.Find(static_cast<Index>(f));
    if (sheetOfRoot[root] < 0)
    {
      sheetOfRoot[root] = static_cast<Index>(out.Sheets.size());
      MedialSheet sheet;
      sheet.MinimumRadius = std::numeric_limits<double>::infinity();
      sheet.MaximumRadius = -std::numeric_limits<double>::infinity();
      out.Sheets.push_back(sheet);
      weightedRadius.push_back(0.0);
    }
    const Index s = sheetOfRoot[root];
    out.FaceSheet[f] = s;
    const auto& t = mesh.Faces[f];
    MedialSheet& sheet = out.Sheets[s];
    const Point3& p = mesh.Centers[t[0]];
    const double area = 0.5 * Norm(Cross(mesh.Centers[t[1]] - p, mesh.Centers[t[2]] - p));
    double sum = 0.0;
    for (Index v : t)
    {
      sum += mesh.Radii[v];
      sheet.MinimumRadius = std::min(sheet.MinimumRadius, mesh.Radii[v]);
      sheet.MaximumRadius = std::max(sheet.MaximumRadius, mesh.Radii[v]);
    }
    ++sheet.Triangles;
    sheet.Area += area;
    weightedRadius[s] += area * sum / 3.0;
  }
  for (std::size_t s = 0; s < out.Sheets.size(); ++s)
  {
    MedialSheet& sheet = out.Sheets[s];
    sheet.MeanRadius = sheet.Area > 0.0 ? weightedRadius[s] / sheet.Area
                                        : 0.5 * (sheet.MinimumRadius + sheet.MaximumRadius);
  }
}

// Seams: chains of seam edges through vertices on exactly two of them.
void NumberSeams(std::size_t nv, const std::vector<Incidence>& incidence, MedialStructure& out)
{
  const std::size_t ne = out.SeamEdges.size();
  DisjointSets chained(ne);
  std::vector<Index> firstEdge(nv, -1);
  for (std::size_t e = 0; e < ne; ++e)
  {
    for (Index v : out.SeamEdges[e])
    {
      if (incidence[v].SeamEdges != 2)
      {
        continue;
      }
      if (firstEdge[v] < 0)
      {
        firstEdge[v] = static_cast<Index>(e);
      }
      else
      {
        chained.Union(firstEdge[v], static_cast<Index>(e));
      }
    }
  }
  out.SeamOfEdge.assign(ne, -1);
  std::vector<Index> seamOfRoot(ne, -1);
  for (std::size_t e = 0; e < ne; ++e)
  {
    const Index root = chained.Find(static_cast<Index>(e));
    if (seamOfRoot[root] < 0)
    {
      seamOfRoot[root] = static_cast<Index>(out.NumberOfSeams++);
    }
    out.SeamOfEdge[e] = seamOfRoot[root];
  }
}
}

MedialStructure ClassifyMedialStructure(
  const MedialMesh& mesh, const MedialStructureOptions& options)
{
  const std::size_t nv = mesh.NumberOfVertices(), nf = mesh.Faces.size();
  const bool featureFlags = options.FeatureVertex.size() == nv;
  const bool filletFlags = options.FilletVertex.size() == nv;
  auto feature = [&](Index v)
  { return featureFlags ? options.FeatureVertex[v] != 0 : mesh.Radii[v] == 0.0; };

  std::vector<Incidence> incidence(nv);
  std::vector<FaceEdge> faceEdges;
  faceEdges.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = mesh.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      ++incidence[t[k]].Faces;
      const Index a = t[k], b = t[(k + 1) % 3];
      faceEdges.push_back({ { std::min(a, b), std::max(a, b) }, static_cast<Index>(f) });
    }
  }
  std::sort(faceEdges.begin(), faceEdges.end());
  // Each edge's run of entries in faceEdges.
  std::vector<std::size_t> runStart;
  for (std::size_t i = 0; i < faceEdges.size(); ++i)
  {
    if (i == 0 || faceEdges[i].Key != faceEdges[i - 1].Key)
    {
      runStart.push_back(i);
    }
  }
  runStart.push_back(faceEdges.size());

  // Sheets: faces joined across edges of two faces, unless both ends are
  // feature vertices.
  DisjointSets joined(nf);
  for (std::size_t r = 0; r + 1 < runStart.size(); ++r)
  {
    const std::size_t i = runStart[r];
    const auto& [a, b] = faceEdges[i].Key;
    if (runStart[r + 1] - i == 2 && !(feature(a) && feature(b)))
    {
      joined.Union(faceEdges[i].Face, faceEdges[i + 1].Face);
    }
  }
  // Flaps: sheets smaller than MinimumSheetFraction of the whole, hanging
  // on another sheet by edges of three or more faces, join the largest
  // sheet they touch, and their faces no longer make those edges seams.
  std::vector<double> area(nf, 0.0), rootArea(nf, 0.0);
  std::vector<Index> firstSheet(nf);
  double totalArea = 0.0;
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = mesh.Faces[f];
    const Point3& p = mesh.Centers[t[0]];
    area[f] = 0.5 * Norm(Cross(mesh.Centers[t[1]] - p, mesh.Centers[t[2]] - p));
    firstSheet[f] = joined.Find(static_cast<Index>(f));
    rootArea[firstSheet[f]] += area[f];
    totalArea += area[f];
  }
  const double flapArea = options.MinimumSheetFraction * totalArea;
  std::vector<std::uint8_t> flapFace(nf, 0);
  for (std::size_t f = 0; f < nf; ++f)
  {
    flapFace[f] = rootArea[firstSheet[f]] < flapArea ? 1 : 0;
  }
  // Whether sheet (root) a is preferred to b as a host: larger, then lower
  // id; any sheet to none (b < 0).
  auto larger = [&](Index a, Index b)
  { return b < 0 || rootArea[a] > rootArea[b] || (rootArea[a] == rootArea[b] && a < b); };
  // Without the flaps, an edge may have two faces left: they join.
  for (std::size_t r = 0; r + 1 < runStart.size(); ++r)
  {
    Index kept[2] = { -1, -1 };
    int count = 0;
    for (std::size_t i = runStart[r]; i < runStart[r + 1]; ++i)
    {
      if (!flapFace[faceEdges[i].Face] && count++ < 2)
      {
        kept[count - 1] = faceEdges[i].Face;
      }
    }
    const auto& [a, b] = faceEdges[runStart[r]].Key;
    if (count == 2 && runStart[r + 1] - runStart[r] > 2 && !(feature(a) && feature(b)))
    {
      joined.Union(kept[0], kept[1]);
    }
  }
  std::vector<Index> hostOf(nf, -1); // per flap root, the root it joins
  for (std::size_t r = 0; r + 1 < runStart.size(); ++r)
  {
    for (std::size_t i = runStart[r]; i < runStart[r + 1]; ++i)
    {
      const Index flap = firstSheet[faceEdges[i].Face];
      if (!flapFace[faceEdges[i].Face])
      {
        continue;
      }
      for (std::size_t j = runStart[r]; j < runStart[r + 1]; ++j)
      {
        const Index other = firstSheet[faceEdges[j].Face];
        Index& host = hostOf[flap];
        if (other != flap && larger(other, host))
        {
          host = other;
        }
      }
    }
  }
  // A flap touching other sheets at vertices only joins the largest of them.
  std::vector<Index> sheetAtVertex(nv, -1); // the largest sheet at each vertex
  for (std::size_t f = 0; f < nf; ++f)
  {
    const Index sheet = firstSheet[f];
    for (Index v : mesh.Faces[f])
    {
      Index& at = sheetAtVertex[v];
      if (!flapFace[f] && larger(sheet, at))
      {
        at = sheet;
      }
    }
  }
  for (std::size_t f = 0; f < nf; ++f)
  {
    const Index flap = firstSheet[f];
    if (!flapFace[f] || (hostOf[flap] >= 0 && !flapFace[hostOf[flap]]))
    {
      continue;
    }
    for (Index v : mesh.Faces[f])
    {
      const Index other = sheetAtVertex[v];
      Index& host = hostOf[flap];
      if (other >= 0 && (host < 0 || flapFace[host] || larger(other, host)))
      {
        host = other;
      }
    }
  }
  for (std::size_t f = 0; f < nf; ++f)
  {
    if (hostOf[f] >= 0)
    {
      joined.Union(static_cast<Index>(f), hostOf[f]);
    }
  }

  // Edges by the faces on them, flaps' faces left out where others remain:
  // one face, a rim; three or more of two sheets or more, a seam.
  MedialStructure out;
  for (std::size_t r = 0; r + 1 < runStart.size(); ++r)
  {
    const std::size_t first = runStart[r], end = runStart[r + 1];
    std::size_t kept = 0;
    for (std::size_t i = first; i < end; ++i)
    {
      kept += flapFace[faceEdges[i].Face] ? 0 : 1;
    }
    const std::size_t faces = kept > 0 ? kept : end - first;
    // A sheet meeting only itself there is folded, not seamed.
    bool distinct = false;
    for (std::size_t i = first + 1; i < end && !distinct; ++i)
    {
      distinct = joined.Find(faceEdges[i].Face) != joined.Find(faceEdges[first].Face);
    }
    const auto& [a, b] = faceEdges[first].Key;
    if (faces == 1)
    {
      ++incidence[a].BoundaryEdges;
      ++incidence[b].BoundaryEdges;
    }
    else if (faces >= 3 && distinct)
    {
      ++incidence[a].SeamEdges;
      ++incidence[b].SeamEdges;
      out.SeamEdges.push_back(faceEdges[first].Key);
    }
  }
  for (const auto& [a, b] : EdgesNotOnFaces(mesh))
  {
    ++incidence[a].CurveEdges;
    ++incidence[b].CurveEdges;
  }

  const bool components = options.TangentComponents.size() == nv;
  out.VertexType.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Index id = static_cast<Index>(v);
    MedialVertexType& type = out.VertexType[v];
    type = TypeOf(incidence[v], feature(id), filletFlags && options.FilletVertex[v]);
    if (components && StructuralType(type))
    {
      const MedialVertexType matfp = TypeFromTangentComponents(options.TangentComponents[v]);
      ++out.ComparedVertices;
      out.Disagreements += matfp != type ? 1 : 0;
      if (options.ByTangentComponents)
      {
        type = matfp;
      }
    }
    ++out.TypeCounts[static_cast<int>(type)];
  }
  NumberSheets(mesh, area, joined, out);
  NumberSeams(nv, incidence, out);
  return out;
}
}
