// vtkPointCloudIO: a cloud written in every format and read back keeps its points and arrays;
// reading picks the reader by extension; every failure is one line naming the file, and a failed
// write leaves no file behind (not even its temporary file) and keeps an existing target intact.
#include "FeaturePointsTestFiles.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <dirent.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <set>
#include <string>

namespace
{
using namespace fptest;

template <typename ArrayT>
vtkSmartPointer<ArrayT> NewArray(const char* name, int components, vtkIdType n)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n);
  return a;
}

// A seeded cloud with the arrays the filter writes, and some it does not.
vtkSmartPointer<vtkPolyData> MakeCloud(vtkIdType n, int pointType)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  points->SetNumberOfPoints(n);
  auto normals = NewArray<vtkFloatArray>("Normals", 3, n);
  auto score = NewArray<vtkFloatArray>("F", 1, n);
  auto ssi = NewArray<vtkDoubleArray>("SSI", 1, n);
  auto mask = NewArray<vtkUnsignedCharArray>("FeatureMask", 1, n);
  auto ids = NewArray<vtkIdTypeArray>("vtkOriginalPointIds", 1, n);
  auto label = NewArray<vtkIntArray>("label", 1, n);
  auto pair = NewArray<vtkDoubleArray>("Pair", 2, n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    // Offset coordinates: the digits of a far-from-origin scan must survive too.
    points->SetPoint(i, 1e6 + u(rng), -2.5e5 + u(rng), u(rng) * 1e-3);
    normals->SetTuple3(i, u(rng), u(rng), u(rng));
    score->SetValue(i, static_cast<float>(std::exp(u(rng) * 20)));
    ssi->SetValue(i, u(rng) * 1e-7);
    mask->SetValue(i, u(rng) > 0.5 ? 1 : 0);
    ids->SetValue(i, 3 * i + 1);
    label->SetValue(i, static_cast<int>(u(rng) * 1e6));
    pair->SetTuple2(i, u(rng), -u(rng));
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ normals, score, ssi, mask, ids,
         label, pair })
  {
    cloud->GetPointData()->AddArray(a);
  }
  cloud->GetPointData()->SetNormals(normals);
  return cloud;
}

// Same points (bit for bit) and every array with the same values, read back as any type that
// holds them: a float comes back exactly as the same float, an integer as the same integer.
void CheckSame(vtkPointSet* original, vtkPointSet* read, const std::string& what)
{
  if (!read)
  {
    Check(false, what + ": nothing read back");
    return;
  }
  const vtkIdType n = original->GetNumberOfPoints();
  Check(read->GetNumberOfPoints() == n, what + ": number of points");
  if (read->GetNumberOfPoints() != n)
  {
    return;
  }
  bool samePoints = true;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    original->GetPoint(i, a);
    read->GetPoint(i, b);
    // CSV reads every value as a double: a float point comes back as the nearest double of its
    // shortest decimal form, which rounds back to the same float.
    const bool asFloat = original->GetPoints()->GetDataType() == VTK_FLOAT;
    for (int c = 0; c < 3 && asFloat; ++c)
    {
      volatile float rounded = static_cast<float>(b[c]);
      b[c] = rounded;
    }
    if (samePoints && !(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]))
    {
      std::printf("%s (type %d): point %lld: %.17g %.17g %.17g read as %.17g %.17g %.17g\n", what.c_str(), original->GetPoints()->GetDataType(),
        static_cast<long long>(i), a[0], a[1], a[2], b[0], b[1], b[2]);
      samePoints = false;
    }
  }
  Check(samePoints, what + ": coordinates bit-identical");
  vtkPointData* pd = original->GetPointData();
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* a = pd->GetArray(k);
    vtkDataArray* b = read->GetPointData()->GetArray(a->GetName());
    if (!b || b->GetNumberOfComponents() != a->GetNumberOfComponents())
    {
      Check(false, what + ": array " + a->GetName() + " missing or with other components");
      continue;
    }
    bool same = true;
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      {
        const double va = a->GetComponent(i, c);
        double vb = b->GetComponent(i, c);
        if (a->GetDataType() == VTK_FLOAT)
        {
          vb = static_cast<float>(vb);
        }
        same = same && va == vb;
      }
    }
    Check(same, what + ": values of " + a->GetName());
  }
}

class Silence : public vtkCommand
{
public:
  static Silence* New() { return new Silence; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};
} // namespace

int TestPointCloudIO(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  std::string error;

  // Round trips through every writable format, double and float points.
  for (int type : { VTK_DOUBLE, VTK_FLOAT })
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(1000, type);
    for (const char* extension : { "vtp", "vtk", "ply", "csv" })
    {
      const std::string file = folder + "/roundtrip_" + (type == VTK_DOUBLE ? "d." : "f.") + extension;
      const std::string what = std::string(".") + extension + (type == VTK_DOUBLE ? " (double)" : " (float)");
      Check(vtkPointCloudIO::Write(cloud, file, error), what + ": write: " + error);
      vtkSmartPointer<vtkPointSet> read = vtkPointCloudIO::Read(file, error);
      Check(error.empty(), what + ": read: " + error);
      CheckSame(cloud, read, what);
      if (read && std::string(extension) != "csv")
      {
        Check(read->GetPoints()->GetDataType() == type, what + ": point precision kept");
      }
    }
  }

  // The text formats that are read but not written, through the same entry point.
  {
    std::ofstream(folder + "/points.txt") << "0 0 0\n1 0 0\n0 1 0\n";
    std::ofstream(folder + "/points.pts") << "1\n0.5 0.25 2\n";
    vtkSmartPointer<vtkPointSet> txt = vtkPointCloudIO::Read(folder + "/points.txt", error);
    Check(txt && txt->GetNumberOfPoints() == 3, "points.txt read: " + error);
    vtkSmartPointer<vtkPointSet> pts = vtkPointCloudIO::Read(folder + "/points.pts", error);
    Check(pts && pts->GetNumberOfPoints() == 1 && pts->GetPoint(0)[2] == 2, "points.pts read: " + error);
  }

  // Reading failures: one line that starts with the file's name.
  auto expectReadError = [&](const std::string& file, const std::string& expected) {
    vtkSmartPointer<vtkPointSet> read = vtkPointCloudIO::Read(file, error);
    Check(!read, file + ": read should fail");
    Check(error.compare(0, file.size(), file) == 0, file + ": message starts with the file: " + error);
    Check(error.find(expected) != std::string::npos,
      file + ": message '" + error + "' lacks '" + expected + "'");
    Check(error.find('\n') == std::string::npos, file + ": one line");
  };
  expectReadError(folder + "/missing.ply", "No such file or directory");
  std::ofstream(folder + "/empty.vtp").close();
  expectReadError(folder + "/empty.vtp", "the file is empty");
  std::ofstream(folder + "/cloud.foo") << "1 2 3\n";
  expectReadError(folder + "/cloud.foo", "cannot tell the format from the extension '.foo'");
  std::ofstream(folder + "/garbage.vtp") << "this is not XML\n";
  vtkObject::GlobalWarningDisplayOff(); // VTK's XML parser reports on the console too
  expectReadError(folder + "/garbage.vtp", "");
  std::printf("garbage.vtp: %s\n", error.c_str());
  vtkObject::GlobalWarningDisplayOn();
  expectReadError(folder, "is a folder");
  std::ofstream(folder + "/image.vtk") << "# vtk DataFile Version 3.0\nimage\nASCII\n"
                                          "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 1\n"
                                          "ORIGIN 0 0 0\nSPACING 1 1 1\n";
  expectReadError(folder + "/image.vtk", "not a point set");

  // Writing failures: no file left behind, an existing target untouched.
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(50, VTK_DOUBLE);
    const std::string nowhere = folder + "/no-such-folder/out.vtp";
    Check(!vtkPointCloudIO::Write(cloud, nowhere, error), "write into a missing folder fails");
    Check(error.compare(0, nowhere.size(), nowhere) == 0 && error.find("No such file") != std::string::npos,
      "missing folder: message " + error);
    Check(!vtkPointCloudIO::CanCreate(nowhere, error), "CanCreate: missing folder");

    const std::string target = folder + "/kept.vtp";
    Check(vtkPointCloudIO::Write(MakeCloud(10, VTK_DOUBLE), target, error), "write kept.vtp");
    const std::set<std::string> before = Entries(folder);
    Check(!vtkPointCloudIO::Write(cloud, target, error, "xyz"), "unknown output format fails");
    Check(error.find("writable: .vtp") != std::string::npos, "unknown output format: " + error);
    // A target that is a folder: the writer succeeds, the rename fails, the temporary goes.
    const std::string sub = folder + "/a-folder.vtp";
    ::mkdir(sub.c_str(), 0755);
    const std::set<std::string> withFolder = Entries(folder);
    Check(!vtkPointCloudIO::Write(cloud, sub, error), "writing over a folder fails");
    Check(Entries(folder) == withFolder, "a failed write leaves no temporary file");
    vtkSmartPointer<vtkPointSet> kept = vtkPointCloudIO::Read(target, error);
    Check(kept && kept->GetNumberOfPoints() == 10, "the existing target is untouched");
    Check(before.count("kept.vtp") == 1, "kept.vtp exists");
  }

  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
