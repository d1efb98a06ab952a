// SPDX-License-Identifier: GPL-3.0-or-later
#include "Format/NpyFormat.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <regex>

namespace medialaxis
{
namespace
{
// The value of `key` in the header's Python dict literal, as text.
std::string HeaderValue(const std::string& header, const std::string& key)
{
  const std::size_t at = header.find("'" + key + "'");
  if (at == std::string::npos)
  {
    return "";
  }
  std::size_t start = header.find(':', at);
  if (start == std::string::npos)
  {
    return "";
  }
  ++start;
  while (start < header.size() && header[start] == ' ')
  {
    ++start;
  }
  if (start < header.size() && header[start] == '(')
  {
    const std::size_t end = header.find(')', start);
    return end == std::string::npos ? "" : header.substr(start, end - start + 1);
  }
  const std::size_t end = header.find_first_of(",}", start);
  return header.substr(start, end == std::string::npos ? std::string::npos : end - start);
}
}

NpyVolume ParseNpyVolume(std::istream& input)
{
  NpyVolume volume;
  char magic[8] = {};
  if (!input.read(magic, 8) || std::memcmp(magic, "\x93NUMPY", 6) != 0)
  {
    volume.Error = "not an .npy file (no \\x93NUMPY magic)";
    return volume;
  }
  const int major = static_cast<unsigned char>(magic[6]);
  std::uint32_t headerLength = 0;
  unsigned char length[4] = {};
  if (major == 1)
  {
    input.read(reinterpret_cast<char*>(length), 2);
    headerLength = length[0] | (length[1] << 8);
  }
  else if (major == 2 || major == 3)
  {
    input.read(reinterpret_cast<char*>(length), 4);
    headerLength = length[0] | (length[1] << 8) | (length[2] << 16) |
      (static_cast<std::uint32_t>(length[3]) << 24);
  }
  else
  {
    volume.Error = ".npy format version " + std::to_string(major) + " is not known";
    return volume;
  }
  if (!input || headerLength > (1u << 20))
  {
    volume.Error = ".npy header is cut short or too long";
    return volume;
  }
  std::string header(headerLength, '\0');
  if (!input.read(header.data(), headerLength))
  {
    volume.Error = ".npy header is cut short";
    return volume;
  }
  const std::string descr = HeaderValue(header, "descr");
  std::size_t itemSize = 0;
  if (descr == "'<f8'" || descr == "'=f8'")
  {
    itemSize = 8;
  }
  else if (descr == "'<f4'" || descr == "'=f4'")
  {
    itemSize = 4;
  }
  else
  {
    volume.Error = "the array's type is " + (descr.empty() ? std::string("not given") : descr) +
      ": little-endian float32 or float64 is needed";
    return volume;
  }
  const bool fortran = HeaderValue(header, "fortran_order") == "True";
  const std::string shape = HeaderValue(header, "shape");
  static const std::regex threeNumbers(R"(\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*,?\s*\))");
  std::smatch match;
  if (!std::regex_match(shape, match, threeNumbers))
  {
    volume.Error = "the array's shape is " + (shape.empty() ? std::string("not given") : shape) +
      ": a 3-D array is needed";
    return volume;
  }
  std::size_t count = 1;
  for (int a = 0; a < 3; ++a)
  {
    const std::string digits = match[a + 1].str();
    const unsigned long long n = digits.size() > 9 ? 0 : std::stoull(digits);
    if (n == 0 || n > (1ull << 20) || count > std::numeric_limits<std::size_t>::max() / n / 8)
    {
      volume.Error = "the array's shape " + shape + " is empty or too large";
      return volume;
    }
    volume.Shape[a] = static_cast<std::size_t>(n);
    count *= volume.Shape[a];
  }
  // Short data is refused before anything that size is allocated.
  const std::streampos here = input.tellg();
  if (here != std::streampos(-1) && input.seekg(0, std::ios::end))
  {
    const std::streamoff left = input.tellg() - here;
    input.seekg(here);
    if (left < 0 || static_cast<std::size_t>(left) < count * itemSize)
    {
      volume.Error = "the .npy data is cut short: " + std::to_string(count) + " values expected";
      return volume;
    }
  }
  input.clear();
  std::vector<char> raw(count * itemSize);
  if (!input.read(raw.data(), static_cast<std::streamsize>(raw.size())))
  {
    volume.Error = "the .npy data is cut short: " + std::to_string(count) + " values expected";
    return volume;
  }
  const std::size_t nx = volume.Shape[0], ny = volume.Shape[1], nz = volume.Shape[2];
  volume.Values.resize(count);
  for (std::size_t k = 0; k < nz; ++k)
  {
    for (std::size_t j = 0; j < ny; ++j)
    {
      for (std::size_t i = 0; i < nx; ++i)
      {
        // Fortran order: i fastest (VTK's); C order: k fastest.
        const std::size_t from = fortran ? (k * ny + j) * nx + i : (i * ny + j) * nz + k;
        double value = 0.0;
        if (itemSize == 8)
        {
          std::memcpy(&value, raw.data() + 8 * from, 8);
        }
        else
        {
          float single = 0.0f;
          std::memcpy(&single, raw.data() + 4 * from, 4);
          value = single;
        }
        volume.Values[(k * ny + j) * nx + i] = value;
      }
    }
  }
  return volume;
}
}
