// SPDX-License-Identifier: GPL-3.0-or-later
// NumPy's .npy array file (format versions 1 to 3): a 3-D array of 32- or
// 64-bit little-endian floats, e.g. an unsigned distance field saved with
// numpy.save. No library we use reads it (VTK 9.1 has no .npy reader).
#ifndef medialaxis_NpyFormat_h
#define medialaxis_NpyFormat_h

#include <array>
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace medialaxis
{
struct NpyVolume
{
  /// shape[0] x shape[1] x shape[2]: the array a[i, j, k] holds the value
  /// at grid point (i, j, k), x along i (numpy.meshgrid(..., indexing="ij")).
  std::array<std::size_t, 3> Shape{ 0, 0, 0 };
  std::vector<double> Values; // x fastest (VTK's order), converted from the file's
  std::string Error;          // empty on success
  bool Ok() const { return this->Error.empty(); }
};

/// Reads a 3-D float array (C or Fortran order) from an .npy stream. Other
/// types, dimensions, big-endian data or a short file give an Error.
NpyVolume ParseNpyVolume(std::istream& input);
}

#endif
