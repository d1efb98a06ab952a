// SPDX-License-Identifier: GPL-3.0-or-later
// Every real mesh of the shared test set (see its SOURCES.md for origin and
// terms) reads and prepares into a closed, manifold, outward surface whose
// genus matches the one SOURCES.md gives. Skipped when the set is absent.
#include "TestHelpers.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkSurfaceFileReader.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace
{
const std::string MeshDir = MEDIALAXIS_MESH_DIR;

struct Expected
{
  int Genus = -1;
  bool Inward = false;
};

// Parses the table of SOURCES.md: | file | category | triangles | vertices |
// closed | manifold | genus | orientation | ...
std::map<std::string, Expected> ReadSourcesTable()
{
  std::map<std::string, Expected> table;
  std::ifstream file(MeshDir + "/SOURCES.md");
  std::string line;
  while (std::getline(file, line))
  {
    if (line.rfind("| ", 0) != 0)
    {
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|'))
    {
      const auto b = cell.find_first_not_of(' ');
      const auto e = cell.find_last_not_of(' ');
      cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    if (cells.size() < 8 || cells[0].find('.') == std::string::npos)
    {
      continue;
    }
    Expected x;
    try
    {
      x.Genus = std::stoi(cells[6]);
    }
    catch (...)
    {
      continue;
    }
    x.Inward = cells[7].find("INWARD") != std::string::npos;
    table[cells[0]] = x;
  }
  return table;
}

class SharedMesh : public ::testing::TestWithParam<const char*>
{
};
}

TEST_P(SharedMesh, PreparesToClosedOutwardSurfaceOfTheRightGenus)
{
  const std::string name = GetParam();
  const std::string path = MeshDir + "/" + name;
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << "shared meshes not present at " << MeshDir;
  }
  const auto table = ReadSourcesTable();
  ASSERT_TRUE(table.count(name)) << name << " missing from SOURCES.md";
  const Expected expected = table.at(name);

  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputConnection(reader->GetOutputPort());
  validator->Update();
  ASSERT_STREQ(reader->GetErrorMessage(), "");
  ASSERT_TRUE(validator->GetValid()) << name << ": " << validator->GetErrorMessage();
  EXPECT_EQ(validator->GetNumberOfComponents(), 1);
  EXPECT_EQ(validator->GetNumberOfInwardComponents(), expected.Inward ? 1 : 0);
  EXPECT_EQ(validator->GetNumberOfReorientedTriangles(), 0);
  EXPECT_GT(validator->GetVolume(), 0.0);

  // Euler characteristic of the closed surface: V - E + F = 2 - 2 genus.
  vtkPolyData* surface = validator->GetOutput();
  const vtkIdType v = surface->GetNumberOfPoints();
  const vtkIdType f = surface->GetNumberOfPolys();
  const vtkIdType e = 3 * f / 2;
  EXPECT_EQ(v - e + f, 2 - 2 * expected.Genus) << name;
}

INSTANTIATE_TEST_SUITE_P(All, SharedMesh,
  ::testing::Values("abc_00000068.obj", "abc_00000077.obj", "abc_00000125.obj", "abc_00000802.obj",
    "armadillo.off", "block.off", "botijo.off", "bunny.obj", "camel.off", "casting.off",
    "cheburashka.off", "cup.off", "dolphin.off", "dragon.obj", "elephant.off", "fandisk.off",
    "fertility.off", "gearwheel.stl", "hand.obj", "horse.ply", "igea.ply", "joint.off",
    "kitten.obj", "octopus.off", "pinion.off", "rocker-arm.obj", "spot.obj", "thingi_69058.stl",
    "vessel.off"),
  [](const ::testing::TestParamInfo<const char*>& info) {
    std::string n = info.param;
    for (char& c : n)
    {
      c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return n;
  });

TEST(SurfaceFileReader, UnknownExtensionAndMissingFile)
{
  std::remove("mesh.xyz"); // left by an earlier run
  vtkNew<vtkSurfaceFileReader> reader;
  vtkNew<medialaxis::test::ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName("mesh.xyz");
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("no such file"), std::string::npos);

  std::ofstream("mesh.xyz") << "1 2 3\n";
  reader->Modified();
  reader->Update();
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("unknown file extension '.xyz'"),
    std::string::npos)
    << reader->GetErrorMessage();
}
