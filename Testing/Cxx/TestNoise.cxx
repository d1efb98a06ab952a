// SPDX-License-Identifier: GPL-3.0-or-later
// Noise (the paper's Sec. 5.5): every vertex of a CAD part (fandisk) and of an
// organic mesh (the Stanford Bunny; both from the shared meshes, see their
// SOURCES.md) moved by up to 0.25% and 0.5% of the bounding-box diagonal in a
// random direction (fixed seed); 10,000 sites simplified to 1,000 vertices.
// The medial axis stays valid, with no degenerate and no more folded
// triangles than the noiseless one's, and its two-sided Hausdorff distance to
// the surface it was computed from stays within twice the noiseless value.
// Skipped when the shared meshes are absent.
#include "Envelope/EnvelopeDistance.h"
#include "Envelope/ReconstructionError.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMeshQuality.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"
#include "TestHelpers.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "Voronoi/VoronoiMedialAxis.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>

using namespace medialaxis;
using test::WithNoise;

namespace
{
const std::string MeshDir = MEDIALAXIS_MESH_DIR;

struct NoisyResult
{
  std::string Error; // of surface preparation, if the noisy surface was refused
  MedialMeshQuality Quality;
  std::string Validity;
  double HausdorffPercent = 0.0;
};

NoisyResult MedialAxisOf(const TriangleMesh& input, bool cad)
{
  NoisyResult result;
  TriangleMesh mesh;
  const SurfacePreparationReport report = PrepareSurface(input, mesh);
  if (!report.Ok())
  {
    result.Error = report.Error;
    return result;
  }
  SamplingOptions sampling;
  sampling.NumberOfSamples = 10000;
  const SurfaceSamples sites = SampleSurface(mesh, sampling);
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(mesh, sites.Points);
  VoronoiMedialAxisResult voronoi =
    ComputeVoronoiMedialAxis(mesh, sites.Points, sites.TriangleIds, rvd.ConcaveFeature);
  AtlasMedialMesh initial;
  initial.Mesh = std::move(voronoi.Mesh);
  initial.AtlasOffsets = std::move(voronoi.AtlasOffsets);
  initial.AtlasSites = std::move(voronoi.AtlasSites);
  AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = 1000;
  options.PreserveSharpFeatures = cad;
  const AtlasSimplifierResult simplified = SimplifyMedialAxis(initial, rvd, sites.Points, options);
  const MedialMesh& medial = simplified.Medial.Mesh;
  result.Quality = MeasureQuality(medial);
  result.Validity = ValidateMedialMesh(medial).Message;
  ReconstructionErrorOptions errorOptions;
  errorOptions.NumberOfSamples = 30000;
  errorOptions.NumberOfEnvelopeSamples = 30000;
  const ReconstructionErrorResult error =
    ComputeReconstructionError(mesh, MedialEnvelope(medial), errorOptions);
  result.HausdorffPercent = 100.0 * error.Hausdorff / error.Diagonal;
  return result;
}

void NoiseKeepsTheMedialAxisValid(
  const std::string& name, bool cad, std::initializer_list<double> amplitudes)
{
  const std::string path = MeshDir + "/" + name;
  if (!std::ifstream(path))
  {
    GTEST_SKIP() << path << " not found";
  }
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  TriangleMesh mesh;
  ASSERT_TRUE(PrepareSurfaceMesh(reader->GetOutput(), mesh).Ok());

  const NoisyResult clean = MedialAxisOf(mesh, cad);
  ASSERT_EQ(clean.Error, "");
  EXPECT_EQ(clean.Validity, "");
  std::printf("%s (%s) noiseless: Hausdorff %.3f%%, %zu degenerate, %zu folded of %zu triangles\n",
    name.c_str(), cad ? "sharp features" : "no sharp features", clean.HausdorffPercent,
    clean.Quality.DegenerateTriangles, clean.Quality.FoldedTriangles, clean.Quality.Triangles);
  for (double amplitude : amplitudes)
  {
    const NoisyResult noisy = MedialAxisOf(WithNoise(mesh, amplitude, 20261129), cad);
    ASSERT_EQ(noisy.Error, "") << amplitude;
    std::printf(
      "%s (%s) noise %.2f%%: Hausdorff %.3f%%, %zu degenerate, %zu folded of %zu triangles\n",
      name.c_str(), cad ? "sharp features" : "no sharp features", 100 * amplitude,
      noisy.HausdorffPercent, noisy.Quality.DegenerateTriangles, noisy.Quality.FoldedTriangles,
      noisy.Quality.Triangles);
    EXPECT_EQ(noisy.Validity, "") << amplitude;
    EXPECT_EQ(noisy.Quality.DegenerateTriangles, 0u) << amplitude;
    EXPECT_LE(noisy.Quality.FoldedTriangles, clean.Quality.FoldedTriangles) << amplitude;
    // Measured against the noisy surface, whose bumps a medial mesh of
    // 1,000 spheres smooths out: at most twice the noiseless distance plus
    // the noise amplitude (bunny at 0.5% noise: 0.72% against 0.32%
    // noiseless; before error bands 0.85% against 0.65%).
    EXPECT_LE(noisy.HausdorffPercent, 2.0 * clean.HausdorffPercent + 100.0 * amplitude)
      << amplitude;
  }
}
}

TEST(Noise, CadPartFandisk)
{
  NoiseKeepsTheMedialAxisValid("fandisk.off", true, { 0.0025 });
  NoiseKeepsTheMedialAxisValid("fandisk.off", false, { 0.0025, 0.005 });
}

// At 0.5% the raw dihedral-angle test takes the noise for sharp edges (1,014
// feature edges instead of 695), and snapping medial vertices onto them
// folded 21 triangles and raised the Hausdorff distance from 1.7% to 10%.
// The filtered normals that must confirm each sharp ridge
// (RestrictedVoronoiOptions::FeatureNormalFiltering) keep it valid.
TEST(Noise, CadPartFandiskHalfPercentWithSharpFeatures)
{
  NoiseKeepsTheMedialAxisValid("fandisk.off", true, { 0.005 });
}

TEST(Noise, OrganicBunny)
{
  NoiseKeepsTheMedialAxisValid("bunny.obj", false, { 0.0025, 0.005 });
}
