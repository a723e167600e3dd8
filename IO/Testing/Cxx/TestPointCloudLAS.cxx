// vtkPointCloudLASReader on files written here byte by byte from the LAS specification's tables
// (public header block of LAS 1.2, 1.3 and 1.4, a variable-length record, point data record
// formats 0 to 10, extra bytes): every attribute read back, coordinates at 10^6 with scale 0.001
// to 1e-9; LAZ refused with its one line; malformed files (lying counts and sizes) refused with
// one line naming the file, before any allocation.
#include "FeaturePointsTestReaders.h"
#include "vtkPointCloudLASReader.h"

#include "FeaturePointsTestFiles.h"
#include "LASTestFile.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace featurepoints::lastest;

namespace
{
using fptest::Spit;

using fptest::Catcher;
using fptest::Failures;
using fptest::Folder;
using fptest::PathOf;

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Cloud;
  std::vector<std::string> Errors;
  std::string Message;
  int Format = -1, Minor = -1;
};

ReadResult Read(const std::string& path)
{
  vtkNew<vtkPointCloudLASReader> reader;
  vtkNew<Catcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->Update();
  ReadResult r;
  r.Cloud = reader->GetOutput();
  r.Errors = catcher->Errors;
  r.Message = reader->GetErrorMessage();
  r.Format = reader->GetPointDataFormat();
  r.Minor = reader->GetVersionMinor();
  return r;
}

std::vector<Point> SamplePoints()
{
  return {
    { 1000, -2000, 300, 17, 1, 2, 2, 1.25e8, 65535, 0, 1024, 4000 },
    { -7, 8, -9, 65535, 2, 2, 6, 1.5, 1, 2, 3, 65535 },
    { 2147483647, -2147483647 - 1, 0, 0, 3, 5, 31, -4.75, 256, 512, 768, 0 },
  };
}

// Every format: the attributes it has, with their values; the ones it lacks, absent.
void Formats()
{
  const std::vector<Point> points = SamplePoints();
  for (int format = 0; format <= 10; ++format)
  {
    // The version each format came with (formats 4, 5 in 1.3; 6-10 in 1.4), and 1.4 for all.
    for (int minor : { format <= 3 ? 2 : (format <= 5 ? 3 : 4), 4 })
    {
      File f;
      f.Minor = minor;
      f.Format = format;
      f.Vlr = format % 2 == 0;
      f.ExtraBytes = format % 3 == 0 ? 6 : 0;
      f.Scale[0] = 0.01;
      f.Scale[1] = 0.5;
      f.Scale[2] = 0.001;
      f.Offset[0] = 100;
      f.Offset[1] = -3;
      f.Offset[2] = 0.25;
      f.Points = points;
      const std::string name =
        "format" + std::to_string(format) + "-1." + std::to_string(minor) + ".las";
      const std::string path = PathOf(name);
      Spit(path, Bytes(f));
      ReadResult r = Read(path);
      FEATUREPOINTS_CHECK(r.Errors.empty() && r.Format == format && r.Minor == minor, "%s: %s", name.c_str(),
        r.Message.c_str());
      vtkPolyData* c = r.Cloud;
      FEATUREPOINTS_CHECK(c->GetNumberOfPoints() == 3 && c->GetPoints()->GetDataType() == VTK_DOUBLE &&
          c->GetNumberOfVerts() == 3,
        "%s: 3 double points with vertex cells", name.c_str());
      if (c->GetNumberOfPoints() != 3)
      {
        continue;
      }
      const bool gps = format == 1 || format >= 3;
      const bool rgb =
        format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
      const bool nir = format == 8 || format == 10;
      vtkPointData* pd = c->GetPointData();
      FEATUREPOINTS_CHECK(pd->GetNumberOfArrays() == 4 + gps + rgb + nir, "%s: %d arrays", name.c_str(),
        pd->GetNumberOfArrays());
      FEATUREPOINTS_CHECK((pd->GetArray("GpsTime") != nullptr) == gps &&
          (pd->GetArray("RGB") != nullptr) == rgb && (pd->GetArray("NIR") != nullptr) == nir,
        "%s: GpsTime, RGB, NIR present as the format has them", name.c_str());
      for (vtkIdType i = 0; i < 3; ++i)
      {
        const Point& p = points[i];
        double x[3];
        c->GetPoint(i, x);
        const double expected[3] = { p.X * 0.01 + 100, p.Y * 0.5 - 3, p.Z * 0.001 + 0.25 };
        for (int k = 0; k < 3; ++k)
        {
          FEATUREPOINTS_CHECK(std::fabs(x[k] - expected[k]) <= 1e-9 * std::max(1.0, std::fabs(expected[k])),
            "%s: point %lld coordinate %d: %.17g, %.17g expected", name.c_str(),
            static_cast<long long>(i), k, x[k], expected[k]);
        }
        auto value = [&](const char* array, int component = 0) {
          vtkDataArray* a = pd->GetArray(array);
          return a ? a->GetComponent(i, component) : -1.0;
        };
        FEATUREPOINTS_CHECK(value("Intensity") == p.Intensity, "%s: Intensity %lld", name.c_str(),
          static_cast<long long>(i));
        FEATUREPOINTS_CHECK(
          value("ReturnNumber") == p.ReturnNumber && value("NumberOfReturns") == p.NumberOfReturns,
          "%s: returns of %lld: %g of %g", name.c_str(), static_cast<long long>(i),
          value("ReturnNumber"), value("NumberOfReturns"));
        // Formats 0-5: the class without its flags (set in every record written here).
        FEATUREPOINTS_CHECK(value("Classification") == p.Classification, "%s: Classification %lld: %g",
          name.c_str(), static_cast<long long>(i), value("Classification"));
        if (gps)
        {
          FEATUREPOINTS_CHECK(value("GpsTime") == p.GpsTime, "%s: GpsTime %lld", name.c_str(),
            static_cast<long long>(i));
        }
        if (rgb)
        {
          FEATUREPOINTS_CHECK(
            value("RGB", 0) == p.Red && value("RGB", 1) == p.Green && value("RGB", 2) == p.Blue,
            "%s: RGB %lld", name.c_str(), static_cast<long long>(i));
        }
        if (nir)
        {
          FEATUREPOINTS_CHECK(value("NIR") == p.Nir, "%s: NIR %lld", name.c_str(), static_cast<long long>(i));
        }
      }
    }
  }
}

// Lidar coordinates: 10^6 with a 0.001 step, in a LAS 1.4 file, exact to 1e-9.
void Precision()
{
  File f;
  f.Minor = 4;
  f.Format = 6;
  f.Scale[0] = f.Scale[1] = f.Scale[2] = 0.001;
  f.Offset[0] = 0;
  f.Offset[1] = 4000000;
  f.Offset[2] = 0;
  f.Points = { { 1000000000, 0, 123456, 0, 1, 1, 2, 0, 0, 0, 0, 0 },
    { 1000000001, 1, -1, 0, 1, 1, 2, 0, 0, 0, 0, 0 },
    { 999999999, -1000000000, 0, 0, 1, 1, 2, 0, 0, 0, 0, 0 } };
  const std::string path = PathOf("precision-1.4.las");
  Spit(path, Bytes(f));
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(
    r.Errors.empty() && r.Cloud->GetNumberOfPoints() == 3, "precision: %s", r.Message.c_str());
  if (r.Cloud->GetNumberOfPoints() != 3)
  {
    return;
  }
  const double expected[3][3] = { { 1e6, 4000000.0, 123.456 }, { 1000000.001, 4000000.001, -0.001 },
    { 999999.999, 3000000.0, 0.0 } };
  for (vtkIdType i = 0; i < 3; ++i)
  {
    double x[3];
    r.Cloud->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      FEATUREPOINTS_CHECK(std::fabs(x[k] - expected[i][k]) <= 1e-9,
        "precision: point %lld coordinate %d: %.17g, %.17g expected (%.3g off)",
        static_cast<long long>(i), k, x[k], expected[i][k], x[k] - expected[i][k]);
    }
  }
  // Through vtkPointCloudIO: the same double coordinates.
  std::string error;
  vtkSmartPointer<vtkPointSet> io = vtkPointCloudIO::Read(path, error);
  double x[3] = { 0, 0, 0 };
  if (io && io->GetNumberOfPoints() == 3)
  {
    io->GetPoint(1, x);
  }
  FEATUREPOINTS_CHECK(
    io && io->GetPoints()->GetDataType() == VTK_DOUBLE && std::fabs(x[0] - 1000000.001) <= 1e-9,
    "precision through vtkPointCloudIO: %s", error.c_str());
}

// LAZ: refused with one line that says why, by extension and by the compression bit.
void Compressed()
{
  File f;
  f.Format = 3;
  f.Points = SamplePoints();
  const std::string laz = PathOf("cloud.laz");
  Spit(laz, Bytes(f));
  const std::string expected = "compressed LAS (LAZ) is not supported in this build";
  ReadResult r = Read(laz);
  FEATUREPOINTS_CHECK(r.Errors.size() == 1 && r.Message.find(laz + ": " + expected) == 0 &&
      r.Message.find("Debian 12") != std::string::npos && r.Message.find('\n') == std::string::npos,
    "laz: [%s]", r.Message.c_str());
  std::string error;
  FEATUREPOINTS_CHECK(vtkPointCloudIO::CanRead("laz") &&
      vtkPointCloudIO::GetReadableExtensions().find("laz") == std::string::npos &&
      !vtkPointCloudIO::Read(laz, error) && error == r.Message,
    "laz through vtkPointCloudIO: [%s]", error.c_str());
  f.FormatByte = 3 | 0x80; // LASzip's mark in a file named .las
  const std::string marked = PathOf("laszip-marked.las");
  Spit(marked, Bytes(f));
  r = Read(marked);
  FEATUREPOINTS_CHECK(
    r.Message.find(marked + ": " + expected) == 0, "compression bit: [%s]", r.Message.c_str());
  f.FormatByte = 99; // bit 6 set, but no LASzip format under it: an unknown format, not LAZ
  const std::string unknown = PathOf("format99.las");
  Spit(unknown, Bytes(f));
  r = Read(unknown);
  FEATUREPOINTS_CHECK(
    r.Message.find("unsupported point data record format 99 (0 to 10 are read)") !=
        std::string::npos,
    "format 99: [%s]", r.Message.c_str());
}

// Malformed files: one line naming the file and the problem, an empty output, no allocation of
// the declared count (each read is timed).
void Malformed()
{
  struct Case
  {
    const char* Name;
    std::string Bytes;
    const char* Expected;
  };
  File base;
  base.Format = 1;
  base.Points = SamplePoints();
  const std::string good = Bytes(base);
  auto with = [&base](auto change) {
    File f = base;
    change(f);
    return Bytes(f);
  };
  std::string wrongSignature = good;
  wrongSignature[3] = 'G';
  // The bytes of a file with a value written over the field at byte `at`.
  auto patched = [](std::string bytes, size_t at, auto value) {
    std::memcpy(&bytes[at], &value, sizeof(value));
    return bytes;
  };
  const std::string withVlr = with([](File& f) { f.Vlr = true; }); // points from byte 291
  const std::string las13 = with([](File& f) { f.Minor = 3; });      // points from byte 235
  const std::string las14 = with([](File& f) { f.Minor = 4; });      // points from byte 375
  std::string version2 = good;
  version2[24] = 2;
  const Case cases[] = {
    { "signature.las", wrongSignature,
      "not a LAS file (it does not start with the signature LASF)" },
    { "tiny.las", "LASF", "the file ends in the LAS header (227 bytes at least, the file has 4)" },
    { "version.las", version2, "unsupported LAS version 2.2 (1.0 to 1.4 are read)" },
    { "format11.las", with([](File& f) { f.FormatByte = 11; }),
      "unsupported point data record format 11 (0 to 10 are read)" },
    { "record-short.las", with([](File& f) { f.RecordLength = 27; }),
      "point record length 27 is shorter than point format 1's 28 bytes" },
    { "header-size.las", with([](File& f) { f.HeaderSize = 100; }),
      "header size 100 is impossible for LAS 1.2" },
    { "header-cut.las", with([](File& f) { f.Minor = 3; }).substr(0, 230),
      "the LAS 1.3 header's size field says 235 bytes, more than the file's 230" },
    { "scale-zero.las", with([](File& f) { f.Scale[1] = 0; }), "y scale factor 0" },
    { "scale-nan.las", with([](File& f) { f.Scale[2] = std::nan(""); }), "z scale factor nan" },
    { "scale-huge.las", with([](File& f) { f.Scale[0] = 1e300; }), "overflow double precision" },
    { "count-lie.las", with([](File& f) { f.DeclaredPoints = 4; }),
      "the header declares 4 points of 28 bytes from byte 227, but the file (311 bytes) holds 3" },
    { "count-huge.las", with([](File& f) {
       f.Minor = 4;
       f.DeclaredPoints = uint64_t(1) << 50;
     }),
      "the header declares 1125899906842624 points" },
    { "cut.las", good.substr(0, good.size() - 1), "the file (310 bytes) holds 2" },
    { "count-fewer.las", with([](File& f) { f.DeclaredPoints = 2; }),
      "the header declares 2 points of 28 bytes from byte 227, but 3 follow there: a wrong point "
      "count" },
    // The VLRs must end by the offset to point data: their count (byte 100), a length (+20).
    { "vlr-count.las", patched(withVlr, 100, uint32_t(2)),
      "VLR 2 of 2 (from byte 291): its 54-byte header runs past the offset to point data (byte "
      "291)" },
    { "vlr-count-huge.las", patched(good, 100, uint32_t(4294967295u)),
      "VLR 1 of 4294967295 (from byte 227): its 54-byte header runs past the offset to point "
      "data (byte 227)" },
    { "vlr-length.las", patched(withVlr, 227 + 20, uint16_t(1000)),
      "VLR 1 of 1 (from byte 227): its header and the 1000 bytes of data it declares end at byte "
      "1281, past the offset to point data (byte 291)" },
    { "format6-1.2.las", with([](File& f) { f.Format = 6; }),
      "point data record format 6 needs LAS 1.4 (the file is LAS 1.2)" },
    { "legacy-count.las", patched(las14, 107, uint32_t(2)),
      "the legacy point count 2 is neither 0 nor the LAS 1.4 point count 3" },
    { "evlr-in-points.las", patched(las14, 235, uint64_t(400)),
      "the header says the first extended VLR starts at byte 400, before the end of the point "
      "data (bytes 375 to 459)" },
    { "evlr-past-end.las", patched(las14, 235, uint64_t(100000)),
      "the header says the first extended VLR starts at byte 100000, past the end of the file "
      "(459 bytes)" },
    { "waveform-in-points.las", patched(las13, 227, uint64_t(300)),
      "the header says the waveform data packet record starts at byte 300, before the end of the "
      "point data (bytes 235 to 319)" },
  };
  for (const Case& c : cases)
  {
    const std::string path = PathOf(c.Name);
    Spit(path, c.Bytes);
    const auto start = std::chrono::steady_clock::now();
    ReadResult r = Read(path);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    FEATUREPOINTS_CHECK(r.Errors.size() == 1 && r.Cloud->GetNumberOfPoints() == 0 &&
        r.Message.find(path + ": ") == 0 && r.Message.find(c.Expected) != std::string::npos &&
        r.Message.find('\n') == std::string::npos && seconds < 1.0,
      "%s: [%s] in %.2f s, expected [%s]", c.Name, r.Message.c_str(), seconds, c.Expected);
    std::string error;
    FEATUREPOINTS_CHECK(!vtkPointCloudIO::Read(path, error) && error == r.Message,
      "%s through vtkPointCloudIO: [%s]", c.Name, error.c_str());
  }
  // The point offset beyond the file.
  std::string offset = good;
  const uint32_t far = 100000;
  std::memcpy(&offset[96], &far, 4);
  const std::string path = PathOf("offset.las");
  Spit(path, offset);
  ReadResult r = Read(path);
  FEATUREPOINTS_CHECK(r.Message.find("the point data cannot start at byte 100000") != std::string::npos,
    "offset: [%s]", r.Message.c_str());

  // What the header may say: a legacy count of 0 in LAS 1.4, or the legacy count alone (a 64-bit
  // count of 0); an extended VLR start at the end of the points; bytes after the last VLR.
  const struct
  {
    const char* Name;
    std::string Bytes;
  } fine[] = {
    { "legacy-zero.las", patched(las14, 107, uint32_t(0)) },
    { "legacy-only.las", patched(las14, 247, uint64_t(0)) },
    { "evlr-after-points.las", patched(las14, 235, uint64_t(459)) },
    { "vlr-short.las", patched(withVlr, 227 + 20, uint16_t(4)) },
  };
  for (const auto& c : fine)
  {
    const std::string at = PathOf(c.Name);
    Spit(at, c.Bytes);
    ReadResult read = Read(at);
    FEATUREPOINTS_CHECK(read.Errors.empty() && read.Cloud->GetNumberOfPoints() == 3,
      "%s: %lld points, [%s]", c.Name, static_cast<long long>(read.Cloud->GetNumberOfPoints()),
      read.Message.c_str());
  }
}
} // namespace

int TestPointCloudLAS(int argc, char* argv[])
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
  Formats();
  Precision();
  Compressed();
  Malformed();
  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
