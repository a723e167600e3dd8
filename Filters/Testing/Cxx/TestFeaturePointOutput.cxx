// The output's shape: input points in input order, input point data passed through, one vertex
// per point, the documented arrays; OutputFeaturesOnly with vtkOriginalPointIds; progress events;
// an abort request stops the run early and leaves a well-formed output.
#include "FeaturePointsTestRun.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"

#include <cstring>
#include <vector>

int TestFeaturePointOutput(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  Cloud cloud = BentPlanes(20000, 71, 90.0);
  const vtkIdType n = cloud.Data->GetNumberOfPoints();
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    label->SetValue(i, static_cast<int>(i * 7 % 1000));
  }
  cloud.Data->GetPointData()->AddArray(label);

  vtkNew<vtkFeaturePointExtraction> filter;
  filter->SetInputData(cloud.Data);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call) {
    static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(call));
  });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();

  FP_CHECK(out->GetNumberOfPoints() == n, "%ld output points", static_cast<long>(out->GetNumberOfPoints()));
  FP_CHECK(out->GetNumberOfVerts() == n, "%ld vertex cells", static_cast<long>(out->GetNumberOfVerts()));
  long moved = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    out->GetPoint(i, a);
    cloud.Data->GetPoint(i, b);
    moved += std::memcmp(a, b, sizeof(a)) != 0;
  }
  FP_CHECK(moved == 0, "%ld points moved or reordered", moved);
  auto* passed = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("Label"));
  FP_CHECK(passed && passed->GetValue(1234) == label->GetValue(1234), "input point data not passed");
  struct Expected
  {
    const char* Name;
    int Type, Components;
  };
  for (const Expected& e : { Expected{ "Normals", VTK_FLOAT, 3 }, Expected{ "SSI", VTK_FLOAT, 1 },
         Expected{ "PDI", VTK_FLOAT, 1 }, Expected{ "F", VTK_FLOAT, 1 },
         Expected{ "Candidate", VTK_UNSIGNED_CHAR, 1 }, Expected{ "FeatureMask", VTK_UNSIGNED_CHAR, 1 } })
  {
    vtkDataArray* a = out->GetPointData()->GetArray(e.Name);
    FP_CHECK(a && a->GetDataType() == e.Type && a->GetNumberOfComponents() == e.Components &&
        a->GetNumberOfTuples() == n,
      "array %s missing or malformed", e.Name);
  }
  // Normals are unit vectors, perpendicular to the flat parts; F > threshold exactly on the mask.
  vtkFloatArray* normals = Floats(out, "Normals");
  vtkFloatArray* f = Floats(out, "F");
  long badNormals = 0, badMask = 0, tilted = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    float v[3];
    normals->GetTypedTuple(i, v);
    badNormals += std::abs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0f) > 1e-4f;
    double p[3];
    out->GetPoint(i, p);
    if (p[0] < -0.3) // the flat half z = 0, away from the crease: normal close to +-z
    {
      tilted += std::abs(v[2]) < 0.9f;
    }
    badMask += (f->GetValue(i) > filter->GetThresholdUsed()) != (Mask(out)->GetValue(i) != 0);
  }
  FP_CHECK(badNormals == 0, "%ld normals are not unit vectors", badNormals);
  // Noise tilts a few normals at the square's rim, where neighbourhoods are one-sided.
  FP_CHECK(tilted <= n / 1000, "%ld normals of the flat half tilted by more than 25 degrees", tilted);
  FP_CHECK(badMask == 0, "%ld mask entries disagree with F > threshold", badMask);
  FP_CHECK(out->GetFieldData()->GetArray("MeanSpacing") &&
      out->GetFieldData()->GetArray("FeatureThreshold"),
    "field data missing");
  FP_CHECK(std::abs(filter->GetMeanSpacing() / cloud.Spacing - 1.0) < 0.3,
    "mean spacing %g, clean spacing %g", filter->GetMeanSpacing(), cloud.Spacing);
  FP_CHECK(progress.size() >= 3 && progress.back() == 1.0, "%zu progress events", progress.size());
  for (size_t i = 1; i < progress.size(); ++i)
  {
    FP_CHECK(progress[i] >= progress[i - 1], "progress went back");
  }

  // Features only.
  const long features = CountSet(Mask(out));
  vtkNew<vtkFeaturePointExtraction> only;
  only->SetInputData(cloud.Data);
  only->OutputFeaturesOnlyOn();
  only->Update();
  vtkPolyData* kept = only->GetOutput();
  auto* ids = vtkIdTypeArray::SafeDownCast(kept->GetPointData()->GetArray("vtkOriginalPointIds"));
  FP_CHECK(kept->GetNumberOfPoints() == features && features > 0, "%ld of %ld features kept",
    static_cast<long>(kept->GetNumberOfPoints()), features);
  FP_CHECK(kept->GetNumberOfVerts() == features, "vertex cells of the features-only output");
  FP_CHECK(ids != nullptr, "vtkOriginalPointIds missing");
  long wrong = 0;
  for (vtkIdType j = 0; ids && j < kept->GetNumberOfPoints(); ++j)
  {
    const vtkIdType i = ids->GetValue(j);
    wrong += Mask(out)->GetValue(i) != 1 || Floats(kept, "F")->GetValue(j) != f->GetValue(i) ||
      vtkIntArray::SafeDownCast(kept->GetPointData()->GetArray("Label"))->GetValue(j) !=
        label->GetValue(i);
  }
  FP_CHECK(wrong == 0, "%ld features-only points disagree with the full output", wrong);

  // Abort at the first progress event: the run stops, the output is well formed and has no feature.
  vtkNew<vtkFeaturePointExtraction> aborted;
  aborted->SetInputData(cloud.Data);
  vtkNew<vtkCallbackCommand> onAbort;
  onAbort->SetCallback([](vtkObject* caller, unsigned long, void*, void*) {
    static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  });
  aborted->AddObserver(vtkCommand::ProgressEvent, onAbort);
  aborted->Update();
  FP_CHECK(aborted->GetOutput()->GetNumberOfPoints() == n, "aborted output malformed");
  FP_CHECK(CountSet(Mask(aborted->GetOutput())) == 0, "aborted run marked features");
  FP_CHECK(AllFinite(aborted->GetOutput()), "aborted run: non-finite values");
  std::printf("%ld feature points, %zu progress events, threshold %.4f, spacing %.5f\n", features,
    progress.size(), filter->GetThresholdUsed(), filter->GetMeanSpacing());
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
