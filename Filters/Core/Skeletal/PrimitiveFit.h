// SPDX-License-Identifier: GPL-3.0-or-later
// Fitting a generalized enveloping primitive to a closed surface (Medial
// Skeletal Diagram, paper 004, section 5.2): each template direction's
// radius r_j grows from the element's inscribed distance towards the
// surface, never past the first exit of its ray from the surface (r_max_j),
// with the template's graph Laplacian keeping the radius function smooth:
//
//   min  Smoothness ||L r||^2 + Expansion ||r - target||^2
//        + Stiffness sum over j in A of (r_j - r_max_j)^2,
//
// A = the directions whose radius passes r_max (an active set updated until
// it settles, as in projective dynamics), the target growing by a fraction
// of each initial ray length per progression. The radii end clamped to
// r_max, so the primitive stays inside the surface.
#ifndef medialaxis_PrimitiveFit_h
#define medialaxis_PrimitiveFit_h

#include "Mesh/TriangleLocator.h"
#include "Skeletal/PrimitiveTemplate.h"

#include <string>
#include <vector>

namespace medialaxis
{
struct PrimitiveFitOptions
{
  /// Weight of the smoothness term ||L r||^2 (L: the template's graph
  /// Laplacian, uniform weights).
  double Smoothness = 1.0;
  /// Weight of the pull towards the growing target radii.
  double Expansion = 2.0;
  /// Weight of the penalty on radii past their ray's exit.
  double Stiffness = 1e3;
  /// Steps of growth; each moves the target by StepFraction of the
  /// direction's ray length (at most to it).
  int Progressions = 20;
  double StepFraction = 0.1;
  /// Active-set rounds per progression.
  int Iterations = 15;
  /// Each direction's radius is its ray's exit, with no smoothing (the
  /// terms above are unused): the primitive meets the surface at every
  /// template direction, and FitPrimitiveRefined splits the template where
  /// the surface lies between directions, inside or outside, farther than
  /// RefinementTolerance. The smooth fit stops short wherever the radii
  /// vary (by its smoothness over expansion ratio times their Laplacian),
  /// which is the larger part of its distance to the surface.
  bool ExactRadii = false;
  /// FitPrimitiveRefined: a template triangle is split where the surface
  /// cuts in between its directions by more than RefinementTolerance
  /// (absolute; 0 never splits), in at most MaximumRefinements rounds, and
  /// no more once the template has RefinementGrowth times its points.
  double RefinementTolerance = 0.0;
  int MaximumRefinements = 8;
  std::size_t RefinementGrowth = 8;
};

struct FittedPrimitive
{
  /// Empty when the fit failed (then Error says why).
  std::vector<double> Radius;
  /// The distance along each direction to the ray's first exit from the
  /// surface.
  std::vector<double> MaximumRadius;
  std::string Error;
  int Progressions = 0; // taken
};

/// Fits the radii of `shape` inside `surface` (closed and outward, as
/// `locator` indexes it). Fails, with a message, when a direction's ray
/// never leaves the surface (the element is not inside it, or the surface
/// is open). Deterministic.
FittedPrimitive FitPrimitive(const TriangleMesh& surface, const TriangleLocator& locator,
  const PrimitiveTemplate& shape, const PrimitiveFitOptions& options = PrimitiveFitOptions());

/// FitPrimitive, then refines `shape` where the fitted primitive leaves the
/// surface between its directions (a narrow gap between two fingers that
/// no template ray meets, a notch) and fits again, until it does not or
/// MaximumRefinements rounds were made. Split, at the middles of their
/// edges (the neighbouring triangles split to match): the template
/// triangle nearest to each surface vertex or triangle centroid lying
/// inside the primitive deeper than RefinementTolerance; and an edge or
/// triangle at whose middle (base points averaged, directions averaged
/// and normalised) the interpolated radius passes the ray's exit from the
/// surface by more than that (the surface cuts in between surface points);
/// with ExactRadii also where it stops short of the exit by more than that.
/// Deterministic.
FittedPrimitive FitPrimitiveRefined(const TriangleMesh& surface, const TriangleLocator& locator,
  PrimitiveTemplate& shape, const PrimitiveFitOptions& options = PrimitiveFitOptions());

/// The refinement of FitPrimitiveRefined on a fit already made of `shape`
/// (left as it is when that fit failed). A round whose system fails to
/// converge ends it with the last fit.
void RefinePrimitive(const TriangleMesh& surface, const TriangleLocator& locator,
  PrimitiveTemplate& shape, FittedPrimitive& fit, const PrimitiveFitOptions& options);

/// The fitted primitive as a closed triangle mesh (the template's triangles
/// over PrimitivePoints); empty when the fit failed.
TriangleMesh PrimitiveSurface(const PrimitiveTemplate& shape, const FittedPrimitive& fit);
}

#endif
