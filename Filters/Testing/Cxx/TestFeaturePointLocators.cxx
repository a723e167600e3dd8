// The detectors with another point locator (SetLocator): vtkStaticPointLocator, and
// vtkKdTreePointLocator (queried one point after the other), give the feature points of the
// default vtkPointCloudGridLocator on a noisy crease, where no two distances tie. After a run the
// locator holds neither the cloud nor its search structure.
#include "FeaturePointsTestRun.h"
#include "vtkCreaseVotingFeatures.h"
#include "vtkKdTreePointLocator.h"
#include "vtkPointCloudGridLocator.h"
#include "vtkStaticPointLocator.h"
#include "vtkSurfaceVariationFeatures.h"

#include <cstdio>
#include <string>

namespace
{
// Runs `filter` on the cloud with `locator` (nullptr: the default) and returns its output.
vtkSmartPointer<vtkPolyData> Run(
  vtkFeaturePointDetector* filter, vtkPolyData* cloud, vtkAbstractPointLocator* locator)
{
  if (locator)
  {
    filter->SetLocator(locator);
  }
  filter->SetInputData(cloud);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

int Compare(const char* name, vtkFeaturePointDetector* reference, vtkFeaturePointDetector* other,
  vtkPolyData* cloud, vtkAbstractPointLocator* locator)
{
  const bool defaultIsGrid = vtkPointCloudGridLocator::SafeDownCast(reference->GetLocator());
  vtkSmartPointer<vtkPolyData> a = Run(reference, cloud, nullptr);
  vtkSmartPointer<vtkPolyData> b = Run(other, cloud, locator);
  vtkUnsignedCharArray* ma = fptest::Mask(a);
  vtkUnsignedCharArray* mb = fptest::Mask(b);
  long different = 0, features = 0;
  for (vtkIdType i = 0; ma && mb && i < ma->GetNumberOfValues(); ++i)
  {
    different += ma->GetValue(i) != mb->GetValue(i) ? 1 : 0;
    features += ma->GetValue(i);
  }
  const double da = reference->GetMeanSpacing(), db = other->GetMeanSpacing();
  // The locator is released after the run: no cloud, no search structure kept.
  const bool released = !locator || !locator->GetDataSet();
  const bool ok = ma && mb && ma->GetNumberOfValues() == mb->GetNumberOfValues() &&
    different == 0 && features > 20 && std::abs(da - db) <= 1e-12 * da && defaultIsGrid &&
    other->GetLocator() == locator && released;
  std::printf("%-22s with %-21s: %ld feature points, %ld different, spacing %.15g / %.15g %s\n",
    name, locator->GetClassName(), features, different, da, db, ok ? "" : "FAILED");
  return ok ? 0 : 1;
}
} // namespace

int TestFeaturePointLocators(int, char*[])
{
  int failures = 0;
  fptest::Cloud cloud = fptest::BentPlanes(12000, 29, 90.0);
  {
    vtkNew<vtkFeaturePointExtraction> reference, other;
    vtkNew<vtkStaticPointLocator> locator;
    failures += Compare("vtkFeaturePointExtraction", reference, other, cloud.Data, locator);
  }
  {
    vtkNew<vtkCreaseVotingFeatures> reference, other;
    vtkNew<vtkStaticPointLocator> locator;
    failures += Compare("vtkCreaseVotingFeatures", reference, other, cloud.Data, locator);
  }
  {
    vtkNew<vtkSurfaceVariationFeatures> reference, other;
    vtkNew<vtkKdTreePointLocator> locator;
    failures += Compare("vtkSurfaceVariationFeatures", reference, other, cloud.Data, locator);
  }
  // The default locator is released too, and SetLocator(nullptr) leaves the default in use.
  {
    vtkNew<vtkSurfaceVariationFeatures> filter;
    filter->SetInputData(cloud.Data);
    filter->Update();
    vtkAbstractPointLocator* grid = filter->GetLocator();
    const bool released = grid && !grid->GetDataSet();
    filter->SetLocator(nullptr);
    filter->Modified();
    filter->Update();
    const bool ok = released && fptest::Mask(filter->GetOutput()) &&
      filter->GetNumberOfFeaturePoints() > 20;
    std::printf("default locator released after the run, no locator: %lld feature points %s\n",
      static_cast<long long>(filter->GetNumberOfFeaturePoints()), ok ? "" : "FAILED");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
