// SPDX-License-Identifier: GPL-3.0-or-later
#include "Format/MaFormat.h"

#include "Format/TextTokens.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <set>
#include <sstream>

namespace medialaxis
{
namespace
{
std::string AtLine(std::size_t line, const std::string& what)
{
  return "line " + std::to_string(line) + ": " + what;
}

// Keeps the first occurrence of every cell (compared with sorted vertex ids)
// and returns how many repeats were dropped. Order of survivors is preserved.
template <std::size_t N>
std::size_t DropDuplicateCells(std::vector<std::array<Index, N>>& cells)
{
  std::set<std::array<Index, N>> seen;
  std::vector<std::array<Index, N>> kept;
  kept.reserve(cells.size());
  for (const auto& c : cells)
  {
    auto key = c;
    std::sort(key.begin(), key.end());
    if (seen.insert(key).second)
    {
      kept.push_back(c);
    }
  }
  const std::size_t dropped = cells.size() - kept.size();
  cells.swap(kept);
  return dropped;
}

void AppendDouble(std::string& out, double value)
{
  char buffer[64];
  const auto r =
    std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 17);
  out.append(buffer, r.ptr);
}
}

MaReadResult ParseMa(std::istream& input)
{
  MaReadResult result;
  auto fail = [&result](std::size_t line, const std::string& what)
  {
    result.Error = AtLine(line, what);
    result.Mesh = MedialMesh();
    return result;
  };

  std::string text;
  std::size_t lineNumber = 0;
  bool haveHeader = false;
  std::int64_t counts[3] = { 0, 0, 0 };
  std::size_t seen[3] = { 0, 0, 0 };
  const char* kindNames[3] = { "vertex", "edge", "face" };
  // Header counts may be huge in a corrupt file: never reserve blindly.
  constexpr std::size_t reserveCap = std::size_t(1) << 22;

  while (std::getline(input, text))
  {
    ++lineNumber;
    const auto tokens = SplitTokens(text);
    if (tokens.empty())
    {
      continue;
    }
    if (!haveHeader)
    {
      if (tokens.size() < 3)
      {
        return fail(lineNumber,
          "header must give three counts 'nv ne nf', found " + std::to_string(tokens.size()) +
            " token(s)");
      }
      for (int k = 0; k < 3; ++k)
      {
        if (!ParseInteger(tokens[k], counts[k]) || counts[k] < 0)
        {
          return fail(lineNumber,
            "header count '" + std::string(tokens[k]) + "' is not a non-negative integer");
        }
      }
      haveHeader = true;
      result.Mesh.Centers.reserve(std::min<std::size_t>(counts[0], reserveCap));
      result.Mesh.Radii.reserve(std::min<std::size_t>(counts[0], reserveCap));
      result.Mesh.Edges.reserve(std::min<std::size_t>(counts[1], reserveCap));
      result.Mesh.Faces.reserve(std::min<std::size_t>(counts[2], reserveCap));
      continue;
    }

    int kind = -1;
    if (tokens[0] == "v")
    {
      kind = 0;
    }
    else if (tokens[0] == "e")
    {
      kind = 1;
    }
    else if (tokens[0] == "f")
    {
      kind = 2;
    }
    else
    {
      return fail(
        lineNumber, "unknown record '" + std::string(tokens[0]) + "' (expected 'v', 'e' or 'f')");
    }
    if (static_cast<std::int64_t>(seen[kind]) >= counts[kind])
    {
      return fail(lineNumber,
        std::string("more ") + kindNames[kind] + " lines than the " + std::to_string(counts[kind]) +
          " announced in the header");
    }
    ++seen[kind];

    const std::size_t needed = kind == 0 ? 5 : (kind == 1 ? 3 : 4);
    if (tokens.size() < needed)
    {
      return fail(lineNumber,
        std::string(kindNames[kind]) + " line needs " + std::to_string(needed - 1) +
          " numbers, found " + std::to_string(tokens.size() - 1));
    }

    if (kind == 0)
    {
      double values[4];
      for (int k = 0; k < 4; ++k)
      {
        if (!ParseDouble(tokens[k + 1], values[k]))
        {
          return fail(lineNumber, "'" + std::string(tokens[k + 1]) + "' is not a number");
        }
        if (!std::isfinite(values[k]))
        {
          return fail(lineNumber,
            std::string(k < 3 ? "coordinate" : "radius") + " '" + std::string(tokens[k + 1]) +
              "' is not finite");
        }
      }
      if (values[3] < 0.0)
      {
        return fail(lineNumber, "radius " + std::string(tokens[4]) + " is negative");
      }
      result.Mesh.Centers.push_back({ values[0], values[1], values[2] });
      result.Mesh.Radii.push_back(values[3]);
      continue;
    }

    Index ids[3] = { 0, 0, 0 };
    const int n = kind == 1 ? 2 : 3;
    for (int k = 0; k < n; ++k)
    {
      if (!ParseInteger(tokens[k + 1], ids[k]))
      {
        return fail(
          lineNumber, "'" + std::string(tokens[k + 1]) + "' is not a vertex index (an integer)");
      }
      if (ids[k] < 0 || ids[k] >= counts[0])
      {
        return fail(lineNumber,
          "vertex index " + std::to_string(ids[k]) + " is outside [0, " +
            std::to_string(counts[0]) + ")");
      }
    }
    if (ids[0] == ids[1] || (n == 3 && (ids[1] == ids[2] || ids[0] == ids[2])))
    {
      return fail(lineNumber,
        std::string(kindNames[kind]) + " repeats vertex " +
          std::to_string(ids[0] == ids[1] || ids[0] == ids[2] ? ids[0] : ids[1]));
    }
    if (kind == 1)
    {
      result.Mesh.Edges.push_back({ ids[0], ids[1] });
    }
    else
    {
      result.Mesh.Faces.push_back({ ids[0], ids[1], ids[2] });
    }
  }

  if (input.bad())
  {
    return fail(lineNumber, "read error");
  }
  if (!haveHeader)
  {
    return fail(lineNumber, "no header 'nv ne nf' found (empty file?)");
  }
  for (int kind = 0; kind < 3; ++kind)
  {
    if (static_cast<std::int64_t>(seen[kind]) != counts[kind])
    {
      return fail(lineNumber,
        std::string("end of file after ") + std::to_string(seen[kind]) + " of the " +
          std::to_string(counts[kind]) + " " + kindNames[kind] + " lines announced in the header");
    }
  }
  result.DuplicateEdges = DropDuplicateCells(result.Mesh.Edges);
  result.DuplicateFaces = DropDuplicateCells(result.Mesh.Faces);
  return result;
}

bool WriteMa(std::ostream& output, const MedialMesh& mesh)
{
  const auto edges = AllEdges(mesh);
  std::string text;
  text.reserve(64 * (mesh.Centers.size() + edges.size() + mesh.Faces.size()) + 64);
  text += std::to_string(mesh.Centers.size()) + ' ' + std::to_string(edges.size()) + ' ' +
    std::to_string(mesh.Faces.size()) + '\n';
  for (std::size_t i = 0; i < mesh.Centers.size(); ++i)
  {
    text += 'v';
    for (double c : mesh.Centers[i])
    {
      text += ' ';
      AppendDouble(text, c);
    }
    text += ' ';
    AppendDouble(text, mesh.Radii[i]);
    text += '\n';
  }
  for (const auto& e : edges)
  {
    text += "e " + std::to_string(e[0]) + ' ' + std::to_string(e[1]) + '\n';
  }
  for (const auto& f : mesh.Faces)
  {
    text +=
      "f " + std::to_string(f[0]) + ' ' + std::to_string(f[1]) + ' ' + std::to_string(f[2]) + '\n';
  }
  output.write(text.data(), static_cast<std::streamsize>(text.size()));
  return static_cast<bool>(output);
}
}
