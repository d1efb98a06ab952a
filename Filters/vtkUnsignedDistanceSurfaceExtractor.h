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
 *    edges of three or more triangles) and the flaps folded back across
 *    such edges (where the shell is sampled coarsely), and closes the holes narrower than
 *    2 Epsilon (the shell closes over any hole that narrow, so it is not in
 *    the field; dropped folds along a sharp fold of the surface leave them);
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
 * `DroppedShrunkTriangles`, `DroppedFinTriangles`, `DroppedFlapTriangles`, `FilledHoles`,
 * `MeanSnapDistance`.
 * Output 1: the epsilon-shell.
 *
 * The distance may also be a function instead of an input (a closed form,
 * a neural field): SetDistanceFunction in C++, SetDistanceMethod (or the
 * Python helper medialaxis.set_distance_function, for f(points) ->
 * distances on numpy arrays) in Python. It is sampled on a grid over
 * FunctionBounds and, when SnapToZeroSet is on, read exactly for the
 * snapping (its gradient by central differences of Epsilon / 8).
 *
 * Errors: no UDF array and no function, negative values (a signed distance: contour it at
 * 0 instead), an Epsilon below the grid spacing (the shell would not be
 * resolved), a shell that reaches the grid's border.
 */
#ifndef vtkUnsignedDistanceSurfaceExtractor_h
#define vtkUnsignedDistanceSurfaceExtractor_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <functional> // for the distance function
#include <memory>     // for the function's state

class vtkDataArray;
class vtkDoubleArray;
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
  /// The distance as a function instead of an input (C++). It is called
  /// with `count` points (x, y, z one after the other) and fills
  /// `distances` with their unsigned distances (never negative; a NaN stops
  /// the filter with an error); on batches of at most 65,536 points, from
  /// the thread that runs the filter, one call at a time. It is sampled on a
  /// grid over FunctionBounds, ResampleDimension points along its longest
  /// side and 6 more cells on every side, and read exactly for the
  /// snapping. It takes the place of the input (none may be connected). An
  /// empty function removes it.
#ifndef __VTK_WRAP__
  using DistanceCallback =
    std::function<void(vtkIdType count, const double* points, double* distances)>;
  void SetDistanceFunction(DistanceCallback function);
#endif
  ///@}

  ///@{
  /// The distance as a function, for Python: `f(arg)` is called (from
  /// Python: the callable, with no arguments) when distances are needed; it
  /// reads GetQueryPoints() (3 components per point) and fills
  /// GetQueryDistances() with one value per point. The Python helper
  /// medialaxis.set_distance_function(extractor, f, bounds) wraps a function
  /// of a numpy array of points. Otherwise as SetDistanceFunction.
  void SetDistanceMethod(void (*f)(void*), void* arg);
  void SetDistanceMethodArgDelete(void (*f)(void*));
  vtkDoubleArray* GetQueryPoints();
  vtkDoubleArray* GetQueryDistances();
  ///@}

  /// Removes the distance function: the input is read again.
  void RemoveDistanceFunction();
  /// Whether a distance function (C++ or Python) is set.
  bool HasDistanceFunction() const;

  ///@{
  /// The box that holds the surface of the distance function: xmin, xmax,
  /// ymin, ymax, zmin, zmax. Unused when the distance is an input.
  vtkSetVector6Macro(FunctionBounds, double);
  vtkGetVector6Macro(FunctionBounds, double);
  ///@}

  ///@{
  /// Grid points along the longest side when the input is not image data
  /// and is resampled, and when the distance is a function. Default 128.
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
  /// Pairs of neighbouring grid points of the input array whose values
  /// differ by more than 1.5 times their spacing, which no distance does
  /// (a warning names the first; 0 for a distance function).
  vtkGetMacro(NumberOfNonDistanceNeighbours, vtkIdType);
  ///@}

protected:
  vtkUnsignedDistanceSurfaceExtractor();
  ~vtkUnsignedDistanceSurfaceExtractor() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkSmartPointer<vtkImageData> ResampleToImage(vtkDataSet* input, vtkDataArray* udf);
  bool ReadInputField(
    vtkInformationVector** inputVector, vtkSmartPointer<vtkImageData>& image, vtkDataArray*& udf);

  double Epsilon = 0.0;
  vtkIdType NumberOfSamples = 0;
  vtkIdType TargetNumberOfVertices = 0;
  int ResampleDimension = 128;
  bool SnapToZeroSet = false;
  int RandomSeed = 0;
  int NumberOfThreads = 0;
  double FunctionBounds[6] = { 0, -1, 0, -1, 0, -1 };
  double UsedEpsilon = 0.0;
  vtkIdType UsedSamples = 0;
  vtkIdType UsedSpheres = 0;
  vtkIdType NumberOfNonDistanceNeighbours = 0;

private:
  struct FunctionState;
  std::unique_ptr<FunctionState> Function;
  vtkUnsignedDistanceSurfaceExtractor(const vtkUnsignedDistanceSurfaceExtractor&) = delete;
  void operator=(const vtkUnsignedDistanceSurfaceExtractor&) = delete;
};

#endif
