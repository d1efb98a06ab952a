// SPDX-License-Identifier: GPL-3.0-or-later
// The Atlas policy's error bound: whether the Atlas samples of a collapse
// stay within ErrorBound of the envelope it leaves, and the bound's growth
// when the queue stalls (the error bands).
#include "Simplification/AtlasPolicy.h"

#include "Envelope/PrimitiveRecords.h"
#include "Support/SortedLists.h"

#include <algorithm>
#include <cmath>

namespace medialaxis
{
// Every site of the merged Atlas within ErrorBound of the merged vertex's
// envelope (ball, cones to the merged neighbours, slabs of the faces that
// stay), on either side.
bool AtlasPolicy::WithinBound(const MedialEdgeCollapse& mesh, Index a, Index b,
  const Sphere& target, CollapseScratch& scratch) const
{
  if (!(this->ErrorBound > 0.0))
  {
    return true;
  }
  const SpherePrimitive ball{ { target[0], target[1], target[2] }, target[3] };
  // How far the merged ball pokes out of the surface, seen from the nearest
  // site of all (its Atlas may lie on one side of a thin part only). The
  // test is monotone in the distance, so the nearest site fails it exactly
  // when some site does: the search stops at the first (a site can only
  // fail it within Radius - ErrorBound, widened for rounding).
  const double reach = ball.Radius - this->ErrorBound;
  scratch.ProvenClearance = -1.0;
  if (reach > 0.0)
  {
    // Known clear from the bounds at a and b (with a margin far above the
    // rounding of the distances, so that the answer is the search's), or
    // else searched: the nearest site, unless one fails the test first.
    const double margin = 1e-9 * this->Diagonal;
    const double known =
      std::max(this->ClearanceAt(a, ball.Center), this->ClearanceAt(b, ball.Center));
    double clearance = known;
    if (known < reach + margin)
    {
      const double d2 = this->SiteTree->NearestUnless(ball.Center, reach * reach * (1.0 + 1e-9),
        [&](double s2) { return ball.Radius - std::sqrt(s2) > this->ErrorBound; });
      if (d2 < 0.0)
      {
        return false;
      }
      clearance = std::sqrt(d2) - margin;
    }
    scratch.ProvenTarget = target;
    scratch.ProvenClearance = clearance;
  }
  // Every Atlas site's value over the primitives the collapse leaves around
  // the merged ball, each primitive at all the sites at once.
  auto& rounds = scratch.RoundRecords;
  rounds.clear();
  ForEachInUnion(mesh.Neighbours(a), mesh.Neighbours(b),
    [&](Index u, bool)
    {
      if (u != a && u != b)
      {
        rounds.push_back(records::MakeRound(
          MakeCone(ball.Center, ball.Radius, mesh.Position(u), mesh.SphereOf(u)[3])));
      }
    });
  if (rounds.empty()) // (every cone holds the ball)
  {
    rounds.push_back(records::MakeRound(ball));
  }
  auto& slabs = scratch.SlabRecords;
  slabs.clear();
  for (const auto& [face, id] : scratch.FaceKeys)
  {
    std::array<Point3, 3> c;
    std::array<double, 3> r;
    for (int k = 0; k < 3; ++k)
    {
      const bool merged = face[k] == a;
      c[k] = merged ? ball.Center : mesh.Position(face[k]);
      r[k] = merged ? ball.Radius : mesh.SphereOf(face[k])[3];
    }
    records::Slab record;
    if (records::MakeSlab(MakeSlabInterior(c, r), record))
    {
      slabs.push_back(record);
    }
  }
  auto& x = scratch.SiteX;
  auto& y = scratch.SiteY;
  auto& z = scratch.SiteZ;
  x.clear();
  y.clear();
  z.clear();
  ForEachInUnion(this->Atlas[a], this->Atlas[b],
    [&](Index s, bool)
    {
      x.push_back(this->Site[s][0]);
      y.push_back(this->Site[s][1]);
      z.push_back(this->Site[s][2]);
    });
  const std::size_t count = x.size();
  if (count % 2 == 1) // the lanes read a pair at a time
  {
    x.push_back(x.back());
    y.push_back(y.back());
    z.push_back(z.back());
  }
  auto& values = scratch.SiteValues;
  values.assign(x.size(), HUGE_VAL);
  // In runs of sites, so that a collapse that fails stops early.
  constexpr std::size_t Run = 32;
  for (std::size_t first = 0; first < count; first += Run)
  {
    const records::PointLanes sites{ x.data() + first, y.data() + first, z.data() + first,
      std::min(Run, count - first) };
    double* value = values.data() + first;
    for (const records::Round& record : rounds)
    {
      records::LowerTo(record, sites, value);
    }
    for (const records::Slab& record : slabs)
    {
      records::LowerTo(record, sites, value);
    }
    for (std::size_t i = 0; i < sites.Count; ++i)
    {
      if (!(std::abs(value[i]) <= this->ErrorBound))
      {
        return false;
      }
    }
  }
  return true;
}

bool AtlasPolicy::RaiseBound()
{
  if (!this->RaisingBound || !(this->ErrorBound > 0.0))
  {
    return false;
  }
  this->ErrorBound *= this->Options.ErrorBandGrowth;
  if (this->ErrorBound > this->Diagonal)
  {
    this->ErrorBound = 0.0; // no bound left
  }
  return true;
}
}
