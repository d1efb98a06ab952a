// SPDX-License-Identifier: GPL-3.0-or-later
// The ".ma" medial mesh text format of Q-MAT, MATFP and the Blender MAT
// add-on:
//
//   nv ne nf            counts
//   v x y z r [...]     nv vertices (sphere centre and radius)
//   e i j [...]         ne edges, 0-based, face edges included
//   f i j k [...]       nf triangles, 0-based
//
// Extra trailing tokens (MATFP's flags), '#' comments and blank lines are
// accepted. Parsing is plain C++ so that it can be fuzzed without VTK.
#ifndef medialaxis_MaFormat_h
#define medialaxis_MaFormat_h

#include "Mesh/MedialMesh.h"

#include <iosfwd>
#include <string>

namespace medialaxis
{
struct MaReadResult
{
  MedialMesh Mesh;
  std::string Error;              // empty on success; names the line number
  std::size_t DuplicateEdges = 0; // dropped while reading
  std::size_t DuplicateFaces = 0; // dropped while reading
  bool Ok() const { return this->Error.empty(); }
};

/// Parses a whole .ma document. On error, Mesh is cleared.
MaReadResult ParseMa(std::istream& input);

/// Writes every vertex, every edge (face edges included, each once) and every
/// face, with 17 significant digits so that reading back is exact.
/// Returns false if the stream failed.
bool WriteMa(std::ostream& output, const MedialMesh& mesh);
}

#endif
