// SPDX-License-Identifier: GPL-3.0-or-later
// OFF reading: polygons kept as polygons, variants, malformed files.
#include "Format/ObjCheck.h"
#include "Format/OffFormat.h"
#include "TestHelpers.h"
#include "vtkOFFReader.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace medialaxis;

namespace
{
const char* CubeWithQuads = "OFF\n"
                            "# a unit cube made of quads\n"
                            "8 6 12\n"
                            "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
                            "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";

OffReadResult Parse(const std::string& text)
{
  std::istringstream in(text);
  return ParseOff(in);
}
}

TEST(OffReader, KeepsPolygons)
{
  const auto r = Parse(CubeWithQuads);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Mesh.Points.size(), 8u);
  ASSERT_EQ(r.Mesh.NumberOfPolygons(), 6u);
  EXPECT_EQ(r.Mesh.Offsets[1], 4);
}

TEST(OffReader, VariantsAndColours)
{
  const auto r = Parse("COFF 3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
                       "3 0 1 2 0.5 0.5 0.5\n");
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Mesh.Points.size(), 3u);
  EXPECT_EQ(r.Mesh.NumberOfPolygons(), 1u);
}

TEST(OffReader, MalformedFiles)
{
  struct Case
  {
    const char* Text;
    const char* Phrase;
  };
  const Case cases[] = { { "", "line 0: empty file" },
    { "PLY\n3 1 0\n", "line 1: not an OFF file" },
    { "OFF\n", "line 1: end of file before the counts" }, { "OFF\n3 x 0\n", "line 2: counts" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n", "line 4: end of file after 2 of 3 vertices" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n", "line 5: 'one' is not a number" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "line 6: vertex index 3 is outside [0, 3)" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "line 6: polygon announces 4" },
    // The largest polygon size once overflowed the token count check.
    { "OFF\n1 1 0\n0 0 0\n9223372036854775807 0\n",
      "line 4: polygon announces 9223372036854775807 vertices but lists 1" },
    { "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "line 6: end of file after 1 of 2 polygons" },
    { "OFF BINARY\n", "binary OFF files are not supported" } };
  for (const Case& c : cases)
  {
    const auto r = Parse(c.Text);
    EXPECT_FALSE(r.Ok()) << c.Text;
    EXPECT_NE(r.Error.find(c.Phrase), std::string::npos) << r.Error;
    EXPECT_TRUE(r.Mesh.Points.empty());
  }
}

TEST(OffReader, VtkReaderOutputsPolygons)
{
  const std::string path = test::WriteTextFile("cube.off", CubeWithQuads);
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_STREQ(reader->GetErrorMessage(), "");
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 8);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), 6);
  EXPECT_EQ(reader->GetOutput()->GetPolys()->GetMaxCellSize(), 4);
}

TEST(OffReader, VtkReaderReportsMalformedFile)
{
  const std::string path = test::WriteTextFile("broken.off", "OFF\n3 1 0\n0 0 0\n");
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<test::ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("broken.off: line 3:"), std::string::npos)
    << reader->GetErrorMessage();
}

// OBJ files are read by VTK after a strict check of their vertex and face
// lines, which vtkOBJReader would misread silently.
TEST(ObjCheck, NamesTheFirstBrokenLine)
{
  auto check = [](const std::string& text)
  {
    std::istringstream in(text);
    return medialaxis::CheckObjText(in);
  };
  const std::string triangle = "v 0 0 0\nv 1 0 0 1.0\nv 0 1 0 0.5 0.5 0.5\n";
  EXPECT_EQ(check(triangle + "f 1 2 3\n"), "");
  EXPECT_EQ(check("# comment\n\n" + triangle + "vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 -1\n"), "");
  EXPECT_EQ(
    check("v 0 0 0\nv nan 0 0\n"), "line 2: vertex coordinate 'nan' is not a finite number");
  EXPECT_EQ(check("v 0 0 1.0x\n"), "line 1: vertex coordinate '1.0x' is not a finite number");
  EXPECT_EQ(check("v 0 0\n"), "line 1: a vertex needs three coordinates");
  EXPECT_EQ(check(triangle + "f 1 2\n"), "line 4: a face needs at least three vertices");
  EXPECT_NE(check(triangle + "f 1 x 3\n").find("line 4: face vertex 'x'"), std::string::npos);
  EXPECT_NE(check(triangle + "f 0 1 2\n").find("line 4:"), std::string::npos);
  EXPECT_NE(check(triangle + "f 1 2 4\n").find("(1 to 3)"), std::string::npos);
  EXPECT_NE(check(triangle + "f -4 1 2\n").find("line 4:"), std::string::npos);
}
