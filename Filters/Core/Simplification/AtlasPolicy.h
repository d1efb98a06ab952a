// SPDX-License-Identifier: GPL-3.0-or-later
// The cost policy of SimplifyMedialAxis (AtlasSimplifier.h): the Atlas
// energy of paper "Structural MAT" for MedialEdgeCollapse. Each vertex keeps
// its Atlas and the quadric of its regular cells; a collapse places the
// merged sphere by that energy over the union of both Atlases, with the
// spike-stability weight, the error bound and the snapping of feature
// vertices onto sharp edges.
#ifndef medialaxis_AtlasPolicy_h
#define medialaxis_AtlasPolicy_h

#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Simplification/AtlasSimplifier.h"
#include "Simplification/EdgeCollapse.h"
#include "Simplification/SphereQuadric.h"
#include "Support/Prefetch.h"

#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace medialaxis
{
// Cost of a collapse and where it puts the merged sphere.
struct Placement
{
  double Energy = HUGE_VAL;
  Sphere Target{};
};

// What the Atlas policy needs of the sites and their restricted Voronoi
// cells alone, in the unit frame of the sites' bounding box: made apart from
// the medial mesh (beside the hair erosion, which needs the mesh alone),
// then handed to the policy. Not movable: SiteTree refers to Site.
struct AtlasSiteCells
{
  AtlasSiteCells(const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites,
    const AtlasSimplifierOptions& options);
  AtlasSiteCells(const AtlasSiteCells&) = delete;
  AtlasSiteCells& operator=(const AtlasSiteCells&) = delete;

  Normalisation UnitFrame;
  double Diagonal = 0.0; // of the sites' bounding box, in the unit frame
  std::vector<Point3> Site;
  std::unique_ptr<KdTree> SiteTree; // with an error bound: for balls poking out
  std::vector<SphereQuadric> CellQuadric;
  std::vector<double> CellArea;
  // Squared distance from each site to the farthest vertex of its cell:
  // every point of the cell lies within it.
  std::vector<double> CellReach;
  // The diagram's polygons of each cell: those of site s are
  // SitePolygons[SitePolygonOffsets[s] .. SitePolygonOffsets[s + 1]).
  std::vector<Index> SitePolygonOffsets;
  std::vector<Index> SitePolygons;
  std::vector<std::uint8_t> Convex, Invaginated;
};

// The Atlas energy of paper 000 as a collapse policy: each vertex carries
// its Atlas and the quadric of its regular cells; feature vertices snap onto
// sharp edges and stay there.
class AtlasPolicy final : public CollapsePolicy
{
public:
  AtlasPolicy(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
    const std::vector<Point3>& sites, const AtlasSimplifierOptions& options);
  /// With the sites' part made already (for the same rvd, sites and options).
  AtlasPolicy(const AtlasMedialMesh& input, const RestrictedVoronoiDiagram& rvd,
    std::unique_ptr<const AtlasSiteCells> cells, const AtlasSimplifierOptions& options);

  const Normalisation& Frame() const { return this->UnitFrame; }
  /// The diagonal of the sites' bounding box, in the unit frame.
  double DiagonalLength() const { return this->Diagonal; }
  Evaluation Evaluate(
    const MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) const override;
  std::array<Sphere, 3> FallbackSpheres(
    const MedialEdgeCollapse& mesh, Index a, Index b) const override;
  bool WithinBound(const MedialEdgeCollapse& mesh, Index a, Index b, const Sphere& target,
    CollapseScratch& scratch) const override;
  bool RaiseBound() override;
  void Merged(MedialEdgeCollapse& mesh, Index a, Index b, CollapseScratch& scratch) override;
  std::vector<Index> Prepare(MedialEdgeCollapse& mesh) override;
  void AfterCollapse(MedialEdgeCollapse& mesh, Index a, CollapseScratch& scratch) override;
  void Prefetch(Index v) const override
  {
    PrefetchObject(&this->AtlasQuadric[v]);
    medialaxis::Prefetch(this->Atlas[v].data());
  }
  AtlasMedialMesh Output(const MedialEdgeCollapse& mesh) const;

  std::atomic<std::size_t> Snapped{ 0 }; // by collapses running at once
  std::size_t ForcedSnaps = 0;

private:
  Placement Solve(const MedialEdgeCollapse& mesh, const SphereQuadric& q,
    const std::vector<std::pair<Point3, double>>& anchors, Index a, Index b) const;
  // Psi (Eq. 16); with the sharpness of absorbed spikes (AbsorbSpikes) when
  // `absorbed`.
  double Weight(double spike, bool absorbed) const;
  double NearestAtlasSite(
    const Point3& centre, const std::vector<Index>& A, const std::vector<Index>& B) const;
  void ClampToAtlas(const SphereQuadric& q, const std::vector<std::pair<Point3, double>>& anchors,
    const std::vector<Index>& A, const std::vector<Index>& B, Placement& p) const;
  // Moves feature vertex v onto its sharp edge (r = 0); with keepValid, not
  // when that would make a zero-area or folded triangle.
  enum class SnapResult
  {
    Moved,
    Refused, // the move would make a zero-area or folded triangle
    NoTarget // no point near the Atlas fits its cells' planes
  };
  SnapResult Snap(MedialEdgeCollapse& mesh, Index v, bool keepValid, CollapseScratch& scratch);
  // Whether a snap target lies among v's Atlas sites (see Snap), or a
  // zero-radius sphere among the sites of the union of two Atlases.
  bool NearAtlas(Index v, const Point3& target) const
  {
    return this->NearAtlas(target, this->Atlas[v], {});
  }
  bool NearAtlas(
    const Point3& target, const std::vector<Index>& A, const std::vector<Index>& B) const;
  void UpdateFeature(Index v);
  // A feature vertex already on its sharp edge (snapped, radius 0).
  bool OnFeature(const MedialEdgeCollapse& mesh, Index v) const
  {
    return this->Feature[v] && mesh.SphereOf(v)[3] == 0.0;
  }

  const AtlasSimplifierOptions& Options;
  const RestrictedVoronoiDiagram& Rvd;
  // Per site (see AtlasSiteCells), read through the references below.
  std::unique_ptr<const AtlasSiteCells> Cells;
  const Normalisation& UnitFrame;
  const double Diagonal;
  const std::unique_ptr<KdTree>& SiteTree;
  const std::vector<SphereQuadric>& CellQuadric;
  const std::vector<double>& CellArea;
  const std::vector<double>& CellReach;
  const std::vector<Index>& SitePolygonOffsets;
  const std::vector<Index>& SitePolygons;
  const std::vector<Point3>& Site;
  const std::vector<std::uint8_t>&Convex, &Invaginated;
  double ErrorBound = 0.0;   // ErrorBound in the unit frame (0: none)
  bool RaisingBound = false; // the bound rises at stalls (error bands)
  // Per vertex.
  std::vector<std::vector<Index>> Atlas;
  std::vector<SphereQuadric> AtlasQuadric; // regular cells of the Atlas, each once
  std::vector<char> Feature;
  std::vector<char> AnyInvaginated; // some cell of the Atlas is invaginated
  // Per vertex, with error bounds: no site is nearer to Centre than Value
  // (-1: nothing known), proved where a merged sphere was placed. The sites
  // stay put, so a bound holds at its point whatever the vertex does next,
  // and gives D(c) >= Value - |c - Centre| anywhere else (the distance to
  // the nearest site is 1-Lipschitz): most merged balls are then known to
  // be clear without a search.
  struct SiteClearanceBound
  {
    Point3 Centre{ 0, 0, 0 };
    double Value = -1.0;
  };
  std::vector<SiteClearanceBound> Clearance;
  double ClearanceAt(Index v, const Point3& c) const
  {
    const SiteClearanceBound& k = this->Clearance[v];
    return k.Value < 0.0 ? -HUGE_VAL : k.Value - std::sqrt(Distance2(c, k.Centre));
  }
};
}

#endif
