// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkUnsignedDistanceSource
 * @brief   The exact unsigned distance to a triangle surface, sampled on a grid.
 *
 * Input: a surface (vtkPolyData; polygons are fanned into triangles), open
 * or closed, manifold or not, oriented or not. Output: a vtkImageData of
 * SamplingDimensions points with point data `UnsignedDistance` (float, the
 * active scalars): at every grid point the distance to the nearest
 * triangle, found exactly through a box tree of the triangles (parallel,
 * deterministic). The grid's cells are cubes; it is centred on the
 * surface's bounding box and leaves Padding cells free around it on the
 * side where the box is tightest, so that the level sets of small distances
 * (the epsilon-shells vtkUnsignedDistanceSurfaceExtractor contours) close
 * inside the grid.
 *
 * Use it to make unsigned distance fields from meshes, e.g. to test the
 * extractor against the mesh as ground truth.
 */
#ifndef vtkUnsignedDistanceSource_h
#define vtkUnsignedDistanceSource_h

#include "vtkImageAlgorithm.h"
#include "vtkMedialAxisFiltersModule.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkUnsignedDistanceSource : public vtkImageAlgorithm
{
public:
  static vtkUnsignedDistanceSource* New();
  vtkTypeMacro(vtkUnsignedDistanceSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Grid points along x, y and z. Default 128 x 128 x 128.
  vtkSetVector3Macro(SamplingDimensions, int);
  vtkGetVector3Macro(SamplingDimensions, int);
  ///@}

  ///@{
  /// Free cells between the surface's bounding box and the grid's border,
  /// along the axis where the box fills the grid most. Default 6; clamped
  /// so that at least 2 cells are left for the surface.
  vtkSetClampMacro(Padding, int, 0, 1000);
  vtkGetMacro(Padding, int);
  ///@}

  ///@{
  /// Threads for the sampling (0: all cores, the default). The values do
  /// not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkUnsignedDistanceSource();
  ~vtkUnsignedDistanceSource() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SamplingDimensions[3] = { 128, 128, 128 };
  int Padding = 6;
  int NumberOfThreads = 0;

private:
  vtkUnsignedDistanceSource(const vtkUnsignedDistanceSource&) = delete;
  void operator=(const vtkUnsignedDistanceSource&) = delete;
};

#endif
