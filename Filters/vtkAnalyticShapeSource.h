// SPDX-License-Identifier: GPL-3.0-or-later
/**
 * @class   vtkAnalyticShapeSource
 * @brief   Closed triangle meshes of shapes whose medial axis is known exactly.
 *
 * Produces a closed, manifold, outward-oriented triangle mesh whose vertices
 * lie exactly on the chosen analytic surface, centred at Center:
 *
 * - Sphere (Radius): medial axis = its centre, radius Radius.
 * - Capsule (Radius, Length = axis length, along z): medial axis = the axis
 *   segment, radius Radius.
 * - Torus (MajorRadius, MinorRadius, around z): medial axis = the centre
 *   circle, radius MinorRadius.
 * - Box (XLength, YLength, ZLength): sharp edges.
 * - RoundedBox (side lengths and FilletRadius): every edge rounded by a
 *   quarter cylinder and every corner by a sphere octant of radius
 *   FilletRadius; the fillet centre lines lie at FilletRadius from both
 *   adjacent faces.
 * - Cylinder (Radius, Length = height, along z).
 * - LBlock (XLength, YLength, ZLength): the box minus its quadrant x > 0,
 *   y > 0, so that the vertical edge on the z axis is a sharp concave edge;
 *   Resolution grid cells per half side.
 * - Dumbbell (Length = pole to pole, along z; Radius = the balls' radius;
 *   MinorRadius = the neck's radius): two balls joined by a thin cylinder;
 *   medial axis = the axis segment through the neck and the balls' centres
 *   (a thin part that uniform sampling misses: see
 *   vtkBlueNoiseSurfaceSampler::Adaptive).
 * - PlateWithBoss (XLength = side of the square plate, ZLength = its
 *   thickness, Radius and Length = radius and height of the cylindrical
 *   boss on its top face, all edges sharp): medial axis = the plate's
 *   mid-plane sheet, without holes, joined to the boss's.
 * - BlockWithFin (XLength x YLength x ZLength block; a fin Thickness thick
 *   along y and Length high standing on the middle of its top face, half
 *   the block's length along x; all edges sharp): medial axis = the
 *   block's, joined to the fin's mid-plane sheet (a thin part that
 *   simplifying far removes first: see
 *   vtkAtlasMedialAxisSimplifier::ErrorBound).
 *
 * - TPlate (thin walls, Thickness thick, extruded XLength along x): a plate
 *   YLength wide (y from -YLength/2, z from -Thickness/2) with a rib
 *   ZLength high on the middle of its top face; FilletRadius > 0 rounds the
 *   two concave corners where they meet. Mid-surfaces z = 0 and y = 0.
 * - LBracket (the same walls): a plate YLength long (y from 0) and a wall
 *   ZLength high (z from 0) meeting at the outer corner y = z = 0;
 *   FilletRadius > 0 rounds the inner corner with FilletRadius and the
 *   outer one with FilletRadius + Thickness. Mid-surfaces z = y =
 *   Thickness/2, joined by a quarter circle of radius FilletRadius +
 *   Thickness/2 where rounded.
 * - WedgePlate (extruded XLength along x): YLength wide, its thickness
 *   varying linearly from Thickness at y = -YLength/2 to EndThickness at
 *   y = YLength/2, symmetric about its mid-surface z = 0.
 *
 * Resolution is the number of segments along a quarter circle (for the sharp
 * box, along its longest side). GetExactArea() / GetExactVolume() give the
 * area and volume of the exact shape (not of its mesh) for tests.
 */
#ifndef vtkAnalyticShapeSource_h
#define vtkAnalyticShapeSource_h

#include "vtkMedialAxisFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkAnalyticShapeSource : public vtkPolyDataAlgorithm
{
public:
  static vtkAnalyticShapeSource* New();
  vtkTypeMacro(vtkAnalyticShapeSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ShapeType
  {
    SPHERE = 0,
    CAPSULE = 1,
    TORUS = 2,
    BOX = 3,
    ROUNDED_BOX = 4,
    CYLINDER = 5,
    L_BLOCK = 6,
    DUMBBELL = 7,
    PLATE_WITH_BOSS = 8,
    BLOCK_WITH_FIN = 9,
    T_PLATE = 10,
    L_BRACKET = 11,
    WEDGE_PLATE = 12
  };

  ///@{
  /// Which shape to generate (default SPHERE).
  vtkSetClampMacro(Shape, int, SPHERE, WEDGE_PLATE);
  vtkGetMacro(Shape, int);
  void SetShapeToSphere() { this->SetShape(SPHERE); }
  void SetShapeToCapsule() { this->SetShape(CAPSULE); }
  void SetShapeToTorus() { this->SetShape(TORUS); }
  void SetShapeToBox() { this->SetShape(BOX); }
  void SetShapeToRoundedBox() { this->SetShape(ROUNDED_BOX); }
  void SetShapeToCylinder() { this->SetShape(CYLINDER); }
  void SetShapeToLBlock() { this->SetShape(L_BLOCK); }
  void SetShapeToDumbbell() { this->SetShape(DUMBBELL); }
  void SetShapeToPlateWithBoss() { this->SetShape(PLATE_WITH_BOSS); }
  void SetShapeToBlockWithFin() { this->SetShape(BLOCK_WITH_FIN); }
  void SetShapeToTPlate() { this->SetShape(T_PLATE); }
  void SetShapeToLBracket() { this->SetShape(L_BRACKET); }
  void SetShapeToWedgePlate() { this->SetShape(WEDGE_PLATE); }
  ///@}

  ///@{
  /// Radius of the sphere, capsule, cylinder, the dumbbell's balls and the
  /// plate's boss (default 1).
  vtkSetClampMacro(Radius, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Axis length of the capsule, height of the cylinder, of the plate's boss
  /// and of the block's fin, pole-to-pole length of the dumbbell (default 2).
  vtkSetClampMacro(Length, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Length, double);
  ///@}

  ///@{
  /// Torus centre-circle radius (default 2) and tube radius (default 0.5);
  /// MinorRadius is also the dumbbell's neck radius.
  vtkSetClampMacro(MajorRadius, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(MajorRadius, double);
  vtkSetClampMacro(MinorRadius, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(MinorRadius, double);
  ///@}

  ///@{
  /// Full side lengths of the box, rounded box and L-block (default 2 x 2 x
  /// 2); XLength and ZLength are also the plate's side and thickness.
  vtkSetClampMacro(XLength, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(XLength, double);
  vtkSetClampMacro(YLength, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(YLength, double);
  vtkSetClampMacro(ZLength, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(ZLength, double);
  ///@}

  ///@{
  /// Thickness of the block's fin and of the walls of the T-plate and the
  /// L-bracket; the wedge plate's thickness at y = -YLength/2 (default 0.05).
  vtkSetClampMacro(Thickness, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(Thickness, double);
  ///@}

  ///@{
  /// The wedge plate's thickness at y = YLength/2 (default 0.1).
  vtkSetClampMacro(EndThickness, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(EndThickness, double);
  ///@}

  ///@{
  /// Fillet radius of the rounded box, at most half its smallest side; of
  /// the concave corners where the T-plate's rib meets its plate and of the
  /// L-bracket's inner bend (0: sharp) (default 0.2).
  vtkSetClampMacro(FilletRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FilletRadius, double);
  ///@}

  ///@{
  /// Segments along a quarter circle (default 16).
  vtkSetClampMacro(Resolution, int, 2, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// Translation of the shape (default origin).
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  ///@}

  /// Area and volume of the exact shape with the current parameters.
  double GetExactArea();
  double GetExactVolume();

protected:
  vtkAnalyticShapeSource();
  ~vtkAnalyticShapeSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Shape = SPHERE;
  double Radius = 1.0;
  double Length = 2.0;
  double MajorRadius = 2.0;
  double MinorRadius = 0.5;
  double XLength = 2.0;
  double YLength = 2.0;
  double ZLength = 2.0;
  double FilletRadius = 0.2;
  double Thickness = 0.05;
  double EndThickness = 0.1;
  int Resolution = 16;
  double Center[3] = { 0.0, 0.0, 0.0 };

private:
  vtkAnalyticShapeSource(const vtkAnalyticShapeSource&) = delete;
  void operator=(const vtkAnalyticShapeSource&) = delete;
};

#endif
