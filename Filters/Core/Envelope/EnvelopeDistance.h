// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope of a medial mesh, U = union of its primitives (MedialPrimitives.h),
// and distance queries to it.
//
// F(p) = min over primitives of their signed distance. Outside U, F is the
// exact Euclidean distance to U. Inside U, -F(p) is the depth of p in the one
// primitive it is deepest in: only a lower bound of its distance to the
// boundary of the union, since a ball around p may fit in the union without
// fitting in any single primitive (at junctions and creases). Its zero set
// is exactly the boundary of U, and F is 1-Lipschitz.
//
// DistanceToBoundary gives the distance from any point to the boundary of U.
// For a point inside U it bounds that distance from both sides:
//  1. lower = -F(p), from the deepest primitive j; its closest boundary point
//     x = p + lower * n_j lies on the boundary of U unless it is strictly
//     inside another primitive. If it is not, x certifies upper = lower: the
//     value is exact (up to the tolerance below).
//  2. Otherwise the boundary of U near p is a crease (or corner) where
//     primitive boundaries cross. Candidate boundary points are found by an
//     active-set projection (the closest point of p on the intersection of
//     up to three primitive boundaries, by Gauss-Newton steps on the
//     linearised constraints, adding the primitive that buries the current
//     point), from
//     the closest boundary points of the deepest primitives, and by tracing
//     rays from p (the caller's hint, e.g. the surface normal, and n_j) until
//     F >= 0. Every candidate is checked to be outside the open union, so the
//     smallest candidate distance is a true upper bound: it is the distance to
//     an actual point of the boundary.
// The result is the pair (Lower, Upper) with Exact when they agree. Lower is
// always a rigorous lower bound, Upper a rigorous upper bound, and callers
// report Upper, so that a Hausdorff distance built from it is never an
// underestimate; how many points were not certified is counted by callers.
#ifndef medialaxis_EnvelopeDistance_h
#define medialaxis_EnvelopeDistance_h

#include "Envelope/PrimitivePairs.h"
#include "Geometry/BoxTree.h"
#include "Mesh/MedialMesh.h"
#include "Mesh/MedialPrimitives.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace medialaxis
{
/// Identifies a primitive: its kind and its id (vertex id for spheres, index
/// into AllEdges(mesh) for cones, face id for slabs).
struct PrimitiveRef
{
  PrimitiveKind Kind;
  Index Id;
};

class MedialEnvelope
{
public:
  /// A 26-sided bounding hull of balls (13 directions: axes, face and body
  /// diagonals). Bound(p) is the largest signed distance of p to its planes, a
  /// lower bound of the signed distance to any union of balls inside it.
  struct Dop
  {
    static constexpr int K = 13;
    double Lo[K], Hi[K];
    Dop()
    {
      for (int k = 0; k < K; ++k)
      {
        this->Lo[k] = std::numeric_limits<double>::infinity();
        this->Hi[k] = -std::numeric_limits<double>::infinity();
      }
    }
    static const Point3& Axis(int k)
    {
      static const double a = 1.0 / std::sqrt(2.0), b = 1.0 / std::sqrt(3.0);
      static const Point3 axes[K] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { a, a, 0 },
        { a, -a, 0 }, { a, 0, a }, { a, 0, -a }, { 0, a, a }, { 0, a, -a }, { b, b, b },
        { b, b, -b }, { b, -b, b }, { -b, b, b } };
      return axes[k];
    }
    void Extend(const SpherePrimitive& s)
    {
      for (int k = 0; k < K; ++k)
      {
        const Point3& u = Axis(k);
        const double t = u[0] * s.Center[0] + u[1] * s.Center[1] + u[2] * s.Center[2];
        this->Lo[k] = std::min(this->Lo[k], t - s.Radius);
        this->Hi[k] = std::max(this->Hi[k], t + s.Radius);
      }
    }
    void Extend(const Point3& p) { this->Extend(SpherePrimitive{ p, 0.0 }); }
    void Extend(const Dop& d)
    {
      for (int k = 0; k < K; ++k)
      {
        this->Lo[k] = std::min(this->Lo[k], d.Lo[k]);
        this->Hi[k] = std::max(this->Hi[k], d.Hi[k]);
      }
    }
    /// p projected on the K axes.
    static void Project(const Point3& p, double t[K])
    {
      for (int k = 0; k < K; ++k)
      {
        const Point3& u = Axis(k);
        t[k] = u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
      }
    }
    /// The bound for a point given by its projections.
    double Bound(const double t[K]) const
    {
      return pairs::Largest(pairs::HullBound<K>(t, this->Lo, this->Hi));
    }
  };

  /// Per tree node: two half-spaces u . x <= h containing every ball below
  /// it, with u the mean outward normal of each side of the slabs below (the
  /// sides of a medial sheet). Near a
  /// sheet's envelope they bound far more tightly than the 13 fixed axes.
  /// Without slabs: u = 0, h = +infinity (no bound).
  /// Stored by component (U[c][side]) so that both sides are one SSE2 step.
  struct SheetPlanes
  {
    double U[3][2];
    double H[2];
  };
  /// Builds every primitive of a valid medial mesh. With accelerate = false
  /// every query loops over all primitives (the brute-force reference).
  explicit MedialEnvelope(const MedialMesh& mesh, bool accelerate = true);

  const std::vector<SpherePrimitive>& Spheres() const { return this->SphereList; }
  const std::vector<ConePrimitive>& Cones() const { return this->ConeList; }
  const std::vector<SlabPrimitive>& Slabs() const { return this->SlabList; }
  /// Vertex pairs of the cones (AllEdges of the medial mesh).
  const std::vector<std::array<Index, 2>>& ConeEdges() const { return this->Edges; }
  const std::vector<std::array<Index, 3>>& SlabFaces() const { return this->Faces; }

  bool Empty() const { return this->Active.empty(); }
  /// Bounding box of the union (empty when there is no primitive).
  const Box& Bounds() const { return this->UnionBounds; }
  double Diagonal() const;
  /// Absolute tolerance of boundary tests: 1e-10 x the diagonal.
  double Tolerance() const { return this->Tol; }

  struct Nearest
  {
    double Distance = 0.0; // F(p)
    Point3 Normal{ 0, 0, 1 };
    PrimitiveRef Primitive{ PrimitiveKind::Sphere, -1 };
  };
  /// F(p): the smallest signed distance over all primitives, the outward
  /// normal at that primitive's closest boundary point, and the primitive.
  ///
  /// `warm` (may be null) carries a primitive from one query to the next:
  /// when set, the search starts from that primitive's value at p (a nearby
  /// point's nearest primitive is near p too, which lets the search skip
  /// more of the tree), and it is set to the primitive found. The value is
  /// the same either way.
  static constexpr std::uint32_t NoPrimitive = std::numeric_limits<std::uint32_t>::max();
  Nearest SignedDistance(const Point3& p, std::uint32_t* warm = nullptr) const;

  /// True when F(p) < -tolerance: p is strictly inside some primitive.
  bool StrictlyInside(const Point3& p, double tolerance) const;
  /// The same, trying first the primitives incident to the given medial
  /// vertices (for a point on a primitive's surface, its neighbours are the
  /// likely ones to bury it).
  bool StrictlyInside(const Point3& p, double tolerance, const Index* vertices, int count) const;

  /// A primitive containing p deeper than tolerance, as an opaque handle, or
  /// NoBurial. Tried in order: `hint` (a handle returned for a nearby point:
  /// neighbouring points are mostly buried by the same primitive), the
  /// primitives incident to the given medial vertices, then the tree. With
  /// maxItems, the tree search gives up after evaluating that many
  /// primitives, so NoBurial only means "none found" (deterministically).
  static constexpr std::uint32_t NoBurial = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t FindBurying(const Point3& p, double tolerance, const Index* vertices, int count,
    std::uint32_t hint = NoBurial,
    std::size_t maxItems = std::numeric_limits<std::size_t>::max()) const;

  /// The primitive behind a handle returned by FindBurying.
  PrimitiveRef BuryingPrimitive(std::uint32_t handle) const;

  struct BoundaryDistance
  {
    double Signed; // F(p) outside; -Upper inside
    double Lower;  // rigorous lower bound of the distance to the boundary of U
    double Upper;  // rigorous upper bound (distance to a boundary point found)
    bool Inside;   // F(p) < 0
    bool Exact;    // Upper - Lower within twice the tolerance
  };
  /// Unsigned distance from p to the boundary of U as a two-sided bound, see
  /// the file comment. `hint` (may be null) is a direction in which the
  /// boundary is likely near, e.g. the outward surface normal at p.
  /// `warm` as for SignedDistance.
  BoundaryDistance DistanceToBoundary(
    const Point3& p, const Point3* hint = nullptr, std::uint32_t* warm = nullptr) const;

  /// The medial vertices of a primitive (1 for a ball, 2 for a cone, 3 for a
  /// slab), written to `vertices`; returns their number.
  int MedialVertices(const PrimitiveRef& ref, Index vertices[3]) const;

  /// Signed distance to one primitive (the full primitive, slabs with their
  /// edge cones).
  PrimitiveDistance PrimitiveSignedDistance(const PrimitiveRef& ref, const Point3& p) const;

private:
  // Primitives taking part in F (an index into this->Active): balls of
  // isolated vertices only (a ball with an edge lies inside that edge's
  // cone), every cone, and the interior part of slabs with tangent planes
  // (their edge cones are cones already).
  double ActiveValue(std::uint32_t active, const Point3& p) const;
  PrimitiveDistance ActiveDistance(std::uint32_t active, const Point3& p) const;
  void Containing(const Point3& p, std::vector<std::pair<double, std::uint32_t>>& out) const;
  double ProjectOntoBoundary(const Point3& p, std::uint32_t start) const;
  double TraceExit(const Point3& p, const Point3& direction, double limit) const;
  void BuildSheetPlanes();
  void BuildLeafParts();
  void BuildLeafBlocks();
  // Tree search for burial tests (visit(position, value) returns true to stop):
  // in each leaf, balls and cones are looked at only if p is inside the hull
  // of their balls, slab interiors only if inside the hull of their regions.
  template <typename Visit>
  void SearchBurial(const Point3& p, double tolerance, Visit&& visit) const;

  std::vector<SpherePrimitive> SphereList;
  std::vector<ConePrimitive> ConeList;
  std::vector<SlabPrimitive> SlabList;
  std::vector<std::array<Index, 2>> Edges;
  std::vector<std::array<Index, 3>> Faces;
  std::vector<PrimitiveRef> Active;
  // Compact copy of each active primitive for the distance loops: sphere
  // (centre, radius), cone (C0, R0, axis, sin, cos, length x cos, C1, R1),
  // slab interior (C0, plane normal, tangent normals and offsets, gamma,
  // edges, inverse Gram matrix).
  struct Compact
  {
    double D[24];
    int Kind; // 0 sphere (or nested cone), 1 cone, 2 slab interior
  };
  std::vector<Compact> Records;    // in the tree's item order (locality)
  std::vector<std::uint32_t> Slot; // active id -> index in Records
  // Active primitives incident to each medial vertex (compressed rows).
  std::vector<std::uint32_t> IncidentOffsets, Incident;
  std::vector<Box> ActiveBoxes;        // boxes of the centres
  std::vector<Box> ActiveBallBoxes;    // boxes of the primitives
  std::vector<Dop> NodeDops;           // per tree node: hull of the balls below it
  std::vector<SheetPlanes> NodePlanes; // per tree node
  // Per leaf (indexed by node): its items are the balls and cones first, then
  // the slab interiors (Split of them before). Balls: hull of their balls.
  // Regions: hull of the parts of space where the slab interiors can bury a
  // point, {f + t n : f in the centre triangle, 0 <= t <= r(f)} for either
  // side's tangent normal n, i.e. the centres and the tangent points. Used
  // by burial tests and, for points outside the regions' hull, SignedDistance.
  struct LeafParts
  {
    std::uint32_t Split = 0;
    Dop Balls, Regions;
    // Where the leaf's blocks of two start in RoundBlocks and SlabBlocks.
    std::uint32_t Round = 0, Slab = 0;
  };
  std::vector<LeafParts> Leaves;
  // The leaves' records again, in blocks of two field by field for the
  // paired evaluation of their scans (PrimitivePairs.h); a leaf part of odd
  // size ends with a padding lane whose value is +infinity.
  std::vector<double> RoundBlocks, SlabBlocks;
  // Values of the records [begin, end) of leaf part `parts` at p, in order,
  // as visit(position, value); stops when visit returns true.
  template <typename Visit>
  bool ScanRound(const LeafParts& parts, std::uint32_t begin, std::uint32_t end,
    const pairs::Query& query, Visit&& visit) const;
  template <typename Visit>
  bool ScanSlabs(const LeafParts& parts, std::uint32_t begin, std::uint32_t end,
    const pairs::Query& query, Visit&& visit) const;
  std::vector<double> ActiveRadius; // largest radius
  BoxTree Tree;
  bool Accelerate;
  Box UnionBounds;
  double Tol = 0.0;
};
}

#endif
