// The results the ParaView plugin must reproduce: every detector on one generated cloud, as
// ParaView/Testing/Data/FeaturePointsReference.txt holds them (arrays, number of feature points,
// feature point ids). The plugin is built against ParaView's own VTK and cannot be installed
// beside this build, so this file carries the plain VTK build's results to the plugin's test.
//
//   TestFeaturePointsReference REFERENCE.txt           compare (the CTest)
//   TestFeaturePointsReference REFERENCE.txt --write   rewrite it after a change of results
#include "vtkCreaseVotingFeatures.h"
#include "vtkCurvatureDensityFeatures.h"
#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSmoothShrinkIndexFeatures.h"
#include "vtkSurfaceVariationFeatures.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

int TestFeaturePointsReference(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::printf("usage: TestFeaturePointsReference REFERENCE.txt [--write]\n");
    return EXIT_FAILURE;
  }
  const std::string file = argv[1];
  const bool write = argc > 2 && std::strcmp(argv[2], "--write") == 0;

  const int model = vtkFeatureModelSource::MODEL_I, points = 20000, seed = 1;
  vtkNew<vtkFeatureModelSource> source;
  source->SetModel(model);
  source->SetNumberOfPoints(points);
  source->SetSeed(seed);

  std::ostringstream text;
  text << "# Written by the plain VTK build's TestFeaturePointsReference (Filters/Testing/Cxx);\n"
          "# read by the ParaView plugin's test. Per detector: server-manager proxy name, number of\n"
          "# feature points, output point arrays, feature point ids.\n"
       << "cloud model=" << model << " points=" << points << " seed=" << seed << "\n";
  const std::pair<const char*, vtkSmartPointer<vtkFeaturePointDetector>> detectors[] = {
    { "CreaseVotingFeatures", vtkSmartPointer<vtkCreaseVotingFeatures>::New() },
    { "FeaturePointExtraction", vtkSmartPointer<vtkFeaturePointExtraction>::New() },
    { "SmoothShrinkIndexFeatures", vtkSmartPointer<vtkSmoothShrinkIndexFeatures>::New() },
    { "SurfaceVariationFeatures", vtkSmartPointer<vtkSurfaceVariationFeatures>::New() },
    { "CurvatureDensityFeatures", vtkSmartPointer<vtkCurvatureDensityFeatures>::New() },
  };
  for (const auto& detector : detectors)
  {
    detector.second->SetInputConnection(source->GetOutputPort());
    detector.second->Update();
    vtkPolyData* out = detector.second->GetOutput();
    std::vector<std::string> names;
    for (int a = 0; a < out->GetPointData()->GetNumberOfArrays(); ++a)
    {
      names.emplace_back(out->GetPointData()->GetArrayName(a));
    }
    std::sort(names.begin(), names.end());
    auto* mask =
      vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("FeatureMask"));
    text << detector.first << " " << detector.second->GetNumberOfFeaturePoints() << " ";
    for (size_t i = 0; i < names.size(); ++i)
    {
      text << (i ? "," : "") << names[i];
    }
    for (vtkIdType i = 0; mask && i < mask->GetNumberOfValues(); ++i)
    {
      if (mask->GetValue(i))
      {
        text << " " << i;
      }
    }
    text << "\n";
    std::printf("%s: %lld feature points of %d\n", detector.first,
      static_cast<long long>(detector.second->GetNumberOfFeaturePoints()), points);
  }

  if (write)
  {
    std::ofstream(file) << text.str();
    std::printf("wrote %s\n", file.c_str());
    return EXIT_SUCCESS;
  }
  std::ifstream in(file);
  std::ostringstream stored;
  stored << in.rdbuf();
  if (stored.str() != text.str())
  {
    std::printf("FAILED: the results differ from %s, which the ParaView plugin's test compares "
                "with. If the change of results is meant, rewrite it: TestFeaturePointsReference "
                "%s --write (FeaturePointsCxxTests), and say so in the commit.\n",
      file.c_str(), file.c_str());
    return EXIT_FAILURE;
  }
  std::printf("same as %s\n", file.c_str());
  return EXIT_SUCCESS;
}
