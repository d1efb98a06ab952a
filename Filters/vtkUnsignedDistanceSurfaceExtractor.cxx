// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkUnsignedDistanceSurfaceExtractor.h"

#include "Surface/SurfacePreparation.h"
#include "Udf/DistanceFunction.h"
#include "Udf/RegularField.h"
#include "Udf/ShellSheet.h"
#include "Udf/UnsignedDistanceField.h"
#include "vtkMedialMeshConversion.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfacePreparation.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkResampleToImage.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkUnsignedDistanceSurfaceExtractor);

// The distance function, from C++ or from Python, as the core evaluates it.
struct vtkUnsignedDistanceSurfaceExtractor::FunctionState
{
  medialaxis::DistanceFunction Distance;
  void (*Method)(void*) = nullptr;
  void* MethodArg = nullptr;
  void (*MethodArgDelete)(void*) = nullptr;
  vtkNew<vtkDoubleArray> QueryPoints;
  vtkNew<vtkDoubleArray> QueryDistances;

  void ReleaseMethod()
  {
    if (this->MethodArg && this->MethodArgDelete)
    {
      this->MethodArgDelete(this->MethodArg);
    }
    this->Method = nullptr;
    this->MethodArg = nullptr;
    this->MethodArgDelete = nullptr;
  }
};

static_assert(sizeof(medialaxis::Point3) == 3 * sizeof(double), "points are packed");

vtkUnsignedDistanceSurfaceExtractor::vtkUnsignedDistanceSurfaceExtractor()
  : Function(new FunctionState)
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->Function->QueryPoints->SetNumberOfComponents(3);
  this->Function->QueryPoints->SetName("QueryPoints");
  this->Function->QueryDistances->SetName("QueryDistances");
}

vtkUnsignedDistanceSurfaceExtractor::~vtkUnsignedDistanceSurfaceExtractor()
{
  this->Function->ReleaseMethod();
}

int vtkUnsignedDistanceSurfaceExtractor::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1); // when the distance is a function
  return 1;
}

void vtkUnsignedDistanceSurfaceExtractor::SetDistanceFunction(DistanceCallback function)
{
  this->Function->ReleaseMethod();
  this->Function->Distance = nullptr;
  if (function)
  {
    this->Function->Distance =
      [function](const std::vector<medialaxis::Point3>& points, std::vector<double>& distances)
    {
      function(static_cast<vtkIdType>(points.size()), points.data()->data(), distances.data());
      return std::string();
    };
  }
  this->Modified();
}

void vtkUnsignedDistanceSurfaceExtractor::SetDistanceMethod(void (*f)(void*), void* arg)
{
  FunctionState& state = *this->Function;
  state.ReleaseMethod();
  state.Distance = nullptr;
  state.Method = f;
  state.MethodArg = arg;
  if (f)
  {
    state.Distance =
      [&state](const std::vector<medialaxis::Point3>& points, std::vector<double>& distances)
    {
      state.QueryPoints->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
      std::memcpy(state.QueryPoints->GetPointer(0), points.data()->data(),
        3 * sizeof(double) * points.size());
      state.QueryDistances->SetNumberOfComponents(1);
      state.QueryDistances->SetNumberOfTuples(0);
      state.Method(state.MethodArg);
      const vtkIdType filled = state.QueryDistances->GetNumberOfTuples();
      if (filled != static_cast<vtkIdType>(points.size()) ||
        state.QueryDistances->GetNumberOfComponents() != 1)
      {
        return "the distance method filled " + std::to_string(filled) +
          " values of QueryDistances for " + std::to_string(points.size()) +
          " query points (did it raise an exception?)";
      }
      std::copy_n(state.QueryDistances->GetPointer(0), points.size(), distances.begin());
      return std::string();
    };
  }
  this->Modified();
}

void vtkUnsignedDistanceSurfaceExtractor::SetDistanceMethodArgDelete(void (*f)(void*))
{
  this->Function->MethodArgDelete = f;
}

vtkDoubleArray* vtkUnsignedDistanceSurfaceExtractor::GetQueryPoints()
{
  return this->Function->QueryPoints;
}

vtkDoubleArray* vtkUnsignedDistanceSurfaceExtractor::GetQueryDistances()
{
  return this->Function->QueryDistances;
}

void vtkUnsignedDistanceSurfaceExtractor::RemoveDistanceFunction()
{
  this->SetDistanceMethod(nullptr, nullptr);
}

bool vtkUnsignedDistanceSurfaceExtractor::HasDistanceFunction() const
{
  return static_cast<bool>(this->Function->Distance);
}

namespace
{
// The smallest value on the grid's six faces.
double BorderMinimum(const medialaxis::RegularField& f)
{
  double lowest = VTK_DOUBLE_MAX;
  const auto& d = f.Dimensions;
  for (int k = 0; k < d[2]; ++k)
  {
    for (int j = 0; j < d[1]; ++j)
    {
      const bool face = k == 0 || k == d[2] - 1 || j == 0 || j == d[1] - 1;
      for (int i = 0; i < d[0]; i += (face || i == d[0] - 1) ? 1 : d[0] - 1)
      {
        lowest = std::min(lowest, f.Values[f.Index(i, j, k)]);
      }
    }
  }
  return lowest;
}
}

vtkSmartPointer<vtkImageData> vtkUnsignedDistanceSurfaceExtractor::ResampleToImage(
  vtkDataSet* input, vtkDataArray* udf)
{
  double bounds[6];
  input->GetBounds(bounds);
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  if (!(longest > 0.0) || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "the input data set has no extent: nothing to resample");
    return nullptr;
  }
  const double spacing = longest / (this->ResampleDimension - 1);
  int dimensions[3];
  for (int a = 0; a < 3; ++a)
  {
    dimensions[a] = std::max(
      3, static_cast<int>(std::floor((bounds[2 * a + 1] - bounds[2 * a]) / spacing + 1e-9)) + 1);
    bounds[2 * a + 1] = bounds[2 * a] + spacing * (dimensions[a] - 1);
  }
  vtkSmartPointer<vtkDataSet> only;
  only.TakeReference(input->NewInstance());
  only->CopyStructure(input);
  only->GetPointData()->SetScalars(udf);
  vtkNew<vtkResampleToImage> resample;
  resample->SetInputDataObject(only);
  resample->UseInputBoundsOff();
  resample->SetSamplingBounds(bounds);
  resample->SetSamplingDimensions(dimensions);
  resample->Update();
  vtkImageData* sampled = resample->GetOutput();
  vtkDataArray* values = sampled->GetPointData()->GetArray(udf->GetName() ? udf->GetName() : "");
  if (!values)
  {
    values = sampled->GetPointData()->GetScalars();
  }
  vtkDataArray* valid = sampled->GetPointData()->GetArray("vtkValidPointMask");
  if (!values)
  {
    vtkErrorMacro(<< "resampling the input onto a grid gave no distance values");
    return nullptr;
  }
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("UnsignedDistance");
  distance->SetNumberOfTuples(values->GetNumberOfTuples());
  const double far = udf->GetRange(0)[1];
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    const bool inside = !valid || valid->GetComponent(i, 0) != 0.0;
    distance->SetValue(i, inside ? values->GetComponent(i, 0) : far);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dimensions);
  image->SetOrigin(bounds[0], bounds[2], bounds[4]);
  image->SetSpacing(spacing, spacing, spacing);
  image->GetPointData()->SetScalars(distance);
  return image;
}

bool vtkUnsignedDistanceSurfaceExtractor::ReadInputField(
  vtkInformationVector** inputVector, vtkSmartPointer<vtkImageData>& image, vtkDataArray*& udf)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  // The array chosen, else the active scalars, else the first point array
  // of one component (what ParaView's array menu holds before the first run).
  udf = input ? this->GetInputArrayToProcess(0, inputVector) : nullptr;
  if (input && !udf)
  {
    vtkPointData* points = input->GetPointData();
    udf = points->GetScalars();
    for (int a = 0; !udf && a < points->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* candidate = points->GetArray(a);
      udf = candidate && candidate->GetNumberOfComponents() == 1 ? candidate : nullptr;
    }
  }
  if (!input || !udf || udf->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< (input ? "the input has no unsigned distance array: give its point data one "
                              "scalar array (or choose it with SetInputArrayToProcess)"
                            : "no input and no distance function: connect a data set holding "
                              "an unsigned distance, or set a distance function"));
    return false;
  }
  // Other data sets are resampled onto a grid of cubic cells over their
  // bounds; points outside the data set count as far from the surface.
  image = vtkImageData::SafeDownCast(input);
  if (!image)
  {
    image = this->ResampleToImage(input, udf);
    if (!image)
    {
      return false;
    }
    udf = image->GetPointData()->GetScalars();
  }
  return true;
}

namespace
{
// A grid of cubic cells over `bounds`, `longest` points along its longest
// side, padded by 6 cells on every side (the shell reaches Epsilon, a few
// cells, beyond the surface).
medialaxis::RegularField FunctionGrid(const double bounds[6], int longest)
{
  constexpr int padding = 6;
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double spacing = extent / (longest - 1 - 2 * padding);
  std::array<int, 3> dimensions{};
  for (int a = 0; a < 3; ++a)
  {
    dimensions[a] =
      static_cast<int>(std::ceil((bounds[2 * a + 1] - bounds[2 * a]) / spacing - 1e-9)) + 1 +
      2 * padding;
  }
  medialaxis::Box box;
  for (int a = 0; a < 3; ++a)
  {
    box.Lo[a] = bounds[2 * a];
    box.Hi[a] = bounds[2 * a + 1];
  }
  return medialaxis::GridAroundBox(box, dimensions, padding);
}
}

int vtkUnsignedDistanceSurfaceExtractor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* shellOutput = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  shellOutput->Initialize();
  this->UsedEpsilon = 0.0;
  this->UsedSamples = this->UsedSpheres = 0;

  // The field: the function's samples, or the input's values.
  medialaxis::RegularField field;
  std::string arrayName = "UnsignedDistance";
  const bool function = this->HasDistanceFunction();
  const double sampled = function ? 0.2 : 0.0; // progress when the field is ready
  if (function)
  {
    if (vtkDataSet::GetData(inputVector[0]))
    {
      vtkErrorMacro(<< "both an input and a distance function are given: disconnect the input "
                       "or remove the function (RemoveDistanceFunction)");
      return 0;
    }
    const double* b = this->FunctionBounds;
    const double extent = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
    if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]) || !(extent > 0.0) ||
      !std::isfinite(extent))
    {
      vtkErrorMacro(<< "FunctionBounds (" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3]
                    << ", " << b[4] << ", " << b[5]
                    << ") is not a box: give the box that holds the distance function's surface "
                       "as xmin, xmax, ymin, ymax, zmin, zmax");
      return 0;
    }
    field = FunctionGrid(b, this->ResampleDimension);
    const std::string problem = medialaxis::SampleDistanceFunction(this->Function->Distance, field,
      [this, sampled](double done)
      {
        this->UpdateProgress(sampled * done);
        return this->GetAbortExecute() != 0;
      });
    if (problem == "stopped")
    {
      return 1;
    }
    if (!problem.empty())
    {
      vtkErrorMacro(<< "the distance function failed: " << problem);
      return 0;
    }
  }
  else
  {
    vtkSmartPointer<vtkImageData> image;
    vtkDataArray* udf = nullptr;
    if (!this->ReadInputField(inputVector, image, udf))
    {
      return 0;
    }
    arrayName = udf->GetName() ? udf->GetName() : "";
    image->GetOrigin(field.Origin.data());
    image->GetSpacing(field.Spacing.data());
    image->GetDimensions(field.Dimensions.data());
    field.Values.resize(static_cast<std::size_t>(udf->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < udf->GetNumberOfTuples(); ++i)
    {
      field.Values[i] = udf->GetComponent(i, 0);
    }
  }
  const auto& dimensions = field.Dimensions;
  if (std::min({ dimensions[0], dimensions[1], dimensions[2] }) < 3)
  {
    vtkErrorMacro(<< "the grid has " << dimensions[0] << " x " << dimensions[1] << " x "
                  << dimensions[2] << " points: at least 3 along every axis are needed");
    return 0;
  }
  const double lowest = *std::min_element(field.Values.begin(), field.Values.end());
  const double spacing = field.LargestSpacing();
  if (!(lowest >= -1e-9 * spacing))
  {
    vtkErrorMacro(<< "the distance " << (function ? "function" : "array '" + arrayName + "'")
                  << " has negative values (down to " << lowest
                  << "): this is a signed distance, whose surface is its zero level set "
                     "(vtkFlyingEdges3D at 0); an unsigned distance is never negative");
    return 0;
  }
  // A sampled distance changes by at most the spacing between neighbours:
  // values that break that by half again were sampled wrongly, and the
  // surface gets holes and stray pieces there. (A function is sampled here,
  // by one caller at a time.)
  this->NumberOfNonDistanceNeighbours = 0;
  if (!function)
  {
    const medialaxis::DistanceCheck check = medialaxis::CheckDistanceBound(field, 1.5);
    this->NumberOfNonDistanceNeighbours = static_cast<vtkIdType>(check.Violations);
    if (check.Violations > 0)
    {
      vtkWarningMacro(<< "the array '" << arrayName << "' is not a distance in " << check.Violations
                      << " places: neighbouring grid points differ by more than their spacing "
                         "(up to "
                      << check.Worst << " times, first near (" << check.First[0] << ", "
                      << check.First[1] << ", " << check.First[2]
                      << ")), and the surface will have holes and stray pieces there. "
                         "vtkImplicitPolyDataDistance sampled by vtkSampleFunction gives such "
                         "values: it is not safe to call from several threads (sample it on one, "
                         "or use vtkUnsignedDistanceSource)");
    }
  }
  const double epsilon = this->Epsilon > 0.0 ? this->Epsilon : 2.0 * spacing;
  if (epsilon < spacing)
  {
    vtkErrorMacro(<< "Epsilon " << epsilon << " is below the grid's spacing " << spacing
                  << ": the shell would be thinner than a cell; use at least the spacing "
                     "(0 chooses twice the spacing)");
    return 0;
  }
  if (BorderMinimum(field) <= epsilon)
  {
    vtkErrorMacro(<< "the shell at Epsilon " << epsilon
                  << " reaches the grid's border, so it is not closed: the grid must extend "
                     "beyond the surface by more than Epsilon (pad it)");
    return 0;
  }
  this->UsedEpsilon = epsilon;

  // 1. The shell.
  // The contour reads the chosen array as the active scalars of a copy.
  vtkNew<vtkDoubleArray> values;
  values->SetName(arrayName.c_str());
  values->SetArray(field.Values.data(), static_cast<vtkIdType>(field.Values.size()), 1);
  vtkNew<vtkImageData> copy;
  copy->SetDimensions(dimensions.data());
  copy->SetOrigin(field.Origin.data());
  copy->SetSpacing(field.Spacing.data());
  copy->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(copy);
  contour->SetValue(0, epsilon);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  medialaxis::TriangleMesh shell;
  const medialaxis::SurfacePreparationReport report =
    medialaxis::PrepareSurfaceMesh(contour->GetOutput(), shell);
  if (!report.Ok())
  {
    vtkErrorMacro(<< "the shell at Epsilon " << epsilon
                  << " is not a valid surface: " << report.Error);
    return 0;
  }
  medialaxis::TriangleMeshToPolyData(shell, shellOutput);
  this->UpdateProgress(sampled + 0.05);

  // 2. Its medial axis, with counts from the shell's own size.
  const double area = medialaxis::SurfaceArea(shell);
  const double perSquare = area / (epsilon * epsilon);
  this->UsedSamples = this->NumberOfSamples > 0
    ? this->NumberOfSamples
    : std::clamp(
        static_cast<vtkIdType>(std::llround(4.0 * perSquare)), vtkIdType(2000), vtkIdType(5000000));
  this->UsedSpheres = this->TargetNumberOfVertices > 0
    ? this->TargetNumberOfVertices
    : std::clamp(static_cast<vtkIdType>(std::llround(0.5 * perSquare)), vtkIdType(100),
        std::max(vtkIdType(100), this->UsedSamples / 4));
  vtkNew<vtkStructuralMedialAxis> medial;
  medial->SetInputData(shellOutput);
  medial->SetPresetToOrganic();
  medial->SetAdaptiveSampling(false); // the shell is equally thin everywhere
  // The shell's medial axis is the surface sought, its junctions and rims
  // included: none of it is hair, fin or pleat to clean away (with the
  // clean-sheet measures three half-planes lose their junction's loop).
  medial->SetHairAngle(0.0);
  medial->SetFinBudget(0.0);
  medial->SetPleatAngle(10.0);
  medial->SetNumberOfSamples(this->UsedSamples);
  medial->SetTargetNumberOfVertices(this->UsedSpheres);
  medial->SetRandomSeed(this->RandomSeed);
  medial->SetNumberOfThreads(this->NumberOfThreads);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* amount)
    {
      auto* extractor = static_cast<vtkUnsignedDistanceSurfaceExtractor*>(self);
      const double start = extractor->HasDistanceFunction() ? 0.25 : 0.05;
      extractor->UpdateProgress(start + (0.95 - start) * *static_cast<double*>(amount));
    });
  medial->AddObserver(vtkCommand::ProgressEvent, progress);
  medial->Update();
  medialaxis::MedialMesh mesh;
  const std::string problem = medialaxis::PolyDataToMedialMesh(medial->GetOutput(0), mesh);
  if (!problem.empty() || mesh.Centers.empty())
  {
    vtkErrorMacro(<< "the medial axis of the shell could not be computed"
                  << (problem.empty() ? "" : ": " + problem));
    return 0;
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // 3. The sheet, 4. snapped.
  medialaxis::ShellSheetOptions options;
  options.Epsilon = epsilon;
  options.SnapSteps = this->SnapToZeroSet ? 2 : 0;
  // A function is read exactly, a field through its trilinear interpolant.
  const medialaxis::FieldProbe fieldProbe(field);
  const medialaxis::FunctionProbe functionProbe(this->Function->Distance);
  const medialaxis::DistanceProbe* probe =
    function ? static_cast<const medialaxis::DistanceProbe*>(&functionProbe) : &fieldProbe;
  const medialaxis::ShellSheet sheet = medialaxis::ExtractShellSheet(mesh, options, probe);
  if (!sheet.Error.empty())
  {
    vtkErrorMacro(<< "the distance function failed while snapping: " << sheet.Error);
    return 0;
  }
  medialaxis::TriangleMeshToPolyData(sheet.Surface, output);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("ShellRadius");
  radius->SetNumberOfTuples(static_cast<vtkIdType>(sheet.ShellRadius.size()));
  std::copy(sheet.ShellRadius.begin(), sheet.ShellRadius.end(), radius->GetPointer(0));
  output->GetPointData()->AddArray(radius);
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetName("MedialVertexId");
  vertexIds->SetNumberOfTuples(static_cast<vtkIdType>(sheet.MedialVertex.size()));
  std::copy(sheet.MedialVertex.begin(), sheet.MedialVertex.end(), vertexIds->GetPointer(0));
  output->GetPointData()->AddArray(vertexIds);
  medialaxis::AddFieldDouble(output, "Epsilon", epsilon);
  medialaxis::AddFieldDouble(output, "ShellArea", area);
  medialaxis::AddFieldValue(output, "Samples", this->UsedSamples);
  medialaxis::AddFieldValue(output, "Spheres", this->UsedSpheres);
  medialaxis::AddFieldValue(output, "NonDistanceNeighbours", this->NumberOfNonDistanceNeighbours);
  medialaxis::AddFieldValue(
    output, "BoundaryLoops", static_cast<long long>(medialaxis::CountBoundaryLoops(sheet.Surface)));
  medialaxis::AddFieldValue(
    output, "JunctionEdges", static_cast<long long>(medialaxis::CountJunctionEdges(sheet.Surface)));
  medialaxis::AddFieldValue(
    output, "DroppedShrunkTriangles", static_cast<long long>(sheet.ShrunkTriangles));
  medialaxis::AddFieldValue(
    output, "DroppedFinTriangles", static_cast<long long>(sheet.FinTriangles));
  medialaxis::AddFieldValue(
    output, "DroppedFlapTriangles", static_cast<long long>(sheet.FlapTriangles));
  medialaxis::AddFieldValue(output, "FilledHoles", static_cast<long long>(sheet.FilledHoles));
  medialaxis::AddFieldDouble(output, "MeanSnapDistance", sheet.MeanSnapDistance);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkUnsignedDistanceSurfaceExtractor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "TargetNumberOfVertices: " << this->TargetNumberOfVertices << "\n";
  os << indent << "DistanceFunction: " << (this->HasDistanceFunction() ? "set" : "none") << "\n";
  os << indent << "FunctionBounds: " << this->FunctionBounds[0] << ", " << this->FunctionBounds[1]
     << ", " << this->FunctionBounds[2] << ", " << this->FunctionBounds[3] << ", "
     << this->FunctionBounds[4] << ", " << this->FunctionBounds[5] << "\n";
  os << indent << "ResampleDimension: " << this->ResampleDimension << "\n";
  os << indent << "SnapToZeroSet: " << this->SnapToZeroSet << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
