// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the .npy parser on arbitrary bytes. A successful parse
// must give exactly shape[0] * shape[1] * shape[2] values; an error leaves
// none.
#include "Format/NpyFormat.h"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  const medialaxis::NpyVolume volume = medialaxis::ParseNpyVolume(in);
  if (!volume.Ok())
  {
    if (!volume.Values.empty())
    {
      std::abort();
    }
    return 0;
  }
  if (volume.Values.size() != volume.Shape[0] * volume.Shape[1] * volume.Shape[2] ||
    volume.Values.empty())
  {
    std::abort();
  }
  return 0;
}
