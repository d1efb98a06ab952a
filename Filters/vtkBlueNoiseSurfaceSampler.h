// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkBlueNoiseSurfaceSampler
 * @brief   Exactly N blue-noise distributed points on a closed surface.
 *
 * The first stage of the medial-axis pipeline. The input surface is prepared
 * like in every MedialAxis filter (see vtkMedialSurfaceValidator) and sampled
 * with area-uniform density by weighted sample elimination (Yuksel 2015):
 * CandidateRatio x NumberOfSamples random points are thinned to exactly
 * NumberOfSamples by repeatedly removing the most crowded one. Optional
 * restricted centroidal Voronoi (Lloyd) steps then even the spacing further.
 *
 * With Adaptive on, the density follows the local thickness of the solid:
 * thin parts (tentacles, ears, thin plates), which uniform samples miss,
 * get a spacing of ThinPartSpacing times their thickness, up to
 * 1 / FinestSpacingRatio^2 times the density elsewhere; the rest is uniform,
 * a little sparser, so that exactly NumberOfSamples come out. The thickness
 * is measured by rays cast inwards from random probe points (the shape
 * diameter function); a shape without thin parts is sampled exactly as
 * with Adaptive off.
 *
 * Output ("sites"): points with one vertex cell each, point data `Normals`
 * (unit normal of the triangle the site lies on) and `TriangleId` (that
 * triangle, numbered as in the prepared surface, which equals the input's
 * numbering for a clean triangle mesh). With Adaptive on, also
 * `LocalThickness` (the solid's thickness behind the site, of the nearest
 * probe; -1 where no ray found the far side) and `Spacing` (the spacing the
 * sizing field asked for there), and field data `AddedSamples` (the
 * samples beyond NumberOfSamples, see ThinPartExtraSamples).
 *
 * The result is identical for identical input, parameters and RandomSeed,
 * whatever NumberOfThreads.
 */
#ifndef vtkBlueNoiseSurfaceSampler_h
#define vtkBlueNoiseSurfaceSampler_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkBlueNoiseSurfaceSampler : public vtkPolyDataAlgorithm
{
public:
  static vtkBlueNoiseSurfaceSampler* New();
  vtkTypeMacro(vtkBlueNoiseSurfaceSampler, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// How many sites to produce, exactly (default 10000; the paper uses 10K
  /// for organic and 50K for CAD models).
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 1, 100000000);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Seed of the random candidates (default 0). Same seed, same sites.
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /// Restricted centroidal Voronoi (Lloyd) relaxation steps after
  /// elimination (default 0). Each costs about one restricted Voronoi diagram.
  vtkSetClampMacro(RelaxationIterations, int, 0, 1000);
  vtkGetMacro(RelaxationIterations, int);
  ///@}

  ///@{
  /// Random candidates per site before elimination (default 4). Higher is
  /// slightly more even and slower.
  vtkSetClampMacro(CandidateRatio, double, 1.5, 50.0);
  vtkGetMacro(CandidateRatio, double);
  ///@}

  ///@{
  /// Sample thin parts densely, by the local thickness (default off).
  vtkSetMacro(Adaptive, bool);
  vtkGetMacro(Adaptive, bool);
  vtkBooleanMacro(Adaptive, bool);
  ///@}

  ///@{
  /// With Adaptive: the spacing wanted on thin parts, as a fraction of
  /// their thickness (default 0.5).
  vtkSetClampMacro(ThinPartSpacing, double, 0.05, 10.0);
  vtkGetMacro(ThinPartSpacing, double);
  ///@}

  ///@{
  /// With Adaptive: the finest spacing, as a fraction of the spacing on the
  /// thick parts (default 0.25, i.e. at most 16 times their density).
  vtkSetClampMacro(FinestSpacingRatio, double, 0.01, 1.0);
  vtkGetMacro(FinestSpacingRatio, double);
  ///@}

  ///@{
  /// With Adaptive: where thin parts want a spacing finer than
  /// FinestSpacingRatio allows (a handle much thinner than the budget can
  /// follow, which the medial axis would lose), give it to them with up to
  /// this fraction of NumberOfSamples in samples beyond it (default 0:
  /// exactly NumberOfSamples). The output's field data `AddedSamples` says
  /// how many were added. vtkStructuralMedialAxis sets it when the medial
  /// axis misses a handle.
  vtkSetClampMacro(ThinPartExtraSamples, double, 0.0, 10.0);
  vtkGetMacro(ThinPartExtraSamples, double);
  ///@}

  ///@{
  /// Threads to use (0 = all cores, default). Does not change the result.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkBlueNoiseSurfaceSampler() = default;
  ~vtkBlueNoiseSurfaceSampler() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfSamples = 10000;
  int RandomSeed = 0;
  int RelaxationIterations = 0;
  double CandidateRatio = 4.0;
  bool Adaptive = false;
  double ThinPartSpacing = 0.5;
  double FinestSpacingRatio = 0.25;
  double ThinPartExtraSamples = 0.0;
  int NumberOfThreads = 0;

private:
  vtkBlueNoiseSurfaceSampler(const vtkBlueNoiseSurfaceSampler&) = delete;
  void operator=(const vtkBlueNoiseSurfaceSampler&) = delete;
};

#endif
