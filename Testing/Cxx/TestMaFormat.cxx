// SPDX-License-Identifier: GPL-3.0-or-later
// .ma reading and writing: exact round trips and every malformed-file case.
#include "Format/MaFormat.h"
#include "TestHelpers.h"
#include "vtkMedialAxisReader.h"
#include "vtkMedialAxisWriter.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

using namespace medialaxis;

namespace
{
MedialMesh RandomMesh(unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-1e3, 1e3), radius(0.0, 10.0);
  MedialMesh m;
  const int nv = 200;
  for (int i = 0; i < nv; ++i)
  {
    m.Centers.push_back({ coord(rng), coord(rng) * 1e-7, coord(rng) * 1e9 });
    m.Radii.push_back(radius(rng));
  }
  // Values whose shortest decimal form is long or special.
  m.Centers[0] = { 0.1, 1.0 / 3.0, -0.0 };
  m.Radii[0] = std::numeric_limits<double>::denorm_min();
  m.Centers[1] = { std::numeric_limits<double>::max(), -std::numeric_limits<double>::min(),
    std::nextafter(1.0, 2.0) };
  m.Radii[1] = 0.0;
  for (int i = 0; i + 2 < nv; i += 3)
  {
    m.Faces.push_back({ i, i + 1, i + 2 });
  }
  m.Edges.push_back({ 0, 5 }); // a cone edge
  m.Edges.push_back({ 1, 0 }); // an edge of face 0
  return m;
}

void ExpectBitIdentical(double a, double b)
{
  EXPECT_EQ(0, std::memcmp(&a, &b, sizeof(double))) << a << " vs " << b;
}

MaReadResult Parse(const std::string& text)
{
  std::istringstream in(text);
  return ParseMa(in);
}
}

TEST(MaFormat, RoundTripIsBitExact)
{
  const MedialMesh original = RandomMesh(7);
  std::ostringstream out;
  ASSERT_TRUE(WriteMa(out, original));
  const MaReadResult read = Parse(out.str());
  ASSERT_TRUE(read.Ok()) << read.Error;
  ASSERT_EQ(read.Mesh.Centers.size(), original.Centers.size());
  for (std::size_t i = 0; i < original.Centers.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      ExpectBitIdentical(read.Mesh.Centers[i][k], original.Centers[i][k]);
    }
    ExpectBitIdentical(read.Mesh.Radii[i], original.Radii[i]);
  }
  EXPECT_EQ(read.Mesh.Faces, original.Faces);
  // Every edge is written, face edges included, each once.
  EXPECT_EQ(read.Mesh.Edges.size(), AllEdges(original).size());
  EXPECT_EQ(AllEdges(read.Mesh), AllEdges(original));
}

TEST(MaFormat, WriterListsFaceEdges)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 5, 5 } };
  m.Radii = { 1, 1, 1, 2 };
  m.Faces = { { 0, 1, 2 } };
  m.Edges = { { 2, 3 } };
  std::ostringstream out;
  ASSERT_TRUE(WriteMa(out, m));
  std::istringstream lines(out.str());
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "4 4 1");
}

TEST(MaFormat, AcceptsCommentsBlankLinesAndMatfpFlags)
{
  const auto r = Parse("# a MATFP file\n\n3 3 1 \n"
                       "v 0 0 0 0.5 1 # flags follow\n"
                       "v 1 0 0 0.5 0\n\n"
                       "v 0 1 0 0.25 2\n"
                       "e 0 1 0\ne 1 2 1\ne 2 0 0\n"
                       "f 0 1 2 0\n");
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Mesh.Centers.size(), 3u);
  EXPECT_EQ(r.Mesh.Radii[2], 0.25);
  EXPECT_EQ(r.Mesh.Faces.size(), 1u);
  EXPECT_EQ(r.Mesh.Edges.size(), 3u);
}

TEST(MaFormat, DropsDuplicateFacesAndEdges)
{
  const auto r = Parse("3 2 2\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\ne 0 1\ne 1 0\nf 0 1 2\nf 2 1 0\n");
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Mesh.Faces.size(), 1u);
  EXPECT_EQ(r.Mesh.Edges.size(), 1u);
  EXPECT_EQ(r.DuplicateFaces, 1u);
  EXPECT_EQ(r.DuplicateEdges, 1u);
}

struct MalformedCase
{
  const char* Name;
  const char* Text;
  int Line;           // line the message must name
  const char* Phrase; // words the message must contain
};

class MaMalformed : public ::testing::TestWithParam<MalformedCase>
{
};

TEST_P(MaMalformed, ErrorNamesTheLine)
{
  const MalformedCase& c = GetParam();
  const auto r = Parse(c.Text);
  ASSERT_FALSE(r.Ok()) << c.Name;
  EXPECT_NE(r.Error.find("line " + std::to_string(c.Line) + ":"), std::string::npos) << r.Error;
  EXPECT_NE(r.Error.find(c.Phrase), std::string::npos) << r.Error;
  EXPECT_TRUE(r.Mesh.Centers.empty());
  EXPECT_TRUE(r.Mesh.Faces.empty());
}

INSTANTIATE_TEST_SUITE_P(AllCases, MaMalformed,
  ::testing::Values(MalformedCase{ "Empty", "", 0, "no header" },
    MalformedCase{ "OnlyComments", "# nothing\n\n", 2, "no header" },
    MalformedCase{ "HeaderTooShort", "3 2\nv 0 0 0 1\n", 1, "three counts" },
    MalformedCase{ "HeaderNotNumber", "3 x 1\n", 1, "'x' is not a non-negative integer" },
    MalformedCase{ "HeaderNegative", "-3 0 0\n", 1, "not a non-negative integer" },
    MalformedCase{ "FewerVertices", "3 0 0\nv 0 0 0 1\nv 1 1 1 1\n", 3, "2 of the 3 vertex" },
    MalformedCase{
      "FewerFaces", "3 0 2\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 1 2\n", 5, "1 of the 2 face" },
    MalformedCase{ "MoreFacesThanAnnounced",
      "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 1 2\nf 0 2 1\n", 6, "more face lines" },
    MalformedCase{ "IndexOutOfRange", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 2\n", 4,
      "vertex index 2 is outside [0, 2)" },
    MalformedCase{ "NegativeIndex", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne -1 0\n", 4, "outside" },
    MalformedCase{ "NegativeRadius", "1 0 0\n\nv 0 0 0 -0.5\n", 3, "negative" },
    MalformedCase{ "NaNRadius", "1 0 0\nv 0 0 0 nan\n", 2, "not finite" },
    MalformedCase{ "InfCoordinate", "1 0 0\nv inf 0 0 1\n", 2, "not finite" },
    MalformedCase{ "NonNumericCoordinate", "1 0 0\nv 0 zero 0 1\n", 2, "'zero' is not a number" },
    MalformedCase{
      "NonNumericIndex", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1.5\n", 4, "not a vertex index" },
    MalformedCase{ "MissingRadius", "1 0 0\nv 0 0 0\n", 2, "needs 4 numbers" },
    MalformedCase{ "FaceRepeatsVertex", "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 1 1\n", 5,
      "repeats vertex 1" },
    MalformedCase{ "UnknownRecord", "1 0 0\nx 0 0 0 1\n", 2, "unknown record 'x'" }),
  [](const ::testing::TestParamInfo<MalformedCase>& info) { return info.param.Name; });

TEST(MaReaderWriter, VtkRoundTripIsBitExact)
{
  const MedialMesh original = RandomMesh(11);
  vtkNew<vtkPolyData> pd;
  MedialMeshToPolyData(original, pd);
  vtkNew<vtkMedialAxisWriter> writer;
  writer->SetInputData(pd);
  writer->SetFileName("roundtrip.ma");
  ASSERT_EQ(writer->Write(), 1) << writer->GetErrorMessage();

  vtkNew<vtkMedialAxisReader> reader;
  reader->SetFileName("roundtrip.ma");
  reader->Update();
  vtkPolyData* out = reader->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), pd->GetNumberOfPoints());
  vtkDataArray* r0 = pd->GetPointData()->GetArray("Radius");
  vtkDataArray* r1 = out->GetPointData()->GetArray("Radius");
  ASSERT_NE(r1, nullptr);
  EXPECT_EQ(out->GetPointData()->GetScalars(), r1); // radius is the active scalar
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    pd->GetPoint(i, a);
    out->GetPoint(i, b);
    for (int k = 0; k < 3; ++k)
    {
      ExpectBitIdentical(a[k], b[k]);
    }
    ExpectBitIdentical(r0->GetComponent(i, 0), r1->GetComponent(i, 0));
  }
  EXPECT_EQ(out->GetNumberOfPolys(), pd->GetNumberOfPolys());
  EXPECT_EQ(out->GetNumberOfLines(), 1); // the cone edge 0-5
  EXPECT_EQ(out->GetNumberOfVerts(), pd->GetNumberOfVerts());
  EXPECT_EQ(out->GetNumberOfVerts(), 2); // 198, 199 are isolated spheres
}

TEST(MaReaderWriter, MalformedFileGivesEmptyOutputAndMessage)
{
  const std::string path = test::WriteTextFile("bad.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 7\n");
  vtkNew<vtkMedialAxisReader> reader;
  vtkNew<test::ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("bad.ma: line 4:"), std::string::npos)
    << reader->GetErrorMessage();
  EXPECT_GE(errors->Count, 1);
}

TEST(MaReaderWriter, MissingFileIsReported)
{
  vtkNew<vtkMedialAxisReader> reader;
  vtkNew<test::ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName("does-not-exist.ma");
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_NE(std::string(reader->GetErrorMessage()).find("cannot open"), std::string::npos);
}

TEST(MaReaderWriter, WriterRefusesInvalidMedialMesh)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  m.Radii = { 1, 1, 1 };
  m.Faces = { { 0, 1, 2 } };
  vtkNew<vtkPolyData> pd;
  MedialMeshToPolyData(m, pd);
  pd->GetPointData()->RemoveArray("Radius");
  vtkNew<vtkMedialAxisWriter> writer;
  vtkNew<test::ErrorCatcher> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputData(pd);
  writer->SetFileName("refused.ma");
  writer->Write();
  EXPECT_NE(std::string(writer->GetErrorMessage()).find("'Radius'"), std::string::npos);
  EXPECT_GE(errors->Count, 1);
}
