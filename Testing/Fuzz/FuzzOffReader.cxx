// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the OFF parser on arbitrary bytes. A successful parse
// must give polygons whose indices are all valid.
#include "Format/OffFormat.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const medialaxis::OffReadResult read = medialaxis::ParseOff(in);
  const medialaxis::PolygonMesh& mesh = read.Mesh;
  if (!read.Ok())
  {
    if (!mesh.Points.empty() || mesh.NumberOfPolygons() != 0 || read.Error.rfind("line ", 0) != 0)
    {
      std::abort(); // errors clear the mesh and name the line
    }
    return 0;
  }
  if (mesh.Offsets.empty() || mesh.Offsets.front() != 0 ||
    static_cast<std::size_t>(mesh.Offsets.back()) != mesh.Connectivity.size())
  {
    std::abort();
  }
  for (std::size_t p = 0; p < mesh.NumberOfPolygons(); ++p)
  {
    if (mesh.Offsets[p + 1] <= mesh.Offsets[p])
    {
      std::abort(); // every polygon has at least one vertex
    }
  }
  for (medialaxis::Index id : mesh.Connectivity)
  {
    if (id < 0 || static_cast<std::size_t>(id) >= mesh.Points.size())
    {
      std::abort();
    }
  }
  return 0;
}
