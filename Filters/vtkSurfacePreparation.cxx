// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkSurfacePreparation.h"

#include "Mesh/TriangleAdjacency.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cstring>
#include <mutex>
#include <tuple>

namespace medialaxis
{
namespace
{
// The stages of a pipeline prepare the same input one after another (four
// times in the one-click filter), so the last input's preparation is
// remembered, keyed by its points and cells with their modification times (a
// new or modified VTK object gets a new time, so a key is never reused) and
// by the options. (The costliest step, the self-intersection test,
// remembers its last answer by content too.)
class PreparationMemo
{
public:
  using Key =
    std::tuple<const void*, vtkMTimeType, const void*, vtkMTimeType, const void*, vtkMTimeType>;
  static Key KeyOf(vtkPolyData* input)
  {
    auto stamp = [](vtkObject* o) { return o ? o->GetMTime() : vtkMTimeType(0); };
    return Key(input->GetPoints(), stamp(input->GetPoints()), input->GetPolys(),
      stamp(input->GetPolys()), input->GetStrips(), stamp(input->GetStrips()));
  }
  /// The options that shape the result but the repair's (a call given known
  /// crossings is not remembered).
  using Options = std::tuple<double, bool, int, double>;
  static Options OptionsOf(const SurfacePreparationOptions& o)
  {
    return Options(
      o.RelativeMergeTolerance, o.FixOrientation, o.LocalFoldRings, o.MaxPassThroughExtent);
  }
  /// The repair's options. A preparation that succeeded without repairing
  /// anything gives the same result whether a repair was allowed or not (the
  /// one-click filter prepares with repair first, its stages without).
  using RepairOptions = std::tuple<bool, double, double>;
  static RepairOptions RepairOptionsOf(const SurfacePreparationOptions& o)
  {
    return RepairOptions(o.RepairSelfIntersections, o.WrapAlpha, o.ContactGap);
  }

  bool FindPrepared(const Key& key, const SurfacePreparationOptions& options,
    SurfacePreparationReport& report, TriangleMesh& prepared)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    const bool sameRepair = RepairOptionsOf(options) == this->PreparedRepair ||
      (this->Report.Ok() && !this->Report.Repaired);
    if (this->PreparedValid && key == this->PreparedKey &&
      OptionsOf(options) == this->PreparedOptions && sameRepair)
    {
      report = this->Report;
      prepared = this->Prepared;
      return true;
    }
    return false;
  }
  void RememberPrepared(const Key& key, const SurfacePreparationOptions& options,
    const SurfacePreparationReport& report, const TriangleMesh& prepared)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->PreparedKey = key;
    this->PreparedOptions = OptionsOf(options);
    this->PreparedRepair = RepairOptionsOf(options);
    this->Report = report;
    this->Prepared = prepared;
    this->PreparedValid = true;
  }

private:
  std::mutex Mutex;
  bool PreparedValid = false;
  Key PreparedKey;
  Options PreparedOptions;
  RepairOptions PreparedRepair;
  SurfacePreparationReport Report;
  TriangleMesh Prepared;
};

PreparationMemo& Memo()
{
  static PreparationMemo memo;
  return memo;
}
}

// Points and triangles written straight into VTK arrays (millions of them
// for a contoured reconstruction).
void TriangleMeshToPolyData(const TriangleMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Points.size()));
  if (!mesh.Points.empty())
  {
    std::memcpy(
      coordinates->GetPointer(0), mesh.Points.data(), mesh.Points.size() * sizeof(Point3));
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  const vtkIdType nt = static_cast<vtkIdType>(mesh.Triangles.size());
  offsets->SetNumberOfTuples(nt + 1);
  connectivity->SetNumberOfTuples(3 * nt);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    offsets->SetValue(t, 3 * t);
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(3 * t + k, mesh.Triangles[t][k]);
    }
  }
  offsets->SetValue(nt, 3 * nt);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
}

TriangleMesh OutwardTriangleMesh(vtkPolyData* input)
{
  TriangleMesh mesh;
  mesh.Points.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    input->GetPoint(i, mesh.Points[i].data());
  }
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType k = 2; k < npts; ++k)
    {
      mesh.Triangles.push_back({ ids[0], ids[k - 1], ids[k] });
    }
  }
  OrientOutward(mesh);
  return mesh;
}

SurfacePreparationReport PrepareSurfacePolyData(
  vtkPolyData* input, vtkPolyData* output, const SurfacePreparationOptions& options)
{
  output->Initialize();
  TriangleMesh prepared;
  const SurfacePreparationReport report = PrepareSurfaceMesh(input, prepared, options);
  if (report.Ok())
  {
    TriangleMeshToPolyData(prepared, output);
  }
  return report;
}

SurfacePreparationReport PrepareSurfaceMesh(
  vtkPolyData* input, TriangleMesh& prepared, const SurfacePreparationOptions& options)
{
  SurfacePreparationReport report;
  prepared = TriangleMesh();
  if (!input || input->GetNumberOfPoints() == 0)
  {
    report.Error = "surface is empty: it has no points";
    return report;
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    report.Error = "surface has no polygons (it has " + std::to_string(input->GetNumberOfLines()) +
      " line and " + std::to_string(input->GetNumberOfVerts()) +
      " vertex cells): a closed triangle mesh is needed";
    return report;
  }

  const PreparationMemo::Key key = PreparationMemo::KeyOf(input);
  if (!options.KnownCrossings && Memo().FindPrepared(key, options, report, prepared))
  {
    return report;
  }

  // Polygons and strips become triangles with VTK's own triangulator, which
  // handles non-convex polygons; the result is checked below like any soup.
  vtkNew<vtkPolyData> shell;
  shell->SetPoints(input->GetPoints());
  shell->SetPolys(input->GetPolys());
  shell->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(shell);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();

  TriangleMesh soup;
  soup.Points.resize(static_cast<std::size_t>(triangles->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < triangles->GetNumberOfPoints(); ++i)
  {
    triangles->GetPoint(i, soup.Points[i].data());
  }
  soup.Triangles.reserve(static_cast<std::size_t>(triangles->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  std::size_t notTriangles = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n == 3)
    {
      soup.Triangles.push_back({ ids[0], ids[1], ids[2] });
    }
    else
    {
      ++notTriangles; // polygons VTK could not triangulate (e.g. degenerate)
    }
  }

  report = PrepareSurface(soup, prepared, options);
  if (notTriangles)
  {
    report.Notes.push_back(
      std::to_string(notTriangles) + " polygon(s) could not be triangulated and were dropped");
  }
  if (!options.KnownCrossings)
  {
    Memo().RememberPrepared(key, options, report, prepared);
  }
  return report;
}
}
