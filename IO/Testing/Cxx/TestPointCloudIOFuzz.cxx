// vtkPointCloudIO::Read on a few thousand mutated versions of small valid files in every readable
// format: bytes flipped, cut, duplicated, deleted, numbers in headers made huge or negative, binary
// header fields set to extremes. The PCD and LAS seeds get more rounds (a few thousand files per
// format). Each read of the project's readers (PLY, text, PCD, LAS) runs in a child process with a
// memory and time limit (a few hundred files per child, each read timed);
// VTK's readers (VTP, VTU, legacy VTK) already run so inside Read(). None may crash, hang, abort or
// give an error of more than one line (or one that does not start with the file name). A failing
// case is kept in the test's folder (fuzz-failure-N.EXT) to reproduce it.
//
//   FeaturePointsIOCxxTests TestPointCloudIOFuzz FOLDER [CASES_PER_SEED]
#include "FeaturePointsTestFiles.h"
#include "LASTestFile.h"

#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointCloudIO.h"
#include "vtkPointCloudPCDWriter.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define FEATUREPOINTS_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FEATUREPOINTS_FUZZ_ASAN 1
#endif
#endif

namespace
{
using namespace fptest;
// Drops VTK's warnings (the organized PCD seed's skipped NaN points, PLY list properties), and
// only them: the readers' errors still reach vtkPointCloudIO, which makes its one line of them.
// (vtkObject::GlobalWarningDisplayOff would silence the errors too.)
class QuietOutputWindow : public vtkOutputWindow
{
public:
  static QuietOutputWindow* New();
  vtkTypeMacro(QuietOutputWindow, vtkOutputWindow);
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
};
vtkStandardNewMacro(QuietOutputWindow);

// Exit codes of a child that read without crashing but broke the rules.
constexpr int ChildOk = 0;
constexpr int ChildBadMessage = 3;
constexpr int ChildBadCloud = 4;

// A small cloud with normals, colours, an integer and a two-component array.
vtkSmartPointer<vtkPolyData> SmallCloud()
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const vtkIdType n = 24;
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  label->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> pair;
  pair->SetName("Pair");
  pair->SetNumberOfComponents(2);
  pair->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, u(rng), u(rng), u(rng));
    normals->SetTuple3(i, u(rng), u(rng), u(rng));
    rgb->SetTuple3(i, 255 * std::abs(u(rng)), 100, 7);
    label->SetValue(i, static_cast<int>(i * 3));
    pair->SetTuple2(i, u(rng), u(rng));
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->GetPointData()->AddArray(normals);
  cloud->GetPointData()->AddArray(rgb);
  cloud->GetPointData()->AddArray(label);
  cloud->GetPointData()->AddArray(pair);
  return cloud;
}

struct Seed
{
  std::string Extension;
  std::string Bytes;
  int Weight = 1; // rounds per round of the other seeds
};

// The PCD and LAS seeds' weight: about 750 mutations of each with the default 150 rounds.
constexpr int NewFormatWeight = 5;

// Valid files in every readable format: the writers' own (binary VTP, VTK, PLY; CSV), and
// hand-written ASCII variants of what the writers do not produce.
std::vector<Seed> Seeds(const std::string& folder)
{
  std::vector<Seed> seeds;
  vtkSmartPointer<vtkPolyData> cloud = SmallCloud();
  std::string error;
  for (const char* extension : { "vtp", "vtk", "ply", "csv" })
  {
    const std::string path = folder + "/seed." + extension;
    if (vtkPointCloudIO::Write(cloud, path, error))
    {
      seeds.push_back({ extension, Slurp(path) });
    }
    else
    {
      std::printf("FAILED: cannot write the seed %s: %s\n", path.c_str(), error.c_str());
    }
    std::remove(path.c_str());
  }
  std::ostringstream xyz, pts, plyAscii, vtkAscii, vtpAscii, vtuAscii;
  pts << cloud->GetNumberOfPoints() << "\n";
  plyAscii << "ply\nformat ascii 1.0\ncomment fuzz seed\nelement vertex " << cloud->GetNumberOfPoints()
           << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
              "property uchar green\nproperty uchar blue\nproperty int label\n"
              "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  vtkAscii << "# vtk DataFile Version 3.0\nfuzz seed\nASCII\nDATASET POLYDATA\nPOINTS "
           << cloud->GetNumberOfPoints() << " float\n";
  std::ostringstream coordinates;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    xyz << x[0] << " " << x[1] << " " << x[2] << " " << i << "\n";
    pts << x[0] << " " << x[1] << " " << x[2] << " " << i % 7 << " 10 20 30\n";
    plyAscii << x[0] << " " << x[1] << " " << x[2] << " 1 2 3 " << i << "\n";
    coordinates << x[0] << " " << x[1] << " " << x[2] << "\n";
  }
  plyAscii << "3 0 1 2\n3 2 3 4\n";
  vtkAscii << coordinates.str() << "VERTICES 1 " << cloud->GetNumberOfPoints() + 1 << "\n"
           << cloud->GetNumberOfPoints();
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    vtkAscii << " " << i;
  }
  vtkAscii << "\nPOINT_DATA " << cloud->GetNumberOfPoints() << "\nSCALARS s float 1\n"
           << "LOOKUP_TABLE default\n";
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    vtkAscii << i * 0.5 << "\n";
  }
  const std::string n = std::to_string(cloud->GetNumberOfPoints());
  vtpAscii << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
              "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\""
           << n << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                   "NumberOfPolys=\"0\">\n<PointData>\n<DataArray type=\"Int32\" Name=\"label\" "
                   "format=\"ascii\">\n";
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    vtpAscii << i << " ";
  }
  vtpAscii << "\n</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float32\" "
              "NumberOfComponents=\"3\" format=\"ascii\">\n"
           << coordinates.str() << "</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  vtuAscii << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
              "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
           << n << "\" NumberOfCells=\"0\">\n<Points>\n<DataArray type=\"Float64\" "
                   "NumberOfComponents=\"3\" format=\"ascii\">\n"
           << coordinates.str()
           << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
              "format=\"ascii\"></DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
              "format=\"ascii\"></DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
              "format=\"ascii\"></DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n"
              "</VTKFile>\n";
  seeds.push_back({ "xyz", xyz.str() });
  seeds.push_back({ "txt", "# x y z id\n" + xyz.str() });
  seeds.push_back({ "pts", pts.str() });
  seeds.push_back({ "ply", plyAscii.str() });
  seeds.push_back({ "vtk", vtkAscii.str() });
  seeds.push_back({ "vtp", vtpAscii.str() });
  seeds.push_back({ "vtu", vtuAscii.str() });

  // PCD in its three encodings (the writer's, with normals, colours, an integer and a 2-value
  // field), and a hand-written organized ASCII cloud with NaN points and packed colours.
  for (int format : { vtkPointCloudPCDWriter::ASCII, vtkPointCloudPCDWriter::BINARY,
         vtkPointCloudPCDWriter::BINARY_COMPRESSED })
  {
    const std::string path = folder + "/seed.pcd";
    vtkNew<vtkPointCloudPCDWriter> writer;
    writer->SetInputData(cloud);
    writer->SetFileName(path.c_str());
    writer->SetDataFormat(format);
    if (writer->Write() == 1)
    {
      seeds.push_back({ "pcd", Slurp(path), NewFormatWeight });
    }
    else
    {
      std::printf("FAILED: cannot write the seed %s (format %d)\n", path.c_str(), format);
    }
    std::remove(path.c_str());
  }
  std::ostringstream organized;
  organized << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb label\nSIZE 4 4 4 4 2\nTYPE F F F F U\n"
               "COUNT 1 1 1 1 1\nWIDTH 6\nHEIGHT 4\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 24\n"
               "DATA ascii\n";
  for (vtkIdType i = 0; i < 24; ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    if (i % 5 == 3)
    {
      organized << "nan nan nan 0 " << i << "\n";
    }
    else
    {
      organized << x[0] << " " << x[1] << " " << x[2] << " " << 65536 * i + 255 << " " << i << "\n";
    }
  }
  seeds.push_back({ "pcd", organized.str(), NewFormatWeight });

  // LAS: format 1 in LAS 1.2 with a variable-length record, 7 in 1.4 with extra bytes, 10 in 1.4.
  using namespace featurepoints::lastest;
  std::vector<Point> points;
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    points.push_back({ static_cast<int32_t>(x[0] * 1000), static_cast<int32_t>(x[1] * 1000),
      static_cast<int32_t>(x[2] * 1000), static_cast<uint16_t>(i * 100), 1, 2,
      static_cast<int>(i % 20), 1000.0 + i, 10, 20, 30, 40 });
  }
  const int formats[3][4] = { { 2, 1, 0, 1 }, { 4, 7, 4, 0 }, { 4, 10, 0, 0 } };
  for (const auto& version : formats)
  {
    File f;
    f.Minor = version[0];
    f.Format = version[1];
    f.ExtraBytes = version[2];
    f.Vlr = version[3] != 0;
    f.Scale[0] = f.Scale[1] = f.Scale[2] = 0.001;
    f.Offset[0] = 500000;
    f.Offset[1] = 4000000;
    f.Points = points;
    seeds.push_back({ "las", Bytes(f), NewFormatWeight });
  }
  return seeds;
}

// One mutation of `bytes`, chosen and placed by `rng`.
std::string Mutate(const std::string& bytes, std::mt19937& rng)
{
  std::string out = bytes;
  auto at = [&rng](size_t size) {
    return size == 0 ? size_t(0) : std::uniform_int_distribution<size_t>(0, size - 1)(rng);
  };
  const int rounds = std::uniform_int_distribution<int>(1, 3)(rng);
  for (int round = 0; round < rounds; ++round)
  {
    switch (std::uniform_int_distribution<int>(0, 8)(rng))
    {
      case 0: // flip bits of a few bytes
        for (int k = std::uniform_int_distribution<int>(1, 8)(rng); k > 0 && !out.empty(); --k)
        {
          out[at(out.size())] ^= static_cast<char>(1 << std::uniform_int_distribution<int>(0, 7)(rng));
        }
        break;
      case 1: // cut the file short
        out.resize(at(out.size() + 1));
        break;
      case 2: // duplicate a chunk in place
      {
        const size_t start = at(out.size());
        const size_t length = std::min(out.size() - start, at(200) + 1);
        out.insert(start, out.substr(start, length));
        break;
      }
      case 3: // delete a chunk
      {
        const size_t start = at(out.size());
        out.erase(start, std::min(out.size() - start, at(64) + 1));
        break;
      }
      case 4: // random bytes somewhere
      {
        const size_t start = at(out.size() + 1);
        std::string noise(at(32) + 1, '\0');
        for (char& c : noise)
        {
          c = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
        }
        out.insert(start, noise);
        break;
      }
      case 5: // a number in the first 600 bytes (the headers' counts) made huge, negative or odd
      case 6:
      {
        const size_t limit = std::min<size_t>(out.size(), 600);
        std::vector<std::pair<size_t, size_t>> numbers;
        for (size_t i = 0; i < limit;)
        {
          if (std::isdigit(static_cast<unsigned char>(out[i])))
          {
            size_t j = i;
            while (j < out.size() && std::isdigit(static_cast<unsigned char>(out[j])))
            {
              ++j;
            }
            numbers.emplace_back(i, j - i);
            i = j;
          }
          else
          {
            ++i;
          }
        }
        if (numbers.empty())
        {
          break;
        }
        static const char* const replacements[] = { "1000000000000", "4294967295", "2147483648",
          "-1", "-2147483649", "0", "99999999999999999999999", "1e308", "nan", "3.5", "" };
        const auto& number = numbers[at(numbers.size())];
        out.replace(number.first, number.second,
          replacements[at(sizeof(replacements) / sizeof(replacements[0]))]);
        break;
      }
      case 7: // a binary header field (1, 2, 4 or 8 bytes in the first 400) set to an extreme
      {
        if (out.empty())
        {
          break;
        }
        static const unsigned char extremes[][8] = { { 0, 0, 0, 0, 0, 0, 0, 0 },
          { 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff },
          { 0xff, 0xff, 0xff, 0x7f, 0xff, 0xff, 0xff, 0x7f }, { 0, 0, 0, 0x80, 0, 0, 0, 0x80 },
          { 1, 0, 0, 0, 0, 0, 0, 0 }, { 0, 0, 0, 0, 0, 0, 0xf0, 0x7f } };
        const size_t width = size_t(1) << std::uniform_int_distribution<int>(0, 3)(rng);
        const size_t start = at(std::min<size_t>(out.size(), 400));
        const auto& value = extremes[at(sizeof(extremes) / sizeof(extremes[0]))];
        for (size_t k = 0; k < width && start + k < out.size(); ++k)
        {
          out[start + k] = static_cast<char>(value[k]);
        }
        break;
      }
      default: // swap two lines' worth of bytes
      {
        const size_t a = at(out.size()), b = at(out.size());
        const size_t length = std::min({ out.size() - a, out.size() - b, at(40) + 1 });
        if (a + length <= b || b + length <= a)
        {
          for (size_t k = 0; k < length; ++k)
          {
            std::swap(out[a + k], out[b + k]);
          }
        }
        break;
      }
    }
  }
  return out;
}

// In the child: reads the file and checks what came back (ChildOk when the rules hold).
int CheckRead(const std::string& path)
{
  std::string error;
  vtkSmartPointer<vtkPointSet> cloud = vtkPointCloudIO::Read(path, error);
  if (!cloud)
  {
    const bool oneLine = !error.empty() && error.find('\n') == std::string::npos &&
      error.compare(0, path.size(), path) == 0;
    if (!oneLine)
    {
      std::fprintf(stderr, "message: [%s]\n", error.c_str());
    }
    return oneLine ? ChildOk : ChildBadMessage;
  }
  // A cloud that was read: every coordinate and value can be read (a sanitizer checks them).
  double sum = 0.0, x[3];
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    cloud->GetPoint(i, x);
    sum += x[0] + x[1] + x[2];
  }
  vtkPointData* pd = cloud->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetNumberOfTuples() < cloud->GetNumberOfPoints())
    {
      std::fprintf(stderr, "array %s has %lld tuples for %lld points\n", array->GetName(),
        static_cast<long long>(array->GetNumberOfTuples()),
        static_cast<long long>(cloud->GetNumberOfPoints()));
      return ChildBadCloud;
    }
    for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
    {
      sum += array->GetComponent(i / array->GetNumberOfComponents(),
        static_cast<int>(i % array->GetNumberOfComponents()));
    }
  }
  volatile double sink = sum; // the sum only makes the reads happen
  (void)sink;
  return ChildOk;
}

// One mutated file for the project's readers.
struct Case
{
  std::string Path;
  std::string Extension;
  size_t Seed;
  int Round;
};

// Reads the cases in child processes (forking once per case costs more than the read): a child
// reads them one after the other under a memory limit, each with its own time limit, and says in
// shared memory which case it is on. A crash, hang or broken rule ends the child; the parent
// reports that case and goes on with the next one in a new child. Returns the failures.
int ReadCases(const std::vector<Case>& cases, const std::string& folder, int& kept)
{
  auto* current = static_cast<volatile size_t*>(
    ::mmap(nullptr, sizeof(size_t), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  if (current == MAP_FAILED)
  {
    std::printf("FAILED: no shared memory for the fuzz children\n");
    return 1;
  }
  int failures = 0;
  for (size_t next = 0; next < cases.size();)
  {
    *current = next;
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0)
    {
#ifndef FEATUREPOINTS_FUZZ_ASAN
      // An address sanitizer reserves terabytes of address space: no memory limit under it.
      const rlimit memory = { rlim_t(1) << 30, rlim_t(1) << 30 };
      ::setrlimit(RLIMIT_AS, &memory);
#endif
      const rlimit core = { 0, 0 };
      ::setrlimit(RLIMIT_CORE, &core);
      // The project's readers report nothing as a warning that is an error (skipped NaN points,
      // list properties): the batches' output stays readable.
      vtkNew<QuietOutputWindow> quiet;
      vtkOutputWindow::SetInstance(quiet);
      for (size_t i = next; i < cases.size(); ++i)
      {
        *current = i;
        ::alarm(30); // a hang ends here, as SIGALRM
        const int code = CheckRead(cases[i].Path);
        if (code != ChildOk)
        {
          std::_Exit(code);
        }
      }
      std::_Exit(ChildOk);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == ChildOk)
    {
      break;
    }
    const size_t bad = *current;
    ++failures;
    const Case& c = cases[bad];
    const std::string keep = folder + "/fuzz-failure-" + std::to_string(kept++) + "." + c.Extension;
    std::ifstream in(c.Path, std::ios::binary);
    std::ofstream out(keep, std::ios::binary | std::ios::trunc);
    out << in.rdbuf();
    std::printf("FAILED: %s (seed %zu, round %d): %s %d\n", keep.c_str(), c.Seed, c.Round,
      WIFSIGNALED(status) ? "killed by signal" : "exit code",
      WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    next = bad + 1;
  }
  ::munmap(const_cast<size_t*>(current), sizeof(size_t));
  return failures;
}
} // namespace

int TestPointCloudIOFuzz(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  const int perSeed = argc > 2 ? std::atoi(argv[2]) : 150;
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  // VTK's readers loop on some mutations: they end in a message after this long (the files are
  // tiny; a hang is what the limit is for).
  vtkPointCloudIO::SetReaderTimeLimit(2.0);
  const std::vector<Seed> seeds = Seeds(folder);
  int failures = seeds.size() == 18 ? 0 : 1;
  std::mt19937 rng(20240523);
  const auto start = std::chrono::steady_clock::now();
  int cases = 0, kept = 0;
  std::vector<int> perFormat(seeds.size(), 0);
  std::vector<Case> batch;
  constexpr size_t BatchSize = 500;
  auto flush = [&]() {
    failures += ReadCases(batch, folder, kept);
    for (const Case& c : batch)
    {
      std::remove(c.Path.c_str());
    }
    batch.clear();
  };
  for (int round = 0; round < perSeed * NewFormatWeight; ++round)
  {
    for (size_t s = 0; s < seeds.size(); ++s)
    {
      const Seed& seed = seeds[s];
      if (round >= perSeed * seed.Weight)
      {
        continue;
      }
      // Round 0 reads the seed itself, which must read.
      const std::string bytes = round == 0 ? seed.Bytes : Mutate(seed.Bytes, rng);
      const std::string path = folder + "/fuzz-" + std::to_string(s) + "." + seed.Extension;
      const bool vtkFormat =
        seed.Extension == "vtp" || seed.Extension == "vtu" || seed.Extension == "vtk";
      if (round == 0)
      {
        Spit(path, bytes);
        std::string error;
        // The organized PCD seed's NaN points are skipped with a warning (VTK's readers keep
        // theirs: the legacy reader's warnings are errors).
        vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
        vtkNew<QuietOutputWindow> quiet;
        if (!vtkFormat)
        {
          vtkOutputWindow::SetInstance(quiet);
        }
        const bool read = vtkPointCloudIO::Read(path, error) != nullptr;
        vtkOutputWindow::SetInstance(previous);
        if (!read)
        {
          std::printf("FAILED: the seed %s does not read: %s\n", path.c_str(), error.c_str());
          ++failures;
        }
        std::remove(path.c_str());
        continue;
      }
      ++cases;
      ++perFormat[s];
      if (vtkFormat)
      {
        // Read() runs VTK's readers in a child process of its own, under its limits: a crash
        // or a hang there must come back as one line, here.
        Spit(path, bytes);
        std::string error;
        const auto begin = std::chrono::steady_clock::now();
        vtkSmartPointer<vtkPointSet> cloud = vtkPointCloudIO::Read(path, error);
        const double took =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        const bool oneLine = cloud ||
          (!error.empty() && error.find('\n') == std::string::npos &&
            error.compare(0, path.size(), path) == 0);
        if (!oneLine || took > 10.0)
        {
          ++failures;
          const std::string keep =
            folder + "/fuzz-failure-" + std::to_string(kept++) + "." + seed.Extension;
          Spit(keep, bytes);
          std::printf("FAILED: %s (seed %zu, round %d): %.1f s, message [%s]\n", keep.c_str(), s,
            round, took, error.c_str());
        }
        continue;
      }
      // The project's readers: in batches, each file under its own name.
      const std::string casePath =
        folder + "/fuzz-case-" + std::to_string(batch.size()) + "." + seed.Extension;
      Spit(casePath, bytes);
      batch.push_back({ casePath, seed.Extension, s, round });
      if (batch.size() == BatchSize)
      {
        flush();
      }
    }
  }
  flush();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int pcd = 0, las = 0;
  for (size_t s = 0; s < seeds.size(); ++s)
  {
    pcd += seeds[s].Extension == "pcd" ? perFormat[s] : 0;
    las += seeds[s].Extension == "las" ? perFormat[s] : 0;
  }
  std::printf("%d mutated files of %zu seeds (%d PCD, %d LAS) read in %.1f s, %d failure(s)\n",
    cases, seeds.size(), pcd, las, seconds, failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
