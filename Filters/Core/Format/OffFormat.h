// SPDX-License-Identifier: GPL-3.0-or-later
// ASCII Object File Format (OFF) reader: "OFF" (or COFF/NOFF/CNOFF, whose
// extra per-vertex values are skipped), counts "nv nf ne", nv vertex lines,
// then nf polygon lines "n i1 ... in [colour]". Polygons keep all their
// vertices; triangulation is surface preparation's job.
#ifndef medialaxis_OffFormat_h
#define medialaxis_OffFormat_h

#include "Mesh/PolygonMesh.h"

#include <iosfwd>
#include <string>

namespace medialaxis
{
struct OffReadResult
{
  PolygonMesh Mesh;
  std::string Error; // empty on success; names the line number
  bool Ok() const { return this->Error.empty(); }
};

OffReadResult ParseOff(std::istream& input);
}

#endif
