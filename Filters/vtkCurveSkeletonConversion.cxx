// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkCurveSkeletonConversion.h"

#include "Geometry/Vec3.h"
#include "Support/DisjointSets.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace medialaxis
{
namespace
{
void AddCount(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  output->GetFieldData()->AddArray(a);
}
}

void CurveSkeletonToPolyData(const CurveSkeleton& s, vtkPolyData* output)
{
  output->Initialize();
  const vtkIdType n = static_cast<vtkIdType>(s.Nodes.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(RadiusArrayName);
  radius->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> type;
  type->SetName("NodeType");
  type->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> nodeBranch;
  nodeBranch->SetName("BranchId");
  nodeBranch->SetNumberOfTuples(n);
  std::size_t junctions = 0, ends = 0;
  for (vtkIdType v = 0; v < n; ++v)
  {
    points->SetPoint(v, s.Nodes[v].data());
    radius->SetValue(v, s.Radii[v]);
    type->SetValue(v, static_cast<unsigned char>(s.Types[v]));
    nodeBranch->SetValue(v, s.NodeBranch[v]);
    junctions += s.Types[v] == SkeletonNodeType::Junction ? 1 : 0;
    ends += s.Types[v] == SkeletonNodeType::End ? 1 : 0;
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetActiveScalars(RadiusArrayName);
  output->GetPointData()->AddArray(type);
  output->GetPointData()->AddArray(nodeBranch);

  // Vertex cells (lone nodes) come before lines in cell order.
  vtkNew<vtkCellArray> verts, lines;
  vtkNew<vtkIdTypeArray> vertBranch, lineBranch;
  vtkNew<vtkDoubleArray> vertLength, lineLength;
  for (std::size_t b = 0; b < s.Branches.size(); ++b)
  {
    const auto& chain = s.Branches[b];
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      length += std::sqrt(Distance2(s.Nodes[chain[i]], s.Nodes[chain[i + 1]]));
    }
    if (chain.size() == 1)
    {
      verts->InsertNextCell(1);
      verts->InsertCellPoint(chain[0]);
      vertBranch->InsertNextValue(static_cast<vtkIdType>(b));
      vertLength->InsertNextValue(0.0);
      continue;
    }
    lines->InsertNextCell(static_cast<vtkIdType>(chain.size()));
    for (Index v : chain)
    {
      lines->InsertCellPoint(v);
    }
    lineBranch->InsertNextValue(static_cast<vtkIdType>(b));
    lineLength->InsertNextValue(length);
  }
  output->SetVerts(verts);
  output->SetLines(lines);
  vtkNew<vtkIdTypeArray> cellBranch;
  cellBranch->SetName("BranchId");
  vtkNew<vtkDoubleArray> cellLength;
  cellLength->SetName("Length");
  for (vtkIdType i = 0; i < vertBranch->GetNumberOfTuples(); ++i)
  {
    cellBranch->InsertNextValue(vertBranch->GetValue(i));
    cellLength->InsertNextValue(vertLength->GetValue(i));
  }
  for (vtkIdType i = 0; i < lineBranch->GetNumberOfTuples(); ++i)
  {
    cellBranch->InsertNextValue(lineBranch->GetValue(i));
    cellLength->InsertNextValue(lineLength->GetValue(i));
  }
  output->GetCellData()->AddArray(cellBranch);
  output->GetCellData()->AddArray(cellLength);

  AddCount(output, "Nodes", static_cast<double>(n));
  AddCount(output, "Branches", static_cast<double>(s.Branches.size()));
  AddCount(output, "Junctions", static_cast<double>(junctions));
  AddCount(output, "Ends", static_cast<double>(ends));
  AddCount(output, "CycleRank", static_cast<double>(s.CycleRank));
  AddCount(output, "Components", static_cast<double>(s.Components));
  AddCount(output, "PrunedBranches", static_cast<double>(s.PrunedBranches));
  AddCount(output, "UncollapsedTriangles", static_cast<double>(s.UncollapsedTriangles));
}

std::string PolyDataToCurveSkeleton(vtkPolyData* input, CurveSkeleton& s)
{
  s = CurveSkeleton();
  if (!input)
  {
    return "no skeleton";
  }
  vtkDataArray* radius = input->GetPointData()->GetArray(RadiusArrayName);
  const vtkIdType n = input->GetNumberOfPoints();
  if (!radius || radius->GetNumberOfTuples() != n)
  {
    return "the skeleton has no point data 'Radius' (connect vtkMedialCurveSkeleton's output 0)";
  }
  if (input->GetNumberOfPolys() > 0 || input->GetNumberOfStrips() > 0)
  {
    return "the skeleton has polygons: a curve skeleton is made of lines";
  }
  for (vtkIdType v = 0; v < n; ++v)
  {
    Point3 p;
    input->GetPoint(v, p.data());
    s.Nodes.push_back(p);
    s.Radii.push_back(radius->GetComponent(v, 0));
  }
  auto vit = vtk::TakeSmartPointer(input->GetVerts()->NewIterator());
  for (vit->GoToFirstCell(); !vit->IsDoneWithTraversal(); vit->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    vit->GetCurrentCell(count, ids);
    for (vtkIdType i = 0; i < count; ++i)
    {
      s.Branches.push_back({ ids[i] });
    }
  }
  auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    it->GetCurrentCell(count, ids);
    std::vector<Index> chain(ids, ids + count);
    for (vtkIdType i = 0; i + 1 < count; ++i)
    {
      if (ids[i] != ids[i + 1])
      {
        s.Edges.push_back(
          { std::min<Index>(ids[i], ids[i + 1]), std::max<Index>(ids[i], ids[i + 1]) });
      }
    }
    s.Branches.push_back(std::move(chain));
  }
  std::sort(s.Edges.begin(), s.Edges.end());
  s.Edges.erase(std::unique(s.Edges.begin(), s.Edges.end()), s.Edges.end());
  std::vector<std::size_t> degree(static_cast<std::size_t>(n), 0);
  DisjointSets pieces(static_cast<std::size_t>(n));
  for (const auto& e : s.Edges)
  {
    ++degree[e[0]];
    ++degree[e[1]];
    pieces.Union(e[0], e[1]);
  }
  vtkDataArray* branch = input->GetPointData()->GetArray("BranchId");
  for (vtkIdType v = 0; v < n; ++v)
  {
    const std::size_t d = degree[v];
    s.Types.push_back(d <= 1 ? SkeletonNodeType::End
                             : (d == 2 ? SkeletonNodeType::Regular : SkeletonNodeType::Junction));
    s.NodeBranch.push_back(branch ? static_cast<Index>(branch->GetComponent(v, 0)) : -1);
    s.Components += pieces.Find(v) == v ? 1 : 0;
  }
  s.CycleRank = s.Edges.size() + s.Components - static_cast<std::size_t>(n);
  return "";
}
}
