// SPDX-License-Identifier: GPL-3.0-or-later
#include "UdfCommand.h"

#include "Format/NpyFormat.h"
#include "MedialAxisVersion.h"
#include "ToolSupport.h"
#include "vtkUnsignedDistanceSurfaceExtractor.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredPoints.h"
#include "vtkStructuredPointsReader.h"
#include "vtkXMLImageDataReader.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace medialaxis
{
namespace tool
{
namespace
{
constexpr int BadArguments = 2, BadInput = 3, ComputationFailed = 4;

std::string Extension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The field as image data, or null with `problem` set (and `code`).
vtkSmartPointer<vtkImageData> ReadField(const UdfOptions& o, std::string& problem, int& code)
{
  code = BadInput;
  const std::string extension = Extension(o.Field);
  if (!std::filesystem::is_regular_file(o.Field))
  {
    problem = "no such file " + o.Field;
    return nullptr;
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (extension == ".npy")
  {
    if (o.Spacing <= 0.0)
    {
      problem = "a .npy field needs --spacing (the distance between grid points)";
      code = BadArguments;
      return nullptr;
    }
    std::ifstream file(o.Field, std::ios::binary);
    NpyVolume volume = ParseNpyVolume(file);
    if (!volume.Ok())
    {
      problem = o.Field + ": " + volume.Error;
      return nullptr;
    }
    image->SetDimensions(static_cast<int>(volume.Shape[0]), static_cast<int>(volume.Shape[1]),
      static_cast<int>(volume.Shape[2]));
    image->SetSpacing(o.Spacing, o.Spacing, o.Spacing);
    image->SetOrigin(o.Origin.data());
    vtkNew<vtkDoubleArray> values;
    values->SetName("UnsignedDistance");
    values->SetNumberOfTuples(static_cast<vtkIdType>(volume.Values.size()));
    std::copy(volume.Values.begin(), volume.Values.end(), values->GetPointer(0));
    image->GetPointData()->SetScalars(values);
    return image;
  }
  LastError error;
  if (extension == ".vti")
  {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(o.Field.c_str());
    Observe(reader, error, nullptr);
    reader->Update();
    image->ShallowCopy(reader->GetOutput());
  }
  else if (extension == ".vtk")
  {
    vtkNew<vtkStructuredPointsReader> reader;
    reader->SetFileName(o.Field.c_str());
    Observe(reader, error, nullptr);
    reader->Update();
    image->ShallowCopy(reader->GetOutput());
  }
  else
  {
    problem = o.Field + ": a field is read from .vti, legacy .vtk (structured points) or .npy";
    code = BadArguments;
    return nullptr;
  }
  if (!error.Message.empty() || image->GetNumberOfPoints() == 0)
  {
    problem =
      "cannot read " + o.Field + (error.Message.empty() ? ": no points" : ": " + error.Message);
    return nullptr;
  }
  if (!o.Array.empty())
  {
    vtkDataArray* chosen = image->GetPointData()->GetArray(o.Array.c_str());
    if (!chosen)
    {
      problem = o.Field + " has no point data array '" + o.Array + "'";
      return nullptr;
    }
    image->GetPointData()->SetScalars(chosen);
  }
  return image;
}
}

int RunUdf(const UdfOptions& o)
{
  const auto start = std::chrono::steady_clock::now();
  std::string problem;
  int code = 0;
  vtkSmartPointer<vtkImageData> field = ReadField(o, problem, code);
  if (!field)
  {
    std::cerr << "medial-axis: " << problem << "\n";
    return code;
  }
  if (!MakeOutputFolder(o.OutputDir))
  {
    return BadArguments;
  }
  vtkNew<vtkUnsignedDistanceSurfaceExtractor> extractor;
  extractor->SetInputData(field);
  extractor->SetEpsilon(o.Epsilon);
  extractor->SetNumberOfSamples(o.Samples);
  extractor->SetTargetNumberOfVertices(o.Target);
  extractor->SetSnapToZeroSet(o.Snap);
  extractor->SetRandomSeed(o.Seed);
  extractor->SetNumberOfThreads(o.Threads);
  ProgressBar bar{ "udf surface" };
  double seconds = 0.0;
  if (!UpdateStage(extractor, "surface extraction",
        !o.Quiet && isatty(STDERR_FILENO) ? &bar : nullptr, seconds))
  {
    return BadInput; // the message names what is wrong with the field
  }
  vtkPolyData* surface = extractor->GetOutput(0);
  const std::filesystem::path dir(o.OutputDir);
  const std::string surfacePath = (dir / "surface.vtp").string();
  const std::string shellPath = (dir / "shell.vtp").string();
  if (!WriteVtp(surface, surfacePath) || !WriteVtp(extractor->GetOutput(1), shellPath))
  {
    std::cerr << "medial-axis: cannot write into " << o.OutputDir << "\n";
    return ComputationFailed;
  }
  const double wall =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto count = [&](const char* name)
  { return static_cast<long long>(FieldValue(surface, name)); };
  std::cout << "surface of " << o.Field << ": " << surface->GetNumberOfPolys() << " triangles, "
            << count("BoundaryLoops") << " boundary loops, " << count("JunctionEdges")
            << " junction edges, epsilon " << extractor->GetUsedEpsilon() << ", " << wall
            << " s\n  wrote " << surfacePath << "\n  wrote " << shellPath << "\n";
  if (!o.Report.empty())
  {
    std::ostringstream json;
    json.precision(10);
    int dimensions[3];
    field->GetDimensions(dimensions);
    const double* spacing = field->GetSpacing();
    json << "{\n  \"version\": " << JsonString(MEDIALAXIS_VERSION)
         << ",\n  \"commit\": " << JsonString(MEDIALAXIS_COMMIT)
         << ",\n  \"field\": " << JsonString(o.Field) << ",\n  \"grid\": {\"dimensions\": ["
         << dimensions[0] << ", " << dimensions[1] << ", " << dimensions[2] << "], \"spacing\": ["
         << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
         << "]},\n  \"epsilon\": " << extractor->GetUsedEpsilon()
         << ",\n  \"samples\": " << extractor->GetUsedSamples()
         << ",\n  \"spheres\": " << extractor->GetUsedSpheres()
         << ",\n  \"snap\": " << (o.Snap ? "true" : "false")
         << ",\n  \"shell_area\": " << FieldValue(surface, "ShellArea")
         << ",\n  \"counts\": {\"points\": " << surface->GetNumberOfPoints()
         << ", \"triangles\": " << surface->GetNumberOfPolys()
         << ", \"boundary_loops\": " << count("BoundaryLoops")
         << ", \"junction_edges\": " << count("JunctionEdges")
         << ", \"dropped_shrunk_triangles\": " << count("DroppedShrunkTriangles")
         << ", \"dropped_fin_triangles\": " << count("DroppedFinTriangles")
         << ", \"non_distance_neighbours\": " << count("NonDistanceNeighbours")
         << "},\n  \"mean_snap_distance\": " << FieldValue(surface, "MeanSnapDistance")
         << ",\n  \"seconds\": {\"extraction\": " << seconds << ", \"wall\": " << wall
         << "},\n  \"peak_memory_mb\": " << PeakMegabytes() << "\n}\n";
    if (!WriteReport(o.Report, json.str()))
    {
      return ComputationFailed;
    }
  }
  return 0;
}
}
}
