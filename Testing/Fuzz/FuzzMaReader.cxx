// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the .ma parser on arbitrary bytes. Whatever parses must
// also write and read back to the same mesh.
#include "Format/MaFormat.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const medialaxis::MaReadResult read = medialaxis::ParseMa(in);
  if (!read.Ok())
  {
    if (!read.Mesh.Centers.empty() || read.Error.rfind("line ", 0) != 0)
    {
      std::abort(); // errors clear the mesh and name the line
    }
    return 0;
  }
  const medialaxis::MedialMesh& mesh = read.Mesh;
  // The parser rejects bad indices, repeated vertices, non-finite values and
  // negative radii, and drops duplicates: what it returns is valid.
  if (!medialaxis::ValidateMedialMesh(mesh).IsValid())
  {
    std::abort();
  }
  std::ostringstream out;
  if (!medialaxis::WriteMa(out, mesh))
  {
    std::abort();
  }
  std::istringstream again(out.str());
  const medialaxis::MaReadResult back = medialaxis::ParseMa(again);
  if (!back.Ok() || back.Mesh.Centers != mesh.Centers || back.Mesh.Radii != mesh.Radii ||
    back.Mesh.Faces != mesh.Faces || medialaxis::AllEdges(back.Mesh) != medialaxis::AllEdges(mesh))
  {
    std::abort(); // the writer must round-trip exactly
  }
  return 0;
}
