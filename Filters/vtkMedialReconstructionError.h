// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkMedialReconstructionError
 * @brief   Distance between a surface and the envelope of its medial mesh.
 *
 * Input port 0: the surface (closed triangle mesh; it is prepared like every
 * surface input, see vtkMedialSurfaceValidator). Input port 1: the medial
 * mesh (points with point data `Radius`). The envelope is the union of the
 * medial primitives (balls, cones, slabs; see vtkSlabReconstructor), measured
 * exactly by closed-form distances instead of a remeshed approximation.
 *
 * Port 1 may instead be any closed surface that reconstructs the input
 * (polygons and no point data `Radius`): the reconstruction output of
 * vtkMedialSkeletalDiagram, vtkSlabReconstructor's boundary mode, another
 * tool's result. It is then the envelope below: distances are to its
 * triangles (exact, so the lower bounds equal them), `SignedDistance` is
 * negative inside it, no local search raises the envelope-to-surface
 * maximum, and the samples output has no `PrimitiveKind` or `PrimitiveId`.
 *
 * Surface to envelope: at every surface vertex and at NumberOfSamples
 * area-uniform random points on the surface, the distance to the boundary of
 * the envelope. Outside the union it is the smallest closed-form distance to
 * a primitive (found through a bounding-box hierarchy over primitives).
 * Inside the union the distance to the union's boundary is not the depth in
 * any single primitive, which is only a lower bound: the deepest primitive's
 * own closest boundary point, when no other primitive buries it, proves that
 * bound exact; otherwise (creases where primitives cross) boundary points are
 * searched by projecting onto the intersection of up to three primitive
 * boundaries and by tracing rays, each checked to lie on the boundary, which
 * gives an upper bound. The reported distance is that upper bound, so the
 * reported Hausdorff distance never underestimates; field data
 * `UncertifiedInsidePoints` counts points where the two bounds differ and
 * `LargestInsideBoundGap` the largest difference, and
 * `HausdorffSurfaceToEnvelopeLowerBound` is the Hausdorff distance of the
 * lower bounds.
 *
 * Envelope to surface: NumberOfEnvelopeSamples area-uniform random points on
 * the boundary of the union (points of a primitive's surface strictly inside
 * another primitive are not on it and are skipped), each with its distance to
 * the surface (bounding-box hierarchy over the surface's triangles). The
 * largest of those distances falls short of the true envelope-to-surface
 * Hausdorff distance by how much the distance varies between samples; from
 * the MaximumSearches farthest samples a local search climbs along the
 * envelope's boundary while the distance grows, and the largest distance
 * reached is reported (every point reached lies on the boundary, so the value
 * is still attained, never an overestimate). Field data
 * `FarthestEnvelopePoint` says where it is.
 *
 * Output port 0: the prepared surface with point data `Distance` (unsigned,
 * to the envelope's boundary), `SignedDistance` (negative inside the
 * envelope) and `DistanceLowerBound`, and field data: `HausdorffSurfaceToEnvelope`,
 * `HausdorffEnvelopeToSurface`, `Hausdorff` (two-sided: the larger),
 * `MeanSurfaceToEnvelope`, `MeanEnvelopeToSurface`, `Mean`, `RMSSurfaceToEnvelope`,
 * `RMSEnvelopeToSurface`, `RMS` (two-sided values are the larger one-sided
 * value), each also as `...Percent` of `BoundingBoxDiagonal` (the surface's),
 * and the sample counts. Hausdorff values are maxima over the samples and
 * vertices; means and RMS are over the area-uniform samples.
 * Output port 1 (optional): the envelope samples as vertices with point data
 * `Distance` (to the surface), `PrimitiveKind` and `PrimitiveId` (as in
 * vtkSlabReconstructor), with the same field data.
 *
 * Same inputs, parameters and seed give the same result at any thread count.
 */
#ifndef vtkMedialReconstructionError_h
#define vtkMedialReconstructionError_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialReconstructionError : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialReconstructionError* New();
  vtkTypeMacro(vtkMedialReconstructionError, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Area-uniform random points on the surface, besides its vertices
  /// (default 100,000).
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 0, 1000000000);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Area-uniform random points on the envelope's boundary (default 50,000:
  /// with the local searches of MaximumSearches, their Hausdorff distance
  /// comes out higher, i.e. closer to the true one, than a million samples'
  /// without them).
  vtkSetClampMacro(NumberOfEnvelopeSamples, vtkIdType, 0, 1000000000);
  vtkGetMacro(NumberOfEnvelopeSamples, vtkIdType);
  ///@}

  ///@{
  /// Local searches raising the envelope-to-surface maximum, each from one
  /// of the farthest envelope samples (default 16; 0 reports the samples'
  /// maximum).
  vtkSetClampMacro(MaximumSearches, int, 0, 10000);
  vtkGetMacro(MaximumSearches, int);
  ///@}
  ///@{
  /// Seed of the random samples: the same seed gives the same samples.
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /// Threads to use (0 = all cores, default). Does not change the result.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Results of the last update (also in the outputs' field data): the
  /// two-sided Hausdorff distance, absolute and in % of the surface's
  /// bounding-box diagonal, and the two one-sided ones.
  vtkGetMacro(Hausdorff, double);
  vtkGetMacro(HausdorffPercent, double);
  vtkGetMacro(HausdorffSurfaceToEnvelope, double);
  vtkGetMacro(HausdorffEnvelopeToSurface, double);
  ///@}

protected:
  vtkMedialReconstructionError();
  ~vtkMedialReconstructionError() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfSamples = 100000;
  vtkIdType NumberOfEnvelopeSamples = 50000;
  int MaximumSearches = 16;
  int RandomSeed = 0;
  int NumberOfThreads = 0;
  double Hausdorff = 0.0;
  double HausdorffPercent = 0.0;
  double HausdorffSurfaceToEnvelope = 0.0;
  double HausdorffEnvelopeToSurface = 0.0;

private:
  vtkMedialReconstructionError(const vtkMedialReconstructionError&) = delete;
  void operator=(const vtkMedialReconstructionError&) = delete;
};

#endif
