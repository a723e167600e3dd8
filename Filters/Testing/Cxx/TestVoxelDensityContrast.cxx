// The voxel pre-filter: a crease sampled three times as densely makes it keep the dense band and
// drop most of the rest; a uniformly sampled cloud shows no contrast, so the feature filter scores
// every point and finds the same features as without the pre-filter. The quick screen on a sample
// of a large cloud agrees with the full test on both.
#include "FeaturePointsTestRun.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkVoxelDensityContrastFilter.h"

int TestVoxelDensityContrast(int, char*[])
{
  using namespace fptest;
  int failures = 0;

  // Dense band |u| < 0.1 around the crease, three times the density of the rest.
  Cloud dense = BentPlanes(30000, 31, 90.0, 0.5, 3.0, 0.1);
  vtkNew<vtkVoxelDensityContrastFilter> voxels;
  voxels->SetInputData(dense.Data);
  voxels->Update();
  auto* candidate =
    vtkUnsignedCharArray::SafeDownCast(voxels->GetOutput()->GetPointData()->GetArray("Candidate"));
  FP_CHECK(candidate != nullptr, "no Candidate array");
  long inBand = 0, outBand = 0, bandPoints = 0;
  const double halfWidth = 0.1;
  for (size_t i = 0; candidate && i < dense.Delta.size(); ++i)
  {
    const bool band = dense.Delta[i] < halfWidth;
    bandPoints += band;
    if (candidate->GetValue(static_cast<vtkIdType>(i)))
    {
      (band ? inBand : outBand)++;
    }
  }
  const long n = dense.Data->GetNumberOfPoints();
  std::printf("dense band: %ld points in band, %ld candidates in band, %ld outside (of %ld)\n",
    bandPoints, inBand, outBand, n - bandPoints);
  FP_CHECK(voxels->GetNumberOfContrastVoxels() > 0, "no contrast voxel found");
  FP_CHECK(inBand + outBand < n / 2, "the pre-filter kept %ld of %ld points", inBand + outBand, n);
  // Measured: all 7418 band points kept, 768 of 22582 outside (the ring of neighbour voxels).
  FP_CHECK(outBand < 0.1 * (n - bandPoints), "%ld candidates outside the dense band", outBand);
  FP_CHECK(inBand > 0.97 * bandPoints, "only %ld of %ld band points kept", inBand, bandPoints);

  // The paper's rule (raw counts of neighbouring voxels) keeps nearly everything on a real surface.
  vtkNew<vtkVoxelDensityContrastFilter> paper;
  paper->SetInputData(dense.Data);
  paper->SetContrastRuleToVoxelCounts();
  paper->Update();
  std::printf("paper's VOXEL_COUNTS rule keeps %ld of %ld points\n",
    static_cast<long>(paper->GetNumberOfCandidates()), n);
  FP_CHECK(paper->GetNumberOfCandidates() > inBand + outBand, "VOXEL_COUNTS kept fewer points");

  // Uniform sampling: no contrast, nothing lost.
  Cloud uniform = BentPlanes(30000, 32, 90.0);
  vtkNew<vtkVoxelDensityContrastFilter> uniformVoxels;
  uniformVoxels->SetInputData(uniform.Data);
  uniformVoxels->Update();
  FP_CHECK(uniformVoxels->GetNumberOfCandidates() == 0,
    "uniform cloud: %ld candidates from spurious contrast",
    static_cast<long>(uniformVoxels->GetNumberOfCandidates()));
  vtkNew<vtkFeaturePointExtraction> with, without;
  with->SetInputData(uniform.Data);
  without->SetInputData(uniform.Data);
  without->UseVoxelFilterOff();
  with->Update();
  without->Update();
  long differ = 0;
  for (vtkIdType i = 0; i < uniform.Data->GetNumberOfPoints(); ++i)
  {
    differ += Mask(with->GetOutput())->GetValue(i) != Mask(without->GetOutput())->GetValue(i);
  }
  std::printf("uniform: %ld candidates, %ld feature points, %ld mask differences with/without\n",
    static_cast<long>(with->GetNumberOfCandidates()), CountSet(Mask(with->GetOutput())), differ);
  FP_CHECK(with->GetNumberOfCandidates() == uniform.Data->GetNumberOfPoints(),
    "uniform cloud not fully scored");
  FP_CHECK(differ == 0, "%ld mask differences", differ);
  // The spacing from the 1-nearest pass and from the k-nearest table (no pre-filter) agree.
  FP_CHECK(with->GetMeanSpacing() == without->GetMeanSpacing(), "spacing %.17g vs %.17g",
    with->GetMeanSpacing(), without->GetMeanSpacing());
  FP_CHECK(CountSet(Mask(with->GetOutput())) > 100, "no feature found on the uniform crease");

  // The quick screen on a spatial sample (clouds of at least 65536 points): it sees the dense
  // band of a large cloud, and no contrast on a uniform one, as the full test does. Small clouds
  // are never screened out.
  for (const double factor : { 3.0, 1.0 })
  {
    Cloud large = BentPlanes(120000, factor > 1.0 ? 33 : 34, 90.0, 0.5, factor, 0.1);
    vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
    FP_CHECK(neighborhoods->Build(large.Data->GetPoints()), "cannot search the large cloud");
    vtkNew<vtkVoxelDensityContrastFilter> screen;
    const bool sampleContrast = screen->SampleShowsContrast(neighborhoods);
    const vtkIdType sampleVoxels = screen->GetNumberOfOccupiedVoxels();
    vtkNew<vtkVoxelDensityContrastFilter> full;
    full->SetInputData(large.Data);
    full->Update();
    std::printf("large cloud, density factor %g: screen %s (%lld sampled voxels of %lld), full "
                "test %lld contrast voxels\n",
      factor, sampleContrast ? "contrast" : "none", static_cast<long long>(sampleVoxels),
      static_cast<long long>(full->GetNumberOfOccupiedVoxels()),
      static_cast<long long>(full->GetNumberOfContrastVoxels()));
    FP_CHECK(sampleContrast == (factor > 1.0), "density factor %g: the screen says %s", factor,
      sampleContrast ? "contrast" : "none");
    FP_CHECK(sampleContrast == (full->GetNumberOfContrastVoxels() > 0),
      "density factor %g: screen and full test disagree", factor);
    FP_CHECK(sampleVoxels > 0 && sampleVoxels < full->GetNumberOfOccupiedVoxels() / 4,
      "the screen voxelized %lld of %lld voxels", static_cast<long long>(sampleVoxels),
      static_cast<long long>(full->GetNumberOfOccupiedVoxels()));
  }
  vtkNew<vtkPointCloudNeighborhoods> small;
  small->Build(uniform.Data->GetPoints());
  vtkNew<vtkVoxelDensityContrastFilter> smallScreen;
  FP_CHECK(smallScreen->SampleShowsContrast(small), "a 30000-point cloud was screened out");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
