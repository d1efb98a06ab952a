// SPDX-License-Identifier: GPL-3.0-or-later
// A final fit of a medial mesh to the surface it stands for: with the
// connectivity fixed, the spheres' centres and radii are moved so that the
// boundary of the envelope (the union of balls, cones and slabs) passes
// through the surface points, by damped Gauss-Newton (Levenberg-Marquardt)
// rounds over closest-primitive correspondences.
//
// Each surface point p gives the residual F(p), its signed distance to the
// envelope (positive where the envelope falls short of the surface, negative
// where it reaches past it); the objective is sum w F(p)^2 plus a penalty on
// balls reaching out of the surface. The nearest primitive interpolates one, two or
// three spheres with weights w_i at its tangency point, and the envelope
// theorem gives dF/dc_i = -w_i n and dF/dr_i = -w_i (n the outward normal
// there), so one round is a sparse linear solve over 4 unknowns per sphere.
// Moves that would fold or flatten a triangle or make a spike edge are
// shortened; a round is kept only when the objective falls, otherwise the
// damping grows and the round is tried again. With SpikeRepairWeight, spike
// edges already there are pulled apart by one more penalty term.
#ifndef medialaxis_EnvelopeFit_h
#define medialaxis_EnvelopeFit_h

#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace medialaxis
{
struct EnvelopeFitOptions
{
  /// Gauss-Newton rounds (each one rebuilds the envelope and measures every
  /// point once).
  int Iterations = 4;
  /// Stop after a kept round that lowered the objective by less than this
  /// fraction (the rounds after it would gain less still).
  double Convergence = 0.03;
  /// Weight of the term that keeps each ball inside the surface, (r - |c -
  /// q|)^2 where the ball reaches past its nearest point q, relative to the
  /// mean surface area per sphere. Without it, balls that grow to reach
  /// points on one side of a thin part poke out between points on the other.
  double OverreachWeight = 1.0;
  /// A sphere moves (centre and radius) by at most this fraction of the mean
  /// length of its edges per round, so that correspondences stay valid.
  double StepLimit = 0.5;
  /// Initial Levenberg-Marquardt damping, relative to the diagonal plus its
  /// mean (the mean keeps moves along the sheets, which change no distance,
  /// small). It never falls below a tenth of this.
  double Damping = 0.1;
  /// No move may turn an edge into a spike: stability ratio (|c1 - c2| -
  /// |r1 - r2|) / |c1 - c2| below this (the simplifier's threshold).
  double SpikeThreshold = 0.025;
  /// No move may fold two triangles of a sheet onto each other: a dihedral
  /// angle below this (degrees) where it was not before. The simplifier's
  /// pleat guard passes its PleatAngle, so that the fit does not bring back
  /// the pleats the collapses kept away (a noisy ellipsoid at 5,000 samples
  /// -> 500 spheres: 3.1% of the sheet edges below 90 degrees after the fit
  /// with the 10 degree guard, none before it).
  double FoldAngle = FoldAngleDegrees;
  /// Weight of the term that pulls spike edges apart, (|r1 - r2| - (1 -
  /// SpikeClearance) |c1 - c2|)^2 where positive, relative to
  /// OverreachWeight (0: spike edges are left as they are).
  double SpikeRepairWeight = 0.0;
  /// The stability ratio the repair aims at: twice the threshold, since the
  /// guard does not keep an edge that was a spike before the fit from
  /// sliding back under the threshold in later rounds (aiming just past it,
  /// 0.026, left 1.1% spike edges on the bunny at 50,000 samples -> 5,000
  /// spheres; 0.05 leaves 0.17%).
  double SpikeClearance = 0.05;
  /// Threads for the distance queries (0 = all); the result does not
  /// depend on it.
  int NumberOfThreads = 0;
  /// Fraction in [0, 1]; returning false stops the fit (the mesh is then
  /// left as the last accepted round made it).
  std::function<bool(double)> Progress;
};

struct EnvelopeFitResult
{
  /// Root mean square and largest |F| over the points, before and after.
  double InitialRms = 0.0, FinalRms = 0.0;
  double InitialMaximum = 0.0, FinalMaximum = 0.0;
  int AcceptedRounds = 0;
  int RejectedRounds = 0;
  bool Aborted = false;
};

/// What the fit may change of a sphere.
enum class SphereFreedom : std::uint8_t
{
  Free,      // centre and radius
  Fixed,     // nothing
  RadiusOnly // the radius; the centre stays
};

/// The surface to fit.
struct FitTarget
{
  /// Points the envelope is pulled through, with the surface area each
  /// stands for (empty: all 1).
  std::vector<Point3> Points;
  std::vector<double> Weights;
  /// Points of the surface, as dense as is cheap, for the test of balls
  /// reaching out of it (empty: Points).
  std::vector<Point3> Surface;
};

/// Moves the spheres of `mesh` as `freedom` allows (empty: all free) to fit
/// `target`. Deterministic at any thread count.
EnvelopeFitResult FitMedialEnvelope(MedialMesh& mesh, const FitTarget& target,
  const std::vector<SphereFreedom>& freedom,
  const EnvelopeFitOptions& options = EnvelopeFitOptions());
}

#endif
