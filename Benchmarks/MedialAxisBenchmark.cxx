// SPDX-License-Identifier: GPL-3.0-or-later
// Per-stage wall time and peak resident memory of the MedialAxis pipeline.
//
//   medialaxis-benchmark [--samples N] [--target V] [--cad] [--threads T] [--scaling]
//                        [--counts N1,N2,...] [--envelope] [--error-samples S]
//                        [--envelope-samples E] [--delaunay] [--adaptive|--uniform] [--no-fit]
//                        [--shape torus|box|...] [--resolution R] [--subdivide K]
//                        [--json FILE] mesh...
//
// Each run ends with a summary line: the stages, then the pipeline's total
// (reading the mesh to the simplified MAT, without --envelope's stages) and
// its peak, and with --delaunay the ratio of the total to the Delaunay
// triangulation of the same samples. --json FILE writes the same figures,
// one record per run, for scripts (docs/performance.md).
//
// Memory: the process's resident peak during each stage, and in brackets
// how far it rose above the resident size at the stage's start.
// --scaling runs every mesh at 10K, 25K, 50K, 100K and 200K samples (or the
// --counts given; target a tenth of the samples), prints the fitted growth
// exponent of each stage's time, and a table of samples against the run's
// time and peak memory with the growth exponent of the memory the run adds
// to the loaded mesh. --resolution sets a --shape's tessellation (torus:
// 128 R^2 triangles, R = 90 gives about 1M). --subdivide K refines each
// loaded mesh K times by Loop subdivision (4^K times the triangles: the bunny
// at K = 3 has 1.8M), a "subdivide" stage outside the total, which stands for
// a scan of that size.
// --envelope adds, on the simplified MAT: "envelope" (the primitives-mode
// envelope surface, core), "envelope-vtk" (the same through
// vtkSlabReconstructor, poly data included) and "error" (reconstruction
// error with S surface samples, default 100,000, and E envelope samples,
// default the library's, 50,000).
// --adaptive samples thin parts densely (SamplingOptions::Adaptive), the
// default without --cad, as in the presets; the sampling stage then includes
// the thickness rays. --uniform samples uniformly, the default with --cad.
// --no-fit leaves out the simplifier's final fit (AtlasSimplifierOptions::
// FinalFit), whose time is otherwise part of "simplify" and printed alone.
// --delaunay also times CGAL's Delaunay triangulation of the same samples
// alone (outside the stages and the total: the least a Voronoi-based MAT
// pays).
// The heap is tuned (HeapTuning.h) unless MEDIALAXIS_TUNE_HEAP=0; the
// first line printed says how.
#include "DelaunayBaseline.h"
#include "Envelope/EnvelopeDistance.h"
#include "Envelope/EnvelopeMesher.h"
#include "Envelope/ReconstructionError.h"
#include "HeapTuning.h"
#include "Mesh/MedialMeshQuality.h"
#include "Mesh/MedialSheets.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"
#include "Support/HeapRelease.h"
#include "Support/Parallel.h"
#include "Surface/AnalyticShapes.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "Voronoi/VoronoiMedialAxis.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSlabReconstructor.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace medialaxis;

namespace
{
// Peak resident memory since the last reset, in MB (Linux /proc).
void ResetPeakMemory()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}
double StatusMB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind(field, 0) == 0)
    {
      return std::stod(line.substr(std::strlen(field))) / 1024.0;
    }
  }
  return 0.0;
}

struct Stage
{
  std::string Name;
  double Seconds;
  double PeakMB;  // resident peak of the whole process during the stage
  double ExtraMB; // that peak minus the resident size when the stage began
};

template <typename F>
Stage Measure(const std::string& name, F&& work)
{
  ResetPeakMemory();
  const double before = StatusMB("VmRSS:");
  const auto start = std::chrono::steady_clock::now();
  work();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double peak = StatusMB("VmHWM:");
  return { name, seconds, peak, peak - before };
}

int ShapeResolution = 0; // 0: each shape's default
int Subdivisions = 0;    // Loop subdivisions of each loaded mesh

bool LoadSurface(
  const std::string& spec, bool isShape, TriangleMesh& mesh, std::vector<Stage>& stages)
{
  if (isShape)
  {
    TriangleMesh shape;
    stages.push_back(Measure("generate",
      [&]
      {
        if (spec == "torus")
          shape = MakeTorus(2.0, 0.5, ShapeResolution ? ShapeResolution : 64);
        else if (spec == "sphere")
          shape = MakeSphere(1.0, ShapeResolution ? ShapeResolution : 64);
        else if (spec == "box")
          shape = MakeRoundedBox({ 2, 2, 2 }, 0.2, ShapeResolution ? ShapeResolution : 32);
      }));
    if (shape.Triangles.empty())
    {
      std::cerr << "unknown shape '" << spec << "' (torus, sphere, box)\n";
      return false;
    }
    SurfacePreparationReport report;
    stages.push_back(Measure("prepare", [&] { report = PrepareSurface(shape, mesh); }));
    if (!report.Ok())
    {
      std::cerr << spec << ": " << report.Error << "\n";
      return false;
    }
    return true;
  }
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(spec.c_str());
  stages.push_back(Measure("read", [&] { reader->Update(); }));
  if (reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << reader->GetErrorMessage() << "\n";
    return false;
  }
  vtkPolyData* surface = reader->GetOutput();
  vtkNew<vtkLoopSubdivisionFilter> subdivision;
  if (Subdivisions > 0)
  {
    subdivision->SetInputData(surface);
    subdivision->SetNumberOfSubdivisions(Subdivisions);
    stages.push_back(Measure("subdivide", [&] { subdivision->Update(); }));
    surface = subdivision->GetOutput();
  }
  // As the one-click filter prepares it: crossings repaired.
  SurfacePreparationOptions options;
  options.RepairSelfIntersections = true;
  SurfacePreparationReport report;
  stages.push_back(
    Measure("prepare", [&] { report = PrepareSurfaceMesh(surface, mesh, options); }));
  if (!report.Ok())
  {
    std::cerr << spec << ": " << report.Error << "\n";
    return false;
  }
  return true;
}

std::size_t TopologyGuard = AtlasSimplifierOptions().TopologyGuardVertexCount;
bool Envelope = false;
bool DelaunayBaseline = false;
double DelaunaySeconds = 0.0; // of the last run, with DelaunayBaseline
std::string JsonPath;
std::vector<std::string> JsonRecords;
int AdaptiveSampling = -1; // -1: as the presets, adaptive unless --cad
bool FinalFit = true;
std::size_t ErrorSamples = 100000;
std::size_t EnvelopeSamples = ReconstructionErrorOptions().NumberOfEnvelopeSamples;

// Envelope (primitives mode) and reconstruction error of a simplified MAT.
void RunEnvelope(const TriangleMesh& mesh, const MedialMesh& medial, std::vector<Stage>& stages)
{
  EnvelopeSurface surface;
  stages.push_back(Measure("envelope",
    [&]
    {
      const MedialEnvelope envelope(medial);
      surface = MeshEnvelopePrimitives(envelope, EnvelopeMeshOptions());
    }));
  vtkNew<vtkPolyData> medialPd;
  MedialMeshToPolyData(medial, medialPd);
  vtkNew<vtkSlabReconstructor> reconstructor;
  reconstructor->SetInputData(medialPd);
  stages.push_back(Measure("envelope-vtk", [&] { reconstructor->Update(); }));
  ReconstructionErrorResult error;
  ReconstructionErrorOptions options;
  options.NumberOfSamples = ErrorSamples;
  options.NumberOfEnvelopeSamples = EnvelopeSamples;
  stages.push_back(Measure("error",
    [&]
    {
      const MedialEnvelope envelope(medial);
      error = ComputeReconstructionError(mesh, envelope, options);
    }));
  std::printf("  envelope: %zu triangles; error (%zu + %zu vertices surface samples, %zu envelope "
              "samples of %zu candidates): Hausdorff %.4f%% (surface->envelope %.4f%%, at least "
              "%.4f%%; envelope->surface %.4f%%), mean %.4f%%, RMS %.4f%%; %zu of %zu inside "
              "points uncertified, largest gap %.3g%%\n",
    surface.Mesh.Triangles.size(), ErrorSamples, mesh.Points.size(), error.EnvelopeSamples.size(),
    error.EnvelopeCandidates, 100 * error.Hausdorff / error.Diagonal,
    100 * error.SurfaceToEnvelope.Hausdorff / error.Diagonal,
    100 * error.SurfaceToEnvelope.HausdorffLowerBound / error.Diagonal,
    100 * error.EnvelopeToSurface.Hausdorff / error.Diagonal, 100 * error.Mean / error.Diagonal,
    100 * error.RMS / error.Diagonal, error.UncertifiedPoints, error.InsidePoints,
    100 * error.LargestBoundGap / error.Diagonal);
  std::printf("  error parts: surface->envelope %.3f s, exposed pieces %.3f s, envelope candidates "
              "%.3f s, envelope->surface %.3f s, inside bounds %.3f s\n",
    error.SurfaceSeconds, error.PiecesSeconds, error.CandidatesSeconds, error.EnvelopeSeconds,
    error.TighteningSeconds);
}

std::vector<Stage> RunPipeline(
  const TriangleMesh& mesh, std::size_t samples, std::size_t target, bool cad)
{
  std::vector<Stage> stages;
  SurfaceSamples sites;
  SamplingOptions sampling;
  sampling.NumberOfSamples = samples;
  sampling.Adaptive = AdaptiveSampling >= 0 ? AdaptiveSampling == 1 : !cad;
  stages.push_back(Measure("sampling", [&] { sites = SampleSurface(mesh, sampling); }));
  if (DelaunayBaseline)
  {
    std::size_t cells = 0;
    const Stage delaunay = Measure("delaunay", [&] { cells = DelaunayCellCount(sites.Points); });
    std::printf("  Delaunay of the same samples alone: %zu cells, %.3f s, %.0f MB (+%.0f)\n", cells,
      delaunay.Seconds, delaunay.PeakMB, delaunay.ExtraMB);
    DelaunaySeconds = delaunay.Seconds;
  }
  RestrictedVoronoiDiagram rvd;
  stages.push_back(Measure("rvd", [&] { rvd = ComputeRestrictedVoronoi(mesh, sites.Points); }));
  VoronoiMedialAxisResult voronoi;
  auto computeVoronoi = [&]
  {
    VoronoiMedialAxisOptions voronoiOptions;
    voronoiOptions.CoveringRadius = rvd.CellRadius.empty()
      ? 0.0
      : *std::max_element(rvd.CellRadius.begin(), rvd.CellRadius.end());
    voronoi = ComputeVoronoiMedialAxis(
      mesh, sites.Points, sites.TriangleIds, rvd.ConcaveFeature, voronoiOptions);
  };
  stages.push_back(Measure("voronoi", computeVoronoi));
  // As vtkStructuralMedialAxis: handles the medial axis missed are sampled
  // again, denser on thin parts or, sampled uniformly, twice as many (never
  // needed on the shared meshes).
  for (int round = 1; voronoi.MissingLoops > 0 && DenserOnThinParts(sampling.Sizing, round);
       ++round)
  {
    if (!sampling.Adaptive)
    {
      sampling.NumberOfSamples *= 2;
    }
    stages.push_back(Measure("resampling",
      [&]
      {
        sites = SampleSurface(mesh, sampling);
        rvd = ComputeRestrictedVoronoi(mesh, sites.Points);
        computeVoronoi();
      }));
    std::printf("  sampled again (round %d): %zu samples, %zu added, %zu handles missed\n", round,
      sites.Points.size(), sites.Points.size() - samples, voronoi.MissingLoops);
  }
  std::printf("  initial MAT: %zu vertices, %zu triangles, %zu lines, Euler characteristic %lld; "
              "%zu Delaunay cells, %zu exact inside tests\n",
    voronoi.Mesh.Centers.size(), voronoi.Mesh.Faces.size(), EdgesNotOnFaces(voronoi.Mesh).size(),
    static_cast<long long>(EulerCharacteristic(voronoi.Mesh)), voronoi.DelaunayCells,
    voronoi.AmbiguousInsideTests);
  std::printf("  topology repair: %zu spanning cells kept, %zu edges across the surface removed, "
              "%zu pieces joined, %zu loops cut, %zu loops capped\n",
    voronoi.SpanningCells, voronoi.EdgesAcrossSurface, voronoi.JoinedPieces, voronoi.CutLoops,
    voronoi.FilledHoles);
  {
    const MedialMeshQuality q0 = MeasureQuality(voronoi.Mesh);
    std::printf("  initial MAT quality: %zu degenerate, %zu folded triangles (%zu folds); mean min "
                "angle %.1f deg, %.1f%% below 30 deg, mean Q %.3f\n",
      q0.DegenerateTriangles, q0.FoldedTriangles, q0.FoldedEdges, q0.MeanMinimumAngle,
      q0.PercentMinimumAngleBelow30, q0.MeanQuality);
  }
  AtlasMedialMesh initial;
  initial.Mesh = std::move(voronoi.Mesh);
  initial.AtlasOffsets = std::move(voronoi.AtlasOffsets);
  initial.AtlasSites = std::move(voronoi.AtlasSites);
  initial.SiteClearance = std::move(voronoi.SiteClearance);
  // The reports above are the benchmark's, not the pipeline's: their freed
  // pages go before the simplification's peak is measured, as the pipeline
  // gives back its own (ReleaseFreeHeapPages in each stage).
  ReleaseFreeHeapPages();
  AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = target;
  options.PreserveSharpFeatures = cad;
  options.TopologyGuardVertexCount = TopologyGuard;
  options.FinalFit = FinalFit;
  AtlasSimplifierResult simplified;
  stages.push_back(Measure("simplify",
    [&] { simplified = SimplifyMedialAxis(std::move(initial), rvd, sites.Points, options); }));
  const MedialMesh& m = simplified.Medial.Mesh;
  std::printf(
    "  simplified MAT: %zu vertices, %zu triangles, %zu lines, Euler characteristic %lld; "
    "%zu collapses, %zu rejected, %zu past the link condition, %zu past the fold guard, "
    "%zu to remove folds; "
    "%zu batches; set-up and first evaluation of every edge %.3f s\n",
    m.Centers.size(), m.Faces.size(), EdgesNotOnFaces(m).size(),
    static_cast<long long>(EulerCharacteristic(m)), simplified.Collapses,
    simplified.RejectedCollapses, simplified.RelaxedCollapses, simplified.FoldingAllowedCollapses,
    simplified.FoldRepairCollapses, simplified.Batches, simplified.QueueInitialisationSeconds);
  if (FinalFit)
  {
    std::printf("  final fit: %d rounds kept, %d rejected; RMS distance of the fit points %.3g -> "
                "%.3g, largest %.3g -> %.3g; %.3f s\n",
      simplified.Fit.AcceptedRounds, simplified.Fit.RejectedRounds, simplified.Fit.InitialRms,
      simplified.Fit.FinalRms, simplified.Fit.InitialMaximum, simplified.Fit.FinalMaximum,
      simplified.FitSeconds);
  }
  const MedialMeshQuality quality = MeasureQuality(m);
  std::printf("  simplified MAT quality: %zu degenerate, %zu folded triangles (%zu folds), %s; "
              "mean min angle %.1f deg, %.1f%% below 30 deg, mean Q %.3f\n",
    quality.DegenerateTriangles, quality.FoldedTriangles, quality.FoldedEdges,
    ValidateMedialMesh(m).IsValid() ? "valid" : ValidateMedialMesh(m).Message.c_str(),
    quality.MeanMinimumAngle, quality.PercentMinimumAngleBelow30, quality.MeanQuality);
  {
    const auto [lo, hi] = BoundingBox(mesh.Points);
    const MedialCleanliness clean = MeasureCleanliness(m, Norm(hi - lo));
    std::printf("  simplified MAT cleanliness: %zu sheets, N80 %zu, largest sheet %.1f%% of the "
                "area, fins %.2f%% of the area, folds %.2f%% of the sheet edges, boundary %.2f "
                "and junctions %.2f diagonals\n",
      clean.Sheets, clean.SheetsFor80PercentArea, 100.0 * clean.LargestSheetAreaFraction,
      100.0 * clean.FinAreaFraction, 100.0 * clean.FoldedEdgeFraction, clean.BoundaryLength,
      clean.JunctionLength);
  }
  if (Envelope)
  {
    RunEnvelope(mesh, m, stages);
  }
  return stages;
}

// The pipeline's stages: all but the envelope and error evaluation.
bool InPipeline(const Stage& s)
{
  return s.Name != "envelope" && s.Name != "envelope-vtk" && s.Name != "error" &&
    s.Name != "subdivide";
}

void PrintStages(const std::string& name, std::size_t triangles, std::size_t samples,
  const std::vector<Stage>& stages, std::size_t target = 0)
{
  std::printf("%-22s %8zu tris %7zu samples |", name.c_str(), triangles, samples);
  double total = 0.0, peak = 0.0;
  for (const Stage& s : stages)
  {
    std::printf(" %s %.3f s %.0f MB (+%.0f) |", s.Name.c_str(), s.Seconds, s.PeakMB, s.ExtraMB);
    if (InPipeline(s))
    {
      total += s.Seconds;
      peak = std::max(peak, s.PeakMB);
    }
  }
  const bool ratio = DelaunayBaseline && samples > 0 && DelaunaySeconds > 0.0;
  std::printf(" total %.3f s, peak %.0f MB", total, peak);
  if (ratio)
  {
    std::printf(" | Delaunay %.3f s, ratio %.1fx", DelaunaySeconds, total / DelaunaySeconds);
  }
  std::printf("\n");
  if (JsonPath.empty() || samples == 0)
  {
    return;
  }
  std::ostringstream json;
  json.precision(6);
  json << "{\"mesh\": \"" << name << "\", \"triangles\": " << triangles
       << ", \"samples\": " << samples << ", \"target\": " << target
       << ", \"total_seconds\": " << total << ", \"peak_mb\": " << peak;
  if (ratio)
  {
    json << ", \"delaunay_seconds\": " << DelaunaySeconds
         << ", \"ratio_to_delaunay\": " << total / DelaunaySeconds;
  }
  json << ", \"stages\": [";
  for (std::size_t i = 0; i < stages.size(); ++i)
  {
    json << (i ? ", " : "") << "{\"name\": \"" << stages[i].Name
         << "\", \"seconds\": " << stages[i].Seconds << ", \"peak_mb\": " << stages[i].PeakMB
         << ", \"extra_mb\": " << stages[i].ExtraMB << "}";
  }
  json << "]}";
  JsonRecords.push_back(json.str());
}

// Writes the records of every run as one JSON array; false (with a message)
// when the file cannot be written.
bool WriteJson()
{
  if (JsonPath.empty())
  {
    return true;
  }
  std::ofstream out(JsonPath);
  out << "[\n";
  for (std::size_t i = 0; i < JsonRecords.size(); ++i)
  {
    out << "  " << JsonRecords[i] << (i + 1 < JsonRecords.size() ? ",\n" : "\n");
  }
  out << "]\n";
  if (!out)
  {
    std::fprintf(stderr, "cannot write %s\n", JsonPath.c_str());
    return false;
  }
  std::printf("wrote %s\n", JsonPath.c_str());
  return true;
}
}

int main(int argc, char* argv[])
{
  medialaxis::TuneHeap(argv);
  std::size_t samples = 50000, target = 5000;
  bool cad = false;
  int threads = 0;
  bool scaling = false;
  std::vector<std::size_t> counts = { 10000, 25000, 50000, 100000, 200000 };
  std::vector<std::pair<std::string, bool>> inputs; // (path or shape, is shape)
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--samples" && i + 1 < argc)
      samples = std::stoul(argv[++i]);
    else if (arg == "--target" && i + 1 < argc)
      target = std::stoul(argv[++i]);
    else if (arg == "--guard" && i + 1 < argc)
      TopologyGuard = std::stoul(argv[++i]);
    else if (arg == "--cad")
      cad = true;
    else if (arg == "--threads" && i + 1 < argc)
      threads = std::stoi(argv[++i]);
    else if (arg == "--scaling")
      scaling = true;
    else if (arg == "--envelope")
      Envelope = true;
    else if (arg == "--delaunay")
      DelaunayBaseline = true;
    else if (arg == "--adaptive" || arg == "--uniform")
      AdaptiveSampling = arg == "--adaptive" ? 1 : 0;
    else if (arg == "--no-fit")
      FinalFit = false;
    else if (arg == "--error-samples" && i + 1 < argc)
      ErrorSamples = std::stoul(argv[++i]);
    else if (arg == "--envelope-samples" && i + 1 < argc)
      EnvelopeSamples = std::stoul(argv[++i]);
    else if (arg == "--shape" && i + 1 < argc)
      inputs.emplace_back(argv[++i], true);
    else if (arg == "--json" && i + 1 < argc)
      JsonPath = argv[++i];
    else if (arg == "--resolution" && i + 1 < argc)
      ShapeResolution = std::stoi(argv[++i]);
    else if (arg == "--subdivide" && i + 1 < argc)
      Subdivisions = std::clamp(std::stoi(argv[++i]), 0, 5);
    else if (arg == "--counts" && i + 1 < argc)
    {
      counts.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        counts.push_back(std::stoul(item));
      }
    }
    else if (arg == "-h" || arg == "--help")
    {
      std::cout << "usage: " << argv[0]
                << " [--samples N] [--target V] [--cad] [--threads T] [--scaling]"
                   " [--counts N1,N2,...] [--envelope] [--error-samples S]"
                   " [--envelope-samples E] [--delaunay] [--adaptive|--uniform] [--no-fit]"
                   " [--shape torus|sphere|box] [--resolution R] [--subdivide K]"
                   " [--json FILE] mesh...\n";
      return 0;
    }
    else
      inputs.emplace_back(arg, false);
  }
  if (inputs.empty())
  {
    inputs.emplace_back("torus", true);
  }
  if (!JsonPath.empty() && !std::ofstream(JsonPath))
  {
    // Said before the runs, not after them.
    std::fprintf(stderr, "cannot write %s\n", JsonPath.c_str());
    return 2;
  }
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("heap: %s\n", medialaxis::HeapTuned() ? tunables : "glibc's defaults");

  return RunWithThreads(threads,
    [&]
    {
      for (const auto& [spec, isShape] : inputs)
      {
        TriangleMesh mesh;
        std::vector<Stage> loading;
        if (!LoadSurface(spec, isShape, mesh, loading))
        {
          return 1;
        }
        const std::string name = spec.substr(spec.find_last_of('/') + 1);
        if (!scaling)
        {
          std::vector<Stage> stages = loading;
          const auto run = RunPipeline(mesh, samples, target, cad);
          stages.insert(stages.end(), run.begin(), run.end());
          PrintStages(name, mesh.Triangles.size(), samples, stages, target);
          continue;
        }
        PrintStages(name + " (input)", mesh.Triangles.size(), 0, loading);
        // The memory the loaded mesh holds, which every run starts from.
        const double baseline = StatusMB("VmRSS:");
        std::vector<std::vector<Stage>> runs;
        for (std::size_t n : counts)
        {
          runs.push_back(RunPipeline(mesh, n, n / 10, cad));
          PrintStages(name, mesh.Triangles.size(), n, runs.back(), n / 10);
        }
        // Least-squares slope of log(time) against log(samples), per stage.
        std::printf("%-22s growth exponent (time ~ samples^k):", name.c_str());
        for (std::size_t s = 0; s < runs[0].size(); ++s)
        {
          double sx = 0, sy = 0, sxx = 0, sxy = 0;
          const double n = static_cast<double>(runs.size());
          for (std::size_t r = 0; r < runs.size(); ++r)
          {
            const double x = std::log(double(counts[r])), y = std::log(runs[r][s].Seconds);
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
          }
          std::printf(
            " %s %.2f", runs[0][s].Name.c_str(), (n * sxy - sx * sy) / (n * sxx - sx * sx));
        }
        std::printf("\n");
        // Samples against the whole run's time and peak memory, and the
        // growth exponent of the memory a run adds to the loaded mesh.
        std::printf("%-22s samples | triangles | seconds | peak MB | MB above the loaded mesh\n",
          name.c_str());
        std::vector<double> xs, ys;
        for (std::size_t r = 0; r < runs.size(); ++r)
        {
          double seconds = 0.0, peak = 0.0;
          for (const Stage& stage : runs[r])
          {
            seconds += stage.Seconds;
            peak = std::max(peak, stage.PeakMB);
          }
          std::printf("%-22s %7zu | %9zu | %7.2f | %7.0f | %.0f\n", "", counts[r],
            mesh.Triangles.size(), seconds, peak, peak - baseline);
          xs.push_back(std::log(double(counts[r])));
          ys.push_back(std::log(std::max(peak - baseline, 1.0)));
        }
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        const double n = static_cast<double>(xs.size());
        for (std::size_t r = 0; r < xs.size(); ++r)
        {
          sx += xs[r];
          sy += ys[r];
          sxx += xs[r] * xs[r];
          sxy += xs[r] * ys[r];
        }
        std::printf("%-22s memory growth exponent (MB above the mesh ~ samples^k): %.2f\n",
          name.c_str(), (n * sxy - sx * sy) / (n * sxx - sx * sx));
      }
      return WriteJson() ? 0 : 1;
    });
}
