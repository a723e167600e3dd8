// vtkPointCloudPCDReader and vtkPointCloudPCDWriter: hand-written known-answer files in each
// encoding (ascii, binary, binary_compressed with LZF bytes written by hand: literal runs and a
// back reference), an organized cloud with NaN points, clouds written and read back bit for bit in
// each encoding, and malformed files (lying headers, truncated or corrupt data) that must give one
// line naming the file, with an empty output.
#include "FeaturePointsTestReaders.h"
#include "vtkPointCloudPCDReader.h"
#include "vtkPointCloudPCDWriter.h"

#include "FeaturePointsTestFiles.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using fptest::Spit;

using fptest::Catcher;
using fptest::Failures;
using fptest::Folder;
using fptest::PathOf;

// The little-endian bytes of a value (the tests run on little-endian hosts: checked in main).
template <typename T>
std::string Bytes(T value)
{
  std::string out(sizeof(T), '\0');
  std::memcpy(&out[0], &value, sizeof(T));
  return out;
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Cloud;
  std::vector<std::string> Errors, Warnings;
  vtkIdType Skipped = 0, Width = 0, Height = 0;
  std::string Message;
};

ReadResult Read(const std::string& path, bool decodeColors = true)
{
  vtkNew<vtkPointCloudPCDReader> reader;
  vtkNew<Catcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->AddObserver(vtkCommand::WarningEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->SetDecodeColors(decodeColors);
  reader->Update();
  ReadResult r;
  r.Cloud = reader->GetOutput();
  r.Errors = catcher->Errors;
  r.Warnings = catcher->Warnings;
  r.Skipped = reader->GetNumberOfSkippedPoints();
  r.Width = reader->GetWidth();
  r.Height = reader->GetHeight();
  r.Message = reader->GetErrorMessage();
  return r;
}

double Component(vtkPolyData* cloud, const char* name, vtkIdType i, int c)
{
  vtkDataArray* array = cloud->GetPointData()->GetArray(name);
  return array && i < array->GetNumberOfTuples() && c < array->GetNumberOfComponents()
    ? array->GetComponent(i, c)
    : std::numeric_limits<double>::quiet_NaN();
}

// ASCII with every kind of field: a packed colour written as PCL writes it (the integer of its
// bits), a float, an unsigned short, a 3-value signed char field, a padding field, comments.
void KnownAscii()
{
  const std::string path = PathOf("known-ascii.pcd");
  Spit(path,
    "# .PCD v0.7 - Point Cloud Data file format\n"
    "VERSION 0.7\n"
    "FIELDS x y z rgb intensity ring hist _\n"
    "SIZE 4 4 4 4 4 2 1 1\n"
    "TYPE F F F F F U I U\n"
    "COUNT 1 1 1 1 1 1 3 1\n"
    "WIDTH 3\n"
    "HEIGHT 1\n"
    "VIEWPOINT 0 0 0 1 0 0 0\n"
    "POINTS 3\n"
    "DATA ascii\n"
    "1.5 -2 3.25 16711935 0.5 7 1 -2 3 pad\n" // padding values are not read (as in PCL)
    "\n"
    "0 0 1e-3 4278255360 nan 65535 -128 0 127 9\r\n"
    "-1.25e2 +4 5 255 -0.125 0 5 6 7 1");
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Errors.empty(), "known ascii: %s", r.Message.c_str());
  vtkPolyData* c = r.Cloud;
  FEATUREPOINTS_CHECK(c->GetNumberOfPoints() == 3, "known ascii: %lld points",
    static_cast<long long>(c->GetNumberOfPoints()));
  if (c->GetNumberOfPoints() != 3)
  {
    return;
  }
  FEATUREPOINTS_CHECK(c->GetPoints()->GetDataType() == VTK_FLOAT, "known ascii: float points");
  double x[3];
  c->GetPoint(0, x);
  FEATUREPOINTS_CHECK(x[0] == 1.5 && x[1] == -2 && x[2] == 3.25, "point 0: %g %g %g", x[0], x[1], x[2]);
  c->GetPoint(1, x);
  FEATUREPOINTS_CHECK(x[0] == 0 && x[1] == 0 && x[2] == static_cast<double>(1e-3f), "point 1: %g %g %g", x[0],
    x[1], x[2]);
  c->GetPoint(2, x);
  FEATUREPOINTS_CHECK(x[0] == -125 && x[1] == 4 && x[2] == 5, "point 2: %g %g %g", x[0], x[1], x[2]);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(c->GetPointData()->GetArray("RGB"));
  FEATUREPOINTS_CHECK(rgb && rgb->GetNumberOfComponents() == 3 && c->GetPointData()->GetScalars() == rgb,
    "RGB: unsigned char, 3 components, the active scalars");
  // 16711935 = 0x00FF00FF, 4278255360 = 0xFF00FF00 (the alpha byte ignored), 255 = 0x0000FF.
  const int expected[3][3] = { { 255, 0, 255 }, { 0, 255, 0 }, { 0, 0, 255 } };
  for (int i = 0; rgb && i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      FEATUREPOINTS_CHECK(rgb->GetComponent(i, k) == expected[i][k], "RGB %d %d: %g, %d expected", i, k,
        rgb->GetComponent(i, k), expected[i][k]);
    }
  }
  FEATUREPOINTS_CHECK(c->GetPointData()->GetArray("intensity") &&
      c->GetPointData()->GetArray("intensity")->GetDataType() == VTK_FLOAT,
    "intensity: float");
  FEATUREPOINTS_CHECK(Component(c, "intensity", 0, 0) == 0.5 && std::isnan(Component(c, "intensity", 1, 0)) &&
      Component(c, "intensity", 2, 0) == -0.125,
    "intensity values");
  auto* ring = vtkUnsignedShortArray::SafeDownCast(c->GetPointData()->GetArray("ring"));
  FEATUREPOINTS_CHECK(ring && ring->GetValue(0) == 7 && ring->GetValue(1) == 65535 && ring->GetValue(2) == 0,
    "ring: unsigned short 7, 65535, 0");
  auto* hist = vtkSignedCharArray::SafeDownCast(c->GetPointData()->GetArray("hist"));
  FEATUREPOINTS_CHECK(hist && hist->GetNumberOfComponents() == 3, "hist: signed char, 3 components");
  const int h[3][3] = { { 1, -2, 3 }, { -128, 0, 127 }, { 5, 6, 7 } };
  for (int i = 0; hist && i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      FEATUREPOINTS_CHECK(hist->GetComponent(i, k) == h[i][k], "hist %d %d", i, k);
    }
  }
  FEATUREPOINTS_CHECK(c->GetPointData()->GetNumberOfArrays() == 4,
    "known ascii: RGB, intensity, ring, hist and no padding array (%d arrays)",
    c->GetPointData()->GetNumberOfArrays());
  FEATUREPOINTS_CHECK(c->GetNumberOfVerts() == 3, "known ascii: vertex cells");

  // DecodeColors off: rgb kept as the float it is written as.
  ReadResult raw = Read(path, false);
  uint32_t bits = 0x00FF00FF;
  float packed;
  std::memcpy(&packed, &bits, 4);
  FEATUREPOINTS_CHECK(raw.Errors.empty() && Component(raw.Cloud, "rgb", 0, 0) == static_cast<double>(packed),
    "DecodeColors off: rgb kept as its float");
}

// Binary: a double x, integer y and z (double points), normals, and a 2-value float field.
void KnownBinary()
{
  std::string body;
  const double xs[2] = { 1234567.125, -0.5 };
  const int32_t ys[2] = { -7, 2000000000 };
  const int16_t zs[2] = { 3, -4 };
  const float normals[2][3] = { { 0, 0, 1 }, { 0.6f, 0.8f, 0 } };
  const float pair[2][2] = { { 1.5f, 2.5f }, { -3, 4e-8f } };
  for (int i = 0; i < 2; ++i)
  {
    body += Bytes(normals[i][0]) + Bytes(xs[i]) + Bytes(normals[i][1]) + Bytes(ys[i]) +
      Bytes(normals[i][2]) + Bytes(zs[i]) + Bytes(pair[i][0]) + Bytes(pair[i][1]) +
      std::string(3, '\x7f'); // padding
  }
  const std::string header = "VERSION .7\nFIELDS normal_x x normal_y y normal_z z pair _\n"
                             "SIZE 4 8 4 4 4 2 4 1\nTYPE F F F I F I F U\n"
                             "COUNT 1 1 1 1 1 1 2 3\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n";
  const std::string path = PathOf("known-binary.pcd");
  Spit(path, header + body);
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Errors.empty(), "known binary: %s", r.Message.c_str());
  vtkPolyData* c = r.Cloud;
  FEATUREPOINTS_CHECK(c->GetNumberOfPoints() == 2 && c->GetPoints()->GetDataType() == VTK_DOUBLE,
    "known binary: 2 double points");
  for (int i = 0; i < 2 && c->GetNumberOfPoints() == 2; ++i)
  {
    double x[3];
    c->GetPoint(i, x);
    FEATUREPOINTS_CHECK(x[0] == xs[i] && x[1] == ys[i] && x[2] == zs[i], "binary point %d: %.17g %g %g", i,
      x[0], x[1], x[2]);
    for (int k = 0; k < 3; ++k)
    {
      FEATUREPOINTS_CHECK(Component(c, "Normals", i, k) == normals[i][k], "binary normal %d %d", i, k);
    }
    for (int k = 0; k < 2; ++k)
    {
      FEATUREPOINTS_CHECK(Component(c, "pair", i, k) == pair[i][k], "binary pair %d %d", i, k);
    }
  }
  FEATUREPOINTS_CHECK(c->GetPointData()->GetNormals() == c->GetPointData()->GetArray("Normals"),
    "known binary: Normals are the active normals");
  FEATUREPOINTS_CHECK(c->GetPointData()->GetNumberOfArrays() == 2, "known binary: Normals, pair");

  // Cut in the second point: an error, no partial cloud.
  const std::string cut = PathOf("cut-binary.pcd");
  Spit(cut, header + body.substr(0, body.size() - 5));
  ReadResult bad = Read(cut);
  FEATUREPOINTS_CHECK(bad.Errors.size() == 1 && bad.Cloud->GetNumberOfPoints() == 0 &&
      bad.Message.find(cut + ": the file ends in point 2 of 2") == 0,
    "cut binary: %s", bad.Message.c_str());
}

// Values below the smallest of their type keep their rounding (a zero of their sign), whatever
// their exponent or digits, as the text and PLY readers read them: "1e-5000" (beyond long double
// too) was refused as out of range.
void Underflow()
{
  const std::string path = PathOf("underflow.pcd");
  Spit(path,
    "VERSION 0.7\nFIELDS x y z s\nSIZE 8 8 8 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 2\n"
    "HEIGHT 1\nPOINTS 2\nDATA ascii\n1e-400 -1e-5000 0." +
      std::string(400, '0') + "1 1e-50\n1 2 3 -1e-5000\n");
  ReadResult r = Read(path);
  auto* s = vtkFloatArray::SafeDownCast(r.Cloud->GetPointData()->GetArray("s"));
  double x[3] = { 1, 1, 1 };
  if (r.Cloud->GetNumberOfPoints() == 2)
  {
    r.Cloud->GetPoint(0, x);
  }
  FEATUREPOINTS_CHECK(r.Errors.empty() && s && s->GetNumberOfTuples() == 2 && x[0] == 0.0 &&
      x[1] == 0.0 && std::signbit(x[1]) && x[2] == 0.0 && s->GetValue(0) == 0.0f &&
      s->GetValue(1) == 0.0f && std::signbit(s->GetValue(1)),
    "underflow: %s; (%g %g %g)", r.Message.c_str(), x[0], x[1], x[2]);
}

// binary_compressed with LZF bytes written by hand. The fields one after the other: x0 x1 y0 y1
// z0 z1 (24 bytes, z1 == z0); the LZF stream is a literal run of 20 bytes (control byte 19) and a
// back reference of 4 bytes at distance 4 (control byte (4 - 2) << 5, offset byte 4 - 1).
void KnownCompressed()
{
  const float x[2] = { 1.0f, -2.5f }, y[2] = { 100.25f, 3.0f }, z = 7.75f;
  std::string literal = Bytes(x[0]) + Bytes(x[1]) + Bytes(y[0]) + Bytes(y[1]) + Bytes(z);
  std::string lzf = std::string(1, char(19)) + literal + std::string(1, char(0x40)) + char(3);
  const std::string header =
    "# hand-written\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
    "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\nDATA binary_compressed\n";
  const std::string path = PathOf("known-compressed.pcd");
  Spit(path, header + Bytes(uint32_t(lzf.size())) + Bytes(uint32_t(24)) + lzf);
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Errors.empty(), "known compressed: %s", r.Message.c_str());
  FEATUREPOINTS_CHECK(r.Cloud->GetNumberOfPoints() == 2, "known compressed: 2 points");
  for (int i = 0; i < 2 && r.Cloud->GetNumberOfPoints() == 2; ++i)
  {
    double p[3];
    r.Cloud->GetPoint(i, p);
    FEATUREPOINTS_CHECK(p[0] == x[i] && p[1] == y[i] && p[2] == z, "compressed point %d: %g %g %g", i, p[0],
      p[1], p[2]);
  }

  struct Case
  {
    const char* Name;
    std::string Bytes;
    const char* Expected;
  };
  const std::string one = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH ";
  const Case cases[] = {
    { "lying-uncompressed.pcd", header + Bytes(uint32_t(lzf.size())) + Bytes(uint32_t(36)) + lzf,
      "the compressed data declares 36 bytes, but 2 points of 12 bytes are 24" },
    { "long-compressed.pcd", header + Bytes(uint32_t(1000)) + Bytes(uint32_t(24)) + lzf,
      "the file ends in the compressed data (1000 bytes" },
    // The back reference reaches before the start of the output.
    { "corrupt-compressed.pcd",
      header + Bytes(uint32_t(lzf.size())) + Bytes(uint32_t(24)) + std::string(1, char(19)) +
        literal + std::string(1, char(0x40)) + char(30),
      "the compressed data is corrupt" },
    // 10^8 points (1.2 GB) from 23 bytes: refused before any allocation.
    { "bomb-compressed.pcd",
      one + "100000000\nHEIGHT 1\nPOINTS 100000000\nDATA binary_compressed\n" +
        Bytes(uint32_t(lzf.size())) + Bytes(uint32_t(1200000000)) + lzf,
      "the compressed data cannot hold 100000000 points" },
    { "short-sizes.pcd", header + "\x17\x00", "the file ends in the sizes of the compressed data" },
    // No LZF byte for a point of 3 bytes: within the bound of 8 bytes, but nothing to decompress.
    { "empty-compressed.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 1 1 1\nTYPE U U U\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n"
      "POINTS 1\nDATA binary_compressed\n" +
        Bytes(uint32_t(0)) + Bytes(uint32_t(3)),
      "the compressed data declares 0 bytes (at byte 108) for 1 points of 3 bytes (3 bytes "
      "uncompressed)" },
  };
  for (const Case& c : cases)
  {
    const std::string bad = PathOf(c.Name);
    Spit(bad, c.Bytes);
    ReadResult b = Read(bad);
    FEATUREPOINTS_CHECK(b.Errors.size() == 1 && b.Cloud->GetNumberOfPoints() == 0 &&
        b.Message.find(bad + ": ") == 0 && b.Message.find(c.Expected) != std::string::npos &&
        b.Message.find('\n') == std::string::npos,
      "%s: [%s], expected [%s]", c.Name, b.Message.c_str(), c.Expected);
  }
  // Bytes after the block: a point's worth (12) is data the header does not declare (was
  // ignored), as in binary data; a newline is none.
  const std::string block = header + Bytes(uint32_t(lzf.size())) + Bytes(uint32_t(24)) + lzf;
  const std::string trailing = PathOf("trailing-compressed.pcd");
  Spit(trailing, block + std::string(12, 'x'));
  ReadResult t = Read(trailing);
  const std::string expected = trailing + ": the compressed data (" + std::to_string(lzf.size()) +
    " bytes from byte " +
    std::to_string(header.size() + 8) + ") ends at byte " + std::to_string(block.size()) +
    ", but 12 more bytes follow it (the file has " + std::to_string(block.size() + 12) +
    " bytes): a wrong compressed size, or data the header does not declare";
  FEATUREPOINTS_CHECK(t.Errors.size() == 1 && t.Cloud->GetNumberOfPoints() == 0 &&
      t.Message == expected,
    "trailing compressed: [%s], expected [%s]", t.Message.c_str(), expected.c_str());
  const std::string newline = PathOf("newline-compressed.pcd");
  Spit(newline, block + "\n");
  ReadResult n = Read(newline);
  FEATUREPOINTS_CHECK(n.Errors.empty() && n.Cloud->GetNumberOfPoints() == 2,
    "compressed data and a newline: %s", n.Message.c_str());
}

// An organized cloud (2 x 3) whose invalid points have NaN coordinates: skipped, and counted.
void Organized()
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float points[6][4] = { { 0, 0, 0, 10 }, { nan, nan, nan, 11 }, { 1, 0, 0, 12 },
    { 0, 1, nan, 13 }, { 1, 1, 1, 14 }, { 2, 2, 2, 15 } };
  std::string body;
  for (const auto& p : points)
  {
    body += Bytes(p[0]) + Bytes(p[1]) + Bytes(p[2]) + Bytes(p[3]);
  }
  const std::string path = PathOf("organized.pcd");
  Spit(path,
    "VERSION 0.7\nFIELDS x y z curvature\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
    "WIDTH 3\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA binary\n" +
      body);
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Errors.empty() && r.Cloud->GetNumberOfPoints() == 4 && r.Skipped == 2 &&
      r.Width == 3 && r.Height == 2,
    "organized: %lld points, %lld skipped, %lld x %lld: %s",
    static_cast<long long>(r.Cloud->GetNumberOfPoints()), static_cast<long long>(r.Skipped),
    static_cast<long long>(r.Width), static_cast<long long>(r.Height), r.Message.c_str());
  FEATUREPOINTS_CHECK(
    r.Warnings.size() == 1 && r.Warnings[0].find("2 of 6 points skipped") != std::string::npos,
    "organized: one warning with the count");
  const double kept[4] = { 10, 12, 14, 15 };
  for (int i = 0; i < 4 && r.Cloud->GetNumberOfPoints() == 4; ++i)
  {
    FEATUREPOINTS_CHECK(Component(r.Cloud, "curvature", i, 0) == kept[i], "organized: curvature %d", i);
  }
  FEATUREPOINTS_CHECK(r.Cloud->GetNumberOfVerts() == 4, "organized: 4 vertex cells");
  // The file's index of each point read, in field data; binary data has no lines.
  const vtkIdType fileIds[4] = { 0, 2, 4, 5 };
  auto* ids = vtkIdTypeArray::SafeDownCast(r.Cloud->GetFieldData()->GetArray("FilePointIds"));
  FEATUREPOINTS_CHECK(ids && ids->GetNumberOfValues() == 4 && ids->GetValue(0) == fileIds[0] &&
      ids->GetValue(1) == fileIds[1] && ids->GetValue(2) == fileIds[2] &&
      ids->GetValue(3) == fileIds[3] && !r.Cloud->GetFieldData()->GetArray("FileLines"),
    "organized: FilePointIds 0 2 4 5, no FileLines");
  // Through vtkPointCloudIO: a cloud without the invalid points, no error, the ids kept.
  std::string error;
  vtkSmartPointer<vtkPointSet> io = vtkPointCloudIO::Read(path, error);
  FEATUREPOINTS_CHECK(
    io && io->GetNumberOfPoints() == 4, "organized through vtkPointCloudIO: %s", error.c_str());
  FEATUREPOINTS_CHECK(io && io->GetFieldData()->GetArray("FilePointIds"),
    "organized through vtkPointCloudIO: FilePointIds kept");

  // ASCII, with blank lines among the points: each point's line as the file numbers it.
  const std::string asciiPath = PathOf("organized-ascii.pcd");
  Spit(asciiPath,
    "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 2\nPOINTS 6\n"
    "DATA ascii\n0 0 0\nnan nan nan\n\n1 0 0\n0 1 nan\n\n\n1 1 1\n2 2 2\n");
  ReadResult a = Read(asciiPath);
  auto* asciiIds =
    vtkIdTypeArray::SafeDownCast(a.Cloud->GetFieldData()->GetArray("FilePointIds"));
  auto* lines = vtkIdTypeArray::SafeDownCast(a.Cloud->GetFieldData()->GetArray("FileLines"));
  const vtkIdType fileLines[4] = { 9, 12, 16, 17 };
  bool same = asciiIds && lines && asciiIds->GetNumberOfValues() == 4 &&
    lines->GetNumberOfValues() == 4;
  for (int i = 0; same && i < 4; ++i)
  {
    same = asciiIds->GetValue(i) == fileIds[i] && lines->GetValue(i) == fileLines[i];
  }
  FEATUREPOINTS_CHECK(a.Errors.empty() && same,
    "organized ASCII: FilePointIds 0 2 4 5 on lines 9 12 16 17: %s", a.Message.c_str());

  // Without a skipped point there is nothing to number.
  const std::string wholePath = PathOf("whole.pcd");
  Spit(wholePath, "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nPOINTS 2\n"
                  "DATA ascii\n0 0 0\n1 1 1\n");
  ReadResult w = Read(wholePath);
  FEATUREPOINTS_CHECK(w.Errors.empty() && w.Cloud->GetNumberOfPoints() == 2 &&
      w.Cloud->GetFieldData()->GetNumberOfArrays() == 0,
    "whole: no field data: %s", w.Message.c_str());
}

vtkSmartPointer<vtkPolyData> RandomCloud(vtkIdType n, bool doublePoints)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1000.0, 1000.0);
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("vtkOriginalPointIds");
  ids->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> pair;
  pair->SetName("two words");
  pair->SetNumberOfComponents(2);
  pair->SetNumberOfTuples(n);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  label->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, u(rng), u(rng), u(rng) * 1e-3);
    normals->SetTuple3(i, u(rng), u(rng), u(rng));
    rgb->SetTuple3(i, i % 256, (7 * i) % 256, 255);
    rgba->SetTuple4(i, 255, i % 256, 0, (3 * i) % 256);
    ids->SetValue(i, (vtkIdType(1) << 40) + i); // beyond float and 32-bit int
    pair->SetTuple2(i, u(rng) * 1e-300, u(rng) * 1e300);
    label->SetValue(i, static_cast<int>(i) - 100);
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->GetPointData()->SetNormals(normals);
  cloud->GetPointData()->AddArray(rgb);
  cloud->GetPointData()->AddArray(rgba);
  cloud->GetPointData()->AddArray(ids);
  cloud->GetPointData()->AddArray(pair);
  cloud->GetPointData()->AddArray(label);
  return cloud;
}

// Written in each encoding and read back: every value the same, bit for bit.
void RoundTrips()
{
  const char* names[] = { "ascii", "binary", "binary_compressed" };
  for (bool doublePoints : { false, true })
  {
    vtkSmartPointer<vtkPolyData> cloud = RandomCloud(3000, doublePoints);
    for (int format = 0; format < 3; ++format)
    {
      const std::string path = PathOf(std::string("round-trip-") + names[format] +
        (doublePoints ? "-double" : "-float") + ".pcd");
      vtkNew<vtkPointCloudPCDWriter> writer;
      writer->SetInputData(cloud);
      writer->SetFileName(path.c_str());
      writer->SetDataFormat(format);
      FEATUREPOINTS_CHECK(writer->Write() == 1 && writer->GetErrorCode() == vtkErrorCode::NoError,
        "write %s: %s", path.c_str(), writer->GetErrorMessage().c_str());
      std::ifstream in(path);
      std::string line;
      bool data = false;
      while (std::getline(in, line))
      {
        if (line.compare(0, 5, "DATA ") == 0)
        {
          data = line == std::string("DATA ") + names[format];
          break;
        }
      }
      FEATUREPOINTS_CHECK(data, "%s: DATA %s", path.c_str(), names[format]);
      ReadResult r = Read(path);
      FEATUREPOINTS_CHECK(r.Errors.empty(), "read %s: %s", path.c_str(), r.Message.c_str());
      vtkPolyData* back = r.Cloud;
      FEATUREPOINTS_CHECK(
        back->GetNumberOfPoints() == cloud->GetNumberOfPoints(), "%s: points", path.c_str());
      FEATUREPOINTS_CHECK(back->GetPoints()->GetDataType() == (doublePoints ? VTK_DOUBLE : VTK_FLOAT),
        "%s: point type", path.c_str());
      if (back->GetNumberOfPoints() != cloud->GetNumberOfPoints())
      {
        continue;
      }
      long differences = 0;
      for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
      {
        double a[3], b[3];
        cloud->GetPoint(i, a);
        back->GetPoint(i, b);
        differences += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
      }
      for (const char* array :
        { "Normals", "RGB", "RGBA", "vtkOriginalPointIds", "two_words", "label" })
      {
        vtkDataArray* original =
          cloud->GetPointData()->GetArray(std::string(array) == "two_words" ? "two words" : array);
        vtkDataArray* read = back->GetPointData()->GetArray(array);
        if (!read || read->GetNumberOfComponents() != original->GetNumberOfComponents() ||
          read->GetNumberOfTuples() != original->GetNumberOfTuples())
        {
          FEATUREPOINTS_CHECK(false, "%s: array %s missing or of another shape", path.c_str(), array);
          continue;
        }
        FEATUREPOINTS_CHECK(read->GetDataType() == original->GetDataType() ||
            (original->GetDataType() == VTK_ID_TYPE && read->GetDataType() == VTK_LONG_LONG),
          "%s: array %s of type %s", path.c_str(), array, read->GetDataTypeAsString());
        for (vtkIdType i = 0; i < original->GetNumberOfValues(); ++i)
        {
          const int k = original->GetNumberOfComponents();
          differences += original->GetComponent(i / k, static_cast<int>(i % k)) !=
            read->GetComponent(i / k, static_cast<int>(i % k));
        }
      }
      auto* ids =
        vtkIdTypeArray::SafeDownCast(cloud->GetPointData()->GetArray("vtkOriginalPointIds"));
      vtkDataArray* readIds = back->GetPointData()->GetArray("vtkOriginalPointIds");
      FEATUREPOINTS_CHECK(readIds &&
          static_cast<long long>(readIds->GetComponent(2999, 0)) ==
            static_cast<long long>(ids->GetValue(2999)),
        "%s: 64-bit ids exact", path.c_str());
      FEATUREPOINTS_CHECK(differences == 0, "%s: %ld values differ", path.c_str(), differences);
    }
  }

  // An empty cloud in each encoding.
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPoints> none;
  empty->SetPoints(none);
  for (int format = 0; format < 3; ++format)
  {
    const std::string path = PathOf(std::string("empty-") + names[format] + ".pcd");
    vtkNew<vtkPointCloudPCDWriter> writer;
    writer->SetInputData(empty);
    writer->SetFileName(path.c_str());
    writer->SetDataFormat(format);
    writer->Write();
    ReadResult r = Read(path);
    FEATUREPOINTS_CHECK(r.Errors.empty() && r.Cloud->GetNumberOfPoints() == 0, "empty %s: %s", names[format],
      r.Message.c_str());
  }

  // Through vtkPointCloudIO: .pcd is written binary, with the feature arrays as fields.
  vtkSmartPointer<vtkPolyData> cloud = RandomCloud(500, false);
  std::string error;
  const std::string path = PathOf("through-io.pcd");
  FEATUREPOINTS_CHECK(
    vtkPointCloudIO::Write(cloud, path, error), "vtkPointCloudIO::Write: %s", error.c_str());
  vtkSmartPointer<vtkPointSet> back = vtkPointCloudIO::Read(path, error);
  FEATUREPOINTS_CHECK(back && back->GetNumberOfPoints() == 500 && back->GetPointData()->GetArray("label") &&
      back->GetPointData()->GetArray("label")->GetComponent(499, 0) == 399,
    "vtkPointCloudIO::Read: %s", error.c_str());
}

// Malformed files: one line naming the file and the problem, an empty output.
void Malformed()
{
  const std::string xyz = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  struct Case
  {
    const char* Name;
    std::string Bytes;
    const char* Expected;
  };
  const Case cases[] = {
    { "not-pcd.pcd", "ply\nformat ascii 1.0\n", "not a PCD file" },
    { "no-data.pcd", xyz + "WIDTH 1\nHEIGHT 1\nPOINTS 1\n", "the header ends without a DATA line" },
    { "points-lie.pcd", xyz + "WIDTH 3\nHEIGHT 1\nPOINTS 5\nDATA ascii\n1 2 3\n",
      "POINTS 5 is not WIDTH x HEIGHT (3 x 1)" },
    { "size-count.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
      ":3: SIZE has 2 values for 3 fields" },
    { "type-unknown.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
      "field 'z': unknown type 'Q' of size 4" },
    { "float-2.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
      "unknown type 'F' of size 2" },
    { "no-z.pcd",
      "VERSION 0.7\nFIELDS x y w\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
      "no z field" },
    { "huge-binary.pcd",
      xyz + "WIDTH 1000000000000\nHEIGHT 1\nPOINTS 1000000000000\nDATA binary\n" +
        std::string(120, '\0'),
      "the file ends in point 11 of 1000000000000" },
    { "more-binary.pcd", xyz + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n" + std::string(60, '\0'),
      "the header declares 2 points of 12 bytes, but 60 bytes of binary data follow it (5 points)" },
    { "huge-ascii.pcd", xyz + "WIDTH 4000000000\nPOINTS 4000000000\nDATA ascii\n1 2 3\n4 5 6\n",
      "the header declares 4000000000 points, but the 12 bytes of ASCII data after it can hold at "
      "most 2" },
    { "few-values.pcd", xyz + "WIDTH 2\nPOINTS 2\nDATA ascii\n1 2 3\n4 5    \n",
      ":10: too few values for point 2 of 2 (2, 3 expected)" },
    { "not-number.pcd", xyz + "WIDTH 2\nPOINTS 2\nDATA ascii\n1 2 3\n4 five 6\n",
      ":10: 'five' is not a number in field 'y' of point 2 of 2" },
    { "short-ascii.pcd", xyz + "WIDTH 3\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n7 8 9",
      "" }, // exactly enough: must read (checked below)
    { "more-ascii.pcd", xyz + "WIDTH 2\nPOINTS 2\nDATA ascii\n1 2 3\n4 5 6\n\n7 8 9\n",
      ":12: data after the 2 points that POINTS declares" },
    { "cut-ascii.pcd", xyz + "WIDTH 3\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n\n\n\n\n\n\n",
      "the file ends in point 3 of 3" },
    { "int-range.pcd",
      "VERSION 0.7\nFIELDS x y z i\nSIZE 4 4 4 1\nTYPE F F F U\nWIDTH 1\nPOINTS 1\nDATA "
      "ascii\n1 2 3 256\n",
      "'256' is out of range for U 1" },
    { "data-unknown.pcd", xyz + "WIDTH 1\nPOINTS 1\nDATA binary_zipped\n",
      "unknown DATA encoding 'binary_zipped'" },
    { "two-x.pcd",
      "VERSION 0.7\nFIELDS x y z x\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 "
      "2 3 4\n",
      "second field named 'x'" },
    { "overflow.pcd", xyz + "WIDTH 4294967296\nHEIGHT 4294967296\nDATA binary\n",
      ":7: WIDTH 4294967296 x HEIGHT 4294967296 overflows" },
    { "count-x.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 2 1 1\nWIDTH 1\nDATA ascii\n"
      "1 1 2 3\n",
      ":5: field x has COUNT 2, 1 expected" },
    { "count-zero.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 0 1\nWIDTH 1\nDATA ascii\n1 3\n",
      "COUNT '0' is not an integer from 1" },
    { "empty.pcd", "", "empty file" },
  };
  for (const Case& c : cases)
  {
    const std::string path = PathOf(c.Name);
    Spit(path, c.Bytes);
    ReadResult r = Read(path);
    if (!*c.Expected)
    {
      FEATUREPOINTS_CHECK(
        r.Errors.empty() && r.Cloud->GetNumberOfPoints() == 3, "%s: %s", c.Name, r.Message.c_str());
      continue;
    }
    FEATUREPOINTS_CHECK(r.Errors.size() == 1 && r.Cloud->GetNumberOfPoints() == 0 &&
        r.Message.find(path) == 0 && r.Message.find(c.Expected) != std::string::npos &&
        r.Message.find('\n') == std::string::npos,
      "%s: [%s], expected [%s]", c.Name, r.Message.c_str(), c.Expected);
    // Through vtkPointCloudIO the same line (the empty file is refused there before the reader).
    std::string error;
    vtkSmartPointer<vtkPointSet> io = vtkPointCloudIO::Read(path, error);
    FEATUREPOINTS_CHECK(!io && error.find(path + ":") == 0 && error.find('\n') == std::string::npos &&
        (c.Bytes.empty() || error == r.Message),
      "%s through vtkPointCloudIO: [%s]", c.Name, error.c_str());
  }
}
} // namespace

int TestPointCloudPCD(int argc, char* argv[])
{
  Folder = argc > 1 ? argv[1] : ".";
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  if (first != 1)
  {
    std::printf("the hand-written files of this test are little-endian: skipped on this host\n");
    return EXIT_SUCCESS;
  }
  KnownAscii();
  KnownBinary();
  KnownCompressed();
  Underflow();
  Organized();
  RoundTrips();
  Malformed();
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
