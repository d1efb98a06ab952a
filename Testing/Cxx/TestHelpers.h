// SPDX-License-Identifier: GPL-3.0-or-later
// Small hand-built meshes and helpers shared by the C++ tests.
#ifndef medialaxis_TestHelpers_h
#define medialaxis_TestHelpers_h

#include "Geometry/Vec3.h"
#include "Mesh/PolygonMesh.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "Voronoi/VoronoiMedialAxis.h"

#include "vtkAlgorithmOutput.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRestrictedVoronoiDiagram.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"
#include "vtkVoronoiMedialAxis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>

namespace medialaxis
{
namespace test
{
/// Unit cube [0,1]^3 as 12 outward triangles over 8 shared points.
/// Records VTK error events (and keeps expected errors out of the log).
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Count = 0;
  std::string Last;
};

// Each vertex moved by a length uniform in [0, amplitude * diagonal] along a
// uniformly random direction.
inline TriangleMesh WithNoise(const TriangleMesh& mesh, double amplitude, std::uint64_t seed)
{
  Point3 lo = mesh.Points[0], hi = mesh.Points[0];
  for (const Point3& p : mesh.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double reach = amplitude * Norm(hi - lo);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  TriangleMesh noisy = mesh;
  for (Point3& p : noisy.Points)
  {
    Point3 direction{ gaussian(random), gaussian(random), gaussian(random) };
    p = p + (reach * uniform(random) / Norm(direction)) * direction;
  }
  return noisy;
}

inline TriangleMesh UnitCube(const Point3& offset = { 0, 0, 0 }, double scale = 1.0)
{
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
  {
    m.Points.push_back({ offset[0] + scale * (i & 1), offset[1] + scale * ((i >> 1) & 1),
      offset[2] + scale * ((i >> 2) & 1) });
  }
  // Each face as two outward triangles.
  m.Triangles = { { 0, 2, 3 }, { 0, 3, 1 }, // z = 0 (normal -z)
    { 4, 5, 7 }, { 4, 7, 6 },               // z = 1
    { 0, 1, 5 }, { 0, 5, 4 },               // y = 0
    { 2, 6, 7 }, { 2, 7, 3 },               // y = 1
    { 0, 4, 6 }, { 0, 6, 2 },               // x = 0
    { 1, 3, 7 }, { 1, 7, 5 } };             // x = 1
  return m;
}

/// The diagonal of the bounding box of the mesh's points.
inline double Diagonal(const TriangleMesh& mesh)
{
  const auto [lo, hi] = BoundingBox(mesh.Points);
  return Norm(hi - lo);
}

/// Regular tetrahedron-like closed mesh with apex `a` over a base.
inline TriangleMesh Tetrahedron(const Point3& o, double s)
{
  TriangleMesh m;
  m.Points = { { o[0], o[1], o[2] }, { o[0] + s, o[1], o[2] }, { o[0], o[1] + s, o[2] },
    { o[0], o[1], o[2] + s } };
  m.Triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  return m;
}

/// Concatenates meshes without merging points.
inline TriangleMesh Append(const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh m = a;
  const Index base = static_cast<Index>(a.Points.size());
  m.Points.insert(m.Points.end(), b.Points.begin(), b.Points.end());
  for (Triangle t : b.Triangles)
  {
    m.Triangles.push_back({ t[0] + base, t[1] + base, t[2] + base });
  }
  return m;
}

/// Reads and prepares the shared mesh `name` (MEDIALAXIS_MESH_DIR) into
/// `mesh`. False if the shared meshes are not there (the caller skips), and
/// also, with a test failure, if the file is not a valid surface.
inline bool ReadSharedMesh(const std::string& name, TriangleMesh& mesh)
{
  const std::string path = std::string(MEDIALAXIS_MESH_DIR) + "/" + name;
  if (!std::ifstream(path).good())
  {
    return false;
  }
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  const SurfacePreparationReport report = PrepareSurfaceMesh(reader->GetOutput(), mesh);
  if (!report.Ok())
  {
    ADD_FAILURE() << name << ": " << report.Error;
    return false;
  }
  return true;
}

inline vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& mesh)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : mesh.Points)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : mesh.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

/// The VTK chain sampler -> restricted Voronoi diagram -> initial medial
/// mesh on a surface, as a user would wire it.
struct InitialMedialPipeline
{
  vtkNew<vtkBlueNoiseSurfaceSampler> Sampler;
  vtkNew<vtkRestrictedVoronoiDiagram> Rvd;
  vtkNew<vtkVoronoiMedialAxis> Voronoi;

  InitialMedialPipeline(vtkAlgorithmOutput* surface, vtkIdType samples)
  {
    this->Sampler->SetInputConnection(surface);
    this->Sampler->SetNumberOfSamples(samples);
    this->Rvd->SetInputConnection(0, surface);
    this->Rvd->SetInputConnection(1, this->Sampler->GetOutputPort());
    this->Voronoi->SetInputConnection(0, surface);
    this->Voronoi->SetInputConnection(1, this->Rvd->GetOutputPort(1));
  }
};

/// The plain C++ chain sampling -> RVD -> Voronoi MAT -> Atlas simplification.
struct SimplifiedRun
{
  SurfaceSamples Sites;
  RestrictedVoronoiDiagram Rvd;
  AtlasMedialMesh Initial;
  AtlasSimplifierResult Result;
};

/// Sampling, RVD and the initial (Voronoi) medial mesh with its Atlases.
inline SimplifiedRun InitialMedialAxis(
  const TriangleMesh& surface, std::size_t samples, bool concaveFiltering = true)
{
  SimplifiedRun run;
  SamplingOptions sampling;
  sampling.NumberOfSamples = samples;
  run.Sites = SampleSurface(surface, sampling);
  run.Rvd = ComputeRestrictedVoronoi(surface, run.Sites.Points);
  VoronoiMedialAxisOptions voronoiOptions;
  voronoiOptions.ConcaveFiltering = concaveFiltering;
  VoronoiMedialAxisResult voronoi = ComputeVoronoiMedialAxis(
    surface, run.Sites.Points, run.Sites.TriangleIds, run.Rvd.ConcaveFeature, voronoiOptions);
  run.Initial.Mesh = std::move(voronoi.Mesh);
  run.Initial.AtlasOffsets = std::move(voronoi.AtlasOffsets);
  run.Initial.AtlasSites = std::move(voronoi.AtlasSites);
  run.Initial.SiteClearance = std::move(voronoi.SiteClearance);
  return run;
}

inline SimplifiedRun Simplify(const TriangleMesh& surface, std::size_t samples, std::size_t target,
  bool cad, bool concaveFiltering = true, bool invaginatedTerm = true,
  FringeCollapseMode fringeCollapses = FringeCollapseMode::Automatic, bool finalFit = true)
{
  SimplifiedRun run = InitialMedialAxis(surface, samples, concaveFiltering);
  AtlasSimplifierOptions options;
  options.FinalFit = finalFit;
  options.TargetNumberOfVertices = target;
  options.PreserveSharpFeatures = cad;
  options.InvaginatedTerm = invaginatedTerm;
  options.FringeCollapses = fringeCollapses;
  run.Result = SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  return run;
}

/// The first value of a field-data array, NaN when it is missing.
inline double FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a ? a->GetComponent(0, 0) : std::nan("");
}

/// Writes `text` to a fresh file in the working directory and returns its path.
inline std::string WriteTextFile(const std::string& name, const std::string& text)
{
  std::ofstream file(name, std::ios::binary | std::ios::trunc);
  file << text;
  return name;
}
}
}

#endif
