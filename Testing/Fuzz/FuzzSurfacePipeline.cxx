// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: surface preparation on a small fuzzed triangle soup and,
// when it accepts the surface, the whole plain C++ pipeline on it (sampling
// -> restricted Voronoi -> Voronoi medial mesh -> Atlas simplification) with
// few sites so that each input runs in milliseconds.
//
// Input layout (see DecodeMesh): flags, point count, points, triangle count,
// triangles. Points are 16-bit grid coordinates (exact, so that closed seed
// meshes stay closed under mutation), or raw doubles when flag bit 0 is set
// (NaN, infinities, 1e300 and denormals). Flag bit 1: CAD mode; bit 2: keep
// the orientation; bit 3: adaptive sampling; bit 4: repair crossing shells
// and a surface passing through itself.
#include "Mesh/MedialMesh.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"
#include "Surface/SurfacePreparation.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "Voronoi/VoronoiMedialAxis.h"

#include <tbb/task_arena.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
using namespace medialaxis;

struct Reader
{
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t At = 0;
  bool Byte(std::uint8_t& b)
  {
    if (this->At >= this->Size)
    {
      return false;
    }
    b = this->Data[this->At++];
    return true;
  }
  bool Bytes(void* out, std::size_t n)
  {
    if (this->Size - this->At < n)
    {
      return false;
    }
    std::memcpy(out, this->Data + this->At, n);
    this->At += n;
    return true;
  }
};

bool DecodeMesh(Reader& in, std::uint8_t flags, TriangleMesh& mesh)
{
  std::uint8_t count = 0;
  if (!in.Byte(count))
  {
    return false;
  }
  const std::size_t np = count % 33;
  for (std::size_t i = 0; i < np; ++i)
  {
    Point3 p;
    for (double& c : p)
    {
      if (flags & 1)
      {
        if (!in.Bytes(&c, sizeof(double)))
        {
          return false;
        }
      }
      else
      {
        std::int16_t v;
        if (!in.Bytes(&v, sizeof(v)))
        {
          return false;
        }
        c = v / 64.0;
      }
    }
    mesh.Points.push_back(p);
  }
  if (!in.Byte(count))
  {
    return false;
  }
  const std::size_t nt = count % 65;
  for (std::size_t t = 0; t < nt; ++t)
  {
    std::uint8_t ids[3];
    if (!in.Bytes(ids, 3))
    {
      return false;
    }
    // Out-of-range indices are not the preparation's concern (the readers
    // and the VTK adapter check them): keep them in range.
    if (np == 0)
    {
      return false;
    }
    mesh.Triangles.push_back({ ids[0] % Index(np), ids[1] % Index(np), ids[2] % Index(np) });
  }
  return true;
}

bool Finite(const Point3& p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// A broken promise of the library: say which, then crash for libFuzzer.
#define Check(condition)                                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::fprintf(stderr, "check failed, line %d: %s\n", __LINE__, #condition);                   \
      std::abort();                                                                                \
    }                                                                                              \
  } while (false)

void RunPipeline(const TriangleMesh& surface, bool cad, bool adaptive)
{
  SamplingOptions sampling;
  sampling.NumberOfSamples = 200;
  sampling.Adaptive = adaptive;
  const SurfaceSamples sites = SampleSurface(surface, sampling);
  Check(sites.Points.size() == sampling.NumberOfSamples);
  Check(sites.Spacing.size() == (adaptive ? sites.Points.size() : 0));
  for (double h : sites.Spacing)
  {
    Check(h > 0.0 && std::isfinite(h));
  }
  for (std::size_t i = 0; i < sites.Points.size(); ++i)
  {
    Check(Finite(sites.Points[i]));
    Check(sites.TriangleIds[i] >= 0 &&
      static_cast<std::size_t>(sites.TriangleIds[i]) < surface.Triangles.size());
  }
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(surface, sites.Points);
  const VoronoiMedialAxisResult voronoi =
    ComputeVoronoiMedialAxis(surface, sites.Points, sites.TriangleIds, rvd.ConcaveFeature);
  const MedialMeshCheck initialCheck = ValidateMedialMesh(voronoi.Mesh);
  if (!initialCheck.IsValid())
  {
    std::fprintf(stderr, "%s\n", initialCheck.Message.c_str());
  }
  Check(initialCheck.IsValid());

  AtlasMedialMesh initial;
  initial.Mesh = voronoi.Mesh;
  initial.AtlasOffsets = voronoi.AtlasOffsets;
  initial.AtlasSites = voronoi.AtlasSites;
  AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = 20;
  options.PreserveSharpFeatures = cad;
  const AtlasSimplifierResult result = SimplifyMedialAxis(initial, rvd, sites.Points, options);
  Check(ValidateMedialMesh(result.Medial.Mesh).IsValid());
}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Reader in{ data, size };
  std::uint8_t flags = 0;
  TriangleMesh soup;
  if (!in.Byte(flags) || !DecodeMesh(in, flags, soup))
  {
    return 0;
  }
  SurfacePreparationOptions options;
  options.FixOrientation = (flags & 4) == 0;
  options.RepairSelfIntersections = (flags & 16) != 0;
  // The wrapping fallback with coarse balls: its cost grows with the square
  // of diagonal / alpha, and at the default a unit outlasts the fuzzer's
  // time limit; the code around it is the same.
  options.WrapAlpha = 0.05;
  TriangleMesh surface;
  const SurfacePreparationReport report = PrepareSurface(soup, surface, options);
  if (!report.Ok())
  {
    return 0;
  }
  // What preparation accepts is a closed, finite triangle mesh with area.
  Check(!surface.Triangles.empty() && report.Area > 0.0 && std::isfinite(report.Area));
  for (const Point3& p : surface.Points)
  {
    Check(Finite(p));
  }
  for (const Triangle& t : surface.Triangles)
  {
    for (Index v : t)
    {
      Check(v >= 0 && static_cast<std::size_t>(v) < surface.Points.size());
    }
  }
  // One thread: the fuzzer's inputs are tiny and results are thread-count
  // independent anyway.
  tbb::task_arena arena(1);
  arena.execute([&] { RunPipeline(surface, (flags & 2) != 0, (flags & 8) != 0); });
  return 0;
}
