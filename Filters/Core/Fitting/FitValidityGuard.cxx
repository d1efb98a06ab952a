// SPDX-License-Identifier: GPL-3.0-or-later
#include "Fitting/FitValidityGuard.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
namespace
{
bool Degenerate(const MedialMesh& mesh, const std::array<Index, 3>& t)
{
  return IsDegenerateTriangle(mesh.Centers[t[0]], mesh.Centers[t[1]], mesh.Centers[t[2]]);
}

int HingeFoldLevel(const MedialMesh& mesh, const TriangleHinge& h, double cosPleat)
{
  const auto& c = mesh.Centers;
  return FoldLevel(c[h.U], c[h.V], c[h.X], c[h.Y], cosPleat);
}
}

ValidityGuard::ValidityGuard(const MedialMesh& mesh, const std::vector<std::array<Index, 2>>& edges,
  double spikeThreshold, double foldAngleDegrees)
  : Edges(edges)
  , Hinges(TriangleHinges(mesh))
  , SpikeThreshold(spikeThreshold)
  // Folds (10 degrees) are always guarded, with the exact constant;
  // larger angles guard against pleats too.
  , GuardCosine(foldAngleDegrees > FoldAngleDegrees
        ? std::cos(foldAngleDegrees * 3.14159265358979323846 / 180.0)
        : FoldCosine)
{
  for (const TriangleHinge& h : this->Hinges)
  {
    this->FoldBefore.push_back(
      static_cast<std::uint8_t>(HingeFoldLevel(mesh, h, this->GuardCosine)));
  }
  for (const auto& t : mesh.Faces)
  {
    this->DegenerateBefore.push_back(Degenerate(mesh, t));
  }
  for (const auto& e : edges)
  {
    this->SpikeBefore.push_back(this->Spike(mesh, e));
  }
}

void ValidityGuard::Shorten(const MedialMesh& current, MedialMesh& candidate) const
{
  const std::size_t nv = current.NumberOfVertices();
  std::vector<double> shareC(nv, 1.0), shareR(nv, 1.0);
  std::vector<Point3> moveC(nv);
  std::vector<double> moveR(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    moveC[v] = candidate.Centers[v] - current.Centers[v];
    moveR[v] = candidate.Radii[v] - current.Radii[v];
  }
  std::vector<Index> flaggedC, flaggedR; // shorten the centre's move, the radius's
  const auto flag = [&](Index v, bool radiusToo)
  {
    if (shareC[v] > 0.0 && moveC[v] != Point3{ 0, 0, 0 })
    {
      flaggedC.push_back(v);
    }
    if ((radiusToo || moveR[v] > 0.0) && shareR[v] > 0.0 && moveR[v] != 0.0)
    {
      flaggedR.push_back(v);
    }
  };
  const auto shorten = [](std::vector<Index>& flagged, std::vector<double>& share)
  {
    std::sort(flagged.begin(), flagged.end());
    flagged.erase(std::unique(flagged.begin(), flagged.end()), flagged.end());
    for (Index v : flagged)
    {
      share[v] = share[v] > 1.0 / 8.0 ? 0.5 * share[v] : 0.0;
    }
  };
  for (;;)
  {
    flaggedC.clear();
    flaggedR.clear();
    for (std::size_t f = 0; f < candidate.Faces.size(); ++f)
    {
      const auto& t = candidate.Faces[f];
      if (!this->DegenerateBefore[f] && Degenerate(candidate, t))
      {
        for (Index v : t)
        {
          flag(v, false);
        }
      }
    }
    for (std::size_t i = 0; i < this->Hinges.size(); ++i)
    {
      const TriangleHinge& h = this->Hinges[i];
      // No pleat where there was none, no fold where there was none (a
      // pleat before the fit may open up, not fold onto itself).
      if (HingeFoldLevel(candidate, h, this->GuardCosine) > this->FoldBefore[i])
      {
        for (Index v : { h.U, h.V, h.X, h.Y })
        {
          flag(v, false);
        }
      }
    }
    for (std::size_t i = 0; i < this->Edges.size(); ++i)
    {
      const auto& e = this->Edges[i];
      if (!this->SpikeBefore[i] && this->Spike(candidate, e))
      {
        flag(e[0], true);
        flag(e[1], true);
      }
    }
    if (flaggedC.empty() && flaggedR.empty())
    {
      return;
    }
    shorten(flaggedC, shareC);
    shorten(flaggedR, shareR);
    for (Index v : flaggedC)
    {
      candidate.Centers[v] = current.Centers[v] + shareC[v] * moveC[v];
    }
    for (Index v : flaggedR)
    {
      candidate.Radii[v] = current.Radii[v] + shareR[v] * moveR[v];
    }
  }
}

bool ValidityGuard::Spike(const MedialMesh& mesh, const std::array<Index, 2>& e) const
{
  return StabilityRatio(mesh.Centers[e[0]], mesh.Radii[e[0]], mesh.Centers[e[1]],
           mesh.Radii[e[1]]) < this->SpikeThreshold;
}
}
