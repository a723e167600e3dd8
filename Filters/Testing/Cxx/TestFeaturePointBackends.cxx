// The output is bit-identical whatever the SMP backend (Sequential, STDThread, TBB where built) and
// the number of threads.
#include "FeaturePointsTestRun.h"
#include "vtkSMPTools.h"

#include <cstring>
#include <string>
#include <vector>

int TestFeaturePointBackends(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  // A dense crease, so that the voxel pre-filter and the background sample are exercised too.
  Cloud cloud = BentPlanes(30000, 51, 90.0, 0.5, 3.0);
  std::vector<float> referenceF, referenceNormals;
  std::vector<unsigned char> referenceMask;
  int runs = 0;
  struct Setting
  {
    const char* Backend;
    int Threads;
  };
  for (const Setting& s : { Setting{ "Sequential", 1 }, Setting{ "STDThread", 1 },
         Setting{ "STDThread", 2 }, Setting{ "STDThread", 7 }, Setting{ "TBB", 2 },
         Setting{ "TBB", 5 } })
  {
    vtkNew<vtkFeaturePointExtraction> filter;
    filter->SetInputData(cloud.Data);
    bool ran = false;
    std::string used;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ s.Threads, s.Backend, false }, [&]() {
      used = vtkSMPTools::GetBackend();
      if (used == s.Backend)
      {
        filter->Update();
        ran = true;
      }
    });
    if (!ran)
    {
      std::printf("backend %s not available in this VTK (got %s): skipped\n", s.Backend, used.c_str());
      FP_CHECK(std::strcmp(s.Backend, "TBB") == 0, "backend %s missing", s.Backend);
      continue;
    }
    vtkFloatArray* f = Floats(filter->GetOutput(), "F");
    vtkFloatArray* normals = Floats(filter->GetOutput(), "Normals");
    vtkUnsignedCharArray* mask = Mask(filter->GetOutput());
    std::vector<float> fv(f->GetPointer(0), f->GetPointer(0) + f->GetNumberOfValues());
    std::vector<float> nv(
      normals->GetPointer(0), normals->GetPointer(0) + normals->GetNumberOfValues());
    std::vector<unsigned char> mv(
      mask->GetPointer(0), mask->GetPointer(0) + mask->GetNumberOfValues());
    std::printf("%-10s %d thread(s): %ld feature points, %ld candidates\n", s.Backend, s.Threads,
      CountSet(mask), static_cast<long>(filter->GetNumberOfCandidates()));
    if (runs++ == 0)
    {
      referenceF = fv;
      referenceNormals = nv;
      referenceMask = mv;
      FP_CHECK(CountSet(mask) > 100, "too few feature points: %ld", CountSet(mask));
      continue;
    }
    FP_CHECK(std::memcmp(fv.data(), referenceF.data(), fv.size() * sizeof(float)) == 0,
      "%s/%d: F differs", s.Backend, s.Threads);
    FP_CHECK(std::memcmp(nv.data(), referenceNormals.data(), nv.size() * sizeof(float)) == 0,
      "%s/%d: normals differ", s.Backend, s.Threads);
    FP_CHECK(mv == referenceMask, "%s/%d: FeatureMask differs", s.Backend, s.Threads);
  }
  FP_CHECK(runs >= 4, "only %d runs", runs);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
