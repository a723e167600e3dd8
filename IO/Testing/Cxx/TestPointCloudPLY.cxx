// vtkPointCloudPLYWriter and vtkPointCloudPLYReader: clouds written and read back bit for bit in
// both formats, hand-written files (ASCII, big-endian binary, faces around the vertices), and
// malformed or truncated files that must give an error naming the file, with an empty output.
#include "FeaturePointsTestReaders.h"
#include "vtkPointCloudPLYReader.h"
#include "vtkPointCloudPLYWriter.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedShortArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using fptest::Catcher;
using fptest::Failures;
using fptest::Folder;
using fptest::PathOf;

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// Same value, sign of zero included.
bool Same(double a, double b)
{
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Data;
  std::string Message;
  unsigned long Code;
  size_t Errors;
  size_t Warnings;
};

ReadResult Read(const std::string& path, vtkPointCloudPLYReader* reuse = nullptr)
{
  vtkSmartPointer<vtkPointCloudPLYReader> reader = reuse;
  if (!reader)
  {
    reader = vtkSmartPointer<vtkPointCloudPLYReader>::New();
  }
  vtkNew<Catcher> catcher;
  const unsigned long e = reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  const unsigned long w = reader->AddObserver(vtkCommand::WarningEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->Update();
  reader->RemoveObserver(e);
  reader->RemoveObserver(w);
  return { reader->GetOutput(), reader->GetErrorMessage(), reader->GetErrorCode(),
    catcher->Errors.size(), catcher->Warnings.size() };
}

struct WriteResult
{
  std::string Message;
  unsigned long Code;
  size_t Errors;
  size_t Warnings;
};

WriteResult Write(vtkDataObject* data, const std::string& path, bool ascii)
{
  vtkNew<vtkPointCloudPLYWriter> writer;
  vtkNew<Catcher> catcher;
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  writer->AddObserver(vtkCommand::WarningEvent, catcher);
  // vtkAlgorithm's setter: vtkWriter::SetInputData is in VTK::IOCore, which the test does not
  // link (the writer itself is called through virtual functions only).
  writer->SetInputDataObject(0, data);
  writer->SetFileName(path.c_str());
  if (ascii)
  {
    writer->SetFileTypeToASCII();
  }
  writer->Write();
  return { writer->GetErrorMessage(), writer->GetErrorCode(), catcher->Errors.size(),
    catcher->Warnings.size() };
}

template <typename ArrayT>
ArrayT* AddArray(vtkPolyData* data, const char* name, int components, vtkIdType n)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  data->GetPointData()->AddArray(array);
  return array;
}

// A seeded random cloud with one array of each kind the writer handles, extreme values first.
vtkSmartPointer<vtkPolyData> MakeCloud(vtkIdType n, unsigned seed, bool doublePoints)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-100.0, 100.0);
  std::uniform_int_distribution<int> byte(0, 255);
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, uniform(rng), uniform(rng), uniform(rng) * 1e-7);
  }
  cloud->SetPoints(points);

  const float floatEdges[] = { std::numeric_limits<float>::max(),
    std::numeric_limits<float>::denorm_min(), -0.0f, std::numeric_limits<float>::lowest(), 0.1f };
  const double doubleEdges[] = { std::numeric_limits<double>::max(),
    std::numeric_limits<double>::denorm_min(), -0.0, 1e-300, 0.1 };
  auto* f = AddArray<vtkFloatArray>(cloud, "F", 1, n);
  auto* normals = AddArray<vtkFloatArray>(cloud, "Normals", 3, n);
  auto* mask = AddArray<vtkUnsignedCharArray>(cloud, "FeatureMask", 1, n);
  auto* rgb = AddArray<vtkUnsignedCharArray>(cloud, "RGB", 3, n);
  auto* ssi = AddArray<vtkDoubleArray>(cloud, "SSI", 1, n);
  auto* ids = AddArray<vtkIdTypeArray>(cloud, "vtkOriginalPointIds", 1, n);
  auto* big = AddArray<vtkIdTypeArray>(cloud, "BigIds", 1, n);
  auto* label = AddArray<vtkIntArray>(cloud, "Label", 1, n);
  auto* pair = AddArray<vtkDoubleArray>(cloud, "Pair", 2, n);
  auto* score = AddArray<vtkFloatArray>(cloud, "my score", 1, n);
  auto* s = AddArray<vtkShortArray>(cloud, "S", 1, n);
  auto* us = AddArray<vtkUnsignedShortArray>(cloud, "US", 1, n);
  auto* ui = AddArray<vtkUnsignedIntArray>(cloud, "UI", 1, n);
  auto* sc = AddArray<vtkSignedCharArray>(cloud, "SC", 1, n);
  auto* x = AddArray<vtkIntArray>(cloud, "x", 1, n); // clashes with the coordinate x
  vtkNew<vtkStringArray> text;                       // not numeric: skipped
  text->SetName("Text");
  text->SetNumberOfValues(n);
  cloud->GetPointData()->AddArray(text);
  cloud->GetPointData()->SetNormals(normals);
  for (vtkIdType i = 0; i < n; ++i)
  {
    f->SetValue(i, i < 5 ? floatEdges[i] : static_cast<float>(uniform(rng)));
    double v[3] = { uniform(rng), uniform(rng), uniform(rng) };
    const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    normals->SetTuple3(i, v[0] / norm, v[1] / norm, v[2] / norm);
    mask->SetValue(i, static_cast<unsigned char>(byte(rng) & 1));
    rgb->SetTuple3(i, byte(rng), byte(rng), byte(rng));
    ssi->SetValue(i, i < 5 ? doubleEdges[i] : uniform(rng) * 1e-3);
    ids->SetValue(i, 3 * i + 7);
    big->SetValue(i, (vtkIdType(1) << 40) + i);
    label->SetValue(i,
      i == 0 ? std::numeric_limits<int>::lowest()
             : (i == 1 ? std::numeric_limits<int>::max() : static_cast<int>(uniform(rng) * 1e7)));
    pair->SetTuple2(i, uniform(rng), i == 0 ? -doubleEdges[0] : uniform(rng) * 1e200);
    score->SetValue(i, static_cast<float>(uniform(rng)));
    s->SetValue(i, static_cast<short>(i == 0 ? -32768 : byte(rng) * 100 - 12800));
    us->SetValue(i, static_cast<unsigned short>(i == 0 ? 65535 : byte(rng) * 200));
    ui->SetValue(i, i == 0 ? 4294967295u : static_cast<unsigned>(byte(rng)) * 16000000u);
    sc->SetValue(i, static_cast<signed char>(byte(rng) - 128));
    x->SetValue(i, static_cast<int>(i) - 50);
    text->SetValue(i, "t");
  }
  return cloud;
}

// Array of the written cloud, array read back, and the type it must come back as.
struct Expected
{
  const char* In;
  const char* Out;
  int Type;
};
const Expected CloudArrays[] = { { "F", "F", VTK_FLOAT }, { "Normals", "Normals", VTK_FLOAT },
  { "FeatureMask", "FeatureMask", VTK_UNSIGNED_CHAR }, { "RGB", "RGB", VTK_UNSIGNED_CHAR },
  { "SSI", "SSI", VTK_DOUBLE }, { "vtkOriginalPointIds", "vtkOriginalPointIds", VTK_INT },
  { "BigIds", "BigIds", VTK_DOUBLE }, { "Label", "Label", VTK_INT }, { "Pair", "Pair", VTK_DOUBLE },
  { "my score", "my_score", VTK_FLOAT }, { "S", "S", VTK_SHORT },
  { "US", "US", VTK_UNSIGNED_SHORT }, { "UI", "UI", VTK_UNSIGNED_INT },
  { "SC", "SC", VTK_SIGNED_CHAR }, { "x", "x_2", VTK_INT } };

// The cloud read back equals the cloud written: points bit for bit, every array value exactly.
void Compare(const std::string& what, vtkPolyData* in, vtkPolyData* out)
{
  const vtkIdType n = in->GetNumberOfPoints();
  FEATUREPOINTS_CHECK(out->GetNumberOfPoints() == n, "%s: %lld points read, %lld written", what.c_str(),
    static_cast<long long>(out->GetNumberOfPoints()), static_cast<long long>(n));
  if (out->GetNumberOfPoints() != n)
  {
    return;
  }
  const int type = in->GetPoints()->GetDataType();
  FEATUREPOINTS_CHECK(out->GetPoints()->GetDataType() == type, "%s: points of type %d, %d written",
    what.c_str(), out->GetPoints()->GetDataType(), type);
  if (n > 0 && out->GetPoints()->GetDataType() == type)
  {
    const size_t bytes = static_cast<size_t>(3 * n) * (type == VTK_FLOAT ? 4 : 8);
    FEATUREPOINTS_CHECK(std::memcmp(in->GetPoints()->GetVoidPointer(0), out->GetPoints()->GetVoidPointer(0),
                bytes) == 0,
      "%s: coordinates differ", what.c_str());
  }
  vtkPointData* pd = out->GetPointData();
  const int expectedArrays = static_cast<int>(sizeof(CloudArrays) / sizeof(CloudArrays[0]));
  FEATUREPOINTS_CHECK(pd->GetNumberOfArrays() == expectedArrays, "%s: %d arrays read, %d expected",
    what.c_str(), pd->GetNumberOfArrays(), expectedArrays);
  for (const Expected& e : CloudArrays)
  {
    vtkDataArray* a = in->GetPointData()->GetArray(e.In);
    vtkDataArray* b = pd->GetArray(e.Out);
    FEATUREPOINTS_CHECK(b, "%s: no array %s", what.c_str(), e.Out);
    if (!b)
    {
      continue;
    }
    FEATUREPOINTS_CHECK(b->GetDataType() == e.Type, "%s: %s of type %s, %d expected", what.c_str(), e.Out,
      b->GetDataTypeAsString(), e.Type);
    FEATUREPOINTS_CHECK(
      b->GetNumberOfComponents() == a->GetNumberOfComponents() && b->GetNumberOfTuples() == n,
      "%s: %s has %d components and %lld tuples", what.c_str(), e.Out, b->GetNumberOfComponents(),
      static_cast<long long>(b->GetNumberOfTuples()));
    if (b->GetNumberOfComponents() != a->GetNumberOfComponents() || b->GetNumberOfTuples() != n)
    {
      continue;
    }
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      {
        differ += Same(a->GetComponent(i, c), b->GetComponent(i, c)) ? 0 : 1;
      }
    }
    FEATUREPOINTS_CHECK(differ == 0, "%s: %lld values of %s differ", what.c_str(),
      static_cast<long long>(differ), e.Out);
  }
  FEATUREPOINTS_CHECK(pd->GetNormals() && pd->GetNormals() == pd->GetArray("Normals"),
    "%s: Normals are not the active normals", what.c_str());
  FEATUREPOINTS_CHECK(pd->GetScalars() && pd->GetScalars() == pd->GetArray("RGB"),
    "%s: RGB is not the active scalars", what.c_str());
  FEATUREPOINTS_CHECK(out->GetNumberOfVerts() == n && out->GetNumberOfCells() == n,
    "%s: %lld vertex cells for %lld points", what.c_str(),
    static_cast<long long>(out->GetNumberOfVerts()), static_cast<long long>(n));
}

void TestRoundTrips()
{
  for (const bool doublePoints : { false, true })
  {
    for (const bool ascii : { false, true })
    {
      const std::string what = std::string(ascii ? "ASCII" : "binary") +
        (doublePoints ? ", double points" : ", float points");
      const std::string path = PathOf(std::string("roundtrip_") + (ascii ? "ascii" : "binary") +
        (doublePoints ? "_double" : "_float") + ".ply");
      vtkSmartPointer<vtkPolyData> cloud = MakeCloud(300, doublePoints ? 11 : 7, doublePoints);
      const WriteResult w = Write(cloud, path, ascii);
      FEATUREPOINTS_CHECK(w.Code == 0 && w.Message.empty() && w.Errors == 0, "%s: write error %s",
        what.c_str(), w.Message.c_str());
      FEATUREPOINTS_CHECK(w.Warnings == 1, "%s: %zu warnings, 1 expected (the string array)", what.c_str(),
        w.Warnings);

      const std::string bytes = fptest::Slurp(path);
      const std::string start = std::string("ply\nformat ") +
        (ascii ? "ascii" : "binary_little_endian") +
        " 1.0\ncomment written by FeaturePoints (vtkPointCloudPLYWriter)\nelement vertex 300\n";
      FEATUREPOINTS_CHECK(bytes.compare(0, start.size(), start) == 0, "%s: header starts with %s",
        what.c_str(), bytes.substr(0, start.size()).c_str());
      const char* coordinate = doublePoints ? "double" : "float";
      for (const std::string& line :
        { std::string("property ") + coordinate + " x\n", std::string("property float nx\n"),
          std::string("property uchar red\n"), std::string("property int vtkOriginalPointIds\n"),
          std::string("property double BigIds\n"), std::string("property double Pair_1\n"),
          std::string("property float my_score\n"), std::string("property int x_2\n"),
          std::string("property char SC\n") })
      {
        FEATUREPOINTS_CHECK(Contains(bytes, line), "%s: no header line %s", what.c_str(), line.c_str());
      }
      if (!ascii)
      {
        // x y z, nx ny nz, RGB, then the arrays in order: F 4, FeatureMask 1, SSI 8, ids 4,
        // BigIds 8, Label 4, Pair 16, my_score 4, S 2, US 2, UI 4, SC 1, x_2 4.
        const size_t row = (doublePoints ? 24 : 12) + 12 + 3 + 62;
        const size_t header = bytes.find("end_header\n") + 11;
        FEATUREPOINTS_CHECK(bytes.size() == header + 300 * row, "%s: %zu bytes, %zu expected", what.c_str(),
          bytes.size(), header + 300 * row);
      }

      const ReadResult r = Read(path);
      FEATUREPOINTS_CHECK(r.Code == 0 && r.Message.empty() && r.Errors == 0, "%s: read error %s",
        what.c_str(), r.Message.c_str());
      Compare(what, cloud, r.Data);
      std::printf("round trip, %s: %lld points, %d arrays\n", what.c_str(),
        static_cast<long long>(r.Data->GetNumberOfPoints()),
        r.Data->GetPointData()->GetNumberOfArrays());
    }
  }

  // A larger cloud takes the chunked paths of both classes.
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(200000, 5, false);
  const std::string path = PathOf("large.ply");
  const WriteResult w = Write(cloud, path, false);
  FEATUREPOINTS_CHECK(w.Code == 0 && w.Message.empty(), "200000 points: write error %s", w.Message.c_str());
  const ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Code == 0 && r.Message.empty(), "200000 points: read error %s", r.Message.c_str());
  Compare("200000 points", cloud, r.Data);
  std::printf("round trip, 200000 points: %lld points read\n",
    static_cast<long long>(r.Data->GetNumberOfPoints()));

  // Without vertex cells, and without points.
  vtkNew<vtkPointCloudPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->CreateVertexCellsOff();
  reader->Update();
  FEATUREPOINTS_CHECK(reader->GetOutput()->GetNumberOfPoints() == 200000 &&
      reader->GetOutput()->GetNumberOfCells() == 0,
    "CreateVertexCells off: %lld cells",
    static_cast<long long>(reader->GetOutput()->GetNumberOfCells()));
  for (const bool ascii : { false, true })
  {
    vtkNew<vtkPolyData> empty; // no vtkPoints at all
    const std::string emptyPath = PathOf(ascii ? "empty_ascii.ply" : "empty_binary.ply");
    const WriteResult we = Write(empty, emptyPath, ascii);
    FEATUREPOINTS_CHECK(we.Code == 0 && we.Errors == 0, "empty cloud: write error %s", we.Message.c_str());
    FEATUREPOINTS_CHECK(Contains(fptest::Slurp(emptyPath), "element vertex 0\n"), "empty cloud: no vertex line");
    const ReadResult re = Read(emptyPath);
    FEATUREPOINTS_CHECK(
      re.Code == 0 && re.Message.empty() && re.Errors == 0 && re.Data->GetNumberOfPoints() == 0,
      "empty cloud: read %lld points, error %s",
      static_cast<long long>(re.Data->GetNumberOfPoints()), re.Message.c_str());
  }
}

// An ASCII file with CRLF line ends, comments, a blank line, odd spacing, elements before and
// after the vertices and properties the writer would not write.
void TestHandWrittenAscii()
{
  const std::string path = PathOf("hand.ply");
  fptest::Spit(path,
    "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info nothing\r\n"
    "element face 2\r\nproperty list uchar int vertex_indices\r\n"
    "element vertex 4\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
    "property float intensity\r\nproperty uchar red\r\nproperty uchar green\r\n"
    "property uchar blue\r\nproperty int label\r\n"
    "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
    "3 0 1 2\r\n3 0 2 3\r\n"
    "0 0 0 0.5 255 0 0 -7\r\n"
    "1.5 -2 3e2 0.25 0 255 0 2147483647\r\n"
    "\r\n"
    "  1 1 0 1e-3 0 0 255 0  \r\n"
    "0\t1 0 +2.5 10 20 30 -2147483648\r\n"
    "3 1 2 3\r\n");
  const ReadResult r = Read(path);
  vtkPolyData* out = r.Data;
  FEATUREPOINTS_CHECK(r.Code == 0 && r.Message.empty(), "hand-written ASCII: error %s", r.Message.c_str());
  FEATUREPOINTS_CHECK(out->GetNumberOfPoints() == 4 && out->GetNumberOfVerts() == 4,
    "hand-written ASCII: %lld points", static_cast<long long>(out->GetNumberOfPoints()));
  if (out->GetNumberOfPoints() != 4)
  {
    return;
  }
  const float xyz[4][3] = { { 0, 0, 0 }, { 1.5f, -2, 300 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const float intensity[4] = { 0.5f, 0.25f, 1e-3f, 2.5f };
  const int rgb[4][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 }, { 10, 20, 30 } };
  const int label[4] = { -7, 2147483647, 0, -2147483647 - 1 };
  auto* i = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("intensity"));
  auto* c = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetScalars());
  auto* l = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("label"));
  FEATUREPOINTS_CHECK(out->GetPoints()->GetDataType() == VTK_FLOAT, "hand-written ASCII: points not float");
  FEATUREPOINTS_CHECK(i && c && l && c->GetName() == std::string("RGB") &&
      out->GetPointData()->GetNumberOfArrays() == 3,
    "hand-written ASCII: arrays intensity (float), RGB (uchar, active scalars), label (int) "
    "expected");
  for (vtkIdType p = 0; p < 4 && i && c && l; ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    FEATUREPOINTS_CHECK(x[0] == xyz[p][0] && x[1] == xyz[p][1] && x[2] == xyz[p][2],
      "hand-written ASCII: point %lld is (%g %g %g)", static_cast<long long>(p), x[0], x[1], x[2]);
    FEATUREPOINTS_CHECK(i->GetValue(p) == intensity[p] && l->GetValue(p) == label[p] &&
        c->GetTypedComponent(p, 0) == rgb[p][0] && c->GetTypedComponent(p, 1) == rgb[p][1] &&
        c->GetTypedComponent(p, 2) == rgb[p][2],
      "hand-written ASCII: values of vertex %lld", static_cast<long long>(p));
  }
  std::printf("hand-written ASCII: 4 points, intensity, RGB and label as written\n");
}

template <typename T>
void PutBigEndian(std::string& bytes, T value)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  std::reverse(b, b + sizeof(T));
  bytes.append(b, sizeof(T));
}

// Big-endian files made byte by byte: one with fixed-size rows, one with list properties both
// in an element before the vertices and in the vertex element itself.
void TestBigEndian()
{
  {
    std::string bytes = "ply\nformat binary_big_endian 1.0\nelement vertex 2\n"
                        "property float x\nproperty float y\nproperty float z\n"
                        "property int label\nproperty double value\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float xyz[2][3] = { { 1.25f, -2.5f, 1e-20f }, { 3e10f, 0.1f, -0.0f } };
    const int label[2] = { -123456789, 42 };
    const double value[2] = { 0.1, -1e300 };
    for (int p = 0; p < 2; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        PutBigEndian(bytes, xyz[p][c]);
      }
      PutBigEndian(bytes, label[p]);
      PutBigEndian(bytes, value[p]);
    }
    bytes += std::string("\x03\0\0\0\0\0\0\0\x01\0\0\0\x02", 13);
    const std::string path = PathOf("big_endian.ply");
    fptest::Spit(path, bytes);
    const ReadResult r = Read(path);
    vtkPolyData* out = r.Data;
    auto* l = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("label"));
    auto* v = vtkDoubleArray::SafeDownCast(out->GetPointData()->GetArray("value"));
    FEATUREPOINTS_CHECK(r.Message.empty() && out->GetNumberOfPoints() == 2 && l && v &&
        out->GetPoints()->GetDataType() == VTK_FLOAT,
      "big-endian: error %s, %lld points", r.Message.c_str(),
      static_cast<long long>(out->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < 2 && l && v && out->GetNumberOfPoints() == 2; ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      FEATUREPOINTS_CHECK(Same(x[0], xyz[p][0]) && Same(x[1], xyz[p][1]) && Same(x[2], xyz[p][2]) &&
          l->GetValue(p) == label[p] && v->GetValue(p) == value[p],
        "big-endian: values of vertex %lld", static_cast<long long>(p));
    }
  }
  {
    std::string bytes = "ply\nformat binary_big_endian 1.0\n"
                        "element face 2\nproperty list uchar int vertex_indices\n"
                        "property uchar flags\n"
                        "element vertex 3\nproperty double x\nproperty double y\n"
                        "property double z\nproperty list ushort float extra\n"
                        "property float nx\nproperty float ny\nproperty float nz\n"
                        "property short s\nproperty ushort C_0\nproperty ushort C_1\n"
                        "property ushort C_2\nproperty char tiny\nproperty uint big\nend_header\n";
    for (int f = 0; f < 2; ++f)
    {
      bytes += '\x03';
      for (int k = 0; k < 3; ++k)
      {
        PutBigEndian(bytes, static_cast<int32_t>(k + f));
      }
      bytes += '\x07';
    }
    const double xyz[3][3] = { { 0.1, 0.2, 0.3 }, { -1e-300, 1e300, 5 }, { 7, 8, 9 } };
    for (int p = 0; p < 3; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        PutBigEndian(bytes, xyz[p][c]);
      }
      PutBigEndian(bytes, static_cast<uint16_t>(p)); // p items in the skipped list
      for (int k = 0; k < p; ++k)
      {
        PutBigEndian(bytes, 99.0f);
      }
      PutBigEndian(bytes, 0.0f);
      PutBigEndian(bytes, 0.6f * static_cast<float>(p));
      PutBigEndian(bytes, 0.8f);
      PutBigEndian(bytes, static_cast<int16_t>(-1000 * p - 1));
      for (int c = 0; c < 3; ++c)
      {
        PutBigEndian(bytes, static_cast<uint16_t>(60000 + 10 * p + c));
      }
      PutBigEndian(bytes, static_cast<int8_t>(-5 * p));
      PutBigEndian(bytes, static_cast<uint32_t>(4000000000u + p));
    }
    const std::string path = PathOf("big_endian_lists.ply");
    fptest::Spit(path, bytes);
    const ReadResult r = Read(path);
    vtkPolyData* out = r.Data;
    vtkPointData* pd = out->GetPointData();
    auto* s = vtkShortArray::SafeDownCast(pd->GetArray("s"));
    auto* c = vtkUnsignedShortArray::SafeDownCast(pd->GetArray("C"));
    auto* tiny = vtkSignedCharArray::SafeDownCast(pd->GetArray("tiny"));
    auto* big = vtkUnsignedIntArray::SafeDownCast(pd->GetArray("big"));
    auto* n = vtkFloatArray::SafeDownCast(pd->GetNormals());
    FEATUREPOINTS_CHECK(r.Message.empty() && out->GetNumberOfPoints() == 3 &&
        out->GetPoints()->GetDataType() == VTK_DOUBLE && s && c && tiny && big && n &&
        c->GetNumberOfComponents() == 3 && pd->GetNumberOfArrays() == 5,
      "big-endian with lists: error %s, %lld points, %d arrays", r.Message.c_str(),
      static_cast<long long>(out->GetNumberOfPoints()), pd->GetNumberOfArrays());
    FEATUREPOINTS_CHECK(r.Warnings == 1, "big-endian with lists: %zu warnings, 1 expected (list skipped)",
      r.Warnings);
    for (vtkIdType p = 0; p < 3 && s && c && tiny && big && n && out->GetNumberOfPoints() == 3; ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      const int q = static_cast<int>(p);
      FEATUREPOINTS_CHECK(x[0] == xyz[p][0] && x[1] == xyz[p][1] && x[2] == xyz[p][2] &&
          n->GetTypedComponent(p, 1) == 0.6f * static_cast<float>(q) &&
          n->GetTypedComponent(p, 2) == 0.8f && s->GetValue(p) == -1000 * q - 1 &&
          c->GetTypedComponent(p, 0) == 60000 + 10 * q &&
          c->GetTypedComponent(p, 2) == 60000 + 10 * q + 2 && tiny->GetValue(p) == -5 * q &&
          big->GetValue(p) == 4000000000u + static_cast<unsigned>(q),
        "big-endian with lists: values of vertex %lld", static_cast<long long>(p));
    }
  }
  std::printf("hand-written big-endian files: values as written\n");
}

// A malformed file: an error naming the file (and the line, if given), no points, no crash.
void ExpectError(const std::string& what, const std::string& name, const std::string& content,
  const std::string& words, int line = 0)
{
  const std::string path = PathOf(name);
  fptest::Spit(path, content);
  const ReadResult r = Read(path);
  const std::string where = line > 0 ? path + ":" + std::to_string(line) + ":" : path + ":";
  FEATUREPOINTS_CHECK(r.Code == vtkErrorCode::FileFormatError && r.Errors == 1 && !r.Message.empty(),
    "%s: error code %lu, %zu errors reported", what.c_str(), r.Code, r.Errors);
  FEATUREPOINTS_CHECK(r.Data->GetNumberOfPoints() == 0 && r.Data->GetPointData()->GetNumberOfArrays() == 0,
    "%s: %lld points in the output", what.c_str(),
    static_cast<long long>(r.Data->GetNumberOfPoints()));
  FEATUREPOINTS_CHECK(r.Message.compare(0, where.size(), where) == 0 && Contains(r.Message, words),
    "%s: message \"%s\" should start with \"%s\" and contain \"%s\"", what.c_str(),
    r.Message.c_str(), where.c_str(), words.c_str());
  std::printf("%-34s %s\n", (what + ":").c_str(), r.Message.substr(Folder.size() + 1).c_str());
}

// Values below the smallest of their type keep their rounding (a zero of their sign), whatever
// their exponent or digits, as the text and PCD readers read them; beyond the largest, an error.
// "1e-5000" (beyond long double too) was refused as out of range.
void TestUnderflow()
{
  const std::string path = PathOf("underflow.ply");
  const std::string zeros = "0." + std::string(400, '0') + "1";
  fptest::Spit(path,
    "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
    "property double z\nproperty float s\nend_header\n"
    "1e-400 -1e-5000 " + zeros + " 1e-50\n1 2 3 -1e-5000\n");
  const ReadResult r = Read(path);
  auto* s = r.Data ? vtkFloatArray::SafeDownCast(r.Data->GetPointData()->GetArray("s")) : nullptr;
  double x[3] = { 1, 1, 1 };
  if (r.Data && r.Data->GetNumberOfPoints() == 2)
  {
    r.Data->GetPoint(0, x);
  }
  FEATUREPOINTS_CHECK(r.Code == 0 && r.Errors == 0 && s && s->GetNumberOfTuples() == 2 &&
      Same(x[0], 0.0) && Same(x[1], -0.0) && Same(x[2], 0.0) && Same(s->GetValue(0), 0.0) &&
      Same(s->GetValue(1), -0.0),
    "underflow: %s; (%g %g %g)", r.Message.c_str(), x[0], x[1], x[2]);
  ExpectError("overflow", "overflow.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n0 1e50 0\n",
    "'1e50' is out of range for type float", 8);
}

void TestErrors()
{
  {
    const std::string path = PathOf("does_not_exist.ply");
    const ReadResult r = Read(path);
    FEATUREPOINTS_CHECK(r.Code == vtkErrorCode::CannotOpenFileError && r.Errors == 1 &&
        r.Message.compare(0, path.size(), path) == 0 && r.Data->GetNumberOfPoints() == 0,
      "missing file: code %lu, message %s", r.Code, r.Message.c_str());
    std::printf("%-34s %s\n", "missing file:", r.Message.substr(Folder.size() + 1).c_str());
  }
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                            "property float y\nproperty float z\n";
  const std::string asciiInt = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nproperty float z\nproperty uchar u\n"
                               "end_header\n";
  ExpectError("empty file", "empty.ply", "", "not a PLY file");
  ExpectError("not a PLY file", "hello.ply", "hello", "not a PLY file");
  ExpectError("no end_header", "no_end.ply", ascii, "no end_header");
  ExpectError(
    "unknown format", "format.ply", "ply\nformat binary_middle_endian 1.0\n", "format", 2);
  ExpectError("malformed element line", "element.ply",
    "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", "element", 3);
  ExpectError("unknown property type", "type.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float128 y\n", "float128",
    5);
  ExpectError(
    "unknown keyword", "keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 1\n", "elemnt", 3);
  // A header's raw bytes are not echoed (a terminal would take them as control sequences).
  ExpectError("unknown keyword with raw bytes", "raw.ply",
    "ply\nformat ascii 1.0\nelem\xff\x1b[2Jnt vertex 1\n", "'elem??[2Jnt'", 3);
  ExpectError("no vertex element", "no_vertex.ply",
    "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
    "no vertex element");
  ExpectError("missing z", "no_z.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
    "property float w\nend_header\n1 2 3\n",
    "no z property");
  ExpectError("non-numeric field", "abc.ply", ascii + "end_header\n0 0 0\n1.0 abc 2.0\n",
    "'abc' is not a number", 9);
  ExpectError("number with trailing letters", "trailing.ply",
    ascii + "end_header\n0 0 0\n1.0 1.5abc 2.0\n", "'1.5abc' is not a number", 9);
  ExpectError(
    "too few values", "few.ply", ascii + "end_header\n0 0 0\n\n1.0 2.0\n", "too few values", 10);
  ExpectError(
    "too many values", "many.ply", ascii + "end_header\n0 0 0 0\n1 1 1\n", "too many values", 8);
  ExpectError("ASCII file ends early", "short_ascii.ply", ascii + "end_header\n0 0 0\n",
    "ends in vertex 2 of 2");
  ExpectError("ASCII vertices beyond the count", "more_ascii.ply",
    ascii + "end_header\n0 0 0\n1 1 1\n\n2 2 2\n",
    "data after the 2 vertices that the header declares", 11);
  ExpectError(
    "fraction in an integer", "fraction.ply", asciiInt + "0 0 0 1.5\n", "not an integer", 9);
  ExpectError("integer out of range", "range.ply", asciiInt + "0 0 0 300\n", "out of range", 9);
  ExpectError("huge count, ASCII", "huge_ascii.ply",
    "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n1 2 3\n",
    "ends in vertex 2 of 4000000000");
  ExpectError("more rows than the count", "more_rows.ply",
    "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n" +
      std::string(60, '\0'),
    "the header declares 2 vertex rows of 12 bytes, but 60 bytes follow end_header (5 rows)");
  ExpectError("huge count, binary", "huge_binary.ply",
    "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n" +
      std::string(24, '\0'),
    "ends in vertex 3 of 4000000000");
  // An element before the vertices: its ASCII rows are checked as they are skipped, and in
  // binary a list count that runs into the vertex data is named, not the vertices.
  const std::string faceFirst = "element face 1\nproperty list uint int vertex_indices\n"
                                "element vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  ExpectError("negative list count before the vertices", "face_negative.ply",
    "ply\nformat ascii 1.0\nelement face 1\nproperty list int int vertex_indices\n"
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
    "-3 0 1 2\n" +
      vertices,
    "negative list count -3 in property 'vertex_indices' of face 1 of 1", 10);
  ExpectError("huge list count before the vertices", "face_huge.ply",
    "ply\nformat ascii 1.0\n" + faceFirst + "4294967295 0 1 2\n" + vertices,
    "list count 4294967295 in property 'vertex_indices' of face 1 of 1, but the line has 3 "
    "values after it",
    10);
  ExpectError("extra list item before the vertices", "face_long.ply",
    "ply\nformat ascii 1.0\n" + faceFirst + "3 0 1 2 5\n" + vertices,
    "too many values for face 1 of 1 (5, 4 expected)", 10);
  ExpectError("non-integer list item before the vertices", "face_item.ply",
    "ply\nformat ascii 1.0\n" + faceFirst + "3 0 1.5 2\n" + vertices,
    "'1.5' is not an integer (type int) in property 'vertex_indices' of face 1 of 1", 10);
  {
    std::string bytes = "ply\nformat binary_little_endian 1.0\nelement face 1\n"
                        "property list uchar int vertex_indices\nelement vertex 3\n"
                        "property float x\nproperty float y\nproperty float z\nend_header\n";
    const size_t header = bytes.size();
    bytes += '\xff'; // 255 items: the 3 written and the vertices after them
    bytes += std::string(12 + 36, '\0');
    ExpectError("list running into the vertices", "face_into_vertices.ply", bytes,
      "list 'vertex_indices' of face 1 of 1 counts 255 items of 4 bytes from byte " +
        std::to_string(header + 1) + ": they run into the data of the vertex element, at least 36 "
        "of the file's " + std::to_string(bytes.size()) + " bytes (a wrong list count)");
  }
  // Elements after the vertices are not read, but must fit in the file.
  ExpectError("huge count after the vertices", "face_count_after.ply",
    "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
    "property float y\nproperty float z\nelement face 4611686018427387904\n"
    "property list uchar int vertex_indices\nend_header\n" +
      std::string(12 + 13, '\0'),
    "element 'face' after the vertices declares 4611686018427387904 rows of at least 1 bytes: "
    "the elements up to it take at least 4611686018427387916 bytes, but 25 bytes follow "
    "end_header",
    7);
  // ... and are read past as those before them: a mesh's faces cut short after whole vertices
  // are the file's end, named with the face (they were taken as whole).
  {
    const std::string head = "element vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 4\n"
                             "property list uchar int vertex_indices\n";
    std::string bytes = "ply\nformat binary_little_endian 1.0\n" + head + "end_header\n" +
      std::string(36, '\0');
    const size_t faces = bytes.size();
    for (int f = 0; f < 2; ++f)
    {
      bytes += '\x03';
      bytes += std::string(12, '\0');
    }
    bytes += '\x03';
    bytes += std::string(5, '\0'); // face 3 cut inside its list
    ExpectError("binary faces cut after the vertices", "faces_cut.ply", bytes,
      "the file ends in face 3 of 4 (binary data from byte " + std::to_string(faces) + ")");
    ExpectError("ASCII faces cut after the vertices", "faces_cut_ascii.ply",
      "ply\nformat ascii 1.0\n" + head + "end_header\n" + vertices + "3 0 1 2\n3 0 1 2\n",
      "the file ends in face 3 of 4 (ASCII data, after line 14)");
    ExpectError("ASCII face short of its list after the vertices", "faces_short_ascii.ply",
      "ply\nformat ascii 1.0\n" + head + "end_header\n" + vertices +
        "3 0 1 2\n3 0 1\n3 0 1 2\n3 0 1 2\n",
      "list count 3 in property 'vertex_indices' of face 2 of 4, but the line has 2 values after "
      "it",
      14);
    // Rows after the last face, as after vertices that come last: a wrong count (a trailing byte
    // or two, as some writers leave, is no row).
    std::string whole = bytes.substr(0, faces);
    for (int f = 0; f < 4; ++f)
    {
      whole += '\x03';
      whole += std::string(12, '\0');
    }
    ExpectError("binary rows after the last face", "faces_more.ply", whole + std::string(13, '\0'),
      "the header declares 4 face rows, but 13 bytes follow the last of them (from byte " +
        std::to_string(whole.size()) + " of " + std::to_string(whole.size() + 13) +
        ", the face element the last): a wrong count, or data the header does not declare");
    fptest::Spit(PathOf("faces_newline.ply"), whole + "\n");
    const ReadResult newline = Read(PathOf("faces_newline.ply"));
    FEATUREPOINTS_CHECK(newline.Errors == 0 && newline.Data->GetNumberOfPoints() == 3,
      "a newline after the last face: read (%s)", newline.Message.c_str());
    ExpectError("ASCII rows after the last face", "faces_more_ascii.ply",
      "ply\nformat ascii 1.0\n" + head + "end_header\n" + vertices +
        "3 0 1 2\n3 0 1 2\n3 0 1 2\n3 0 1 2\n\n3 0 1 2\n",
      "data after the 4 face rows that the header declares (the face element is the last)", 18);
    // A list count of the faces that runs into the element after them is the faces' error.
    std::string two = "ply\nformat binary_little_endian 1.0\n" + head +
      "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n" +
      std::string(36, '\0');
    const size_t list = two.size() + 14;
    for (int f = 0; f < 4; ++f)
    {
      two += f == 1 ? '\x0a' : '\x03'; // face 2 counts 10 items: past faces 3 and 4
      two += std::string(12, '\0');
    }
    two += std::string(16, '\0');
    ExpectError("face list running into the edges", "faces_into_edges.ply", two,
      "list 'vertex_indices' of face 2 of 4 counts 10 items of 4 bytes from byte " +
        std::to_string(list) + ": they run into the data of the edge element, at least 16 of the "
        "file's " + std::to_string(two.size()) + " bytes (a wrong list count)");
  }

  // A valid binary file cut in the header, right after it, in a vertex, one byte short.
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(50, 3, false);
  const std::string full = PathOf("full.ply");
  Write(cloud, full, false);
  const std::string bytes = fptest::Slurp(full);
  const size_t header = bytes.find("end_header\n") + 11;
  const size_t row = (bytes.size() - header) / 50;
  const struct
  {
    size_t Length;
    const char* Words;
  } cuts[] = { { header / 2, "no end_header" }, { header, "ends in vertex 1 of 50" },
    { header + 10 * row + row / 2, "ends in vertex 11 of 50" },
    { bytes.size() - 1, "ends in vertex 50 of 50" } };
  for (const auto& cut : cuts)
  {
    ExpectError("binary cut at byte " + std::to_string(cut.Length),
      "cut_" + std::to_string(cut.Length) + ".ply", bytes.substr(0, cut.Length), cut.Words);
  }

  // The same reader reads a good file after a bad one: the error is gone.
  vtkNew<vtkPointCloudPLYReader> reader;
  const ReadResult bad = Read(PathOf("hello.ply"), reader);
  const ReadResult good = Read(full, reader);
  FEATUREPOINTS_CHECK(!bad.Message.empty() && good.Message.empty() && good.Code == 0 &&
      good.Data->GetNumberOfPoints() == 50,
    "reader reused after an error: message \"%s\", code %lu", good.Message.c_str(), good.Code);

  // The writer names the file it cannot write.
  const std::string unwritable = PathOf("no_such_folder/cloud.ply");
  const WriteResult w = Write(cloud, unwritable, false);
  FEATUREPOINTS_CHECK(w.Code == vtkErrorCode::CannotOpenFileError && w.Errors == 1 &&
      w.Message.compare(0, unwritable.size(), unwritable) == 0,
    "unwritable path: code %lu, message %s", w.Code, w.Message.c_str());
  std::printf("%-34s %s\n", "unwritable path:", w.Message.substr(Folder.size() + 1).c_str());
}
// Pieces (MPI processes): a binary file's pieces hold consecutive shares of the vertices, read
// from their byte ranges, and together the whole cloud in order; an ASCII file goes to piece 0.
void TestPieces()
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(103, 5, true);
  for (const bool ascii : { false, true })
  {
    const std::string path = PathOf(ascii ? "pieces_ascii.ply" : "pieces_binary.ply");
    Write(cloud, path, ascii);
    const int pieces = 4;
    vtkIdType next = 0;
    for (int p = 0; p < pieces; ++p)
    {
      vtkNew<vtkPointCloudPLYReader> reader;
      reader->SetFileName(path.c_str());
      reader->UpdatePiece(p, pieces, 0);
      vtkPolyData* piece = reader->GetOutput();
      const vtkIdType n = piece->GetNumberOfPoints();
      // Binary: 103 = 25 + 26 + 26 + 26 (floor(103 p / 4) onwards); ASCII: all on piece 0.
      const vtkIdType expected = ascii ? (p == 0 ? 103 : 0) : 103 * (p + 1) / 4 - 103 * p / 4;
      FEATUREPOINTS_CHECK(reader->GetErrorCode() == 0 && n == expected &&
          piece->GetNumberOfVerts() == n,
        "%s piece %d of %d: %lld points (%lld expected)", ascii ? "ASCII" : "binary", p, pieces,
        static_cast<long long>(n), static_cast<long long>(expected));
      vtkDataArray* label = piece->GetPointData()->GetArray("Label");
      vtkDataArray* original = cloud->GetPointData()->GetArray("Label");
      for (vtkIdType i = 0; i < n && next + i < 103; ++i)
      {
        double x[3], y[3];
        piece->GetPoint(i, x);
        cloud->GetPoint(next + i, y);
        const bool same = x[0] == y[0] && x[1] == y[1] && x[2] == y[2] && label && original &&
          label->GetTuple1(i) == original->GetTuple1(next + i);
        if (!same)
        {
          FEATUREPOINTS_CHECK(same, "%s piece %d: point %lld is not point %lld of the file",
            ascii ? "ASCII" : "binary", p, static_cast<long long>(i),
            static_cast<long long>(next + i));
          break;
        }
      }
      next += n;
    }
    FEATUREPOINTS_CHECK(next == 103, "%s pieces hold %lld points", ascii ? "ASCII" : "binary",
      static_cast<long long>(next));
  }
  std::printf("%-34s binary 25+26+26+26 points by byte ranges, ASCII all on piece 0\n", "pieces:");
}
} // namespace

int TestPointCloudPLY(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::printf("usage: TestPointCloudPLY OUTPUT_FOLDER\n");
    return EXIT_FAILURE;
  }
  Folder = argv[1];
  TestRoundTrips();
  TestHandWrittenAscii();
  TestUnderflow();
  TestBigEndian();
  TestErrors();
  TestPieces();
  if (Failures > 0)
  {
    std::printf("%d checks failed\n", Failures);
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
