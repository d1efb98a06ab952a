// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkAnalyticShapeSource.h"

#include "Surface/AnalyticShapes.h"
#include "vtkSurfacePreparation.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <stdexcept>

vtkStandardNewMacro(vtkAnalyticShapeSource);

vtkAnalyticShapeSource::vtkAnalyticShapeSource()
{
  this->SetNumberOfInputPorts(0);
}

namespace
{
medialaxis::AreaVolume Exact(vtkAnalyticShapeSource* s)
{
  switch (s->GetShape())
  {
    case vtkAnalyticShapeSource::SPHERE:
      return medialaxis::CapsuleAreaVolume(s->GetRadius(), 0.0);
    case vtkAnalyticShapeSource::CAPSULE:
      return medialaxis::CapsuleAreaVolume(s->GetRadius(), s->GetLength());
    case vtkAnalyticShapeSource::TORUS:
      return medialaxis::TorusAreaVolume(s->GetMajorRadius(), s->GetMinorRadius());
    case vtkAnalyticShapeSource::BOX:
      return medialaxis::RoundedBoxAreaVolume(
        { s->GetXLength(), s->GetYLength(), s->GetZLength() }, 0.0);
    case vtkAnalyticShapeSource::ROUNDED_BOX:
      return medialaxis::RoundedBoxAreaVolume(
        { s->GetXLength(), s->GetYLength(), s->GetZLength() }, s->GetFilletRadius());
    case vtkAnalyticShapeSource::L_BLOCK:
      return medialaxis::LBlockAreaVolume({ s->GetXLength(), s->GetYLength(), s->GetZLength() });
    case vtkAnalyticShapeSource::DUMBBELL:
      return medialaxis::DumbbellAreaVolume(s->GetLength(), s->GetRadius(), s->GetMinorRadius());
    case vtkAnalyticShapeSource::BLOCK_WITH_FIN:
      return medialaxis::BlockWithFinAreaVolume(
        { s->GetXLength(), s->GetYLength(), s->GetZLength() }, s->GetLength(), s->GetThickness());
    case vtkAnalyticShapeSource::PLATE_WITH_BOSS:
      return medialaxis::PlateWithBossAreaVolume(
        s->GetXLength(), s->GetZLength(), s->GetRadius(), s->GetLength());
    default:
      return medialaxis::CylinderAreaVolume(s->GetRadius(), s->GetLength());
  }
}
}

double vtkAnalyticShapeSource::GetExactArea()
{
  return Exact(this).Area;
}

double vtkAnalyticShapeSource::GetExactVolume()
{
  return Exact(this).Volume;
}

int vtkAnalyticShapeSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  medialaxis::TriangleMesh mesh;
  try
  {
    switch (this->Shape)
    {
      case SPHERE:
        mesh = medialaxis::MakeSphere(this->Radius, this->Resolution);
        break;
      case CAPSULE:
        mesh = medialaxis::MakeCapsule(this->Radius, this->Length, this->Resolution);
        break;
      case TORUS:
        mesh = medialaxis::MakeTorus(this->MajorRadius, this->MinorRadius, this->Resolution);
        break;
      case BOX:
        mesh = medialaxis::MakeRoundedBox(
          { this->XLength, this->YLength, this->ZLength }, 0.0, this->Resolution);
        break;
      case ROUNDED_BOX:
        mesh = medialaxis::MakeRoundedBox(
          { this->XLength, this->YLength, this->ZLength }, this->FilletRadius, this->Resolution);
        break;
      case L_BLOCK:
        mesh =
          medialaxis::MakeLBlock({ this->XLength, this->YLength, this->ZLength }, this->Resolution);
        break;
      case DUMBBELL:
        mesh =
          medialaxis::MakeDumbbell(this->Length, this->Radius, this->MinorRadius, this->Resolution);
        break;
      case BLOCK_WITH_FIN:
        mesh = medialaxis::MakeBlockWithFin({ this->XLength, this->YLength, this->ZLength },
          this->Length, this->Thickness, this->Resolution);
        break;
      case PLATE_WITH_BOSS:
        mesh = medialaxis::MakePlateWithBoss(
          this->XLength, this->ZLength, this->Radius, this->Length, this->Resolution);
        break;
      default:
        mesh = medialaxis::MakeCylinder(this->Radius, this->Length, this->Resolution);
        break;
    }
  }
  catch (const std::invalid_argument& e)
  {
    output->Initialize();
    vtkErrorMacro(<< "invalid shape parameters: " << e.what());
    return 0;
  }
  for (auto& p : mesh.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] += this->Center[k];
    }
  }
  medialaxis::TriangleMeshToPolyData(mesh, output);
  return 1;
}

void vtkAnalyticShapeSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shape: " << this->Shape << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "MajorRadius: " << this->MajorRadius << "\n";
  os << indent << "MinorRadius: " << this->MinorRadius << "\n";
  os << indent << "XLength: " << this->XLength << " YLength: " << this->YLength
     << " ZLength: " << this->ZLength << "\n";
  os << indent << "FilletRadius: " << this->FilletRadius << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
}
