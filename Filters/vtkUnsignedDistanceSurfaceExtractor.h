// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkUnsignedDistanceSurfaceExtractor
 * @brief   The surface of an unsigned distance field: the medial axis of its epsilon-shell.
 *
 * Unsigned distance fields (UDFs) describe open surfaces, garments,
 * non-manifold and non-orientable sheets, which marching cubes cannot
 * extract for want of a sign. The level set {UDF = Epsilon} is a thin
 * closed double layer around the surface; its medial axis is the surface
 * itself, with clean boundaries (the Structural MAT paper, section 5.7).
 * This filter:
 * 1. contours the epsilon-shell (vtkFlyingEdges3D) and validates it (closed,
 *    manifold: refused when it reaches the grid's border);
 * 2. computes its Structural MAT (vtkStructuralMedialAxis, organic settings
 *    with uniform sampling) with the shell's own counts: about
 *    4 * shell area / Epsilon^2 samples, and spheres about Epsilon apart on
 *    the sheet (half the shell's area / Epsilon^2);
 * 3. keeps the medial triangles whose spheres have radius at least half of
 *    Epsilon (the shell's medial axis also branches towards its own ridges,
 *    where the spheres shrink) and drops the small folds hanging on
 *    junctions (pieces below 4 Epsilon^2 joined to the rest only through
 *    edges of three or more triangles);
 * 4. optionally projects the points onto the UDF's zero set (SnapToZeroSet).
 *
 * Input: a vtkImageData (or any vtkDataSet, resampled with
 * vtkResampleToImage onto cubic cells, ResampleDimension points along its
 * longest side; points outside the data set count as far from the surface)
 * whose point data holds the UDF (the array chosen
 * with SetInputArrayToProcess(0, 0, 0, POINTS, name); default: the active
 * scalars, else the first point array of one component). Output 0: the extracted surface as
 * triangles, open boundaries kept as boundaries and junctions as edges of three or more triangles;
 * point data `ShellRadius` (the sphere's radius, about Epsilon: a
 * diagnostic) and `MedialVertexId`; field data `Epsilon`, `ShellArea`,
 * `Samples`, `Spheres`, `BoundaryLoops`, `JunctionEdges`,
 * `DroppedShrunkTriangles`, `DroppedFinTriangles`, `MeanSnapDistance`.
 * Output 1: the epsilon-shell.
 *
 * Errors: no UDF array, negative values (a signed distance: contour it at
 * 0 instead), an Epsilon below the grid spacing (the shell would not be
 * resolved), a shell that reaches the grid's border.
 */
#ifndef vtkUnsignedDistanceSurfaceExtractor_h
#define vtkUnsignedDistanceSurfaceExtractor_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

class vtkDataArray;
class vtkDataSet;
class vtkImageData;

class VTKMEDIALAXISFILTERS_EXPORT vtkUnsignedDistanceSurfaceExtractor : public vtkPolyDataAlgorithm
{
public:
  static vtkUnsignedDistanceSurfaceExtractor* New();
  vtkTypeMacro(vtkUnsignedDistanceSurfaceExtractor, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The shell's distance from the surface, in the field's units. 0
  /// (default): twice the grid's largest spacing. At least the largest
  /// spacing.
  vtkSetClampMacro(Epsilon, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /// Surface samples of the shell's medial axis (0, default: 4 * shell area
  /// / Epsilon^2, at least 2,000).
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 0, 100000000);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Spheres left on the medial axis (0, default: half the shell's area /
  /// Epsilon^2, at least 100 and at most a quarter of the samples).
  vtkSetClampMacro(TargetNumberOfVertices, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfVertices, vtkIdType);
  ///@}

  ///@{
  /// Grid points along the longest side when the input is not image data
  /// and is resampled. Default 128.
  vtkSetClampMacro(ResampleDimension, int, 4, 4096);
  vtkGetMacro(ResampleDimension, int);
  ///@}

  ///@{
  /// Project every point where the surface is one layer onto the UDF's
  /// zero set: from the points Epsilon away on both sides, a step back along
  /// the UDF's gradient by the distance read there; the mean of the two
  /// feet. Default off.
  vtkSetMacro(SnapToZeroSet, bool);
  vtkGetMacro(SnapToZeroSet, bool);
  vtkBooleanMacro(SnapToZeroSet, bool);
  ///@}

  ///@{
  /// Seed of the sampler. Same seed, same result.
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /// Threads for the parallel stages (0: all cores, the default).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Results of the last update: the epsilon used, the samples and spheres.
  vtkGetMacro(UsedEpsilon, double);
  vtkGetMacro(UsedSamples, vtkIdType);
  vtkGetMacro(UsedSpheres, vtkIdType);
  ///@}

protected:
  vtkUnsignedDistanceSurfaceExtractor();
  ~vtkUnsignedDistanceSurfaceExtractor() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSmartPointer<vtkImageData> ResampleToImage(vtkDataSet* input, vtkDataArray* udf);

  double Epsilon = 0.0;
  vtkIdType NumberOfSamples = 0;
  vtkIdType TargetNumberOfVertices = 0;
  int ResampleDimension = 128;
  bool SnapToZeroSet = false;
  int RandomSeed = 0;
  int NumberOfThreads = 0;
  double UsedEpsilon = 0.0;
  vtkIdType UsedSamples = 0;
  vtkIdType UsedSpheres = 0;

private:
  vtkUnsignedDistanceSurfaceExtractor(const vtkUnsignedDistanceSurfaceExtractor&) = delete;
  void operator=(const vtkUnsignedDistanceSurfaceExtractor&) = delete;
};

#endif
