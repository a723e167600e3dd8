// vtkPointCloudIO from several threads at once: writers in two threads each write their whole
// file, leave no temporary file and give VTK's output window back as they found it; the
// temporary files known to the signal handler are each removed by RemoveTemporaryFileInProgress()
// until released.
#include "FeaturePointsTestFiles.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace
{
using namespace fptest;

// A seeded cloud of n points with one score array whose value i is i.
vtkSmartPointer<vtkPolyData> MakeCloud(vtkIdType n)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> score;
  score->SetName("Score");
  score->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, u(rng), u(rng), u(rng));
    score->SetValue(i, static_cast<float>(i));
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->GetPointData()->AddArray(score);
  return cloud;
}
} // namespace

int TestPointCloudIOConcurrent(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  const auto path = [&](const std::string& name) { return folder + "/" + name; };
  const std::set<std::string> before = Entries(folder);
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();

  // Two writers at once, each several files in turn, in each writable format. Each writes its
  // own cloud: VTK's writers touch the information of their input's arrays, so one data set is
  // not written by two threads at once.
  const vtkIdType n = 200000;
  const vtkSmartPointer<vtkPolyData> clouds[2] = { MakeCloud(n), MakeCloud(n) };
  const std::vector<std::string> extensions = { "vtp", "ply", "csv", "vtk" };
  std::vector<int> written(2, 0);
  std::vector<std::string> errors(2);
  std::vector<std::thread> writers;
  for (int t = 0; t < 2; ++t)
  {
    writers.emplace_back([&, t]() {
      for (int round = 0; round < 2; ++round)
      {
        for (const std::string& extension : extensions)
        {
          std::string error;
          const std::string file = path("writer" + std::to_string(t) + "." + extension);
          if (vtkPointCloudIO::Write(clouds[t], file, error))
          {
            ++written[t];
          }
          else if (errors[t].empty())
          {
            errors[t] = error;
          }
        }
      }
    });
  }
  for (std::thread& writer : writers)
  {
    writer.join();
  }
  for (int t = 0; t < 2; ++t)
  {
    Check(written[t] == 2 * static_cast<int>(extensions.size()),
      "writer " + std::to_string(t) + " wrote " + std::to_string(written[t]) + " files: " +
        errors[t]);
    for (const std::string& extension : extensions)
    {
      const std::string file = path("writer" + std::to_string(t) + "." + extension);
      std::string error;
      vtkSmartPointer<vtkPointSet> back = vtkPointCloudIO::Read(file, error);
      Check(back && back->GetNumberOfPoints() == n, file + ": not read back whole: " + error);
      vtkDataArray* score = back ? back->GetPointData()->GetArray("Score") : nullptr;
      Check(score && score->GetNumberOfTuples() == n && score->GetTuple1(n - 1) == n - 1,
        file + ": the score array is not read back");
    }
  }
  Check(vtkOutputWindow::GetInstance() == window,
    "the output window is not the one the writers found");

  // The signal handler's files: each removed until released, whichever thread made it.
  std::string error;
  std::vector<std::string> temporaries(2);
  std::vector<std::thread> makers;
  for (int t = 0; t < 2; ++t)
  {
    makers.emplace_back([&, t]() {
      std::string e;
      temporaries[t] = vtkPointCloudIO::CreateTemporaryFile(path("made.vtp"), e, true);
    });
  }
  for (std::thread& maker : makers)
  {
    maker.join();
  }
  Check(!temporaries[0].empty() && !temporaries[1].empty() && temporaries[0] != temporaries[1],
    "two temporary files were not made");
  const std::string released = vtkPointCloudIO::CreateTemporaryFile(path("kept.vtp"), error, true);
  vtkPointCloudIO::ReleaseTemporaryFile(released);
  const std::string plain = vtkPointCloudIO::CreateTemporaryFile(path("plain.vtp"), error);
  Check(Exists(temporaries[0]) && Exists(temporaries[1]) && Exists(released) && Exists(plain),
    "a temporary file was not created");
  vtkPointCloudIO::RemoveTemporaryFileInProgress();
  Check(!Exists(temporaries[0]) && !Exists(temporaries[1]),
    "RemoveTemporaryFileInProgress left a registered temporary file");
  Check(Exists(released), "RemoveTemporaryFileInProgress removed a released temporary file");
  Check(Exists(plain), "RemoveTemporaryFileInProgress removed an unregistered temporary file");
  for (const std::string& t : temporaries)
  {
    vtkPointCloudIO::ReleaseTemporaryFile(t);
  }
  std::remove(released.c_str());
  std::remove(plain.c_str());

  // Nothing left but the written files.
  std::set<std::string> after = Entries(folder);
  for (int t = 0; t < 2; ++t)
  {
    for (const std::string& extension : extensions)
    {
      const std::string name = "writer" + std::to_string(t) + "." + extension;
      after.erase(name);
      std::remove(path(name).c_str());
    }
  }
  std::string left;
  for (const std::string& name : after)
  {
    left += before.count(name) ? "" : " " + name;
  }
  Check(left.empty(), "files left behind:" + left);
  std::printf("two writers: %d and %d files of %lld points; %d failure(s)\n", written[0],
    written[1], static_cast<long long>(n), Failures);
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
