// FeaturePointsExample: the feature filter in a VTK pipeline.
//
//   FeaturePointsExample [OUTPUT.vtp [PICTURE.png [INPUT]]]
//
// INPUT is any point cloud file vtkPointCloudIO reads (PLY, VTP, VTU, legacy VTK, PTS, XYZ/TXT,
// CSV). Without INPUT it builds its own example: the surface of a unit cube sampled at random (60,000
// points), its edges sampled three times as densely, with Gaussian noise of half the mean spacing.
// It writes the cloud with the filter's arrays (Normals, SSI, PDI, F, Candidate, FeatureMask) to
// OUTPUT (default features.vtp) and an offscreen picture, points coloured by F and feature points
// in red, to PICTURE (default features.png).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFeaturePointExtraction.h"
#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataWriter.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace
{
// A noisy cube surface whose edges (within 0.05 of an edge) are sampled three times as densely.
vtkSmartPointer<vtkPolyData> NoisyCube(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  while (points->GetNumberOfPoints() < n)
  {
    const int face = static_cast<int>(u(rng) * 6) % 6;
    double p[3] = { u(rng), u(rng), u(rng) };
    p[face / 2] = face % 2; // the face's fixed coordinate
    const int a = (face / 2 + 1) % 3, b = (face / 2 + 2) % 3;
    const double edge = std::min(std::min(p[a], 1 - p[a]), std::min(p[b], 1 - p[b]));
    if (edge < 0.05 || u(rng) < 1.0 / 3.0)
    {
      points->InsertNextPoint(p);
    }
  }
  // Noise of half the mean spacing: spacing of n points over the cube's area 6 (about
  // 0.5 / sqrt(density) for random sampling, the edges' extra points ignored).
  const double sigma = 0.5 * 0.5 / std::sqrt(n / 6.0);
  std::normal_distribution<double> g(0.0, sigma);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + g(rng), p[1] + g(rng), p[2] + g(rng));
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  return cloud;
}
} // namespace

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "features.vtp";
  const char* picture = argc > 2 ? argv[2] : "features.png";

  vtkSmartPointer<vtkPointSet> cloud;
  if (argc > 3)
  {
    std::string error;
    cloud = vtkPointCloudIO::Read(argv[3], error);
    if (!cloud)
    {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
  }
  else
  {
    cloud = NoisyCube(60000, 2023);
  }

  vtkNew<vtkFeaturePointExtraction> features;
  features->SetInputData(cloud);
  const auto start = std::chrono::steady_clock::now();
  features->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%lld points, %lld scored by the voxel pre-filter, %lld feature points, mean spacing "
              "%.5g, threshold on F %.4f, %.3f s\n",
    static_cast<long long>(cloud->GetNumberOfPoints()),
    static_cast<long long>(features->GetNumberOfCandidates()),
    static_cast<long long>(features->GetNumberOfFeaturePoints()), features->GetMeanSpacing(),
    features->GetThresholdUsed(), seconds);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(features->GetOutputPort());
  writer->SetFileName(output);
  if (writer->Write() != 1)
  {
    std::fprintf(stderr, "%s: cannot write the result\n", output);
    return 1;
  }

  // Offscreen picture: F on a blue-to-green scale up to the threshold, feature points in red.
  vtkNew<vtkFeaturePointExtraction> onlyFeatures;
  onlyFeatures->SetInputData(cloud);
  onlyFeatures->OutputFeaturesOnlyOn();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.333);
  lut->Build();
  vtkNew<vtkPolyDataMapper> cloudMapper;
  cloudMapper->SetInputConnection(features->GetOutputPort());
  cloudMapper->SetScalarModeToUsePointFieldData();
  cloudMapper->SelectColorArray("F");
  cloudMapper->SetLookupTable(lut);
  cloudMapper->SetScalarRange(0.0, features->GetThresholdUsed());
  vtkNew<vtkActor> cloudActor;
  cloudActor->SetMapper(cloudMapper);
  cloudActor->GetProperty()->SetPointSize(2);
  vtkNew<vtkPolyDataMapper> featureMapper;
  featureMapper->SetInputConnection(onlyFeatures->GetOutputPort());
  featureMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> featureActor;
  featureActor->SetMapper(featureMapper);
  featureActor->GetProperty()->SetColor(0.9, 0.05, 0.05);
  featureActor->GetProperty()->SetPointSize(3);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(cloudActor);
  renderer->AddActor(featureActor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(800, 600);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->Azimuth(35);
  renderer->GetActiveCamera()->Elevation(25);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(picture);
  png->Write();
  std::printf("wrote %s and %s\n", output, picture);
  return 0;
}
