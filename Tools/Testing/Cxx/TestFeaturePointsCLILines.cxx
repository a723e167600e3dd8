// featurepoints --lines: each format is written and holds the curves of a box (12 edges); a bad
// folder fails with exit status 1 and leaves no file; a bad extension is a usage error (2).
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFeatureModelSource.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>

namespace
{
int failures = 0;
void Expect(bool ok, const std::string& what)
{
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  failures += ok ? 0 : 1;
}

bool Exists(const std::string& file)
{
  struct stat info;
  return ::stat(file.c_str(), &info) == 0;
}

// Runs the command line; returns its exit status, stdout in `out`.
int Shell(const std::string& command, const std::string& folder, std::string& out)
{
  const std::string capture = folder + "/stdout.txt";
  const int status = std::system((command + " > '" + capture + "' 2>&1").c_str());
  std::ifstream in(capture);
  std::stringstream text;
  text << in.rdbuf();
  out = text.str();
  std::remove(capture.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int CountLines(const std::string& file, const std::string& prefix)
{
  std::ifstream in(file);
  std::string line;
  int n = 0;
  while (std::getline(in, line))
  {
    n += line.compare(0, prefix.size(), prefix) == 0;
  }
  return n;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: %s FEATUREPOINTS FOLDER\n", argv[0]);
    return EXIT_FAILURE;
  }
  const std::string program = argv[1], folder = argv[2];
  // The folder and its parent (this test may run before the one that makes the parent).
  const size_t slash = folder.find_last_of('/');
  if (slash != std::string::npos && slash > 0)
  {
    ::mkdir(folder.substr(0, slash).c_str(), 0755);
  }
  ::mkdir(folder.c_str(), 0755);
  vtkNew<vtkFeatureModelSource> box;
  box->SetModel(vtkFeatureModelSource::BOX);
  box->SetNumberOfPoints(20000);
  box->Update();
  const std::string input = folder + "/box.vtp";
  std::string error, out;
  if (!vtkPointCloudIO::Write(box->GetOutput(), input, error))
  {
    std::fprintf(stderr, "%s\n", error.c_str());
    return EXIT_FAILURE;
  }
  const std::string output = folder + "/box_features.vtp";
  for (const std::string extension : { "vtp", "vtk", "csv", "obj" })
  {
    const std::string lines = folder + "/box_lines." + extension;
    std::remove(lines.c_str());
    const int code = Shell("'" + program + "' '" + input + "' '" + output + "' --lines '" + lines + "'",
      folder, out);
    Expect(code == 0 && Exists(lines), "--lines ." + extension + " written, exit 0");
    Expect(out.find("curves      12, total length") != std::string::npos,
      "--lines ." + extension + ": summary prints 12 curves");
    if (extension == "vtp" || extension == "vtk")
    {
      vtkSmartPointer<vtkPolyData> data;
      if (extension == "vtp")
      {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName(lines.c_str());
        reader->Update();
        data = reader->GetOutput();
      }
      else
      {
        vtkNew<vtkPolyDataReader> reader;
        reader->SetFileName(lines.c_str());
        reader->Update();
        data = reader->GetOutput();
      }
      Expect(data->GetNumberOfLines() == 12, "." + extension + ": 12 polylines");
      for (const char* name : { "CurveId", "FeatureType", "CreaseAngle", "Length" })
      {
        Expect(data->GetCellData()->GetArray(name) != nullptr,
          "." + extension + ": cell array " + name);
      }
      Expect(data->GetPointData()->GetArray("Tangent") != nullptr, "." + extension + ": Tangent");
    }
    else if (extension == "csv")
    {
      std::ifstream in(lines);
      std::string header, row, last;
      std::getline(in, header);
      int rows = 0;
      while (std::getline(in, row))
      {
        ++rows;
        last = row;
      }
      Expect(header.rfind("x,y,z,CurveId,Tangent", 0) == 0, ".csv: header x,y,z,CurveId,Tangent");
      int curve = -1;
      double x, y, z;
      Expect(rows > 100 && std::sscanf(last.c_str(), "%lf,%lf,%lf,%d", &x, &y, &z, &curve) == 4 &&
          curve == 11,
        ".csv: vertices of curves 0 to 11");
    }
    else
    {
      Expect(CountLines(lines, "l ") == 12 && CountLines(lines, "v ") > 100,
        ".obj: 12 'l' lines over the 'v' vertices");
    }
  }
  // The point output has CurveId.
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(output.c_str());
    reader->Update();
    Expect(reader->GetOutput()->GetPointData()->GetArray("CurveId") != nullptr,
      "the output has CurveId");
  }
  // A folder that does not exist: exit 1, one line, no file.
  const std::string missing = folder + "/no/such/folder/lines.obj";
  const std::string other = folder + "/other_features.vtp";
  std::remove(other.c_str());
  int code = Shell("'" + program + "' '" + input + "' '" + other + "' --lines '" + missing + "'",
    folder, out);
  Expect(code == 1 && !Exists(missing) && !Exists(other), "missing folder: exit 1, no file");
  Expect(out.find("featurepoints: " + missing) == 0 && out.find('\n') + 1 == out.size(),
    "missing folder: one line naming the file");
  // An extension --lines does not write: a usage error.
  code = Shell("'" + program + "' '" + input + "' '" + other + "' --lines '" + folder + "/l.ply'",
    folder, out);
  Expect(code == 2 && !Exists(other), "--lines .ply: exit 2, no file");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
