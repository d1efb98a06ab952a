// SPDX-License-Identifier: GPL-3.0-or-later
// NumPy .npy volumes: both orders, both float sizes, and the errors.
#include "Format/NpyFormat.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace medialaxis;

namespace
{
// An .npy file (version 1) with the given header dict and raw data.
std::string Npy(const std::string& dict, const std::string& data)
{
  std::string header = dict;
  while ((10 + header.size() + 1) % 64 != 0)
  {
    header += ' ';
  }
  header += '\n';
  std::string file = "\x93NUMPY";
  file += '\x01';
  file += '\x00';
  file += static_cast<char>(header.size() & 0xff);
  file += static_cast<char>(header.size() >> 8);
  return file + header + data;
}

template <typename T>
std::string Raw(const std::vector<T>& values)
{
  std::string raw(values.size() * sizeof(T), '\0');
  std::memcpy(raw.data(), values.data(), raw.size());
  return raw;
}

NpyVolume Parse(const std::string& file)
{
  std::istringstream in(file);
  return ParseNpyVolume(in);
}
}

TEST(NpyFormat, COrderIsTurnedXFastest)
{
  // a[i, j, k] = 100 i + 10 j + k, shape (2, 3, 4), C order: k fastest.
  std::vector<double> c;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 4; ++k)
        c.push_back(100 * i + 10 * j + k);
  const NpyVolume v =
    Parse(Npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3, 4), }", Raw(c)));
  ASSERT_TRUE(v.Ok()) << v.Error;
  EXPECT_EQ(v.Shape, (std::array<std::size_t, 3>{ 2, 3, 4 }));
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 2; ++i)
        EXPECT_EQ(v.Values[(k * 3 + j) * 2 + i], 100 * i + 10 * j + k);
}

TEST(NpyFormat, FortranOrderFloat32)
{
  std::vector<float> f;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        f.push_back(static_cast<float>(i + 0.5 * j + 0.25 * k));
  const NpyVolume v =
    Parse(Npy("{'descr': '<f4', 'fortran_order': True, 'shape': (3, 2, 2), }", Raw(f)));
  ASSERT_TRUE(v.Ok()) << v.Error;
  for (std::size_t n = 0; n < f.size(); ++n)
    EXPECT_EQ(v.Values[n], f[n]);
}

TEST(NpyFormat, ErrorsNameTheProblem)
{
  const std::string data = Raw(std::vector<double>(8, 1.0));
  EXPECT_NE(Parse("PK\x03\x04 not numpy").Error.find("not an .npy file"), std::string::npos);
  EXPECT_NE(Parse(Npy("{'descr': '<i4', 'fortran_order': False, 'shape': (2, 2, 2), }", data))
              .Error.find("float32 or float64"),
    std::string::npos);
  EXPECT_NE(Parse(Npy("{'descr': '>f8', 'fortran_order': False, 'shape': (2, 2, 2), }", data))
              .Error.find("little-endian"),
    std::string::npos);
  EXPECT_NE(Parse(Npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 2), }", data))
              .Error.find("a 3-D array is needed"),
    std::string::npos);
  EXPECT_NE(Parse(Npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 3), }", data))
              .Error.find("cut short"),
    std::string::npos);
  EXPECT_NE(Parse(Npy("{'descr': '<f8', 'fortran_order': False, 'shape': (0, 2, 3), }", data))
              .Error.find("empty or too large"),
    std::string::npos);
  // A dimension too long for any integer (found by fuzzing).
  EXPECT_NE(Parse(Npy("{'descr': '<f8', 'fortran_order': False, 'shape': "
                      "(31111111111111111111111111, 1, 1), }",
                    data))
              .Error.find("empty or too large"),
    std::string::npos);
}
