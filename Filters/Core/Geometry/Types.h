// SPDX-License-Identifier: GPL-3.0-or-later
// The two types every part of the core shares: a point (or vector) in space
// and the index of a vertex, edge, face or sample.
#ifndef medialaxis_Types_h
#define medialaxis_Types_h

#include <array>
#include <cstdint>

namespace medialaxis
{
using Point3 = std::array<double, 3>;
using Index = std::int64_t;
}

#endif
