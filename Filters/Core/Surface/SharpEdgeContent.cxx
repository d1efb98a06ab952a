// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/SharpEdgeContent.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Support/DisjointSets.h"
#include "Surface/FeatureNormals.h"
#include "Surface/SurfacePreparation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace medialaxis
{
double SharpEdgeContent::Ratio() const
{
  return this->Area > 0.0 ? this->CreaseLength / std::sqrt(this->Area) : 0.0;
}

SharpEdgeContent MeasureSharpEdgeContent(
  const TriangleMesh& mesh, double featureAngle, int normalFiltering, double creaseFraction)
{
  SharpEdgeContent content;
  content.Area = SurfaceArea(mesh);
  content.CreaseFraction = creaseFraction;
  // Convex edges are confirmed by the filtered normals there already; the
  // test below confirms concave ones the same way.
  std::vector<Point3> filtered;
  const TriangleAdjacency adjacency =
    FeatureAdjacency(mesh, featureAngle, normalFiltering, &filtered);
  const double cosine = std::cos(featureAngle);
  struct SharpEdge
  {
    Index A, B;
    double Length;
    double Angle; // between the two triangles' normals
  };
  std::vector<SharpEdge> sharp;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index other = adjacency.Neighbour[t][k];
      // Each edge once: from the triangle with the smaller id.
      if (other < 0 || static_cast<std::size_t>(other) < t ||
        adjacency.Feature[t][k] == EdgeFeature::None)
      {
        continue;
      }
      if (!filtered.empty() && Dot(filtered[t], filtered[other]) >= cosine)
      {
        continue;
      }
      const Index a = mesh.Triangles[t][k], b = mesh.Triangles[t][(k + 1) % 3];
      const double angle = std::acos(std::clamp(
        Dot(TriangleNormal(mesh, static_cast<Index>(t)), TriangleNormal(mesh, other)), -1.0, 1.0));
      sharp.push_back({ a, b, std::sqrt(Distance2(mesh.Points[a], mesh.Points[b])), angle });
      content.SharpLength += sharp.back().Length;
    }
  }
  // Creases: sharp edges joined where exactly two meet at a vertex, the line
  // turns there by less than kMaximumTurn and the normals' angle changes by
  // less than kMaximumAngleChange. Noise that survives the filter forms
  // branching, zig-zagging networks, which fall apart into short pieces; a
  // machined edge runs on smoothly, at one angle, from corner to corner.
  constexpr double kMaximumTurn = 0.5235987755982988;        // 30 degrees
  constexpr double kMaximumAngleChange = 0.2617993877991494; // 15 degrees
  std::vector<std::vector<std::size_t>> atVertex(mesh.Points.size());
  for (std::size_t e = 0; e < sharp.size(); ++e)
  {
    atVertex[sharp[e].A].push_back(e);
    atVertex[sharp[e].B].push_back(e);
  }
  DisjointSets creases(sharp.size());
  for (std::size_t v = 0; v < atVertex.size(); ++v)
  {
    if (atVertex[v].size() != 2)
    {
      continue;
    }
    const SharpEdge& in = sharp[atVertex[v][0]];
    const SharpEdge& out = sharp[atVertex[v][1]];
    const Point3& here = mesh.Points[v];
    const Point3 before = here - mesh.Points[in.A == static_cast<Index>(v) ? in.B : in.A];
    const Point3 after = mesh.Points[out.A == static_cast<Index>(v) ? out.B : out.A] - here;
    if (Dot(before, after) > std::cos(kMaximumTurn) * Norm(before) * Norm(after) &&
      std::abs(in.Angle - out.Angle) < kMaximumAngleChange)
    {
      creases.Union(static_cast<Index>(atVertex[v][0]), static_cast<Index>(atVertex[v][1]));
    }
  }
  std::map<Index, double> creaseLength;
  for (std::size_t e = 0; e < sharp.size(); ++e)
  {
    creaseLength[creases.Find(static_cast<Index>(e))] += sharp[e].Length;
  }
  const double shortest = creaseFraction * std::sqrt(content.Area);
  for (const auto& [root, length] : creaseLength)
  {
    if (length >= shortest)
    {
      content.CreaseLength += length;
      ++content.Creases;
    }
  }
  return content;
}

bool LooksLikeCad(const SharpEdgeContent& content, double minimumRatio)
{
  return content.Ratio() >= minimumRatio;
}
}
