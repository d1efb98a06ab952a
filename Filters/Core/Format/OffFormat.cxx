// SPDX-License-Identifier: GPL-3.0-or-later
#include "Format/OffFormat.h"

#include "Format/TextTokens.h"

#include <algorithm>
#include <istream>

namespace medialaxis
{
OffReadResult ParseOff(std::istream& input)
{
  OffReadResult result;
  auto fail = [&result](std::size_t line, const std::string& what)
  {
    result.Error = "line " + std::to_string(line) + ": " + what;
    result.Mesh = PolygonMesh();
    return result;
  };

  enum class Stage
  {
    Keyword,
    Counts,
    Vertices,
    Faces,
    Done
  };
  Stage stage = Stage::Keyword;
  std::int64_t nv = 0, nf = 0;
  std::vector<Index> ids;
  std::string text;
  std::size_t lineNumber = 0;
  constexpr std::size_t reserveCap = std::size_t(1) << 22;

  while (stage != Stage::Done && std::getline(input, text))
  {
    ++lineNumber;
    auto tokens = SplitTokens(text);
    if (tokens.empty())
    {
      continue;
    }
    if (stage == Stage::Keyword)
    {
      const std::string_view keyword = tokens[0];
      const bool isOff = keyword.size() >= 3 && keyword.substr(keyword.size() - 3) == "OFF" &&
        keyword.find_first_not_of("STCNOF4") == std::string_view::npos;
      if (!isOff)
      {
        return fail(
          lineNumber, "not an OFF file: expected 'OFF', found '" + std::string(keyword) + "'");
      }
      if (keyword.find('4') != std::string_view::npos)
      {
        return fail(lineNumber, "4D OFF files are not supported");
      }
      if (tokens.size() > 1 && tokens[1] == "BINARY")
      {
        return fail(lineNumber, "binary OFF files are not supported; convert to ASCII OFF");
      }
      stage = Stage::Counts;
      tokens.erase(tokens.begin());
      if (tokens.empty())
      {
        continue;
      }
    }
    if (stage == Stage::Counts)
    {
      if (tokens.size() < 2)
      {
        return fail(lineNumber, "expected counts 'nv nf ne'");
      }
      if (!ParseInteger(tokens[0], nv) || nv < 0 || !ParseInteger(tokens[1], nf) || nf < 0)
      {
        return fail(lineNumber,
          "counts '" + std::string(tokens[0]) + " " + std::string(tokens[1]) +
            "' are not non-negative integers");
      }
      result.Mesh.Points.reserve(std::min<std::size_t>(nv, reserveCap));
      result.Mesh.Offsets.reserve(std::min<std::size_t>(nf, reserveCap) + 1);
      stage = nv > 0 ? Stage::Vertices : (nf > 0 ? Stage::Faces : Stage::Done);
      continue;
    }
    if (stage == Stage::Vertices)
    {
      if (tokens.size() < 3)
      {
        return fail(
          lineNumber, "vertex line needs 3 coordinates, found " + std::to_string(tokens.size()));
      }
      Point3 p;
      for (int k = 0; k < 3; ++k)
      {
        // Non-finite values are passed through: surface validation names them.
        if (!ParseDouble(tokens[k], p[k]))
        {
          return fail(lineNumber, "'" + std::string(tokens[k]) + "' is not a number");
        }
      }
      result.Mesh.Points.push_back(p);
      if (static_cast<std::int64_t>(result.Mesh.Points.size()) == nv)
      {
        stage = nf > 0 ? Stage::Faces : Stage::Done;
      }
      continue;
    }
    // Stage::Faces
    std::int64_t n = 0;
    if (!ParseInteger(tokens[0], n) || n < 1)
    {
      return fail(
        lineNumber, "polygon size '" + std::string(tokens[0]) + "' is not a positive integer");
    }
    if (static_cast<std::int64_t>(tokens.size()) - 1 < n) // not n + 1: n may be INT64_MAX
    {
      return fail(lineNumber,
        "polygon announces " + std::to_string(n) + " vertices but lists " +
          std::to_string(tokens.size() - 1));
    }
    ids.resize(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k)
    {
      if (!ParseInteger(tokens[k + 1], ids[k]))
      {
        return fail(
          lineNumber, "'" + std::string(tokens[k + 1]) + "' is not a vertex index (an integer)");
      }
      if (ids[k] < 0 || ids[k] >= nv)
      {
        return fail(lineNumber,
          "vertex index " + std::to_string(ids[k]) + " is outside [0, " + std::to_string(nv) + ")");
      }
    }
    result.Mesh.AddPolygon(ids.data(), ids.size());
    if (static_cast<std::int64_t>(result.Mesh.NumberOfPolygons()) == nf)
    {
      stage = Stage::Done;
    }
  }

  if (input.bad())
  {
    return fail(lineNumber, "read error");
  }
  switch (stage)
  {
    case Stage::Keyword:
      return fail(lineNumber, "empty file: no 'OFF' keyword");
    case Stage::Counts:
      return fail(lineNumber, "end of file before the counts 'nv nf ne'");
    case Stage::Vertices:
      return fail(lineNumber,
        "end of file after " + std::to_string(result.Mesh.Points.size()) + " of " +
          std::to_string(nv) + " vertices");
    case Stage::Faces:
      return fail(lineNumber,
        "end of file after " + std::to_string(result.Mesh.NumberOfPolygons()) + " of " +
          std::to_string(nf) + " polygons");
    case Stage::Done:
      break;
  }
  return result;
}
}
