// SPDX-License-Identifier: GPL-3.0-or-later
#include "vtkAnalyticShapeSource.h"

#include "Surface/AnalyticShapes.h"
#include "Surface/WallShapes.h"
#include "vtkSurfacePreparation.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkAnalyticShapeSource);

vtkAnalyticShapeSource::vtkAnalyticShapeSource()
{
  this->SetNumberOfInputPorts(0);
}

namespace
{
bool IsWallShape(int shape)
{
  return shape == vtkAnalyticShapeSource::T_PLATE || shape == vtkAnalyticShapeSource::L_BRACKET ||
    shape == vtkAnalyticShapeSource::WEDGE_PLATE;
}

// The longest straight segment of a wall shape's outline and of its sides
// along x.
double Spacing(vtkAnalyticShapeSource* s)
{
  return std::max(s->GetYLength(), s->GetZLength()) / (2.0 * s->GetResolution());
}

// The section of a wall shape (throws on invalid parameters).
medialaxis::WallSection SectionOf(vtkAnalyticShapeSource* s)
{
  const double spacing = Spacing(s);
  switch (s->GetShape())
  {
    case vtkAnalyticShapeSource::T_PLATE:
      return medialaxis::TPlateSection(s->GetYLength(), s->GetZLength(), s->GetThickness(),
        s->GetFilletRadius(), spacing, s->GetResolution());
    case vtkAnalyticShapeSource::L_BRACKET:
      return medialaxis::LBracketSection(s->GetYLength(), s->GetZLength(), s->GetThickness(),
        s->GetFilletRadius(), spacing, s->GetResolution());
    default:
      return medialaxis::WedgePlateSection(
        s->GetYLength(), s->GetThickness(), s->GetEndThickness(), spacing);
  }
}

medialaxis::AreaVolume Exact(vtkAnalyticShapeSource* s)
{
  if (IsWallShape(s->GetShape()))
  {
    try
    {
      return medialaxis::ExtrudedAreaVolume(SectionOf(s), s->GetXLength());
    }
    catch (const std::invalid_argument&)
    {
      return { std::nan(""), std::nan("") };
    }
  }
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
      case T_PLATE:
      case L_BRACKET:
      case WEDGE_PLATE:
        mesh = medialaxis::ExtrudeSection(SectionOf(this), this->XLength, Spacing(this));
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
  os << indent << "EndThickness: " << this->EndThickness << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
}
