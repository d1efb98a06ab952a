// SPDX-License-Identifier: GPL-3.0-or-later
// A small, fully specified random generator (SplitMix64). The standard
// library's distributions are implementation-defined; this one gives the
// same numbers for the same seed everywhere.
#ifndef medialaxis_Random_h
#define medialaxis_Random_h

#include <cstdint>

namespace medialaxis
{
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }

  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, 1) with 53 random bits.
  double Uniform() { return static_cast<double>(this->Next() >> 11) * 0x1.0p-53; }

  /// The generator as it will be `draws` draws later (the state is a
  /// counter: streams can be drawn from in parallel, each part from its own
  /// offset, with the numbers of one sequential stream).
  Random After(std::uint64_t draws) const
  {
    Random later(*this);
    later.State += draws * 0x9E3779B97F4A7C15ull;
    return later;
  }

private:
  std::uint64_t State;
};
}

#endif
