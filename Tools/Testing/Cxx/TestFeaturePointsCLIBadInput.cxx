// The featurepoints command on hostile input, run as a child process under a deadline:
//
//   TestFeaturePointsCLIBadInput PROGRAM FOLDER
//
// Huge declared counts, stacks of coincident points, files of 100,000 columns, cut or corrupt
// legacy VTK files, clouds scaled to 1e-300 and 1e300, signals during the run, a FIFO, VTK's
// many-line errors, a dropped column, oversized pictures and thread counts, PCD and LAS files that
// are cut, lie about their counts, sizes or types, or are compressed LAS (LAZ). Each case checks its
// exit code, its one-line message, its time, and that no file is left behind.
#include "FeaturePointsTestFiles.h"
#include "LASTestFile.h"

#include "vtkBase64Utilities.h"
#include "vtkDataArray.h"
#include "vtkFeatureModelSource.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataWriter.h"

#include <cctype>
#include <dirent.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace fptest;
std::string Program, Folder;

std::string Path(const std::string& name)
{
  return Folder + "/" + name;
}

struct Run
{
  int Code = -1;
  bool TimedOut = false;
  double Seconds = 0.0;
  std::string Out, Err;
};

struct Limits
{
  double Timeout = 60.0;       // killed after this long (TimedOut)
  double SignalAfter = -1.0;   // seconds after the start at which to send Signal
  int Signal = 0;
  std::string SignalOnMessage; // or as soon as stderr holds this text
  long FileSizeLimit = -1;     // RLIMIT_FSIZE in bytes
  long MemoryLimit = -1;       // RLIMIT_AS in bytes (a run past it fails to allocate)
  std::string StandardOutput;  // a file for stdout instead of the captured one (/dev/full)
};

// Runs the program with these arguments, stdout and stderr captured.
Run Execute(const std::vector<std::string>& arguments, const Limits& limits = Limits())
{
  std::vector<std::string> all = { Program };
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : all)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  const std::string out = Folder + "/../bad-input-stdout.txt";
  const std::string err = Folder + "/../bad-input-stderr.txt";
  std::fflush(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    const std::string& to = limits.StandardOutput.empty() ? out : limits.StandardOutput;
    const int o = ::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (limits.FileSizeLimit >= 0)
    {
      const rlimit size = { static_cast<rlim_t>(limits.FileSizeLimit),
        static_cast<rlim_t>(limits.FileSizeLimit) };
      ::setrlimit(RLIMIT_FSIZE, &size);
    }
    if (limits.MemoryLimit >= 0)
    {
      const rlimit memory = { static_cast<rlim_t>(limits.MemoryLimit),
        static_cast<rlim_t>(limits.MemoryLimit) };
      ::setrlimit(RLIMIT_AS, &memory);
    }
    ::execv(Program.c_str(), argv.data());
    ::_exit(127);
  }
  Run run;
  bool signalled = false;
  int status = 0;
  for (;;)
  {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    run.Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == pid)
    {
      break;
    }
    if (!signalled && limits.Signal &&
      ((limits.SignalAfter >= 0.0 && run.Seconds >= limits.SignalAfter) ||
        (!limits.SignalOnMessage.empty() &&
          Slurp(err).find(limits.SignalOnMessage) != std::string::npos)))
    {
      ::kill(pid, limits.Signal);
      signalled = true;
    }
    if (run.Seconds > limits.Timeout)
    {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      run.TimedOut = true;
      break;
    }
    ::usleep(2000);
  }
  run.Code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.Out = Slurp(out);
  run.Err = Slurp(err);
  ::unlink(out.c_str());
  ::unlink(err.c_str());
  return run;
}

// The lines of stderr that are not progress lines ("featurepoints: reading..." and the like).
std::vector<std::string> Messages(const std::string& err)
{
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
  {
    if (line.size() < 3 || line.compare(line.size() - 3, 3, "...") != 0)
    {
      lines.push_back(line);
    }
  }
  return lines;
}

// A failed run: its code, one message line holding `expected` (and the usage hint for code 2),
// no VTK log text, no new file, and done within `seconds`.
void ExpectFailure(const std::string& what, const std::vector<std::string>& arguments, int code,
  const std::string& expected, double seconds = 20.0, const Limits& given = Limits())
{
  const std::set<std::string> before = Entries(Folder);
  Limits limits = given;
  limits.Timeout = std::max(limits.Timeout, seconds + 30.0);
  const Run run = Execute(arguments, limits);
  const std::vector<std::string> lines = Messages(run.Err);
  Check(!run.TimedOut && run.Seconds < seconds,
    what + ": took " + std::to_string(run.Seconds) + " s, at most " + std::to_string(seconds));
  Check(run.Code == code,
    what + ": exit code " + std::to_string(run.Code) + ", expected " + std::to_string(code));
  Check(lines.size() == (code == 2 ? 2u : 1u),
    what + ": " + std::to_string(lines.size()) + " message lines: " + run.Err);
  Check(!lines.empty() && lines[0].compare(0, 15, "featurepoints: ") == 0 &&
      lines[0].find(expected) != std::string::npos,
    what + ": the message lacks '" + expected + "': " + run.Err);
  Check(run.Err.find("ERROR: In") == std::string::npos && run.Err.find("ERR|") == std::string::npos &&
      run.Err.find("vtkExecutive") == std::string::npos,
    what + ": VTK's raw error text leaked: " + run.Err);
  Check(Entries(Folder) == before, what + ": files left behind by a failed run");
}

// A run that must succeed within `seconds`; returns it.
Run ExpectSuccess(const std::string& what, const std::vector<std::string>& arguments,
  double seconds = 20.0, const Limits& given = Limits())
{
  Limits limits = given;
  limits.Timeout = seconds + 30.0;
  const Run run = Execute(arguments, limits);
  Check(!run.TimedOut && run.Seconds < seconds,
    what + ": took " + std::to_string(run.Seconds) + " s, at most " + std::to_string(seconds));
  Check(run.Code == 0, what + ": exit code " + std::to_string(run.Code) + ": " + run.Err);
  return run;
}

// Whether a file written by the program has a NaN or an infinity in any of its arrays.
bool HasNonFinite(const std::string& file)
{
  std::string error;
  vtkSmartPointer<vtkPointSet> data = vtkPointCloudIO::Read(file, error);
  if (!data)
  {
    return true;
  }
  vtkPointData* pd = data->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
    {
      if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
            static_cast<int>(i % array->GetNumberOfComponents()))))
      {
        return true;
      }
    }
  }
  return false;
}

std::vector<unsigned char> MaskOf(const std::string& file)
{
  std::string error;
  vtkSmartPointer<vtkPointSet> data = vtkPointCloudIO::Read(file, error);
  auto* mask = data
    ? vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetArray("FeatureMask"))
    : nullptr;
  std::vector<unsigned char> values;
  for (vtkIdType i = 0; mask && i < mask->GetNumberOfTuples(); ++i)
  {
    values.push_back(mask->GetValue(i));
  }
  return values;
}

// The points of a model of vtkFeatureModelSource as "x y z" lines, each coordinate multiplied by
// `scale` (a power of two scales exactly).
std::string ModelText(int model, vtkIdType n, double scale)
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(n);
  source->Update();
  vtkPoints* points = source->GetOutput()->GetPoints();
  std::ostringstream text;
  text.precision(17);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    text << x[0] * scale << " " << x[1] * scale << " " << x[2] * scale << "\n";
  }
  return text.str();
}

std::string Repeat(const std::string& line, int times)
{
  std::string out;
  out.reserve(line.size() * times);
  for (int i = 0; i < times; ++i)
  {
    out += line;
  }
  return out;
}

void HugeCounts()
{
  std::string points;
  for (int i = 0; i < 100; ++i)
  {
    points += std::to_string(i % 7) + " " + std::to_string(i % 5) + " " + std::to_string(i) + " ";
  }
  Spit(Path("huge.vtp"),
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
    "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\"1000000000000\" "
    "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n"
    "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n" +
      points + "\n</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n");
  ExpectFailure("VTP declaring 10^12 points", { Path("huge.vtp"), Path("o.vtp") }, 1,
    "huge.vtp: an unnamed array declares NumberOfComponents=\"3\" for 1000000000000 points");
  // NumberOfComponents 2^32: VTK's reader spun until the 60 s limit (2^31 - 1: 16 GB).
  Spit(Path("components.vtp"),
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
    "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\"100\" "
    "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n"
    "<DataArray type=\"Float32\" NumberOfComponents=\"4294967296\" format=\"ascii\">\n" +
      points + "\n</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n");
  ExpectFailure("VTP declaring 2^32 components", { Path("components.vtp"), Path("o.vtp") }, 1,
    "components.vtp: an unnamed array declares NumberOfComponents=\"4294967296\" for 100 points");
  // Counts VTK's reader misreads: one beyond 64 bits ("missing its NumberOfPoints attribute"), a
  // negative one ("the data array ... may be too short"), and fewer points than the ASCII array
  // holds (read silently, the rest dropped).
  auto piece = [&points](const std::string& count) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\"" +
      count +
      "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      "<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n" +
      points + "\n</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  };
  Spit(Path("overflow.vtp"), piece("99999999999999999999"));
  ExpectFailure("VTP declaring 10^20 points", { Path("overflow.vtp"), Path("o.vtp") }, 1,
    "overflow.vtp: piece 0 declares NumberOfPoints=\"99999999999999999999\": not a whole number "
    "from 0 to 2^63 - 1");
  Spit(Path("negative.vtp"), piece("-3"));
  ExpectFailure("VTP declaring -3 points", { Path("negative.vtp"), Path("o.vtp") }, 1,
    "negative.vtp: piece 0 declares NumberOfPoints=\"-3\"");
  Spit(Path("fewer.vtp"), piece("60"));
  ExpectFailure("ASCII VTP declaring fewer points than it holds", { Path("fewer.vtp"),
    Path("o.vtp") }, 1, "fewer.vtp: a piece declares NumberOfPoints=\"60\", but its ASCII Points "
                        "array holds 300 values, 100 points");
  Spit(Path("exact.vtp"), piece(" 100 "));
  ExpectSuccess("ASCII VTP declaring \" 100 \" points", { Path("exact.vtp"), Path("o.vtp"), "--quiet" });
  Spit(Path("huge.vtk"),
    "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 1000000000000 float\n0 0 0 "
    "1 0 0 0 1 0\n");
  ExpectFailure("legacy VTK declaring 10^12 points", { Path("huge.vtk"), Path("o.vtp") }, 1,
    "huge.vtk:5: the POINTS line declares 1000000000000 points, more than the file's 97 bytes can "
    "hold");
  Spit(Path("huge.ply"),
    "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n" + std::string(120, '\0'));
  ExpectFailure("PLY declaring 10^12 vertices", { Path("huge.ply"), Path("o.vtp") }, 1,
    "huge.ply");
}

// Hostile files a fuzzing run found: a NaN or an infinity in an attribute (coordinates are
// checked by the readers), element counts past 2^64, a legacy file whose tiny body declares a
// billion cells (took all the memory of the machine for a minute), array names that a CSV
// file would repeat.
void FuzzedFiles()
{
  const std::string body = ModelText(1, 1500, 1.0);
  std::string binary;
  std::istringstream in(body);
  for (std::string line; std::getline(in, line);)
  {
    std::istringstream fields(line);
    float v[4] = { 0.0f, 0.0f, 0.0f, std::numeric_limits<float>::quiet_NaN() };
    fields >> v[0] >> v[1] >> v[2];
    binary.append(reinterpret_cast<const char*>(v), sizeof(v)); // little-endian machines
  }
  Spit(Path("nan-attribute.ply"),
    "ply\nformat binary_little_endian 1.0\nelement vertex 1500\nproperty float x\n"
    "property float y\nproperty float z\nproperty float nx\nend_header\n" + binary);
  ExpectFailure("PLY with a NaN attribute", { Path("nan-attribute.ply"), Path("o.csv") }, 1,
    "nan-attribute.ply: point 0 (counting from 0): point array 'nx' holds nan");
  Spit(Path("count-2e64.ply"),
    "ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n" + body);
  ExpectFailure("PLY count past 2^64", { Path("count-2e64.ply"), Path("o.vtp") }, 1,
    "count '18446744073709551616' is beyond any file");
  Spit(Path("count-2e63.pts"), "9223372036854775808\n" + body);
  ExpectFailure("PTS count past 2^63", { Path("count-2e63.pts"), Path("o.vtp") }, 1,
    "count-2e63.pts:1: the PTS count line says 9223372036854775808 points");
  Spit(Path("billion-cells.vtk"),
    "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 1500 float\n" + body +
      "VERTICES 1000000000 2000000000\n1 0\n");
  ExpectFailure("legacy VTK declaring 10^9 cells", { Path("billion-cells.vtk"), Path("o.vtp") }, 1,
    "billion-cells.vtk: the VERTICES block (line 1506) declares 1000000000 cells; the file ends "
    "after 1 of them",
    10.0);
  // A zlib-compressed VTP whose first block header declares blocks of 0 bytes: VTK's reader
  // divides by it (a floating-point exception in its child process); refused with the array named.
  {
    vtkNew<vtkFeatureModelSource> part;
    part->SetNumberOfPoints(1500);
    vtkNew<vtkXMLPolyDataWriter> zlib;
    zlib->SetInputConnection(part->GetOutputPort());
    zlib->SetFileName(Path("zlib.vtp").c_str());
    zlib->SetDataModeToAppended();
    zlib->EncodeAppendedDataOff();
    zlib->SetHeaderTypeToUInt32();
    zlib->Write();
    ExpectSuccess("a zlib-compressed VTP", { Path("zlib.vtp"), Path("zlib.csv"), "--quiet" });
    std::string zero = Slurp(Path("zlib.vtp"));
    const size_t data = zero.find("<AppendedData encoding=\"raw\">");
    const size_t underscore = data == std::string::npos ? data : zero.find('_', data);
    Check(underscore != std::string::npos, "zlib.vtp: no raw appended data");
    if (underscore != std::string::npos)
    {
      // The first array's header (offset 0): blocks, block size, last block's size, ...
      std::fill_n(zero.begin() + static_cast<std::ptrdiff_t>(underscore + 1 + 4), 4, '\0');
      Spit(Path("zlib-zero.vtp"), zero);
      ExpectFailure("a zlib VTP declaring blocks of 0 bytes", { Path("zlib-zero.vtp"), Path("o.csv") },
        1, "at appended offset 0 declares 1 compressed block(s) of 0 bytes");
    }
  }
  // A VTP with raw appended data cut short: VTK's reader fills the missing points with zeros and
  // says nothing; the command refuses it.
  {
    vtkNew<vtkFeatureModelSource> part;
    part->SetNumberOfPoints(1500);
    vtkNew<vtkXMLPolyDataWriter> raw;
    raw->SetInputConnection(part->GetOutputPort());
    raw->SetFileName(Path("raw.vtp").c_str());
    raw->SetDataModeToAppended();
    raw->EncodeAppendedDataOff();
    raw->SetCompressorTypeToNone();
    raw->Write();
    ExpectSuccess("a raw appended VTP", { Path("raw.vtp"), Path("raw.csv"), "--quiet" });
    const std::string whole = Slurp(Path("raw.vtp"));
    Spit(Path("raw-cut.vtp"), whole.substr(0, whole.size() - 1000));
    ExpectFailure("a raw appended VTP cut short", { Path("raw-cut.vtp"), Path("o.csv") }, 1,
      "but the file ends at byte " + std::to_string(whole.size() - 1000) +
        ": the file is cut short");
    // NumberOfPoints below the Points array's size: VTK reads the first ones and says nothing.
    std::string fewer = whole;
    const size_t declared = fewer.find("NumberOfPoints=\"1500\"");
    Check(declared != std::string::npos, "raw.vtp: no NumberOfPoints=\"1500\"");
    if (declared != std::string::npos)
    {
      fewer.replace(declared, 22, "NumberOfPoints=\"1400\"");
      Spit(Path("raw-fewer.vtp"), fewer);
      ExpectFailure("a raw appended VTP declaring fewer points", { Path("raw-fewer.vtp"),
        Path("o.csv") }, 1, "a piece declares NumberOfPoints=\"1400\", but its Points array "
                            "holds 36000 bytes, 1500 points");
    }
    // 8-byte size fields under header_type="UInt32" (VTK's reader ran out of memory).
    raw->SetHeaderTypeToUInt64();
    raw->SetFileName(Path("raw64.vtp").c_str());
    raw->Write();
    ExpectSuccess("a raw appended VTP with 8-byte sizes", { Path("raw64.vtp"), Path("raw.csv"),
                                                            "--quiet" });
    std::string narrowed = Slurp(Path("raw64.vtp"));
    const size_t wide64 = narrowed.find("header_type=\"UInt64\"");
    Check(wide64 != std::string::npos, "raw64.vtp: no header_type=\"UInt64\"");
    if (wide64 != std::string::npos)
    {
      narrowed.replace(wide64, 20, "header_type=\"UInt32\"");
      Spit(Path("raw64-as-32.vtp"), narrowed);
      ExpectFailure("8-byte sizes read as 4-byte ones", { Path("raw64-as-32.vtp"),
        Path("o.csv") }, 1, "raw64-as-32.vtp: every raw appended block leaves 4 bytes unread "
                            "before the next: its size fields are 8 bytes wide");
    }
    ::unlink(Path("raw.csv").c_str());
    // 4-byte size fields under header_type="UInt64": each size takes in the 4 bytes after it.
    // Where those are zeros (an array whose first value is 0), the size reads right and VTK's
    // reader reads the data 4 bytes late; the block then runs into the next one.
    part->Update();
    vtkNew<vtkPolyData> zeros;
    zeros->SetPoints(part->GetOutput()->GetPoints());
    vtkNew<vtkFloatArray> w;
    w->SetName("w");
    w->SetNumberOfTuples(zeros->GetNumberOfPoints());
    w->FillValue(0.0f);
    zeros->GetPointData()->AddArray(w);
    vtkNew<vtkXMLPolyDataWriter> narrow;
    narrow->SetInputData(zeros);
    narrow->SetFileName(Path("raw32.vtp").c_str());
    narrow->SetDataModeToAppended();
    narrow->EncodeAppendedDataOff();
    narrow->SetCompressorTypeToNone();
    narrow->SetHeaderTypeToUInt32();
    narrow->Write();
    ExpectSuccess("a raw appended VTP with 4-byte sizes", { Path("raw32.vtp"), Path("raw.csv"),
                                                            "--quiet" });
    // Attributes as VTK's reader reads them: an offset with a '+', and text like an attribute
    // inside another attribute's value.
    std::string odd = Slurp(Path("raw32.vtp"));
    const size_t named = odd.find("Name=\"w\"");
    const size_t zero = odd.find("offset=\"0\"");
    Check(named != std::string::npos && zero != std::string::npos, "raw32.vtp: no w at offset 0");
    if (named != std::string::npos && zero != std::string::npos)
    {
      odd.replace(zero, 10, "offset=\"+0\"");
      odd.replace(named, 8, "Name=\"w offset='99999999'\"");
      Spit(Path("raw32-odd.vtp"), odd);
      ExpectSuccess("a raw appended VTP with odd attributes", { Path("raw32-odd.vtp"),
                                                                Path("raw.csv"), "--quiet" });
    }
    std::string wide = Slurp(Path("raw32.vtp"));
    const size_t header = wide.find("header_type=\"UInt32\"");
    Check(header != std::string::npos, "raw32.vtp: no header_type=\"UInt32\"");
    if (header != std::string::npos)
    {
      wide.replace(header, 20, "header_type=\"UInt64\"");
      Spit(Path("raw32-as-64.vtp"), wide);
      ExpectFailure("4-byte sizes read as 8-byte ones", { Path("raw32-as-64.vtp"),
        Path("o.csv") }, 1, "array 'w' at appended offset 0 holds 6000 bytes after its 8-byte size, "
                            "more than the 5996 bytes before the next block, at offset 6004: its "
                            "size field (header_type UInt64) does not match the data");
    }
    ::unlink(Path("raw.csv").c_str());
  }
  // Array names a CSV header would repeat or read as components: an input array named x (a CSV
  // header with x twice), one-component arrays named "Normals:0" and "t:1" beside the output's own
  // Normals. The output names each column once and reads back.
  vtkNew<vtkFeatureModelSource> source;
  source->SetNumberOfPoints(1500);
  source->Update();
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(source->GetOutput()->GetPoints());
  for (const char* name : { "x", "Normals:0", "t:1" })
  {
    vtkNew<vtkFloatArray> array;
    array->SetName(name);
    array->SetNumberOfTuples(cloud->GetNumberOfPoints());
    array->FillValue(1.0f);
    cloud->GetPointData()->AddArray(array);
  }
  std::string error;
  Check(vtkPointCloudIO::Write(cloud, Path("names.vtp"), error), "names.vtp: " + error);
  ExpectSuccess("names like columns", { Path("names.vtp"), Path("names.csv"), "--quiet" });
  const std::string out = Slurp(Path("names.csv"));
  const std::string header = out.substr(0, out.find('\n'));
  Check(header.find(",x_2,") != std::string::npos && header.find(",t_1,") != std::string::npos &&
      header.find(",Normals_0,") != std::string::npos,
    "names like columns: CSV header " + header);
  ExpectSuccess("names like columns, read back", { Path("names.csv"), Path("names-again.csv"),
                                                   "--quiet" });
  // A NUL inside a number (binary data, not text) and a 5,000-digit field: the message stays one
  // short, whole line.
  const size_t fifth = [&]() {
    size_t at = 0;
    for (int line = 0; line < 4; ++line)
    {
      at = body.find('\n', at) + 1;
    }
    return at;
  }();
  std::string nul = body;
  nul.insert(fifth + 1, 1, '\0');
  Spit(Path("nul.xyz"), nul);
  ExpectFailure("a NUL in a number", { Path("nul.xyz"), Path("o.vtp") }, 1,
    "nul.xyz:5: binary data (a NUL byte at byte " + std::to_string(fifth + 1) +
      "), not a text file");
  Spit(Path("long.xyz"), std::string(5000, '1') + " 0 0\n" + body);
  ExpectFailure("a 5,000-digit field", { Path("long.xyz"), Path("o.vtp") }, 1, "1111... (500");
  // An output name within 8 bytes of the longest a folder takes: the temporary file gets a
  // short name.
  const long nameMax = ::pathconf(Folder.c_str(), _PC_NAME_MAX);
  const std::string longest =
    std::string(static_cast<size_t>(nameMax > 16 ? nameMax : 255) - 9, 'a') + ".csv";
  ExpectSuccess("an output name 5 bytes short of the longest", { Path("names.csv"), Path(longest),
                                                                "--quiet" });
  Check(!Slurp(Path(longest)).empty(), "an output name 5 bytes short of the longest: not written");
  // An output that is a symbolic link is written through it; the link stays.
  ::mkdir(Path("linked").c_str(), 0755);
  Spit(Path("linked/target.csv"), "old\n");
  ::unlink(Path("link.csv").c_str());
  Check(::symlink("linked/target.csv", Path("link.csv").c_str()) == 0, "cannot make link.csv");
  ExpectSuccess("an output through a link", { Path("names.csv"), Path("link.csv"), "--quiet" });
  struct stat link;
  Check(::lstat(Path("link.csv").c_str(), &link) == 0 && S_ISLNK(link.st_mode),
    "an output through a link: the link was replaced");
  Check(Slurp(Path("linked/target.csv")).compare(0, 6, "x,y,z,") == 0,
    "an output through a link: the target was not written");
  // A link to a file not there yet: written through as well (it was replaced by a file).
  ::unlink(Path("dangling.csv").c_str());
  ::unlink(Path("linked/new.csv").c_str());
  Check(::symlink("linked/new.csv", Path("dangling.csv").c_str()) == 0, "cannot make dangling.csv");
  ExpectSuccess("an output through a dangling link", { Path("names.csv"), Path("dangling.csv"), "--quiet" });
  Check(::lstat(Path("dangling.csv").c_str(), &link) == 0 && S_ISLNK(link.st_mode) &&
      Slurp(Path("linked/new.csv")).compare(0, 6, "x,y,z,") == 0,
    "an output through a dangling link: the link was replaced or its target not written");
}

// VTP files with binary (base64) data cut short, inline or appended: VTK's reader fills the
// missing values with zeros and says nothing; the command refuses them.
void Base64Files()
{
  vtkNew<vtkFeatureModelSource> part;
  part->SetNumberOfPoints(1500);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(part->GetOutputPort());
  writer->SetCompressorTypeToNone();
  writer->SetHeaderTypeToUInt64();
  writer->SetDataModeToBinary();
  writer->SetFileName(Path("inline.vtp").c_str());
  writer->Write();
  ExpectSuccess("an inline binary VTP", { Path("inline.vtp"), Path("inline.csv"), "--quiet" });
  const std::string whole = Slurp(Path("inline.vtp"));
  // The Points array's text: from its tag's end to the next tag (its InformationKeys).
  const size_t points = whole.find("<Points>");
  const size_t open = points == std::string::npos ? points : whole.find('>', points + 8);
  size_t close = open == std::string::npos ? open : whole.find('<', open);
  while (close != std::string::npos && close > open &&
    (std::isspace(whole[close - 1]) || whole[close - 1] == '='))
  {
    --close;
  }
  Check(close != std::string::npos && close > open + 1000, "inline.vtp: no Points array");
  if (close != std::string::npos && close > open + 1000)
  {
    // 36,000 bytes of points after their 8-byte size field, in 48,000 characters after the
    // field's 12: 400 fewer hold 35,700 bytes.
    std::string cut = whole;
    cut.erase(close - 400, 400);
    Spit(Path("inline-cut.vtp"), cut);
    ExpectFailure("an inline binary VTP cut short", { Path("inline-cut.vtp"), Path("o.csv") }, 1,
      "inline-cut.vtp: array 'Points' declares 36000 bytes of binary (base64) data, but its text "
      "holds 35700 after its size field: the file is cut short");
  }
  std::string fewer = whole;
  const size_t declared = fewer.find("NumberOfPoints=\"1500\"");
  Check(declared != std::string::npos, "inline.vtp: no NumberOfPoints=\"1500\"");
  if (declared != std::string::npos)
  {
    fewer.replace(declared, 22, "NumberOfPoints=\"1400\"");
    Spit(Path("inline-fewer.vtp"), fewer);
    ExpectFailure("an inline binary VTP declaring fewer points", { Path("inline-fewer.vtp"),
      Path("o.csv") }, 1, "a piece declares NumberOfPoints=\"1400\", but its Points array "
                          "holds 36000 bytes, 1500 points");
  }
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOn();
  writer->SetFileName(Path("base64.vtp").c_str());
  writer->Write();
  ExpectSuccess("a base64 appended VTP", { Path("base64.vtp"), Path("base64.csv"), "--quiet" });
  const std::string encoded = Slurp(Path("base64.vtp"));
  // The Points block's size field (12 characters at its offset) made to declare 3,000 bytes
  // more than the block holds before the next one.
  std::string grown = encoded;
  const size_t tag = grown.find("<DataArray", grown.find("<Points>"));
  const size_t at = tag == std::string::npos ? tag : grown.find("offset=\"", tag);
  const size_t data = grown.find("<AppendedData encoding=\"base64\">");
  const size_t underscore = data == std::string::npos ? data : grown.find('_', data);
  Check(at != std::string::npos && underscore != std::string::npos,
    "base64.vtp: no Points offset or appended data");
  if (at != std::string::npos && underscore != std::string::npos)
  {
    const size_t offset = std::stoul(grown.substr(at + 8));
    const unsigned char size[8] = { 0x58, 0x98, 0, 0, 0, 0, 0, 0 }; // 39,000, little-endian
    unsigned char field[13] = { 0 };
    vtkBase64Utilities::Encode(size, 8, field);
    grown.replace(underscore + 1 + offset, 12, reinterpret_cast<const char*>(field), 12);
    Spit(Path("base64-grown.vtp"), grown);
    ExpectFailure("a base64 appended VTP whose size field overruns its block",
      { Path("base64-grown.vtp"), Path("o.csv") }, 1,
      "array 'Points' at appended offset " + std::to_string(offset) +
        " declares 39000 bytes, more than the 48012 base64 characters before the next block");
  }
}

// The number after "features" in a run's summary (-1: none).
long SummaryFeatures(const std::string& out)
{
  const size_t at = out.find("\nfeatures ");
  return at == std::string::npos ? -1 : std::atol(out.c_str() + at + 10);
}

void CompressedFiles()
{
  // Data that do not decompress with the compressor the file declares: VTK says only "Unknown
  // error" for zlib data declared LZMA, and prints zlib's "Zlib error while uncompressing data"
  // for corrupt LZ4 data too (found by fuzzing).
  vtkNew<vtkFeatureModelSource> part;
  part->SetNumberOfPoints(2000);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(part->GetOutputPort());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetFileName(Path("packed.vtp").c_str());
  writer->Write();
  ExpectSuccess("a VTP compressed with zlib", { Path("packed.vtp"), Path("packed.csv"), "--quiet" });
  ::unlink(Path("packed.csv").c_str());
  std::string whole = Slurp(Path("packed.vtp"));
  const size_t declared = whole.find("vtkZLibDataCompressor");
  Check(declared != std::string::npos, "packed.vtp: no compressor attribute");
  if (declared != std::string::npos)
  {
    whole.replace(declared, 21, "vtkLZMADataCompressor");
    Spit(Path("declared.vtp"), whole);
    ExpectFailure("a VTP of zlib data that declares LZMA", { Path("declared.vtp"), Path("o.csv") },
      1,
      "declared.vtp: cannot read: its data do not decompress with vtkLZMADataCompressor, the "
      "compressor it declares");
    ::unlink(Path("declared.vtp").c_str());
  }
  ::unlink(Path("packed.vtp").c_str());
}

void XMLPointsArrays()
{
  // VTK reads a String-typed Points array as no point at all, and says of a word in an ASCII
  // Points array only that the array "may be too short" (found by fuzzing).
  const std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
                           "byte_order=\"LittleEndian\">\n<PolyData><Piece NumberOfPoints=\"3\" "
                           "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                           "NumberOfPolys=\"0\">\n<Points><DataArray type=\"";
  const std::string tail = "</DataArray></Points>\n</Piece></PolyData></VTKFile>\n";
  Spit(Path("string-points.vtp"),
    head + "String\" NumberOfComponents=\"3\" format=\"ascii\">48 0 48 0 48 0 48 0 48 0" + tail);
  ExpectFailure("a VTP whose Points array holds strings",
    { Path("string-points.vtp"), Path("o.csv") }, 1,
    "string-points.vtp: cannot read: its Points array is of type String, which holds no "
    "coordinates");
  Spit(Path("word-points.vtp"),
    head + "Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 +1 0 0 abc 1 0" + tail);
  ExpectFailure("a VTP with a word among its ASCII points",
    { Path("word-points.vtp"), Path("o.csv") }, 1,
    "word-points.vtp: cannot read: its ASCII Points array holds 'abc' as value 6 (point 2, "
    "counting from 0), not a number");
  ::unlink(Path("string-points.vtp").c_str());
  ::unlink(Path("word-points.vtp").c_str());
  // A String array of point data that holds fewer strings than points: VTK's reader crashed
  // ("VTK's reader failed on the file (Segmentation fault)"). The cloud is read without it, with
  // a warning that names it; a whole String array is kept.
  std::string points;
  for (int i = 0; i < 40; ++i)
  {
    points += std::to_string(i % 7) + " " + std::to_string(i % 5) + " " + std::to_string(i) + " ";
  }
  auto withLabels = [&points](const std::string& labels) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n<PolyData><Piece NumberOfPoints=\"40\" "
           "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
           "NumberOfPolys=\"0\">\n<PointData><DataArray type=\"String\" Name=\"a&amp;b\" "
           "format=\"ascii\">" +
      labels + "</DataArray>\n<DataArray type=\"Float32\" Name=\"f\" format=\"ascii\">" +
      Repeat("1 ", 40) +
      "</DataArray></PointData>\n<Points><DataArray type=\"Float32\" "
      "NumberOfComponents=\"3\" format=\"ascii\">" +
      points + "</DataArray></Points>\n</Piece></PolyData></VTKFile>\n";
  };
  auto arrays = [](const std::string& file) {
    std::string error, names = ",";
    vtkSmartPointer<vtkPointSet> data = vtkPointCloudIO::Read(file, error);
    for (int a = 0; data && a < data->GetPointData()->GetNumberOfArrays(); ++a)
    {
      const char* name = data->GetPointData()->GetArrayName(a);
      names += std::string(name ? name : "(none)") + ",";
    }
    return names;
  };
  Spit(Path("few-strings.vtp"), withLabels("97 0 98 0"));
  const Run few = ExpectSuccess("a VTP whose String array holds 2 strings for 40 points",
    { Path("few-strings.vtp"), Path("few-strings-out.vtp") });
  Check(few.Err.find("featurepoints: warning: " + Path("few-strings.vtp") +
          ": point array 'a&b' (type String) left out: VTK's reader crashes on it (") !=
        std::string::npos &&
      few.Err.find("it holds 2 strings for 40 points); the cloud is read without it") !=
        std::string::npos,
    "a VTP whose String array holds 2 strings: no warning naming it: " + few.Err);
  const std::string fewArrays = arrays(Path("few-strings-out.vtp"));
  Check(fewArrays.find(",f,") != std::string::npos && fewArrays.find("a&b") == std::string::npos,
    "a VTP whose String array holds 2 strings: output arrays " + fewArrays);
  Spit(Path("word-strings.vtp"), withLabels("nan 0" + Repeat(" 97 0", 39)));
  const Run word = ExpectSuccess("a VTP whose String array holds a word",
    { Path("word-strings.vtp"), Path("few-strings-out.vtp") });
  Check(word.Err.find("it holds 'nan' as value 0 (counting from 0), not a character's code") !=
      std::string::npos,
    "a VTP whose String array holds a word: no warning naming it: " + word.Err);
  Spit(Path("strings.vtp"), withLabels(Repeat("97 0 ", 40)));
  const Run whole = ExpectSuccess("a VTP with a whole String array",
    { Path("strings.vtp"), Path("few-strings-out.vtp") });
  Check(whole.Err.find("left out") == std::string::npos &&
      arrays(Path("few-strings-out.vtp")).find(",a&b,") != std::string::npos,
    "a VTP with a whole String array: not kept: " + whole.Err);
  // A string holding a NUL byte (a binary legacy file may hold one): VTK's XML writer wrote it as
  // it is, and VTK's XML reader crashed on the .vtp written. The array is left out of a .vtp
  // output, with a warning that names it.
  std::string legacy = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET POLYDATA\nPOINTS 40 float\n";
  for (int i = 0; i < 40; ++i)
  {
    for (const float v : { float(i % 7), float(i % 5), float(i) })
    {
      uint32_t bits = 0;
      std::memcpy(&bits, &v, 4);
      for (int shift = 24; shift >= 0; shift -= 8)
      {
        legacy += static_cast<char>((bits >> shift) & 0xFF);
      }
    }
  }
  legacy += "\nPOINT_DATA 40\nFIELD FieldData 1\ns 1 40 string\n";
  for (int i = 0; i < 40; ++i)
  {
    legacy += i == 1 ? std::string("\xC3" "a\0b", 4) : std::string("\xC2" "ab");
  }
  Spit(Path("nul-string.vtk"), legacy + "\n");
  const Run nul = ExpectSuccess("a string holding a NUL byte, to a VTP",
    { Path("nul-string.vtk"), Path("nul-string.vtp") });
  Check(nul.Err.find("featurepoints: warning: " + Path("nul-string.vtp") +
          ": point array 's' (type String) left out: its value 1 (counting from 0) holds a NUL "
          "byte, which a VTK XML file cannot hold") != std::string::npos,
    "a string holding a NUL byte: no warning naming it: " + nul.Err);
  Check(Slurp(Path("nul-string.vtp")).find("Name=\"s\"") == std::string::npos &&
      arrays(Path("nul-string.vtp")).find(",FeatureMask,") != std::string::npos,
    "a string holding a NUL byte: the .vtp written holds it, or does not read");
  for (const char* name : { "few-strings.vtp", "word-strings.vtp", "strings.vtp",
         "few-strings-out.vtp", "nul-string.vtk", "nul-string.vtp" })
  {
    ::unlink(Path(name).c_str());
  }
}

void FarOutliers()
{
  // A unit cube's surface, then the same with 1 % of its points replaced by points up to 1e200
  // away: the far points set the cloud's scale, which shrank the cube into underflow (at 1e200:
  // 40 feature points instead of 446, and an error after 24 s at 1e160). The cube's own points
  // must be found as without them; the far points are isolated.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::ostringstream cube, far;
  cube.precision(17);
  far.precision(17);
  for (int i = 0; i < 8000; ++i)
  {
    double x[3] = { u(rng), u(rng), u(rng) };
    const int face = i % 6;
    x[face / 2] = face % 2;
    cube << x[0] << " " << x[1] << " " << x[2] << "\n";
    if (i % 100 == 0)
    {
      far << (u(rng) - 0.5) * 1e200 << " " << (u(rng) - 0.5) * 1e200 << " " << u(rng) * 1e200
          << "\n";
    }
    else
    {
      far << x[0] << " " << x[1] << " " << x[2] << "\n";
    }
  }
  Spit(Path("cube.xyz"), cube.str());
  Spit(Path("far.xyz"), far.str());
  {
    // The cube scaled by 2^200 (exact): the method runs in a scaled frame and its arrays of a
    // length unit come back in the input's units, in double (PDI, an inverse length, was 0 in
    // float: 2^-200 lies below float's range).
    std::ostringstream big;
    big.precision(17);
    std::istringstream cubeRows(cube.str());
    for (double x, y, z; cubeRows >> x >> y >> z;)
    {
      big << std::ldexp(x, 200) << " " << std::ldexp(y, 200) << " " << std::ldexp(z, 200) << "\n";
    }
    Spit(Path("big.xyz"), big.str());
    ExpectSuccess("the cube scaled by 2^200, huang2023",
      { Path("big.xyz"), Path("big.vtp"), "--method", "huang2023" });
    ExpectSuccess("the cube, huang2023", { Path("cube.xyz"), Path("cube.vtp"), "--method", "huang2023" });
    std::string error;
    vtkSmartPointer<vtkPointSet> scaled = vtkPointCloudIO::Read(Path("big.vtp"), error);
    vtkSmartPointer<vtkPointSet> plain = vtkPointCloudIO::Read(Path("cube.vtp"), error);
    vtkDataArray* a = scaled ? scaled->GetPointData()->GetArray("PDI") : nullptr;
    vtkDataArray* b = plain ? plain->GetPointData()->GetArray("PDI") : nullptr;
    long off = 0, nonzero = 0;
    for (vtkIdType i = 0; a && b && i < b->GetNumberOfTuples(); ++i)
    {
      nonzero += b->GetTuple1(i) != 0.0;
      off += std::abs(std::ldexp(a->GetTuple1(i), 200) - b->GetTuple1(i)) >
        1e-6 * std::abs(b->GetTuple1(i));
    }
    std::printf("the cube scaled by 2^200: %ld of %ld PDI values off\n", off, nonzero);
    Check(a && b && nonzero > 0 && off == 0,
      "the cube scaled by 2^200: PDI not in the input's units (" + std::to_string(off) + " off)");
    ::unlink(Path("big.vtp").c_str());
    ::unlink(Path("cube.vtp").c_str());
  }
  const Run alone = ExpectSuccess("a cube", { Path("cube.xyz"), Path("cube.csv") });
  const Run mixed = ExpectSuccess("a cube with 1 % of its points near 1e200",
    { Path("far.xyz"), Path("far.csv") }, 20.0);
  const long a = SummaryFeatures(alone.Out), m = SummaryFeatures(mixed.Out);
  std::printf("a cube: %ld feature points; with 1 %% of its points near 1e200: %ld\n", a, m);
  Check(a > 300 && m >= 0.97 * 0.99 * a && m <= 1.03 * a,
    "a cube with far points: " + std::to_string(m) + " feature points, alone " + std::to_string(a));
  Check(mixed.Err.find("straight line") == std::string::npos &&
      mixed.Err.find("one plane") == std::string::npos,
    "a cube with far points: a false warning: " + mixed.Err);
  ::unlink(Path("cube.csv").c_str());
  ::unlink(Path("far.csv").c_str());

  // The cube scaled to 1e-60 and one point at 1e260: no power of two scales both into doubles
  // whose squares neither overflow nor underflow. The far point is skipped, and said to be too
  // far, not (as before, found by fuzzing) to have NaN or infinite coordinates.
  std::ostringstream tiny;
  tiny.precision(17);
  std::istringstream rows(cube.str());
  for (double x, y, z; rows >> x >> y >> z;)
  {
    tiny << x * 1e-60 << " " << y * 1e-60 << " " << z * 1e-60 << "\n";
  }
  tiny << "1e260 0 0\n";
  Spit(Path("tiny-far.xyz"), tiny.str());
  const Run scaled = ExpectSuccess(
    "a cube 1e-60 wide and a point at 1e260", { Path("tiny-far.xyz"), Path("tiny-far.csv") });
  Check(scaled.Err.find("1 point(s) lie too far from the rest of the cloud") != std::string::npos &&
      scaled.Err.find("the first is point 8000") != std::string::npos &&
      scaled.Err.find("NaN or infinite") == std::string::npos,
    "a cube 1e-60 wide and a point at 1e260: not told why the point is skipped: " + scaled.Err);
  const long t = SummaryFeatures(scaled.Out);
  Check(t == a, "a cube 1e-60 wide and a point at 1e260: " + std::to_string(t) +
      " feature points, the cube alone " + std::to_string(a));
  ::unlink(Path("tiny-far.csv").c_str());

  // Spacings shrinking geometrically from 1 to 1e-300 (found by fuzzing): the paper's method's
  // PDI and Wang & Yuan's density leave the range of their arrays. The message names the cause,
  // points closer than any precision, not (as before) a point far from the rest.
  std::ostringstream shrinking;
  shrinking.precision(17);
  const int count = 2000;
  for (int i = 0; i < count; ++i)
  {
    const double e = std::exp(-700.0 * i / (count - 1));
    const double u = std::fmod(i * 0.6180339887, 1.0), v = std::fmod(i * 0.4142135623, 1.0);
    shrinking << e << " " << e * u << " " << e * v << "\n";
  }
  Spit(Path("shrinking.xyz"), shrinking.str());
  for (const char* method : { "huang2023", "wang-yuan" })
  {
    ExpectFailure(std::string("spacings shrinking to 1e-300, ") + method,
      { Path("shrinking.xyz"), Path("o.vtp"), "--method", method, "--quiet" }, 1,
      "far below any measurement's precision");
  }
}

void ScatteredFeatureCurves()
{
  // 17 points on a unit cube's faces and 34 scattered over magnitudes from 1e-44 to 1e38 (each
  // coordinate of its own sign and power of ten: a cloud found by fuzzing), their curves asked
  // for. The scattered points are feature points, and their median distance to one another set
  // the curves' fit radius, so that a curve 1e38 long was resampled at the cube's spacing: the
  // process grew to 24 GB in 40 s with the PCA and SSI methods. Under a 4 GB limit here.
  const std::string text =
    "-1 -0.67805381766178607 0.11548909473138425\n"
    "-0.26384011667145746 1 -0.22835192482160305\n"
    "-0.14367100181278314 -1 0.47277174102657304\n"
    "-0.96942068680657689 -0.49191817241472147 1\n"
    "-1 0.99552736184595303 0.66469224900140778\n"
    "-0.92644528466535037 1 0.21868027409020696\n"
    "-0.98614684097146355 -1 -0.67015557294720862\n"
    "-0.07608418093227165 -1 -0.096181552325696584\n"
    "0.83955136021652566 0.62984841373831513 1\n"
    "-0.59367688707633848 -1 0.72407007247473421\n"
    "-0.30236889083415064 0.9821312440827954 1\n"
    "1 0.3173946101023617 0.32045302179126667\n"
    "-1 -0.44181405668169793 0.25983639366900291\n"
    "-1 0.30657762975347036 0.084480554177652101\n"
    "-0.75757771035433441 1 -0.96557347922488579\n"
    "-1 -0.65727287714584781 -0.313900054918542\n"
    "0.23502946924981982 1 0.43219055823220032\n"
    "8.8576372637584321e-15 -2.9775242964137856e+18 1.167845517319217e-16\n"
    "-2.6601531689140835e+26 37080234479031.914 -4.9581945536308762e+17\n"
    "1.0409805462458815e-11 1.456699896525272e-30 6.2102193473166058e-44\n"
    "2.385392075177977e-11 1.5341731299191187e-06 3.7700778004969763e-13\n"
    "-3.0142703530425987e-36 3.6387334147530636e-41 -9.2259632659301128e+27\n"
    "1.1226399323351647e-12 1.3922447176346982e+27 -1.9996414843760902e+24\n"
    "-1321.910281427055 -7.3651518345754399e+26 -1.1245124715910696e+34\n"
    "174386189.10516614 -1.6977778834136996e-44 -362878343.43743575\n"
    "-0.00028416382250622343 -6.8992354313744299e+20 2.8095142548490327e-15\n"
    "-7288811399742.4072 -8.6803939758299762e-15 -7734.0324996587287\n"
    "-1.0916487440789195e-07 1.9115991190812104e-27 1.8428570896640777e-18\n"
    "1.7034716002570307e-39 -13845459.230901241 -1.462209799340113e+29\n"
    "67418.45437331211 -8.8319515814136146e-31 -1.3307717280562328\n"
    "2.0411486977594268e-23 2.811117755197863e-13 -1.6096321391362671e-44\n"
    "-4.3595250062437011e+34 -0.075784073235668534 731.08297621967426\n"
    "5.8380051816151443e-37 -6.3875633941770914e-34 -2.1880332652467605e+28\n"
    "-2.3131268967597219e+25 173396995029.15198 9650717132533.4609\n"
    "2.4217631884176512e+32 287979065684.88263 210742.06846718158\n"
    "-1.4871734626058289e-32 -6.5510684880896823e-26 -9.2666367877602737e-27\n"
    "3.784989704985186e-41 -8.4955119112842754e-11 5.8721703251672381e-41\n"
    "3.0478255708089513e+30 -12119744.561720507 2.2401806929352836e-17\n"
    "4.9607784120554544e-23 28692161930811872 4.6144647211335494e+29\n"
    "-3.7712651198733015e+37 -7.8211829246277548e-38 -3.2545962753871294e-08\n"
    "6.2983844067567214e+35 13972.12932478131 -4.5543842361880032e+21\n"
    "-3.788481310929223e-13 5.4656008048372519e+27 1.2994395101698488e+35\n"
    "1.0350438604539505e-22 -2.3792763237308228e-17 2.0889720562937746e-10\n"
    "8.7049784635781198e+34 -3.1796094801325494e-39 -577948.85705741635\n"
    "-1493.6821607842471 -7.502500394605868e+18 3.0162701989236712e-38\n"
    "-1.0934244402972682e-31 7.6795491420687801e+20 -3.2692184703634418e+33\n"
    "-1.6857512502592562 -0.017081072832561661 172447069641468.47\n"
    "2.2262313331074395e-28 6.8951276418806217e+23 -1.0698096022121412e-42\n"
    "-38657979.007182971 1.1185362786050114e+25 3.2292831469388141e-34\n"
    "-3.678394199801313e-15 -2.6565043721896418e-22 -4.7448680164913316e+19\n"
    "-4.7152617921268352e-30 -5.5469108268415002e-12 -6849.5309451714365\n";
  Spit(Path("scattered.xyz"), text);
  Limits limits;
  limits.MemoryLimit = 4L << 30;
  for (const char* method : { "ssi", "pca", "crease" })
  {
    for (const char* lines : { "scattered-lines.vtp", "scattered-lines.obj" })
    {
      const std::string what = std::string("curves over points scattered to 1e38, ") + method +
        ", " + lines;
      ExpectSuccess(what,
        { Path("scattered.xyz"), Path("scattered.vtp"), "--method", method, "--lines",
          Path(lines), "--quiet" },
        10.0, limits);
      Check(!HasNonFinite(Path("scattered.vtp")), what + ": NaN or Inf in the output");
      ::unlink(Path(lines).c_str());
    }
  }
  ::unlink(Path("scattered.vtp").c_str());
  ::unlink(Path("scattered.xyz").c_str());
}

void CoincidentPoints()
{
  // Before: 20,000 copies did not finish in 60 s; 12,000 copies among 14,000 points took 38-57 s.
  Spit(Path("copies.xyz"), Repeat("1 2 3\n", 20000));
  for (const char* method : { "crease", "pca" })
  {
    const Run run = ExpectSuccess(std::string("20,000 copies of one point, ") + method,
      { Path("copies.xyz"), Path("copies.csv"), "--method", method }, 10.0);
    Check(run.Err.find("All points coincide") != std::string::npos,
      std::string("20,000 copies, ") + method + ": no 'All points coincide' warning: " + run.Err);
  }
  // Five points: nothing is scored, and the summary says so instead of a threshold of 0.
  Spit(Path("five.xyz"), "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n");
  const Run five = ExpectSuccess("five points", { Path("five.xyz"), Path("five.csv") });
  Check(five.Out.find("threshold   none: no point was scored") != std::string::npos,
    "five points: the summary's threshold line: " + five.Out);
  ::unlink(Path("five.csv").c_str());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::ostringstream mixed;
  for (int i = 0; i < 14000; ++i)
  {
    if (i % 7 == 0)
    {
      mixed << u(rng) << " " << u(rng) << " " << u(rng) << "\n";
    }
    else
    {
      mixed << "0.5 0.5 0.5\n";
    }
  }
  Spit(Path("stack.xyz"), mixed.str());
  for (const char* method : { "crease", "huang2023", "ssi", "pca", "wang-yuan" })
  {
    ExpectSuccess(std::string("12,000 copies among 14,000 points, ") + method,
      { Path("stack.xyz"), Path("stack.vtp"), "--method", method, "--quiet" }, 10.0);
    Check(!HasNonFinite(Path("stack.vtp")),
      std::string("12,000 copies, ") + method + ": NaN or Inf in the output");
  }
  // The curves over stacks of copies, every point a feature: 10,000 copies of each of two
  // positions took 26 s (every search around a stack returned all of it), now one position each.
  Spit(Path("two-stacks.xyz"), Repeat("0 0 0\n1 1 1\n", 10000));
  ExpectSuccess("the curves over 2 x 10,000 copies",
    { Path("two-stacks.xyz"), Path("two-stacks.vtp"), "--method", "pca", "--threshold", "-1",
      "--lines", Path("two-stacks-lines.vtp"), "--quiet" },
    10.0);
  ::unlink(Path("copies.csv").c_str());
  ::unlink(Path("stack.vtp").c_str());
  ::unlink(Path("two-stacks.vtp").c_str());
  ::unlink(Path("two-stacks-lines.vtp").c_str());
}

void DenseCluster()
{
  // A plane of 40,000 points and a cluster of 30,000 a few spacings wide on it: the detector
  // types most of the cluster's points as features, and every fit of the curves around it read
  // all of them (40 s in the curve stage; a cluster of 27,000 in a 200,000-point cloud: 156 s).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 0.006);
  std::ostringstream text;
  for (int i = 0; i < 40000; ++i)
  {
    text << u(rng) << " " << u(rng) << " 0\n";
  }
  for (int i = 0; i < 30000; ++i)
  {
    text << 0.5 + g(rng) << " " << 0.5 + g(rng) << " " << g(rng) << "\n";
  }
  Spit(Path("cluster.xyz"), text.str());
  const Run run = ExpectSuccess("the curves around a dense cluster",
    { Path("cluster.xyz"), Path("cluster.vtp"), "--lines", Path("cluster-lines.vtp") }, 25.0);
  Check(run.Out.find("curves      ") != std::string::npos,
    "the curves around a dense cluster: no curve summary: " + run.Out);
  Check(!HasNonFinite(Path("cluster.vtp")) && !HasNonFinite(Path("cluster-lines.vtp")),
    "the curves around a dense cluster: NaN or Inf in the output");
  for (const char* name : { "cluster.xyz", "cluster.vtp", "cluster-lines.vtp" })
  {
    ::unlink(Path(name).c_str());
  }
}

void WideFiles()
{
  // Before: none finished in 60 s (10,000 columns: 4.7 s).
  const int columns = 100000;
  std::string row;
  for (int c = 0; c < columns; ++c)
  {
    row += (c ? " " : "") + std::to_string(c % 10);
  }
  Spit(Path("wide.xyz"), row + "\n" + row + "\n" + row + "\n" + row + "\n");
  ExpectFailure("XYZ rows of 100,000 columns", { Path("wide.xyz"), Path("o.vtp") }, 1,
    "wide.xyz:1: 100000 fields: at most 1003 are read", 10.0);
  std::string header = "x,y,z", csvRow = "1,2,3";
  for (int c = 3; c < columns; ++c)
  {
    header += ",c" + std::to_string(c);
    csvRow += ",0";
  }
  Spit(Path("wide.csv"), header + "\n" + csvRow + "\n");
  ExpectFailure("CSV of 100,000 columns", { Path("wide.csv"), Path("o.vtp") }, 1,
    "the header names 99997 point arrays besides x, y, z; at most 1000", 10.0);
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 1\n";
  for (int c = 0; c < columns - 3; ++c)
  {
    ply += "property float p" + std::to_string(c) + "\n";
  }
  ply += "property float x\nproperty float y\nproperty float z\nend_header\n" + row + "\n";
  Spit(Path("wide.ply"), ply);
  ExpectFailure("PLY of 100,000 vertex properties", { Path("wide.ply"), Path("o.vtp") }, 1,
    "the vertex element has 99997 properties besides x, y, z", 10.0);
}

void LegacyFiles()
{
  const std::string header = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n";
  Spit(Path("cut-header.vtk"), header.substr(0, header.size() - 6));
  ExpectFailure("legacy VTK cut in its header", { Path("cut-header.vtk"), Path("o.vtp") }, 1,
    "cut-header.vtk: not a legacy VTK data set file");
  Spit(Path("cut-body.vtk"), header + "POINTS 10 float\n0 0 0 1 0 0 0 1 0\n");
  // VTK's legacy reader says only "Error reading ascii data": the count read, or the line and
  // the value, are named.
  ExpectFailure("legacy VTK cut in its body", { Path("cut-body.vtk"), Path("o.vtp") }, 1,
    "cut-body.vtk: the POINTS line declares 10 points; the file ends after 3 of them");
  // More values than POINTS declares: VTK says "Unrecognized keyword: 0".
  Spit(Path("more-points.vtk"), header + "POINTS 2 float\n0 0 0\n1 0 0\n0 1 0\n");
  ExpectFailure("legacy VTK with more points than declared", { Path("more-points.vtk"),
    Path("o.vtp") }, 1,
    "more-points.vtk:8: the POINTS block holds more than 2 x 3 values (a wrong POINTS count)");
  Spit(Path("more-values.vtk"), header + "POINTS 2 float\n0 0 0 1 0 0 0 1 0\n");
  ExpectFailure("legacy VTK with more values on a line", { Path("more-values.vtk"),
    Path("o.vtp") }, 1,
    "more-values.vtk:6: the POINTS block holds more than 2 x 3 values (a wrong POINTS count)");
  Spit(Path("nan.vtk"), header + "POINTS 4 float\n0 0 0 1 nan 0 0 1 0\n0 0 1\n");
  ExpectFailure("legacy VTK with a nan token", { Path("nan.vtk"), Path("o.vtp") }, 1,
    "nan.vtk:6: coordinate 2 of point 2 ('nan') is not a finite number");
  // In the point data (found by fuzzing): VTK's "Possible mismatch of datasize with declaration".
  Spit(Path("nan-data.vtk"), header +
      "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOINT_DATA 3\nSCALARS s float 1\nLOOKUP_TABLE "
      "default\n1 nan 3\n");
  ExpectFailure("legacy VTK with a nan in its point data", { Path("nan-data.vtk"), Path("o.vtp") },
    1, "nan-data.vtk:10: value 2 of the line ('nan') is not a finite number");
  // Binary, cut short in its point data (VTK's reader says only "Error reading binary data!"):
  // the block's header and where it starts are named. 100 points (1,200 bytes), then a field
  // array of 100 floats of which 40 bytes are there.
  std::string binary = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET POLYDATA\nPOINTS 100 float\n";
  binary += std::string(1200, '\0') + "\nPOINT_DATA 100\nFIELD FieldData 1\nv 1 100 float\n";
  const size_t arrayLine = binary.rfind("v 1 100 float");
  binary += std::string(40, '\0');
  Spit(Path("cut-binary.vtk"), binary);
  ExpectFailure("binary legacy VTK cut in its point data", { Path("cut-binary.vtk"),
    Path("o.vtp") }, 1, "cut-binary.vtk: the field array line 'v 1 100 float' at byte " +
      std::to_string(arrayLine) + " needs 400 bytes of binary data after it, but the file ends "
      "40 bytes after it (a file cut short)");
  // Cell blocks whose counts lie (VTK's reader crashed, said "Unrecognized keyword: 1", "Error
  // reading ascii data" or nothing): the block, its line and what disagrees are named.
  auto refused = [](const std::string& what, const std::string& name, const std::string& bytes,
                   const std::string& expected) {
    Spit(Path(name), bytes);
    ExpectFailure(what, { Path(name), Path("o.vtp") }, 1, expected);
  };
  const std::string three = "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  refused("legacy VTK whose cells hold fewer values than declared", "cells-size.vtk",
    header + three + "VERTICES 3 7\n1 0\n1 1\n1 2\n",
    "cells-size.vtk:7: the VERTICES line declares 3 cells in 7 values, but its cells hold 6 (a "
    "corrupt size)");
  // VTK's writer follows an array with its information keys (METADATA up to an empty line).
  refused("legacy VTK with fewer cells than declared, after metadata", "cells-metadata.vtk",
    header + three +
      "METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1.41421\n\n"
      "VERTICES 4 8\n1 0\n1 1\n1 2\n",
    "cells-metadata.vtk: the VERTICES block (line 12) declares 4 cells; the file ends after 3 of "
    "them");
  refused("legacy VTK with more cells than declared", "cells-more.vtk",
    header + three + "VERTICES 2 4\n1 0\n1 1\n1 2\n",
    "cells-more.vtk:10: a number ('1') after the last value of the VERTICES block (line 7): the "
    "block holds more than its line declares");
  const std::string v5 = "# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n" + three;
  const std::string ids = "CONNECTIVITY vtktypeint64\n0 1 2\n";
  refused("legacy VTK 5.1 with a negative offset count", "cells-negative.vtk",
    v5 + "VERTICES -4 3\nOFFSETS vtktypeint64\n0 1 2 3\n" + ids,
    "cells-negative.vtk:7: the VERTICES line declares '-4' offsets, not a whole number of 0 or "
    "more");
  refused("legacy VTK 5.1 with fewer offsets than declared", "offsets-few.vtk",
    v5 + "VERTICES 4 3\nOFFSETS vtktypeint64\n0 1 2\n" + ids,
    "offsets-few.vtk:10: 'CONNECTIVITY' where offset 3 (counting from 0) of the 4 that the "
    "VERTICES block (line 7) declares should be: the block holds fewer offsets than declared");
  refused("legacy VTK 5.1 with no OFFSETS type", "offsets-type.vtk",
    v5 + "VERTICES 4 3\nOFFSETS\n0 1 2 3\n" + ids,
    "offsets-type.vtk:8: the OFFSETS line of the VERTICES block (line 7) names no integer type "
    "('0' follows it)");
  refused("legacy VTK 5.1 with fewer point ids than declared", "connectivity-few.vtk",
    v5 + "VERTICES 4 3\nOFFSETS vtktypeint64\n0 1 2 3\nCONNECTIVITY vtktypeint64\n0 1\n",
    "connectivity-few.vtk: the VERTICES block (line 7) declares 3 connectivity values; the file "
    "ends before the point id as connectivity value 2");
  const std::string grid = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" +
    three + "CELLS 3 6\n1 0\n1 1\n1 2\n";
  refused("legacy VTK grid with fewer cell types than cells", "types-count.vtk",
    grid + "CELL_TYPES 2\n1\n1\n1\n",
    "types-count.vtk:11: the CELL_TYPES line declares 2 cell types for the 3 cells of the CELLS "
    "block");
  refused("legacy VTK grid cut in its cell types", "types-cut.vtk", grid + "CELL_TYPES 3\n1\n1\n",
    "types-cut.vtk: the CELL_TYPES block (line 11) declares 3 cell types; the file ends after 2 "
    "of them");
  // Point and cell data arrays cut short or holding more than declared: VTK's reader said only
  // "Error reading ascii data. Possible mismatch of datasize with declaration." (or "Unrecognized
  // keyword"); the array, its line and the counts are named.
  const std::string data = three + "POINT_DATA 3\nSCALARS s float 1\nLOOKUP_TABLE default\n";
  refused("legacy VTK whose point data ends early", "data-end.vtk", header + data + "1 2\n",
    "data-end.vtk: the SCALARS array 's' (line 8) declares 3 values (POINT_DATA 3, 1 component "
    "each); the file ends after 2 of them");
  refused("legacy VTK whose point data holds fewer values than declared", "data-few.vtk",
    header + data + "1 2\nNORMALS n float\n0 0 1 0 0 1 0 0 1\n",
    "data-few.vtk:11: 'NORMALS' where value 2 (counting from 0) of the 3 that the SCALARS array "
    "'s' (line 8) declares (POINT_DATA 3, 1 component each) should be: the array holds 2, fewer "
    "than declared");
  refused("legacy VTK whose point data holds more values than declared", "data-more.vtk",
    header + data + "1 2 3\n4\n",
    "data-more.vtk:11: a number ('4') after the last value of the SCALARS array 's' (line 8): the "
    "array holds more values than declared");
  refused("legacy VTK whose cell data field array is cut short", "data-cells.vtk",
    header + three + "VERTICES 3 6\n1 0\n1 1\n1 2\nCELL_DATA 3\nFIELD FieldData 2\nc 1 3 int\n"
      "1 2 3\nd 2 3 float\n1 2 3 4 5\n",
    "data-cells.vtk: the field array 'd' (line 15) declares 6 values (3 tuples of 2 components); "
    "the file ends after 5 of them");
  // Binary, a cells line whose counts cannot be: VTK's reader crashed or said "Unrecognized
  // keyword:".
  const std::string cellsBinary =
    "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n" +
    std::string(36, '\0') + "\n";
  const std::string atByte = "' at byte " + std::to_string(cellsBinary.size());
  refused("binary legacy VTK with a negative cells size", "cells-binary.vtk",
    cellsBinary + "VERTICES 3 -1\n" + std::string(24, '\0'),
    "cells-binary.vtk: the cells line 'VERTICES 3 -1" + atByte +
      " declares counts that are not whole numbers of 0 or more");
  refused("binary legacy VTK with cells of no values", "cells-binary-size.vtk",
    cellsBinary + "VERTICES 3 0\n" + std::string(24, '\0'),
    "cells-binary-size.vtk: the cells line 'VERTICES 3 0" + atByte +
      " declares 3 cells in 0 values: each cell holds at least its number of points");
  // A '+' before a count is a count, as VTK's reader reads it: the cut block is what is wrong.
  refused("binary legacy VTK with a '+' count, cut short", "cells-binary-plus.vtk",
    cellsBinary + "VERTICES +3 6\n" + std::string(8, '\0'),
    "cells-binary-plus.vtk: the cells line 'VERTICES +3 6" + atByte +
      " needs 24 bytes of binary data after it, but the file ends 8 bytes after it (a file cut "
      "short)");
  // Binary, a corrupt count inside a cells block (VTK's reader crashed on 2^31 - 1, or said
  // "Number of cells don't match number data values!"): the cell, its line and the count's byte.
  auto bigEndian = [](std::initializer_list<uint32_t> values) {
    std::string bytes;
    for (const uint32_t v : values)
    {
      for (int shift = 24; shift >= 0; shift -= 8)
      {
        bytes += static_cast<char>((v >> shift) & 0xFF);
      }
    }
    return bytes;
  };
  const std::string verticesLine = "VERTICES 3 6\n";
  const std::string countByte = std::to_string(cellsBinary.size() + verticesLine.size() + 8);
  refused("binary legacy VTK with a corrupt cell count", "cells-binary-count.vtk",
    cellsBinary + verticesLine + bigEndian({ 1, 0, 0x7FFFFFFF, 1, 1, 2 }) + "\n",
    "cells-binary-count.vtk: cell 1 (counting from 0) of the cells line 'VERTICES 3 6" + atByte +
      " declares 2147483647 points at byte " + countByte +
      ": more than the 3 values left of the 6 that its line declares (a corrupt count)");
  refused("binary legacy VTK with a negative cell count", "cells-binary-negative.vtk",
    cellsBinary + verticesLine + bigEndian({ 1, 0, 0xFFFFFFFF, 1, 1, 2 }) + "\n" +
      "CELL_DATA 3\nSCALARS c int 1\nLOOKUP_TABLE default\n" + bigEndian({ 1, 2, 3 }),
    "cells-binary-negative.vtk: cell 1 (counting from 0) of the cells line 'VERTICES 3 6" +
      atByte + " declares -1 points at byte " + countByte + ", not a count of 0 or more");
  const std::string cellData = cellsBinary + verticesLine + bigEndian({ 1, 0, 1, 1, 1, 2 }) + "\n";
  refused("binary legacy VTK whose CELL_DATA count is not its cells'", "cell-data-count.vtk",
    cellData + "CELL_DATA 2\nSCALARS c int 1\nLOOKUP_TABLE default\n" + bigEndian({ 1, 2 }),
    "cell-data-count.vtk: the CELL_DATA line 'CELL_DATA 2' at byte " +
      std::to_string(cellData.size()) + " declares 2 cells, but the cell blocks hold 3 (a corrupt "
      "count)");
  const std::string fieldLine = cellData + "CELL_DATA 3\nFIELD FieldData 1\n";
  refused("binary legacy VTK with a negative field array count", "field-negative.vtk",
    fieldLine + "f 1 -3 int\n" + bigEndian({ 1, 2, 3 }),
    "field-negative.vtk: the field array line 'f 1 -3 int' at byte " +
      std::to_string(fieldLine.size()) + " declares '1' components and '-3' tuples: not whole "
      "numbers of 0 or more (a corrupt count)");
  // Version 5: the last offset is not the connectivity's size, which holds a value more than its
  // line declares (VTK's reader read on, misaligned: "Unrecognized keyword").
  const std::string cells51 = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET POLYDATA\n"
                              "POINTS 3 float\n" + std::string(36, '\0') + "\nVERTICES 4 2\n";
  const std::string offsetsLine = cells51 + "OFFSETS vtktypeint64\n";
  refused("binary legacy VTK 5.1 whose last offset is not its connectivity's size",
    "offsets-binary.vtk",
    offsetsLine + bigEndian({ 0, 0, 0, 1, 0, 2, 0, 3 }) + "\nCONNECTIVITY vtktypeint64\n" +
      bigEndian({ 0, 0, 0, 1, 0, 2 }) + "\n",
    "offsets-binary.vtk: offset 3 (counting from 0) of the line 'OFFSETS vtktypeint64' at byte " +
      std::to_string(cells51.size()) + " is 3 (at byte " + std::to_string(offsetsLine.size() + 24) +
      "), the last, but the cells line 'VERTICES 4 2' at byte " +
      std::to_string(cells51.size() - 13) + " declares 2 connectivity values");
  // Found by fuzzing. A version beyond 5.1 (VTK's reader crashed on 7; it refuses 6.0), a type
  // no type of the format ("Unsupported data type: bogus"), binary data where a keyword should
  // follow a block ("Unrecognized keyword: " and the bytes), a FIELD line declaring more arrays
  // than follow (no word), ASCII points of an integer type that are not whole ("Error reading
  // ascii data"): each is named with its line or byte.
  refused("legacy VTK of version 7", "version7.vtk",
    "# vtk DataFile Version 7.0\nt\nASCII\nDATASET POLYDATA\n" + three,
    "version7.vtk:1: the header declares file version 7.0, newer than VTK's legacy reader reads "
    "(at most 5.1)");
  refused("legacy VTK with a bogus type", "bogus-type.vtk",
    cellsBinary + "POINT_DATA 3\nNORMALS n bogus\n" + std::string(36, '\0') + "\n",
    "bogus-type.vtk: the NORMALS line 'NORMALS n bogus' at byte " +
      std::to_string(cellsBinary.size() + 13) + " names no type of the legacy format");
  const std::string onePoint = "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET POLYDATA\n"
                               "POINTS 1 float\n";
  refused("binary legacy VTK whose POINTS count is too small", "points-small.vtk",
    onePoint + bigEndian({ 0x3F800000, 0x3F800000, 0x3F800000, 0x3F800000, 0x3F800000,
                 0x3F800000, 0x3F800000, 0x3F800000, 0x3F800000 }) + "\n",
    "points-small.vtk: byte " + std::to_string(onePoint.size() + 12) +
      ", after the POINTS line 'POINTS 1 float' at byte " + std::to_string(onePoint.size() - 15) +
      " and its 12 bytes, holds no keyword ('????????????????????...'): the block's line declares "
      "another count or type than its data have");
  const std::string fieldCount = cellsBinary + "POINT_DATA 3\nFIELD FieldData 2\n";
  refused("binary legacy VTK with fewer field arrays than declared", "field-arrays.vtk",
    fieldCount + "f 1 3 float\n" + std::string(12, '\0') + "\n",
    "field-arrays.vtk: the FIELD line 'FIELD FieldData 2' at byte " +
      std::to_string(fieldCount.size() - 18) + " declares 2 arrays; the file ends after 1 of them");
  refused("legacy VTK with char points that are not whole", "char-points.vtk",
    header + "POINTS 3 char\n0 0 0.5 1 0 0 0 1 0\n",
    "char-points.vtk:6: coordinate 3 of point 1 ('0.5') is not a whole number, as the POINTS "
    "line's type 'char' needs");
  refused("legacy VTK with points of no type", "bogus-points.vtk",
    header + "POINTS 3 bogus\n0 0 0 1 0 0 0 1 0\n",
    "bogus-points.vtk:5: the POINTS line names the type 'bogus', no numeric type of the legacy "
    "format");
  // ASCII, a POINT_DATA line of other points than the POINTS line's (VTK's reader read on,
  // misaligned: "Unsupported point attribute type").
  refused("legacy VTK whose POINT_DATA count is not its points'", "point-data-count.vtk",
    header + three + "POINT_DATA 2\nSCALARS s float 1\nLOOKUP_TABLE default\n1 2\n",
    "point-data-count.vtk:7: the POINT_DATA line declares 2 points, but the POINTS line declares 3 "
    "(a corrupt count)");
  refused("legacy VTK with a negative field array count", "field-negative-ascii.vtk",
    header + three + "POINT_DATA 3\nFIELD FieldData 1\nf 1 -3 float\n1 2 3\n",
    "field-negative-ascii.vtk:9: the field array 'f' declares '1' components and '-3' tuples: not "
    "whole numbers of 0 or more (a corrupt count)");
  // What VTK's reader reads is not refused: a '+' and leading zeros in the count; field data
  // before the points whose array is named POINTS (its line is no data set's POINTS line).
  Spit(Path("plus.vtk"), header + "POINTS +0003 float\n0 0 0 1 0 0 0 1 0\n");
  ExpectSuccess("legacy VTK counting +0003 points", { Path("plus.vtk"), Path("plus.csv"),
                                                      "--quiet" });
  std::string zeros;
  for (int i = 0; i < 5000; ++i)
  {
    zeros += "0 ";
  }
  Spit(Path("field.vtk"), header + "FIELD FieldData 1\nPOINTS 5000 1 float\n" + zeros +
      "\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n");
  ExpectSuccess("legacy VTK with a field array named POINTS", { Path("field.vtk"),
                                                               Path("plus.csv"), "--quiet" });
  ::unlink(Path("plus.csv").c_str());
  Spit(Path("negative.vtk"), header + "POINTS -1 float\n0 0 0\n");
  ExpectFailure("legacy VTK declaring -1 points", { Path("negative.vtk"), Path("o.vtp") }, 1,
    "negative.vtk:5: the POINTS line declares '-1' points, not a whole number of 0 or more");
  std::mt19937 rng(5);
  std::string garbage(3000, '\0');
  for (char& c : garbage)
  {
    c = static_cast<char>(rng());
  }
  Spit(Path("garbage.vtk"), garbage);
  ExpectFailure("garbage legacy VTK", { Path("garbage.vtk"), Path("o.vtp") }, 1,
    "garbage.vtk: not a legacy VTK data set file");
}

void ExtremeScales()
{
  // A power of two scales exactly: the masks must be the unit cloud's. 1e200 in decimal: no NaN.
  Spit(Path("unit.xyz"), ModelText(1, 6000, 1.0));
  Spit(Path("big.xyz"), ModelText(1, 6000, std::ldexp(1.0, 700)));
  Spit(Path("tiny.xyz"), ModelText(1, 6000, std::ldexp(1.0, -1000)));
  Spit(Path("e200.xyz"), ModelText(1, 6000, 1e200));
  for (const char* method : { "crease", "huang2023", "ssi", "pca", "wang-yuan" })
  {
    const std::string m = method;
    ExpectSuccess("unit cloud, " + m, { Path("unit.xyz"), Path("unit.vtp"), "--method", m });
    const std::vector<unsigned char> unit = MaskOf(Path("unit.vtp"));
    Check(!unit.empty(), "unit cloud, " + m + ": no mask");
    for (const char* scaled : { "big", "tiny", "e200" })
    {
      const std::string name = scaled;
      const Run run = ExpectSuccess(name + " cloud, " + m,
        { Path(name + ".xyz"), Path(name + ".vtp"), "--method", m });
      Check(run.Err.find("scaled by 2^") != std::string::npos,
        name + ", " + m + ": no note of the scaled frame: " + run.Err);
      Check(run.Out.find("nan") == std::string::npos && run.Out.find("inf") == std::string::npos,
        name + ", " + m + ": NaN or Inf in the summary: " + run.Out);
      Check(!HasNonFinite(Path(name + ".vtp")), name + ", " + m + ": NaN or Inf in the output");
      const std::vector<unsigned char> mask = MaskOf(Path(name + ".vtp"));
      if (name != "e200")
      {
        Check(mask == unit, name + ", " + m + ": not the unit cloud's mask");
      }
      else
      {
        size_t differ = 0;
        for (size_t i = 0; i < std::min(mask.size(), unit.size()); ++i)
        {
          differ += mask[i] != unit[i] ? 1 : 0;
        }
        Check(mask.size() == unit.size() && differ * 100 <= unit.size(),
          "1e200 cloud, " + m + ": " + std::to_string(differ) + " mask values differ");
      }
    }
  }
  // The curves in the scaled frame too: 2^700 (exact) gives the unit cloud's curves, their
  // lengths 2^700 times (the curves used to run on the input's coordinates: none found).
  const Run unitLines = ExpectSuccess("unit cloud, curves",
    { Path("unit.xyz"), Path("unit.vtp"), "--lines", Path("unit-lines.vtp") });
  const Run bigLines = ExpectSuccess("2^700 cloud, curves",
    { Path("big.xyz"), Path("big.vtp"), "--lines", Path("big-lines.vtp") });
  auto curvesOf = [](const std::string& out, double& length) {
    const size_t at = out.find("curves      ");
    long long count = -1;
    length = 0.0;
    if (at != std::string::npos)
    {
      std::sscanf(out.c_str() + at, "curves %lld, total length %lf", &count, &length);
    }
    return count;
  };
  double unitLength = 0.0, bigLength = 0.0;
  const long long unitCurves = curvesOf(unitLines.Out, unitLength);
  const long long bigCurves = curvesOf(bigLines.Out, bigLength);
  Check(unitCurves > 0 && bigCurves == unitCurves &&
      std::abs(std::ldexp(bigLength, -700) / unitLength - 1.0) < 1e-5,
    "2^700 cloud: " + std::to_string(bigCurves) + " curves, the unit cloud " +
      std::to_string(unitCurves));
  ::unlink(Path("unit-lines.vtp").c_str());
  ::unlink(Path("big-lines.vtp").c_str());
  // A box 2^1018 times the generated one: its coordinates (at most 50 x 2^1018, 1.4e308) are
  // doubles, its edges' lengths (2.8e308) are not. The cloud is found; its curves are refused
  // with the reason, and no file is written (they were written with infinite lengths).
  Spit(Path("beyond.xyz"), ModelText(vtkFeatureModelSource::BOX, 6000, std::ldexp(1.0, 1018)));
  ExpectSuccess("box of 2.8e308", { Path("beyond.xyz"), Path("beyond.vtp") });
  Check(!HasNonFinite(Path("beyond.vtp")), "box of 2.8e308: NaN or Inf in the output");
  ::unlink(Path("beyond.vtp").c_str());
  ExpectFailure("box of 2.8e308, curves",
    { Path("beyond.xyz"), Path("beyond.vtp"), "--lines", Path("beyond-lines.vtp"), "--quiet" }, 1,
    "beyond.xyz: a feature curve is longer than the largest double");
  Check(::access(Path("beyond.vtp").c_str(), F_OK) != 0 &&
      ::access(Path("beyond-lines.vtp").c_str(), F_OK) != 0,
    "box of 2.8e308, curves: a file was written");
  // One point at 1e30 among 20,000 on a slab: not "a straight line".
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::ostringstream slab;
  for (int i = 0; i < 20000; ++i)
  {
    if (i == 777)
    {
      slab << "1e30 1e30 1e30\n";
    }
    else
    {
      slab << u(rng) << " " << u(rng) << " " << 0.1 * u(rng) << "\n";
    }
  }
  Spit(Path("outlier.xyz"), slab.str());
  const Run run =
    ExpectSuccess("one point at 1e30", { Path("outlier.xyz"), Path("outlier.vtp"), "--method", "pca" });
  Check(run.Err.find("straight line") == std::string::npos,
    "one point at 1e30: the rest is called a straight line: " + run.Err);
  // One point at 1e308 (its distance to any other point overflows): no coincident point. Two
  // copies of the part 1e12 apart: no straight line, no plane.
  const std::string part = ModelText(1, 1500, 1.0);
  Spit(Path("e308.xyz"), part + "1e308 1e308 1e308\n");
  const Run far = ExpectSuccess("one point at 1e308", { Path("e308.xyz"), Path("e308.vtp") });
  Check(far.Err.find("coincide") == std::string::npos,
    "one point at 1e308 is said to coincide with another: " + far.Err);
  std::ostringstream apart;
  apart.precision(17);
  std::istringstream rows(part);
  for (std::string line; std::getline(rows, line);)
  {
    std::istringstream fields(line);
    double x, y, z;
    fields >> x >> y >> z;
    apart << x << " " << y << " " << z << "\n" << x + 1e12 << " " << y + 1e12 << " " << z << "\n";
  }
  Spit(Path("apart.xyz"), apart.str());
  const Run two = ExpectSuccess("two parts 1e12 apart", { Path("apart.xyz"), Path("apart.vtp") });
  Check(two.Err.find("straight line") == std::string::npos &&
      two.Err.find("one plane") == std::string::npos,
    "two parts 1e12 apart are called degenerate: " + two.Err);
  // A part and 30 points spread up to 1e27 away (finite): the default method's gain there
  // exceeds float's range; it is kept at the largest float, not written as inf (was refused).
  std::ostringstream spread;
  spread << ModelText(1, 1500, 1.0);
  for (int i = 0; i < 30; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      spread << ((i >> a) & 1 ? "" : "-") << "1.5e" << (i * 7 + 3 * a) % 28 << (a < 2 ? " " : "\n");
    }
  }
  Spit(Path("spread.xyz"), spread.str());
  ExpectSuccess("a part and points up to 1e27 away", { Path("spread.xyz"), Path("spread.vtp") });
  for (const char* name : { "unit", "big", "tiny", "e200", "outlier", "e308", "apart", "spread" })
  {
    ::unlink(Path(std::string(name) + ".vtp").c_str());
  }
}

void Signals()
{
  // Signals while reading, computing and writing (sent as soon as the progress line of the
  // stage appears): SIGHUP, SIGPIPE and SIGQUIT leave no file, like SIGINT and SIGTERM.
  Spit(Path("signal.xyz"), ModelText(1, 300000, 1.0));
  for (int signal : { SIGHUP, SIGPIPE, SIGQUIT, SIGINT, SIGTERM })
  {
    int interruptedWriting = 0;
    for (const char* stage : { "reading...", "extracting...", "writing...", "writing...",
           "writing..." })
    {
      const std::set<std::string> before = Entries(Folder);
      Limits limits;
      limits.Signal = signal;
      limits.SignalOnMessage = stage;
      const Run run = Execute({ Path("signal.xyz"), Path("signal.csv"), "--method", "pca" }, limits);
      const std::string what = std::string(strsignal(signal)) + " on '" + stage + "'";
      Check(run.Code == 128 + signal || run.Code == 0,
        what + ": exit code " + std::to_string(run.Code));
      interruptedWriting +=
        run.Code == 128 + signal && std::string(stage) == "writing..." ? 1 : 0;
      std::set<std::string> after = Entries(Folder);
      if (after.count("signal.csv"))
      {
        // Written before the signal came (renamed into place, whole): it must hold every point.
        std::string error;
        vtkSmartPointer<vtkPointSet> written = vtkPointCloudIO::Read(Path("signal.csv"), error);
        Check(written && written->GetNumberOfPoints() == 300000,
          what + ": a partial output file: " + error);
        after.erase("signal.csv");
      }
      std::string left;
      for (const std::string& name : after)
      {
        left += before.count(name) ? "" : " " + name;
      }
      Check(after == before, what + ": files left behind:" + left);
      ::unlink(Path("signal.csv").c_str());
    }
    Check(interruptedWriting > 0,
      std::string(strsignal(signal)) + ": no run was interrupted while writing");
  }
  // A FIFO without a writer: refused at once rather than waited on.
  ::mkfifo(Path("fifo.xyz").c_str(), 0644);
  ExpectFailure("FIFO", { Path("fifo.xyz"), Path("o.vtp") }, 1,
    "fifo.xyz: is a FIFO (named pipe), not a regular file", 5.0);
  ::unlink(Path("fifo.xyz").c_str());
  ::symlink("/dev/urandom", Path("random.xyz").c_str());
  ExpectFailure("a character device", { Path("random.xyz"), Path("o.vtp") }, 1,
    "random.xyz: is a character device", 5.0);
  ::unlink(Path("random.xyz").c_str());
}

void OneLineErrors()
{
  std::mt19937 rng(6);
  std::string garbage(3000, '\0');
  for (char& c : garbage)
  {
    c = static_cast<char>(rng());
  }
  Spit(Path("garbage.vtp"), garbage);
  ExpectFailure("garbage VTP", { Path("garbage.vtp"), Path("o.vtp") }, 1,
    "garbage.vtp: cannot read: Error parsing XML");
  Spit(Path("cloud.xyz"), ModelText(1, 3000, 1.0));
  ExpectSuccess("a VTP to misname", { Path("cloud.xyz"), Path("cloud.vtp"), "--quiet" });
  ::rename(Path("cloud.vtp").c_str(), Path("polydata.vtu").c_str());
  ExpectFailure("a VTP named .vtu", { Path("polydata.vtu"), Path("o.vtp") }, 1,
    "polydata.vtu: cannot read: Cannot find UnstructuredGrid element");
  Spit(Path("cut.vtu"), "<?xml version=\"1.0\"?>\n<VTKFile type=\"Unstr");
  ExpectFailure("a cut VTU", { Path("cut.vtu"), Path("o.vtp") }, 1, "cut.vtu: cannot read");
  // A write past the file size limit: the writer's message, once, and no file.
  for (const char* extension : { "vtp", "vtk", "ply", "csv" })
  {
    Limits limits;
    limits.FileSizeLimit = 4096;
    ExpectFailure(std::string("a failed .") + extension + " write",
      { Path("cloud.xyz"), Path(std::string("full.") + extension), "--quiet" }, 1,
      std::string("full.") + extension + ": ", 20.0, limits);
  }
  // A summary that cannot be written (standard output on a full device) fails the run, saying
  // so; the output file, written before, is whole.
  Limits full;
  full.StandardOutput = "/dev/full";
  const Run run = Execute({ Path("cloud.xyz"), Path("summary.vtp") }, full);
  Check(run.Code == 1 &&
      run.Err.find("featurepoints: standard output: cannot write the summary") !=
        std::string::npos,
    "summary to /dev/full: exit code " + std::to_string(run.Code) + ", " + run.Err);
  std::string error;
  vtkSmartPointer<vtkPointSet> written = vtkPointCloudIO::Read(Path("summary.vtp"), error);
  Check(written && written->GetNumberOfPoints() == 3000, "summary to /dev/full: output " + error);
  ::unlink(Path("summary.vtp").c_str());
}

void KeptColumns()
{
  // "x y z" lines to "x,y,z,nx" rows.
  std::string rows = "x,y,z,nx\n";
  std::istringstream in(ModelText(1, 2000, 1.0));
  for (std::string line; std::getline(in, line);)
  {
    std::istringstream fields(line);
    std::string x, y, z;
    fields >> x >> y >> z;
    rows += x + "," + y + "," + z + ",0.25\n";
  }
  Spit(Path("nx.csv"), rows);
  ExpectSuccess("x,y,z,nx to CSV", { Path("nx.csv"), Path("nx-out.csv"), "--quiet" });
  const std::string out = Slurp(Path("nx-out.csv"));
  Check(out.substr(0, out.find('\n')).find(",nx,") != std::string::npos,
    "x,y,z,nx: the CSV output lost nx: " + out.substr(0, out.find('\n')));
  ExpectSuccess("x,y,z,nx to PLY", { Path("nx.csv"), Path("nx-out.ply"), "--quiet" });
  const std::string ply = Slurp(Path("nx-out.ply"));
  Check(ply.find("property double nx") != std::string::npos ||
      ply.find("property double nx_2") != std::string::npos,
    "x,y,z,nx: the PLY output lost nx");
  // Other delimiters, a byte order mark, a header with a 'nan' column.
  std::string commas, tabs;
  std::istringstream again(ModelText(1, 2000, 1.0));
  for (std::string line; std::getline(again, line);)
  {
    std::istringstream fields(line);
    std::string x, y, z;
    fields >> x >> y >> z;
    commas += x + "," + y + "," + z + "\n";
    tabs += x + "\t" + y + "\t" + z + "\n";
  }
  Spit(Path("commas.xyz"), commas);
  Spit(Path("tabs.csv"), "x\ty\tz\n" + tabs);
  Spit(Path("bom.csv"), "\xEF\xBB\xBFx,y,z\n" + commas);
  Spit(Path("nan-header.csv"), "x,y,z,nan\n" + [&] {
    std::string withColumn;
    std::istringstream c(commas);
    for (std::string line; std::getline(c, line);)
    {
      withColumn += line + ",1\n";
    }
    return withColumn;
  }());
  for (const char* name : { "commas.xyz", "tabs.csv", "bom.csv", "nan-header.csv" })
  {
    const Run run = ExpectSuccess(name, { Path(name), Path("delimited.vtp") });
    Check(run.Out.find(": 2000 points") != std::string::npos,
      std::string(name) + ": not read as 2000 points: " + run.Out + run.Err);
  }
  ::unlink(Path("nx-out.csv").c_str());
  ::unlink(Path("nx-out.ply").c_str());
  ::unlink(Path("delimited.vtp").c_str());
}

// PCD and LAS: cut, lying or compressed files end in one line, at once; an organized PCD cloud's
// NaN points are skipped with a warning.
void NewFormats()
{
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(1);
  source->SetNumberOfPoints(2000);
  source->Update();
  vtkPoints* points = source->GetOutput()->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();

  // An organized 50 x 40 cloud, every tenth point invalid (NaN), as PCL writes it.
  std::string body;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    const float v[4] = { i % 10 == 9 ? nan : static_cast<float>(x[0]), static_cast<float>(x[1]),
      static_cast<float>(x[2]), static_cast<float>(i) };
    body.append(reinterpret_cast<const char*>(v), sizeof(v));
  }
  const std::string fields = "VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\n"
                             "COUNT 1 1 1 1\n";
  Spit(Path("organized.pcd"),
    fields + "WIDTH 50\nHEIGHT 40\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2000\nDATA binary\n" + body);
  const Run organized = ExpectSuccess("organized PCD", { Path("organized.pcd"), Path("o.vtp") });
  Check(organized.Out.find(": 1800 points") != std::string::npos &&
      organized.Err.find("featurepoints: warning: ") != std::string::npos &&
      organized.Err.find("200 of 2000 points skipped") != std::string::npos,
    "organized PCD: 1800 points read, 200 skipped with a warning: " + organized.Out + organized.Err);
  std::string error;
  vtkSmartPointer<vtkPointSet> written = vtkPointCloudIO::Read(Path("o.vtp"), error);
  Check(written && !written->GetFieldData()->GetArray("FilePointIds"),
    "organized PCD: the output carries no FilePointIds (the reader's numbering): " + error);
  ::unlink(Path("o.vtp").c_str());
  // A NaN intensity after skipped points is named by the file's numbering (point 1234, after
  // 123 NaN points), not the cloud's (1111); in ASCII data also by its line.
  std::string nanBody = body;
  std::memcpy(&nanBody[1234 * 16 + 12], &nan, 4);
  Spit(Path("organized-nan.pcd"),
    fields + "WIDTH 50\nHEIGHT 40\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2000\nDATA binary\n" + nanBody);
  ExpectFailure("organized PCD with a NaN intensity",
    { Path("organized-nan.pcd"), Path("o.vtp"), "--quiet" }, 1,
    "organized-nan.pcd: point 1234 (counting from 0, as the file numbers its points; 123 points "
    "with a NaN or infinite coordinate before it skipped): point array 'intensity' holds nan, not "
    "a finite number");
  Spit(Path("nan-ascii.pcd"),
    "VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 4\nPOINTS 4\n"
    "DATA ascii\n0 0 0 1\nnan nan nan 1\n\n1 0 0 1\n0 1 0 nan\n");
  ExpectFailure("ASCII PCD with a NaN intensity",
    { Path("nan-ascii.pcd"), Path("o.vtp"), "--quiet" }, 1,
    "nan-ascii.pcd:12: point 3 (counting from 0, as the file numbers its points; 1 point with a "
    "NaN or infinite coordinate before it skipped): point array 'intensity' holds nan");

  Spit(Path("cut.pcd"),
    fields + "WIDTH 2000\nHEIGHT 1\nPOINTS 2000\nDATA binary\n" + body.substr(0, body.size() / 2));
  ExpectFailure("cut binary PCD", { Path("cut.pcd"), Path("o.vtp") }, 1,
    "cut.pcd: the file ends in point 1001 of 2000", 5.0);
  Spit(Path("huge.pcd"),
    fields + "WIDTH 1000000000000\nHEIGHT 1\nPOINTS 1000000000000\nDATA binary\n" + body);
  ExpectFailure("PCD declaring 10^12 points", { Path("huge.pcd"), Path("o.vtp") }, 1,
    "huge.pcd: the file ends in point 2001 of 1000000000000", 5.0);
  Spit(Path("lying.pcd"),
    fields + "WIDTH 2000\nHEIGHT 1\nPOINTS 3000\nDATA binary\n" + body);
  ExpectFailure("PCD POINTS other than WIDTH x HEIGHT", { Path("lying.pcd"), Path("o.vtp") }, 1,
    "lying.pcd:8: POINTS 3000 is not WIDTH x HEIGHT (2000 x 1)", 5.0);
  Spit(Path("type.pcd"),
    "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F D\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n");
  ExpectFailure("PCD unknown type", { Path("type.pcd"), Path("o.vtp") }, 1,
    "type.pcd:4: field 'z': unknown type 'D' of size 4", 5.0);
  // 10^8 points declared by 8 bytes of compressed data: refused before any allocation.
  const uint32_t sizes[2] = { 8, 1600000000 }; // compressed, uncompressed (10^8 x 16 bytes)
  Spit(Path("bomb.pcd"),
    fields + "WIDTH 100000000\nPOINTS 100000000\nDATA binary_compressed\n" +
      std::string(reinterpret_cast<const char*>(sizes), 8) + std::string(8, '\0'));
  ExpectFailure("PCD compression bomb", { Path("bomb.pcd"), Path("o.vtp") }, 1,
    "bomb.pcd: the compressed data cannot hold 100000000 points", 5.0);

  using namespace featurepoints::lastest;
  File las;
  las.Format = 3;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    las.Points.push_back({ static_cast<int32_t>(x[0] * 100), static_cast<int32_t>(x[1] * 100),
      static_cast<int32_t>(x[2] * 100), 0, 1, 1, 2, 0.0, 0, 0, 0, 0 });
  }
  const std::string lasBytes = Bytes(las);
  Spit(Path("cut.las"), lasBytes.substr(0, lasBytes.size() - 10));
  ExpectFailure("cut LAS", { Path("cut.las"), Path("o.vtp") }, 1,
    "cut.las: the header declares 2000 points of 34 bytes from byte 227, but the file (68217 "
    "bytes) holds 1999",
    5.0);
  File huge = las;
  huge.Minor = 4;
  huge.DeclaredPoints = uint64_t(1) << 40;
  Spit(Path("huge.las"), Bytes(huge));
  ExpectFailure("LAS 1.4 declaring 2^40 points", { Path("huge.las"), Path("o.vtp") }, 1,
    "huge.las: the header declares 1099511627776 points", 5.0);
  File format = las;
  format.FormatByte = 12;
  Spit(Path("format.las"), Bytes(format));
  ExpectFailure("LAS point format 12", { Path("format.las"), Path("o.vtp") }, 1,
    "format.las: unsupported point data record format 12 (0 to 10 are read)", 5.0);
  Spit(Path("cloud.laz"), lasBytes);
  ExpectFailure("LAZ", { Path("cloud.laz"), Path("o.vtp") }, 1,
    "cloud.laz: compressed LAS (LAZ) is not supported in this build", 5.0);
  Spit(Path("good.las"), lasBytes);
  const Run good = ExpectSuccess("LAS format 3", { Path("good.las"), Path("o.vtp") });
  Check(good.Out.find(": 2000 points") != std::string::npos, "LAS format 3: " + good.Out);
  for (const char* name : { "organized.pcd", "organized-nan.pcd", "nan-ascii.pcd", "cut.pcd",
         "huge.pcd", "lying.pcd", "type.pcd", "bomb.pcd", "cut.las", "huge.las", "format.las",
         "cloud.laz", "good.las", "o.vtp" })
  {
    ::unlink(Path(name).c_str());
  }
}

void Options()
{
  Spit(Path("small.xyz"), ModelText(1, 2000, 1.0));
  ExpectFailure("--size 8192x8192",
    { Path("small.xyz"), Path("o.vtp"), "--screenshot", Path("o.png"), "--size", "8192x8192" }, 2,
    "--size 8192x8192 is 67.1 megapixels");
  const Run run = ExpectSuccess("--threads 4096", { Path("small.xyz"), Path("t.vtp"), "--threads", "4096" });
  Check(run.Err.find("TBB") == std::string::npos, "--threads 4096: TBB's warning: " + run.Err);
  Check(run.Err.find("core(s); using") != std::string::npos, "--threads 4096: no note: " + run.Err);
  ExpectSuccess("--density-contrast 1e301",
    { Path("small.xyz"), Path("t.vtp"), "--method", "huang2023", "--density-contrast", "1e301" });
  ::unlink(Path("t.vtp").c_str());
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::printf("usage: TestFeaturePointsCLIBadInput PROGRAM FOLDER\n");
    return EXIT_FAILURE;
  }
  Program = argv[1];
  Folder = argv[2];
  ::mkdir(Folder.c_str(), 0755);
  const auto start = std::chrono::steady_clock::now();
  HugeCounts();
  FuzzedFiles();
  Base64Files();
  CoincidentPoints();
  CompressedFiles();
  XMLPointsArrays();
  FarOutliers();
  ScatteredFeatureCurves();
  DenseCluster();
  WideFiles();
  LegacyFiles();
  ExtremeScales();
  Signals();
  OneLineErrors();
  KeptColumns();
  NewFormats();
  Options();
  std::printf("bad input cases done in %.1f s, %d failure(s)\n",
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
