// SPDX-License-Identifier: GPL-3.0-or-later
// A fillet's centre line, once its medial edges are chained: the envelope of
// its rolling ball (which surface points it explains), the refinement of its
// vertices and radii by circle fits to the surface, the trimming of folded
// ends and the measures reported for it.
#ifndef medialaxis_CentreLine_h
#define medialaxis_CentreLine_h

#include "Fillets/FilletDetector.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialPrimitives.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace medialaxis
{
// One piece of a centre line's envelope, with the radius that scales the
// tolerance of points near it.
struct EnvelopePiece
{
  ConePrimitive Cone;     // a ball when both ends coincide
  Point3 Lo, Hi;          // bounding box, grown by the tolerance
  bool Extension = false; // extrapolated past an end of the line
  Point3 LineDirection;   // unit, of the centre line there (zero: none)
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

LineEnd FitLineEnd(const std::vector<Point3>& centres, const std::vector<double>& radii, bool back);

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
        // The last vertex and the fitted end nearly coincide: the piece
        // between them takes the fitted line's direction, not theirs.
        this->Add(centres[last], radii[last], fit.Centre, fit.Radius, true, &fit.Direction);
        this->Add(fit.Centre, fit.Radius, fit.Centre + reach * fit.Direction,
          fit.Radius * (1.0 + 2.0 * fit.Slope), true);
      }
    }
  }

  // Where p lies on the envelope, within `tolerance` times the local radius,
  // with the surface normal `normal`: the envelope's normal there, the
  // centre line's direction (zero on a ball) and the tolerance applied
  // (larger past the ends).
  struct Match
  {
    Point3 Normal;
    Point3 LineDirection;
    double Tolerance;
  };
  std::optional<Match> Find(const Point3& p, const Point3& normal, double tolerance) const
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
        return Match{ d.Normal, piece.LineDirection, tol };
      }
    }
    return std::nullopt;
  }

  // Whether p lies on the envelope (see Find).
  bool Matches(const Point3& p, const Point3& normal, double tolerance) const
  {
    return this->Find(p, normal, tolerance).has_value();
  }

private:
  void Add(const Point3& c0, double r0, const Point3& c1, double r1, bool extension = false,
    const Point3* lineDirection = nullptr)
  {
    EnvelopePiece piece;
    piece.Extension = extension;
    piece.Cone = MakeCone(c0, r0, c1, r1);
    piece.LineDirection = lineDirection ? *lineDirection
      : piece.Cone.Length > 0.0         ? piece.Cone.Axis
                                        : Point3{ 0, 0, 0 };
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

// Moves each centre-line vertex to the centre of the circle fitted to the
// fillet's cross-section there (the surface points nearest to it, projected
// on the plane across the line), and takes that circle's radius.
// With `fromLine`, each point is measured from its closest point on the
// current line instead of from the vertex: on a curved line, sections then
// do not smear, provided the line is already close to the true one.
void RefineCentreLine(
  Fillet& fillet, const std::vector<Point3>& points, double inlier, bool fromLine);

// The arc (radians) of the circle around the line that `points` (the
// corners of its faces) cover: the median over the line's segments of the
// angle the points beside each span around it.
double FacesArc(const Fillet& fillet, const std::vector<Point3>& points);

// The last medial edges of an open line may turn back on it (the ends of
// medial sheets zig-zag); such an end vertex is no further along the line.
void TrimFoldedEnds(Fillet& chain);

// Whether the point nearest to p on an open polyline is one of its ends.
bool PastAnEnd(const std::vector<Point3>& line, const Point3& p);

// Length and radii (minimum, maximum, length-weighted mean, variation).
void MeasureFillet(Fillet& chain);
}

#endif
