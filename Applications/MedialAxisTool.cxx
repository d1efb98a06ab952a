// SPDX-License-Identifier: GPL-3.0-or-later
// medial-axis: the Structural MAT of a closed triangle surface from the
// command line. See PrintHelp() for the options and exit codes.
#include "HeapTuning.h"
#include "MedialAxisVersion.h"
#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"
#include "Mesh/MedialSheets.h"
#include "Screenshot.h"
#include "Structure/MedialStructure.h"
#include "Surface/SharpEdgeContent.h"
#include "ToolOptions.h"
#include "ToolSupport.h"
#include "UdfCommand.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkCurveSkeletonWriter.h"
#include "vtkErrorEventText.h"
#include "vtkFilletDetector.h"
#include "vtkMedialAxisWriter.h"
#include "vtkMedialCurveSkeleton.h"
#include "vtkMedialMeshConversion.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialSkeletalDiagram.h"
#include "vtkMedialStructure.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkMidSurfaceExtractor.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace medialaxis::tool;

enum ExitCode
{
  Ok = 0,
  BadArguments = 2,
  BadInput = 3,
  ComputationFailed = 4
};

// Writes a stage's outputs, one file name per port, and notes them.
void WriteOutputs(vtkPolyDataAlgorithm* stage, std::initializer_list<const char*> names,
  const std::filesystem::path& dir, std::vector<std::string>& written)
{
  int port = 0;
  for (const char* name : names)
  {
    const std::string path = (dir / name).string();
    WriteVtp(stage->GetOutput(port++), path);
    written.push_back(path);
  }
}

// The primitives of a skeletal diagram as one mesh, each triangle with its
// element's ElementType and ElementId as cell data (one file for any viewer).
vtkSmartPointer<vtkPolyData> JoinPrimitives(vtkPartitionedDataSetCollection* primitives)
{
  vtkNew<vtkAppendPolyData> append;
  for (unsigned int e = 0; e < primitives->GetNumberOfPartitionedDataSets(); ++e)
  {
    auto* mesh = vtkPolyData::SafeDownCast(primitives->GetPartition(e, 0));
    if (!mesh || mesh->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkPolyData> labelled;
    labelled->ShallowCopy(mesh);
    for (const char* name : { "ElementType", "ElementId" })
    {
      vtkNew<vtkIdTypeArray> label;
      label->SetName(name);
      label->SetNumberOfTuples(mesh->GetNumberOfCells());
      label->FillValue(static_cast<vtkIdType>(mesh->GetFieldData()->GetArray(name)->GetTuple1(0)));
      labelled->GetCellData()->AddArray(label);
    }
    labelled->GetFieldData()->Initialize();
    append->AddInputData(labelled);
  }
  vtkSmartPointer<vtkPolyData> joined = vtkSmartPointer<vtkPolyData>::New();
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    joined->ShallowCopy(append->GetOutput());
  }
  return joined;
}

}

int main(int argc, char** argv)
{
  medialaxis::TuneHeap(argv);
  // Errors are reported below, once, in the tool's own words.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  Options o;
  bool help = false, version = false;
  const std::string problem = Parse(argc, argv, o, help, version);
  if (version && !help)
  {
    std::cout << "medial-axis " << MEDIALAXIS_VERSION << " (commit " << MEDIALAXIS_COMMIT << ")\n";
    return Ok;
  }
  if (help)
  {
    PrintHelp();
    return Ok;
  }
  if (!problem.empty())
  {
    std::cerr << "medial-axis: " << problem << "\n";
    return BadArguments;
  }
  if (o.Udf)
  {
    medialaxis::tool::UdfOptions& udf = o.UdfRun;
    udf.Field = o.Input;
    udf.OutputDir = o.OutputDir;
    udf.Report = o.Report;
    udf.Samples = o.Samples > 0 ? o.Samples : 0;
    udf.Target = o.Target > 0 ? o.Target : 0;
    udf.Seed = o.Seed;
    udf.Threads = o.Threads;
    udf.Quiet = o.Quiet;
    return medialaxis::tool::RunUdf(udf);
  }
  // Offscreen rendering needs an X display: run under a virtual one.
  if (!o.Screenshot.empty() && !std::getenv("DISPLAY"))
  {
    if (std::getenv("MEDIALAXIS_UNDER_XVFB"))
    {
      std::cerr << "medial-axis: --screenshot needs an X display, and xvfb-run gave none\n";
      return BadArguments;
    }
    setenv("MEDIALAXIS_UNDER_XVFB", "1", 1);
    std::vector<char*> args{ const_cast<char*>("xvfb-run"), const_cast<char*>("-a"),
      const_cast<char*>("-s"), const_cast<char*>("-screen 0 1280x1024x24") };
    for (int i = 0; i < argc; ++i)
    {
      args.push_back(argv[i]);
    }
    args.push_back(nullptr);
    execvp("xvfb-run", args.data());
    std::cerr << "medial-axis: --screenshot needs an X display or xvfb-run (Debian package "
                 "xvfb)\n";
    return BadArguments;
  }
  if (!MakeOutputFolder(o.OutputDir))
  {
    return BadArguments;
  }
  const bool showProgress = !o.Quiet && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();

  // Read and validate: problems of the input exit with code 3.
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(o.Input.c_str());
  LastError readError;
  Observe(reader, readError, nullptr);
  reader->Update();
  if (!readError.Message.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    // The reader's message names the file and, for malformed files, the line.
    std::cerr << "medial-axis: cannot read "
              << (readError.Message.empty() ? o.Input + ": no points" : readError.Message) << "\n";
    return BadInput;
  }
  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputConnection(reader->GetOutputPort());
  validator->SetRepairSelfIntersections(o.Repair);
  LastError validationError;
  Observe(validator, validationError, nullptr);
  validator->Update();
  if (!validator->GetValid())
  {
    std::cerr << "medial-axis: invalid surface " << o.Input << ": " << validator->GetErrorMessage()
              << "\n";
    return BadInput;
  }

  vtkPolyData* surface = validator->GetOutput();
  if (validator->GetRepaired() && !o.Quiet)
  {
    if (validator->GetWrapped())
    {
      std::cout << "  repaired: " << validator->GetNumberOfCrossingPairs()
                << " pairs of crossing triangles could not be resolved exactly; the surface was "
                   "wrapped instead, within "
                << 100.0 * validator->GetRepairDeviation() << "% of the diagonal of the input\n";
    }
    else if (std::string(validator->GetRepairMethod()) == "pulled apart")
    {
      std::cout << "  repaired: " << validator->GetNumberOfCrossingPairs()
                << " pairs of crossing triangles far apart, a vertex poking through a wall: "
                   "moved back behind it, by at most "
                << 100.0 * validator->GetRepairDeviation() << "% of the diagonal of the input\n";
    }
    else
    {
      std::cout << "  repaired: " << validator->GetNumberOfCrossingPairs()
                << " pairs of crossing triangles resolved into the outer boundary, area "
                << validator->GetRemovedArea() << " inside removed\n";
    }
  }
  medialaxis::SharpEdgeContent sharpEdges;
  if (o.AutomaticPreset)
  {
    sharpEdges = medialaxis::MeasureSharpEdgeContent(
      medialaxis::OutwardTriangleMesh(surface), vtkMath::RadiansFromDegrees(o.FeatureAngle));
    o.Cad = medialaxis::LooksLikeCad(sharpEdges);
  }

  vtkNew<vtkStructuralMedialAxis> structural;
  if (o.Cad)
  {
    structural->SetPresetToCAD();
  }
  if (o.Samples > 0)
  {
    structural->SetNumberOfSamples(o.Samples);
  }
  if (o.Target > 0)
  {
    structural->SetTargetNumberOfVertices(o.Target);
  }
  if (o.Sharp >= 0)
  {
    structural->SetPreserveSharpFeatures(o.Sharp == 1);
  }
  structural->SetMaximumError(o.MaximumError);
  structural->SetFeatureAngle(o.FeatureAngle);
  structural->SetFeatureNormalFiltering(o.FeatureNormalFiltering);
  structural->SetFringeCollapses(o.FringeCollapses);
  structural->SetErrorBands(o.ErrorBands);
  structural->SetHairAngle(o.HairAngle);
  structural->SetFinBudget(o.FinBudget);
  structural->SetPleatAngle(o.PleatAngle);
  structural->SetEulerNeutralSpikeCollapses(o.SpikeCollapses);
  structural->SetClampRadiiToAtlas(o.ClampRadii);
  structural->SetAbsorbSpikes(o.AbsorbSpikes);
  structural->SetFinalFit(o.FinalFit);
  structural->SetFitSpikeRepair(o.SpikeRepair);
  structural->SetFitSheetBoundaryRadii(o.FitBoundaryRadii);
  structural->SetStrategy(
    o.QMat ? vtkStructuralMedialAxis::QMat : vtkStructuralMedialAxis::Structural);
  structural->SetRandomSeed(o.Seed);
  if (o.Adaptive >= 0)
  {
    structural->SetAdaptiveSampling(o.Adaptive == 1);
  }
  structural->SetNumberOfThreads(o.Threads);
  structural->SetGenerateEnvelope(o.Envelope);
  // A repaired surface is repaired again inside (the same result), so that
  // the correspondence names the input's triangles (InputTriangleId).
  structural->SetRepairSelfIntersections(o.Repair);
  structural->SetInputConnection(
    validator->GetRepaired() ? reader->GetOutputPort() : validator->GetOutputPort());
  ProgressBar bar{ "medial axis" };
  LastError computeError;
  Observe(structural, computeError, showProgress ? &bar : nullptr);
  structural->Update();
  vtkPolyData* mat = structural->GetOutput(0);
  if (!computeError.Message.empty() || mat->GetNumberOfPoints() == 0)
  {
    std::cerr << "medial-axis: computation failed: "
              << (computeError.Message.empty() ? "empty result" : computeError.Message) << "\n";
    return ComputationFailed;
  }

  const std::filesystem::path dir(o.OutputDir);
  std::vector<std::string> written;
  vtkNew<vtkMedialAxisWriter> maWriter;
  maWriter->SetInputData(mat);
  const std::string maPath = (dir / "mat.ma").string();
  maWriter->SetFileName(maPath.c_str());
  if (maWriter->Write() != 1 || !WriteVtp(mat, (dir / "mat.vtp").string()))
  {
    std::cerr << "medial-axis: cannot write into " << o.OutputDir << "\n";
    return ComputationFailed;
  }
  written.push_back(maPath);
  written.push_back((dir / "mat.vtp").string());
  if (o.Correspondence)
  {
    const std::string path = (dir / "correspondence.vtp").string();
    WriteVtp(vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)), path);
    written.push_back(path);
  }
  double envelopeSeconds = 0.0;
  if (o.Envelope)
  {
    // The one-click filter made it (port 3).
    envelopeSeconds = FieldValue(mat, "EnvelopeSeconds");
    const std::string path = (dir / "envelope.vtp").string();
    WriteVtp(vtkPolyData::SafeDownCast(structural->GetOutputDataObject(3)), path);
    written.push_back(path);
  }
  double filletSeconds = 0.0;
  vtkNew<vtkFilletDetector> fillets;
  if (o.Fillets)
  {
    fillets->SetInputData(0, mat);
    fillets->SetInputData(1, vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)));
    fillets->SetInputConnection(2, validator->GetOutputPort());
    ProgressBar filletBar{ "fillets" };
    if (!UpdateStage(
          fillets, "fillet detection", showProgress ? &filletBar : nullptr, filletSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(fillets, { "fillets.vtp", "fillet_faces.vtp" }, dir, written);
  }
  double structureSeconds = 0.0;
  vtkNew<vtkMedialStructure> structure;
  if (o.Structure)
  {
    structure->SetInputData(0, mat);
    if (o.Fillets)
    {
      structure->SetInputData(1, fillets->GetOutput(0));
    }
    structure->SetInputData(2, vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1)));
    if (!UpdateStage(structure, "structure", nullptr, structureSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(structure, { "structure.vtp", "seams.vtp" }, dir, written);
  }
  double midSurfaceSeconds = 0.0;
  vtkNew<vtkMidSurfaceExtractor> midSurface;
  if (o.MidSurface)
  {
    midSurface->SetInputConnection(0, validator->GetOutputPort());
    midSurface->SetInputData(1, mat);
    if (!UpdateStage(midSurface, "mid-surface", nullptr, midSurfaceSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(midSurface, { "mid_surface.vtp" }, dir, written);
  }
  double diagramSeconds = 0.0;
  vtkNew<vtkMedialSkeletalDiagram> diagram;
  if (o.SkeletalDiagram > 0)
  {
    diagram->SetInputConnection(0, validator->GetOutputPort());
    diagram->SetInputDataObject(1, mat);
    diagram->SetMaximumElements(o.SkeletalDiagram);
    if (!UpdateStage(diagram, "skeletal diagram", nullptr, diagramSeconds))
    {
      return ComputationFailed;
    }
    const std::string skeletonPath = (dir / "skeleton.vtp").string();
    WriteVtp(diagram->GetSkeleton(), skeletonPath);
    written.push_back(skeletonPath);
    const std::string primitivesPath = (dir / "primitives.vtp").string();
    WriteVtp(JoinPrimitives(diagram->GetPrimitives()), primitivesPath);
    written.push_back(primitivesPath);
    const std::string reconstructionPath = (dir / "reconstruction.vtp").string();
    WriteVtp(diagram->GetReconstruction(), reconstructionPath);
    written.push_back(reconstructionPath);
  }
  double curveSeconds = 0.0;
  vtkNew<vtkMedialCurveSkeleton> curve;
  if (o.CurveSkeleton)
  {
    curve->SetInputConnection(0, validator->GetOutputPort());
    curve->SetInputDataObject(1, mat);
    if (!UpdateStage(curve, "curve skeleton", nullptr, curveSeconds))
    {
      return ComputationFailed;
    }
    WriteOutputs(curve, { "curve_skeleton.vtp", "segmentation.vtp" }, dir, written);
    for (const char* name : { "curve_skeleton.swc", "curve_skeleton.json" })
    {
      vtkNew<vtkCurveSkeletonWriter> writer;
      writer->SetInputData(curve->GetSkeleton());
      writer->SetFileName((dir / name).string().c_str());
      const std::string header = "curve skeleton of " + o.Input + "\nmedial-axis " +
        MEDIALAXIS_VERSION + "\nunits: those of the input mesh";
      writer->SetHeader(header.c_str());
      if (!writer->Write())
      {
        std::cerr << "medial-axis: " << writer->GetErrorMessage() << "\n";
        return ComputationFailed;
      }
      written.push_back((dir / name).string());
    }
  }
  if (!o.Screenshot.empty())
  {
    vtkPolyData* shown =
      o.CurveSkeleton ? curve->GetSkeleton() : (o.MidSurface ? midSurface->GetOutput() : mat);
    const std::string problem = medialaxis::WriteScreenshot(o.Screenshot, validator->GetOutput(),
      shown, o.Fillets ? fillets->GetOutput(1) : nullptr,
      o.Fillets ? fillets->GetOutput(0) : nullptr, 1200, 900);
    if (!problem.empty())
    {
      std::cerr << "medial-axis: screenshot failed: " << problem << "\n";
      return ComputationFailed;
    }
    written.push_back(o.Screenshot);
  }
  // Two-sided distances between the surface and a reconstruction of it (the
  // MAT's envelope, or the skeletal diagram's union), absolute.
  struct Distances
  {
    double Hausdorff = -1.0, HausdorffPercent = -1.0, ToEnvelope = -1.0, ToSurface = -1.0,
           Mean = -1.0, MeanPercent = -1.0;
  };
  auto measure = [&](vtkPolyData* reconstruction, const char* what, double& seconds,
                   vtkMedialReconstructionError* error, Distances& d)
  {
    error->SetInputConnection(0, validator->GetOutputPort());
    error->SetInputData(1, reconstruction);
    error->SetNumberOfThreads(o.Threads);
    ProgressBar errorBar{ "error" };
    if (!UpdateStage(error, what, showProgress ? &errorBar : nullptr, seconds))
    {
      return false;
    }
    d.Hausdorff = error->GetHausdorff();
    d.HausdorffPercent = error->GetHausdorffPercent();
    d.ToEnvelope = error->GetHausdorffSurfaceToEnvelope();
    d.ToSurface = error->GetHausdorffEnvelopeToSurface();
    d.Mean = FieldValue(error->GetOutput(0), "Mean");
    d.MeanPercent = FieldValue(error->GetOutput(0), "MeanPercent");
    return true;
  };
  Distances matDistances, diagramDistances;
  double errorSeconds = 0.0, diagramErrorSeconds = 0.0;
  vtkNew<vtkMedialReconstructionError> error, diagramError;
  if (o.Error)
  {
    if (!measure(mat, "error measurement", errorSeconds, error, matDistances))
    {
      return ComputationFailed;
    }
    const std::string path = (dir / "distance.vtp").string();
    WriteVtp(error->GetOutput(0), path);
    written.push_back(path);
    if (o.SkeletalDiagram > 0 && diagram->GetReconstruction()->GetNumberOfPolys() > 0 &&
      !measure(diagram->GetReconstruction(), "skeletal diagram error measurement",
        diagramErrorSeconds, diagramError, diagramDistances))
    {
      return ComputationFailed;
    }
  }
  const double hausdorff = matDistances.Hausdorff, hausdorffPercent = matDistances.HausdorffPercent,
               toEnvelope = matDistances.ToEnvelope, toSurface = matDistances.ToSurface;
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  medialaxis::MedialMesh mesh;
  medialaxis::PolyDataToMedialMesh(mat, mesh);
  const medialaxis::MedialMeshQuality quality = medialaxis::MeasureQuality(mesh);
  const medialaxis::MedialCleanliness clean =
    medialaxis::MeasureCleanliness(mesh, surface->GetLength());
  const long long euler = medialaxis::EulerCharacteristic(mesh);
  const medialaxis::MedialMeshCheck check = medialaxis::ValidateMedialMesh(mesh);
  std::cout << "medial axis of " << o.Input << ": " << mesh.Centers.size() << " spheres, "
            << quality.Triangles << " slabs, Euler characteristic " << euler << ", " << seconds
            << " s";
  if (o.Error)
  {
    std::cout << ", two-sided Hausdorff " << hausdorffPercent << "% of the diagonal";
  }
  std::cout << "\n  sheets: " << clean.Sheets << ", N80 " << clean.SheetsFor80PercentArea
            << ", largest " << 100.0 * clean.LargestSheetAreaFraction << "% of the area, fins "
            << 100.0 * clean.FinAreaFraction << "% of the area, folds "
            << 100.0 * clean.FoldedEdgeFraction << "% of the sheet edges, boundary "
            << clean.BoundaryLength << " and junctions " << clean.JunctionLength
            << " diagonals long\n";
  if (FieldValue(mat, "AddedSamples") > 0)
  {
    std::cout << "  sampled again: " << FieldValue(mat, "AddedSamples")
              << " samples added (on thin parts when adaptive), where the first sampling "
                 "missed handles\n";
  }
  if (o.AutomaticPreset)
  {
    std::cout << "  preset: " << (o.Cad ? "cad" : "organic") << " (sharp-edge creases "
              << sharpEdges.Ratio() << " times the square root of the area, " << sharpEdges.Creases
              << " creases)\n";
  }
  vtkPolyData* filletLines = fillets->GetOutput(0);
  if (o.Fillets)
  {
    vtkCellData* cells = filletLines->GetCellData();
    std::cout << "  " << filletLines->GetNumberOfCells() << " fillets\n";
    for (vtkIdType f = 0; f < filletLines->GetNumberOfCells(); ++f)
    {
      std::cout << "    fillet " << f << ": radius " << cells->GetArray("MeanRadius")->GetTuple1(f)
                << " (from " << cells->GetArray("MinimumRadius")->GetTuple1(f) << " to "
                << cells->GetArray("MaximumRadius")->GetTuple1(f) << "), length "
                << cells->GetArray("Length")->GetTuple1(f) << "\n";
    }
  }
  auto typeName = [](int t)
  { return medialaxis::MedialVertexTypeName(static_cast<medialaxis::MedialVertexType>(t)); };
  if (o.Structure)
  {
    std::cout << "  " << structure->GetNumberOfSheets() << " sheets, "
              << structure->GetNumberOfSeams() << " seams; spheres:";
    for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
    {
      std::cout << (t ? ", " : " ") << structure->GetNumberOfVerticesOfType(t) << " "
                << typeName(t);
    }
    std::cout << "\n";
  }
  if (o.MidSurface)
  {
    std::cout << "  mid-surface: " << midSurface->GetNumberOfWalls() << " walls from "
              << midSurface->GetNumberOfWallSheets() << " medial sheets, wall thickness "
              << midSurface->GetEstimatedWallThickness() << ", "
              << midSurface->GetNumberOfJunctionEdges() << " junction edges\n";
  }
  if (o.SkeletalDiagram > 0)
  {
    vtkPolyData* skeleton = diagram->GetSkeleton();
    std::cout << "  skeletal diagram: " << FieldValue(skeleton, "Vertices") << " vertices, "
              << skeleton->GetNumberOfLines() << " edges, " << skeleton->GetNumberOfPolys()
              << " triangles, surface within " << 100.0 * diagram->GetReachedError()
              << "% of the diagonal of the primitives";
    if (diagramDistances.Hausdorff >= 0.0)
    {
      std::cout << ", reconstruction: two-sided Hausdorff " << diagramDistances.HausdorffPercent
                << "%, mean " << diagramDistances.MeanPercent << "%";
    }
    std::cout << "\n";
  }
  if (o.CurveSkeleton)
  {
    vtkPolyData* skeleton = curve->GetSkeleton();
    std::cout << "  curve skeleton: " << FieldValue(skeleton, "Nodes") << " nodes, "
              << FieldValue(skeleton, "Branches") << " branches, "
              << FieldValue(skeleton, "Junctions") << " junctions, "
              << FieldValue(skeleton, "CycleRank") << " loops\n";
  }
  for (const std::string& path : written)
  {
    std::cout << "  wrote " << path << "\n";
  }

  if (!o.Report.empty())
  {
    std::ostringstream json;
    json.precision(10);
    json << "{\n  \"version\": " << JsonString(MEDIALAXIS_VERSION)
         << ",\n  \"commit\": " << JsonString(MEDIALAXIS_COMMIT)
         << ",\n  \"input\": " << JsonString(o.Input)
         << ",\n  \"surface\": {\"points\": " << surface->GetNumberOfPoints()
         << ", \"triangles\": " << surface->GetNumberOfPolys()
         << ", \"area\": " << FieldValue(surface, "Area")
         << ", \"volume\": " << FieldValue(surface, "Volume") << "}"
         << ",\n  \"repair\": {\"repaired\": " << (validator->GetRepaired() ? "true" : "false")
         << ", \"crossing_pairs\": " << validator->GetNumberOfCrossingPairs()
         << ", \"removed_area\": " << validator->GetRemovedArea() << ", \"method\": "
         << (validator->GetRepaired() ? JsonString(validator->GetRepairMethod()) : "null")
         << ", \"deviation\": " << validator->GetRepairDeviation() << "}"
         << ",\n  \"preset\": " << (o.Cad ? "\"cad\"" : "\"organic\"")
         << ", \"preset_chosen\": " << (o.AutomaticPreset ? "\"auto\"" : "\"given\"");
    if (o.AutomaticPreset)
    {
      json << ", \"sharp_edges\": {\"crease_ratio\": " << sharpEdges.Ratio()
           << ", \"creases\": " << sharpEdges.Creases
           << ", \"crease_length\": " << sharpEdges.CreaseLength
           << ", \"sharp_length\": " << sharpEdges.SharpLength << "}";
    }
    json << ",\n  \"parameters\": {"
         << "\"samples\": " << structural->GetNumberOfSamples()
         << ", \"adaptive_sampling\": " << (structural->GetAdaptiveSampling() ? "true" : "false")
         << ", \"target\": " << structural->GetTargetNumberOfVertices()
         << ", \"max_error\": " << structural->GetMaximumError()
         << ", \"preserve_sharp_features\": "
         << (structural->GetPreserveSharpFeatures() ? "true" : "false")
         << ", \"feature_angle\": " << o.FeatureAngle
         << ", \"feature_normal_filtering\": " << o.FeatureNormalFiltering
         << ", \"fringe_collapses\": "
         << (o.FringeCollapses == vtkAtlasMedialAxisSimplifier::FringeAutomatic ? "\"automatic\""
                : o.FringeCollapses == vtkAtlasMedialAxisSimplifier::FringeOn   ? "\"on\""
                                                                                : "\"off\"")
         << ", \"error_bands\": "
         << (o.ErrorBands == vtkAtlasMedialAxisSimplifier::BandsAutomatic ? "\"automatic\""
                : o.ErrorBands == vtkAtlasMedialAxisSimplifier::BandsOn   ? "\"on\""
                                                                          : "\"off\"")
         << ", \"hair_angle\": " << o.HairAngle << ", \"fin_budget\": " << o.FinBudget
         << ", \"pleat_angle\": " << o.PleatAngle << ", \"euler_neutral_spike_collapses\": "
         << (structural->GetEulerNeutralSpikeCollapses() ? "true" : "false")
         << ", \"absorb_spikes\": " << (structural->GetAbsorbSpikes() ? "true" : "false")
         << ", \"clamp_radii_to_atlas\": "
         << (structural->GetClampRadiiToAtlas() ? "true" : "false")
         << ", \"final_fit\": " << (structural->GetFinalFit() ? "true" : "false")
         << ", \"spike_repair\": " << structural->GetFitSpikeRepair()
         << ", \"fit_boundary_radii\": "
         << (structural->GetFitSheetBoundaryRadii() ? "true" : "false")
         << ", \"strategy\": " << (o.QMat ? "\"qmat\"" : "\"structural\"")
         << ", \"seed\": " << o.Seed << ", \"threads\": " << o.Threads << "},\n  \"seconds\": {";
    const char* stages[] = { "Sampling", "RestrictedVoronoi", "VoronoiMedialAxis", "Simplification",
      "Total" };
    for (int k = 0; k < 5; ++k)
    {
      json << (k ? ", " : "") << JsonString(stages[k]) << ": "
           << FieldValue(mat, (std::string(stages[k]) + "Seconds").c_str());
    }
    json << ", \"QueueInitialisation\": " << FieldValue(mat, "QueueInitialisationSeconds")
         << ", \"Envelope\": " << envelopeSeconds << ", \"Fillets\": " << filletSeconds
         << ", \"Structure\": " << structureSeconds << ", \"MidSurface\": " << midSurfaceSeconds
         << ", \"SkeletalDiagram\": " << diagramSeconds << ", \"Error\": " << errorSeconds
         << ", \"SkeletalDiagramError\": " << diagramErrorSeconds
         << ", \"CurveSkeleton\": " << curveSeconds << ", \"wall\": " << seconds
         << "},\n  \"peak_memory_mb\": " << PeakMegabytes()
         << ",\n  \"counts\": {\"sites\": " << FieldValue(mat, "Sites")
         << ", \"added_samples\": " << FieldValue(mat, "AddedSamples")
         << ", \"missing_handles\": " << FieldValue(mat, "MissingLoops")
         << ", \"initial_vertices\": " << FieldValue(mat, "InitialVertices")
         << ", \"initial_triangles\": " << FieldValue(mat, "InitialTriangles")
         << ", \"vertices\": " << mesh.Centers.size()
         << ", \"edges\": " << medialaxis::AllEdges(mesh).size()
         << ", \"triangles\": " << mesh.Faces.size()
         << ", \"boundary_edges\": " << quality.BoundaryEdges
         << ", \"nonmanifold_edges\": " << quality.NonManifoldEdges
         << ", \"collapses\": " << FieldValue(mat, "Collapses")
         << ", \"fin_collapses\": " << FieldValue(mat, "FinCollapses")
         << ", \"eroded_triangles\": " << FieldValue(mat, "ErodedTriangles")
         << ", \"fringe_collapses_used\": "
         << (FieldValue(mat, "FringeCollapsesUsed") == 1.0 ? "true" : "false")
         << ", \"error_bands_used\": "
         << (FieldValue(mat, "ErrorBandsUsed") == 1.0 ? "true" : "false")
         << ", \"error_target_evaluations\": " << FieldValue(mat, "ErrorTargetEvaluations")
         << ", \"error_target_hausdorff_percent\": "
         << 100.0 * FieldValue(mat, "ErrorTargetHausdorff") << "},\n"
         << "  \"valid\": " << (check.IsValid() ? "true" : "false")
         << ", \"validity_problem\": " << JsonString(check.Message) << ",\n"
         << "  \"euler_characteristic\": " << euler << ",\n  \"triangle_quality\": {"
         << "\"degenerate\": " << quality.DegenerateTriangles
         << ", \"folded\": " << quality.FoldedTriangles
         << ", \"mean_min_angle_deg\": " << quality.MeanMinimumAngle
         << ", \"percent_min_angle_below_30\": " << quality.PercentMinimumAngleBelow30
         << ", \"mean_q\": " << quality.MeanQuality << "},\n  \"cleanliness\": {"
         << "\"sheets\": " << clean.Sheets << ", \"n80\": " << clean.SheetsFor80PercentArea
         << ", \"largest_sheet_area_percent\": " << 100.0 * clean.LargestSheetAreaFraction
         << ", \"fin_area_percent\": " << 100.0 * clean.FinAreaFraction
         << ", \"folds_percent\": " << 100.0 * clean.FoldedEdgeFraction
         << ", \"junction_edges\": " << clean.JunctionEdges
         << ", \"boundary_length_diagonals\": " << clean.BoundaryLength
         << ", \"junction_length_diagonals\": " << clean.JunctionLength << "}";
    if (o.Fillets)
    {
      vtkCellData* cells = filletLines->GetCellData();
      json << ",\n  \"fillets\": [";
      for (vtkIdType f = 0; f < filletLines->GetNumberOfCells(); ++f)
      {
        json << (f ? ",\n    " : "\n    ")
             << "{\"mean_radius\": " << cells->GetArray("MeanRadius")->GetTuple1(f)
             << ", \"minimum_radius\": " << cells->GetArray("MinimumRadius")->GetTuple1(f)
             << ", \"maximum_radius\": " << cells->GetArray("MaximumRadius")->GetTuple1(f)
             << ", \"length\": " << cells->GetArray("Length")->GetTuple1(f)
             << ", \"surface_area\": " << cells->GetArray("SurfaceArea")->GetTuple1(f) << "}";
      }
      json << "]";
    }
    if (o.Structure)
    {
      json << ",\n  \"structure\": {\"sheets\": " << structure->GetNumberOfSheets()
           << ", \"seams\": " << structure->GetNumberOfSeams() << ", \"spheres\": {";
      for (int t = 0; t < medialaxis::NumberOfMedialVertexTypes; ++t)
      {
        json << (t ? ", " : "") << JsonString(typeName(t)) << ": "
             << structure->GetNumberOfVerticesOfType(t);
      }
      json << "}, \"tangent_component_agreement\": "
           << FieldValue(structure->GetOutput(0), "TangentComponentAgreement") << "}";
    }
    if (o.MidSurface)
    {
      json << ",\n  \"mid_surface\": {\"walls\": " << midSurface->GetNumberOfWalls()
           << ", \"wall_sheets\": " << midSurface->GetNumberOfWallSheets()
           << ", \"wall_thickness\": " << midSurface->GetEstimatedWallThickness()
           << ", \"junction_edges\": " << midSurface->GetNumberOfJunctionEdges()
           << ", \"triangles\": " << midSurface->GetOutput()->GetNumberOfPolys() << "}";
    }
    if (o.SkeletalDiagram > 0)
    {
      vtkPolyData* skeleton = diagram->GetSkeleton();
      json << ",\n  \"skeletal_diagram\": {\"vertices\": " << FieldValue(skeleton, "Vertices")
           << ", \"edges\": " << skeleton->GetNumberOfLines()
           << ", \"triangles\": " << skeleton->GetNumberOfPolys()
           << ", \"error\": " << diagram->GetReachedError()
           << ", \"mean_error\": " << FieldValue(skeleton, "MeanError")
           << ", \"failed_elements\": " << FieldValue(skeleton, "FailedElements")
           << ", \"omitted_triangles\": " << FieldValue(skeleton, "OmittedTriangles")
           << ", \"continuous_parameters\": " << FieldValue(skeleton, "ContinuousParameters");
      if (diagramDistances.Hausdorff >= 0.0)
      {
        json << ", \"hausdorff\": {\"two_sided\": " << diagramDistances.Hausdorff
             << ", \"two_sided_percent\": " << diagramDistances.HausdorffPercent
             << ", \"surface_to_envelope\": " << diagramDistances.ToEnvelope
             << ", \"envelope_to_surface\": " << diagramDistances.ToSurface
             << ", \"mean_two_sided\": " << diagramDistances.Mean
             << ", \"mean_two_sided_percent\": " << diagramDistances.MeanPercent << "}";
      }
      json << "}";
    }
    if (o.CurveSkeleton)
    {
      vtkPolyData* skeleton = curve->GetSkeleton();
      json << ",\n  \"curve_skeleton\": {";
      const char* counts[] = { "Nodes", "Branches", "Junctions", "Ends", "CycleRank", "Components",
        "PrunedBranches", "UncollapsedTriangles" };
      const char* keys[] = { "nodes", "branches", "junctions", "ends", "cycle_rank", "components",
        "pruned_branches", "uncollapsed_triangles" };
      for (int k = 0; k < 8; ++k)
      {
        json << (k ? ", " : "") << JsonString(keys[k]) << ": " << FieldValue(skeleton, counts[k]);
      }
      json << "}";
    }
    if (o.Error)
    {
      json << ",\n  \"hausdorff\": {\"two_sided\": " << hausdorff
           << ", \"two_sided_percent\": " << hausdorffPercent
           << ", \"surface_to_envelope\": " << toEnvelope
           << ", \"envelope_to_surface\": " << toSurface
           << ", \"mean_two_sided\": " << matDistances.Mean
           << ", \"mean_two_sided_percent\": " << matDistances.MeanPercent << "}";
    }
    json << "\n}\n";
    if (!WriteReport(o.Report, json.str()))
    {
      return ComputationFailed;
    }
  }
  return Ok;
}
