// SPDX-License-Identifier: GPL-3.0-or-later
#include "Format/ObjCheck.h"

#include "Format/TextTokens.h"

#include <cmath>
#include <cstdint>

namespace medialaxis
{
std::string CheckObjText(std::istream& in)
{
  std::string line;
  std::int64_t vertices = 0;
  for (std::size_t number = 1; std::getline(in, line); ++number)
  {
    const auto tokens = SplitTokens(line);
    if (tokens.empty())
    {
      continue;
    }
    const std::string where = "line " + std::to_string(number) + ": ";
    if (tokens[0] == "v")
    {
      if (tokens.size() < 4)
      {
        return where + "a vertex needs three coordinates";
      }
      for (std::size_t k = 1; k < 4; ++k)
      {
        double value = 0.0;
        if (!ParseDouble(tokens[k], value) || !std::isfinite(value))
        {
          return where + "vertex coordinate '" + std::string(tokens[k]) +
            "' is not a finite number";
        }
      }
      ++vertices;
    }
    else if (tokens[0] == "f")
    {
      if (tokens.size() < 4)
      {
        return where + "a face needs at least three vertices";
      }
      for (std::size_t k = 1; k < tokens.size(); ++k)
      {
        // i, i/t, i/t/n or i//n: the vertex index comes first.
        const std::string_view reference = tokens[k];
        const std::string_view index = reference.substr(0, reference.find('/'));
        std::int64_t value = 0;
        if (!ParseInteger(index, value) || value == 0 || value > vertices || -value > vertices)
        {
          return where + "face vertex '" + std::string(reference) +
            "' is not the index of a vertex read before (1 to " + std::to_string(vertices) + ")";
        }
      }
    }
  }
  return "";
}
}
