// Renders a noisy 90-degree crease offscreen, points coloured by F and feature points highlighted,
// and compares the picture with the baseline Filters/Testing/Data/Baseline/TestFeaturePointRendering.png
// (vtkRegressionTestImage: pass -V <baseline> -T <output dir>). Debian's VTK renders through X, so
// CTest runs this test under an Xvfb of its own (scripts/run-with-xvfb.sh); a VTK built with
// OSMesa or EGL renders it without X.
#include "FeaturePointsTestRun.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestFeaturePointRendering(int argc, char* argv[])
{
  using namespace fptest;
  Cloud cloud = BentPlanes(12000, 81, 90.0);
  vtkNew<vtkFeaturePointExtraction> filter;
  filter->SetInputData(cloud.Data);
  vtkNew<vtkFeaturePointExtraction> features;
  features->SetInputData(cloud.Data);
  features->OutputFeaturesOnlyOn();
  filter->Update();
  features->Update();

  const double* range = Floats(filter->GetOutput(), "F")->GetRange();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.333); // blue (low F) to green (high F)
  lut->Build();
  vtkNew<vtkPolyDataMapper> cloudMapper;
  cloudMapper->SetInputConnection(filter->GetOutputPort());
  cloudMapper->SetScalarModeToUsePointFieldData();
  cloudMapper->SelectColorArray("F");
  cloudMapper->SetLookupTable(lut);
  cloudMapper->SetScalarRange(range[0], filter->GetThresholdUsed());
  vtkNew<vtkActor> cloudActor;
  cloudActor->SetMapper(cloudMapper);
  cloudActor->GetProperty()->SetPointSize(2);

  vtkNew<vtkPolyDataMapper> featureMapper;
  featureMapper->SetInputConnection(features->GetOutputPort());
  featureMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> featureActor;
  featureActor->SetMapper(featureMapper);
  featureActor->GetProperty()->SetColor(1.0, 0.1, 0.1);
  featureActor->GetProperty()->SetPointSize(4);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(cloudActor);
  renderer->AddActor(featureActor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 300);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(-1.2, -2.0, 1.6);
  camera->SetFocalPoint(0.0, 0.5, 0.2);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  window->Render();

  const int result = vtkRegressionTestImageThreshold(window, 5.0);
  std::printf("%ld feature points drawn; image comparison %s\n",
    static_cast<long>(features->GetOutput()->GetNumberOfPoints()),
    result == vtkTesting::PASSED ? "passed" : "failed");
  return result == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
