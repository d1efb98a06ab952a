// SPDX-License-Identifier: GPL-3.0-or-later
// The parts of the primitives' surfaces that can lie on the boundary of the
// envelope (the union of the medial primitives), from which the envelope
// samples of the reconstruction error are drawn, and the draw itself.
#ifndef medialaxis_ExposedPieces_h
#define medialaxis_ExposedPieces_h

#include "Envelope/EnvelopeDistance.h"
#include "Geometry/AreaSampling.h"
#include "Geometry/Vec3.h"
#include "Support/Random.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace medialaxis
{
// A piece of a primitive surface that candidates are drawn from: a direction
// cell of a ball (A = z range, B = angle range), a slant and angle range of a
// cone band (A = fraction of the slant, B = angle), or a slab's tangent
// triangle (Side).
struct ExposedPiece
{
  PrimitiveRef Ref;
  int Side;
  double A0, A1, B0, B1;
  double Area = 0.0;
};

// Direction of unit z-coordinate z and angle theta about the z axis.
inline Point3 Direction(double z, double theta)
{
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  return { rho * std::cos(theta), rho * std::sin(theta), z };
}

// Point of a cone band at slant fraction sigma and angle theta.
inline Point3 BandPoint(const ConePrimitive& c, double sigma, double theta)
{
  const Point3 radial = std::cos(theta) * c.Perp1 + std::sin(theta) * c.Perp2;
  const Point3 slant = c.CosPhi * c.Axis - c.SinPhi * radial;
  return ConeTangentPoint(c, 0, theta) + (sigma * c.Length * c.CosPhi) * slant;
}

inline Point3 SamplePiece(const MedialEnvelope& envelope, const ExposedPiece& piece, Random& rng)
{
  const double u = rng.Uniform(), v = rng.Uniform();
  switch (piece.Ref.Kind)
  {
    case PrimitiveKind::Sphere:
    {
      const SpherePrimitive& s = envelope.Spheres()[piece.Ref.Id];
      return s.Center +
        s.Radius *
        Direction(piece.A0 + u * (piece.A1 - piece.A0), piece.B0 + v * (piece.B1 - piece.B0));
    }
    case PrimitiveKind::Cone:
    {
      // Area density along the slant grows linearly with the ring radius:
      // rho(sigma) = rho0 + k sigma; invert its integral from A0.
      const ConePrimitive& c = envelope.Cones()[piece.Ref.Id];
      const double rho0 = c.R[0] * c.CosPhi, k = (c.R[1] - c.R[0]) * c.CosPhi;
      const double s0 = piece.A0, s1 = piece.A1;
      double sigma = s0 + u * (s1 - s0);
      if (std::abs(k) > 1e-12 * (std::abs(rho0) + std::abs(k)))
      {
        const double total = rho0 * (s1 - s0) + 0.5 * k * (s1 * s1 - s0 * s0);
        const double q = rho0 * s0 + 0.5 * k * s0 * s0 + u * total;
        sigma =
          std::clamp((std::sqrt(std::max(0.0, rho0 * rho0 + 2.0 * k * q)) - rho0) / k, s0, s1);
      }
      return BandPoint(c, sigma, piece.B0 + v * (piece.B1 - piece.B0));
    }
    default:
    {
      const auto t = SlabTangentTriangle(envelope.Slabs()[piece.Ref.Id], piece.Side);
      return PointInTriangle(t[0], t[1], t[2], u, v);
    }
  }
}

// The pieces of every primitive surface that can be on the boundary of the
// union, with their areas: a piece is dropped when the support-function test
// (file comment) or a burial test excludes it. Burial: a point x of the piece
// with every point of the piece within g of x, and some primitive containing
// x deeper than g + tolerance: since signed distances are 1-Lipschitz, the
// whole piece is strictly inside that primitive.
struct ExposedPieceSet
{
  std::vector<ExposedPiece> Pieces;
  GuidedCdf Cdf; // of the pieces' areas
};

ExposedPieceSet EnvelopePieces(const MedialEnvelope& envelope);
}

#endif
