// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkSlabReconstructor.h"

#include "Envelope/EnvelopeDistance.h"
#include "Envelope/EnvelopeMesher.h"
#include "Geometry/Vec3.h"
#include "Support/Parallel.h"
#include "vtkDistanceGridContour.h"
#include "vtkMedialMeshConversion.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkSlabReconstructor);

namespace
{
using namespace medialaxis;

std::array<Index, 3> PrimitiveVertices(const MedialEnvelope& envelope, const PrimitiveRef& ref)
{
  switch (ref.Kind)
  {
    case PrimitiveKind::Sphere:
      return { ref.Id, -1, -1 };
    case PrimitiveKind::Cone:
    {
      const auto& e = envelope.ConeEdges()[ref.Id];
      return { e[0], e[1], -1 };
    }
    default:
      return envelope.SlabFaces()[ref.Id];
  }
}

// Cell data PrimitiveKind / PrimitiveId / PrimitiveVertices, one per cell.
void AddPrimitiveArrays(
  vtkPolyData* output, const MedialEnvelope& envelope, const std::vector<PrimitiveRef>& refs)
{
  const vtkIdType n = static_cast<vtkIdType>(refs.size());
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("PrimitiveKind");
  kind->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> id, vertices;
  id->SetName("PrimitiveId");
  id->SetNumberOfTuples(n);
  vertices->SetName("PrimitiveVertices");
  vertices->SetNumberOfComponents(3);
  vertices->SetNumberOfTuples(n);
  for (vtkIdType c = 0; c < n; ++c)
  {
    kind->SetValue(c, static_cast<unsigned char>(refs[c].Kind));
    id->SetValue(c, refs[c].Id);
    const auto v = PrimitiveVertices(envelope, refs[c]);
    for (int k = 0; k < 3; ++k)
    {
      vertices->SetTypedComponent(c, k, v[k]);
    }
  }
  output->GetCellData()->AddArray(kind);
  output->GetCellData()->AddArray(id);
  output->GetCellData()->AddArray(vertices);
  output->GetCellData()->SetActiveScalars("PrimitiveKind");
}
}

const char* vtkSlabReconstructor::GetModeAsString()
{
  return this->Mode == BOUNDARY ? "boundary" : "primitives";
}

int vtkSlabReconstructor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();

  MedialMesh medial;
  const std::string error = PolyDataToMedialMesh(input, medial);
  if (!error.empty())
  {
    vtkErrorMacro(<< "cannot reconstruct the envelope: " << error);
    return 0;
  }
  if (medial.NumberOfVertices() == 0)
  {
    vtkErrorMacro(<< "cannot reconstruct the envelope: the medial mesh has no points "
                     "(connect a medial mesh with point data 'Radius')");
    return 0;
  }
  const double maxRadius = *std::max_element(medial.Radii.begin(), medial.Radii.end());
  if (this->Mode == BOUNDARY && !(maxRadius > 0.0))
  {
    vtkErrorMacro(<< "cannot bound the envelope: every radius is 0, so the union of the "
                     "primitives has no volume (use the primitives mode to see the medial mesh)");
    return 0;
  }
  this->UpdateProgress(0.05);

  return RunWithThreads(this->NumberOfThreads,
    [&]() -> int
    {
      const MedialEnvelope envelope(medial);
      std::size_t nested = 0, flat = 0;
      for (const ConePrimitive& c : envelope.Cones())
      {
        nested += c.Nested ? 1 : 0;
      }
      for (const SlabPrimitive& s : envelope.Slabs())
      {
        flat += s.HasTangentPlanes ? 0 : 1;
      }
      auto progress = [this](double from, double span)
      {
        return [this, from, span](double f)
        {
          this->UpdateProgress(from + span * f);
          return !this->GetAbortExecute();
        };
      };

      if (this->Mode == PRIMITIVES)
      {
        EnvelopeMeshOptions options;
        options.SphereResolution = this->SphereResolution;
        options.ConeResolution = this->ConeResolution;
        options.Progress = progress(0.05, 0.7);
        const EnvelopeSurface surface = MeshEnvelopePrimitives(envelope, options);
        if (surface.Aborted)
        {
          return 1;
        }
        TriangleMeshToPolyData(surface.Mesh, output);
        AddPrimitiveArrays(output, envelope, surface.Primitive);
      }
      else
      {
        const Box& b = envelope.Bounds();
        const double longest =
          std::max({ b.Hi[0] - b.Lo[0], b.Hi[1] - b.Lo[1], b.Hi[2] - b.Lo[2] });
        const double spacing = longest / this->BoundaryResolution;
        const DistanceGrid grid = SampleUnionDistance(envelope, spacing, progress(0.05, 0.7));
        if (grid.Aborted)
        {
          return 1;
        }
        const TriangleMesh mesh = ContourDistanceGrid(grid);
        std::vector<Point3> centroids(mesh.Triangles.size());
        for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
        {
          const Triangle& tri = mesh.Triangles[t];
          centroids[t] =
            (1.0 / 3.0) * (mesh.Points[tri[0]] + mesh.Points[tri[1]] + mesh.Points[tri[2]]);
        }
        this->UpdateProgress(0.85);
        TriangleMeshToPolyData(mesh, output);
        AddPrimitiveArrays(output, envelope, SurfacePrimitives(envelope, centroids));
        long long thin = 0;
        for (double r : medial.Radii)
        {
          thin += r < spacing ? 1 : 0;
        }
        AddFieldDouble(output, "GridSpacing", spacing);
        AddFieldValue(output, "ThinVertices", thin);
        AddFieldValue(output, "ExactGridPoints", static_cast<long long>(grid.ExactPoints));
      }
      AddFieldValue(output, "NestedCones", static_cast<long long>(nested));
      AddFieldValue(output, "SlabsWithoutTangentPlanes", static_cast<long long>(flat));
      this->UpdateProgress(1.0);
      return 1;
    });
}

void vtkSlabReconstructor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->GetModeAsString() << "\n";
  os << indent << "SphereResolution: " << this->SphereResolution << "\n";
  os << indent << "ConeResolution: " << this->ConeResolution << "\n";
  os << indent << "BoundaryResolution: " << this->BoundaryResolution << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
