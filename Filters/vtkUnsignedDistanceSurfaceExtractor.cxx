// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkUnsignedDistanceSurfaceExtractor.h"

#include "Surface/SurfacePreparation.h"
#include "Udf/RegularField.h"
#include "Udf/ShellSheet.h"
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

vtkStandardNewMacro(vtkUnsignedDistanceSurfaceExtractor);

vtkUnsignedDistanceSurfaceExtractor::vtkUnsignedDistanceSurfaceExtractor()
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

int vtkUnsignedDistanceSurfaceExtractor::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
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

int vtkUnsignedDistanceSurfaceExtractor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* shellOutput = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  shellOutput->Initialize();
  this->UsedEpsilon = 0.0;
  this->UsedSamples = this->UsedSpheres = 0;

  // The array chosen, else the active scalars, else the first point array
  // of one component (what ParaView's array menu holds before the first run).
  vtkDataArray* udf = this->GetInputArrayToProcess(0, inputVector);
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
    vtkErrorMacro(<< "the input has no unsigned distance array: give its point data one scalar "
                     "array (or choose it with SetInputArrayToProcess)");
    return 0;
  }
  // Other data sets are resampled onto a grid of cubic cells over their
  // bounds; points outside the data set count as far from the surface.
  vtkSmartPointer<vtkImageData> image = vtkImageData::SafeDownCast(input);
  if (!image)
  {
    image = this->ResampleToImage(input, udf);
    if (!image)
    {
      return 0;
    }
    udf = image->GetPointData()->GetScalars();
  }
  int dimensions[3];
  image->GetDimensions(dimensions);
  if (std::min({ dimensions[0], dimensions[1], dimensions[2] }) < 3)
  {
    vtkErrorMacro(<< "the grid has " << dimensions[0] << " x " << dimensions[1] << " x "
                  << dimensions[2] << " points: at least 3 along every axis are needed");
    return 0;
  }
  medialaxis::RegularField field;
  image->GetOrigin(field.Origin.data());
  image->GetSpacing(field.Spacing.data());
  std::copy(dimensions, dimensions + 3, field.Dimensions.begin());
  field.Values.resize(static_cast<std::size_t>(udf->GetNumberOfTuples()));
  double lowest = VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < udf->GetNumberOfTuples(); ++i)
  {
    field.Values[i] = udf->GetComponent(i, 0);
    lowest = std::min(lowest, field.Values[i]);
  }
  const double spacing = field.LargestSpacing();
  if (!(lowest >= -1e-9 * spacing))
  {
    vtkErrorMacro(<< "the distance array '" << (udf->GetName() ? udf->GetName() : "")
                  << "' has negative values (down to " << lowest
                  << "): this is a signed distance, whose surface is its zero level set "
                     "(vtkFlyingEdges3D at 0); an unsigned distance is never negative");
    return 0;
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
  vtkNew<vtkImageData> copy;
  copy->SetDimensions(dimensions);
  copy->SetOrigin(image->GetOrigin());
  copy->SetSpacing(image->GetSpacing());
  copy->GetPointData()->SetScalars(udf);
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
  this->UpdateProgress(0.05);

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
  medial->SetNumberOfSamples(this->UsedSamples);
  medial->SetTargetNumberOfVertices(this->UsedSpheres);
  medial->SetRandomSeed(this->RandomSeed);
  medial->SetNumberOfThreads(this->NumberOfThreads);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* amount)
    {
      static_cast<vtkUnsignedDistanceSurfaceExtractor*>(self)->UpdateProgress(
        0.05 + 0.9 * *static_cast<double*>(amount));
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
  const medialaxis::ShellSheet sheet = medialaxis::ExtractShellSheet(mesh, options, &field);
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
  medialaxis::AddFieldValue(
    output, "BoundaryLoops", static_cast<long long>(medialaxis::CountBoundaryLoops(sheet.Surface)));
  medialaxis::AddFieldValue(
    output, "JunctionEdges", static_cast<long long>(medialaxis::CountJunctionEdges(sheet.Surface)));
  medialaxis::AddFieldValue(
    output, "DroppedShrunkTriangles", static_cast<long long>(sheet.ShrunkTriangles));
  medialaxis::AddFieldValue(
    output, "DroppedFinTriangles", static_cast<long long>(sheet.FinTriangles));
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
  os << indent << "ResampleDimension: " << this->ResampleDimension << "\n";
  os << indent << "SnapToZeroSet: " << this->SnapToZeroSet << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
