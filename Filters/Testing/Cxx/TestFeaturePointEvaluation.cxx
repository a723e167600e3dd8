// vtkFeaturePointEvaluation on hand-built cases whose figures are worked out by hand below.
#include "FeaturePointsTestRun.h"
#include "vtkFeaturePointEvaluation.h"

namespace
{
template <typename ArrayT, typename T>
vtkSmartPointer<ArrayT> Make(std::initializer_list<T> values)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  for (T v : values)
  {
    a->InsertNextValue(v);
  }
  return a;
}
bool Near(double a, double b)
{
  return std::abs(a - b) < 1e-12;
}
} // namespace

int TestFeaturePointEvaluation(int, char*[])
{
  using namespace fptest;
  int failures = 0;
  vtkNew<vtkFeaturePointEvaluation> e;

  // Distances with s = 1 (positives delta <= 2, correct <= 4, Pt radius 1.3):
  //   delta:    0.5  1.0  1.5  2.0  3.0  5.0  9.0  0.2  1.2  8.0
  //   detected:  1    1    0    1    1    1    0    0    0    0
  // detections 5; correct (delta <= 4) 4 -> precision 4/5; positives (delta <= 2): 6 points,
  // 3 detected -> recall 1/2; F1 = 2 * 0.8 * 0.5 / 1.3; Pr = 5/6; within 1.3: 4 points
  // (0.5, 1.0, 0.2, 1.2), 2 detected -> Pt 1/2. Confusion against delta <= 2: TP 3, FP 2 (3.0,
  // 5.0), FN 3, TN 2 -> MCC = (3*2 - 2*3) / sqrt(5*6*4*5) = 0. Far detections (delta > 4): 1 of
  // 10 points -> 100 per 1000.
  auto delta = Make<vtkDoubleArray, double>({ 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 9.0, 0.2, 1.2, 8.0 });
  auto hit = Make<vtkUnsignedCharArray, unsigned char>({ 1, 1, 0, 1, 1, 1, 0, 0, 0, 0 });
  FP_CHECK(e->EvaluateDistances(hit, delta, 1.0), "%s", e->GetErrorText().c_str());
  FP_CHECK(e->GetDetections() == 5 && e->GetPositives() == 6, "counts %lld %lld",
    (long long)e->GetDetections(), (long long)e->GetPositives());
  FP_CHECK(Near(e->GetPrecision(), 0.8), "precision %g", e->GetPrecision());
  FP_CHECK(Near(e->GetRecall(), 0.5), "recall %g", e->GetRecall());
  FP_CHECK(Near(e->GetF1(), 0.8 / 1.3), "F1 %g", e->GetF1());
  FP_CHECK(Near(e->GetPr(), 5.0 / 6.0), "Pr %g", e->GetPr());
  FP_CHECK(Near(e->GetPt(), 0.5), "Pt %g", e->GetPt());
  FP_CHECK(Near(e->GetMCC(), 0.0), "MCC %g", e->GetMCC());
  FP_CHECK(Near(e->GetFalsePerThousand(), 100.0), "false per 1000 %g", e->GetFalsePerThousand());

  // The same distances in another unit (x 1000, s = 1000) give the same figures.
  auto scaled = Make<vtkDoubleArray, double>({ 500, 1000, 1500, 2000, 3000, 5000, 9000, 200, 1200, 8000 });
  e->EvaluateDistances(hit, scaled, 1000.0);
  FP_CHECK(Near(e->GetF1(), 0.8 / 1.3) && Near(e->GetPt(), 0.5), "scaled: F1 %g Pt %g", e->GetF1(), e->GetPt());

  // Labels: TP 2, FP 1, FN 1, TN 6 -> precision 2/3, recall 2/3, MCC (2*6 - 1*1) / sqrt(3*3*7*7)
  // = 11/21, Pr = 3/3; Pt does not apply (-1).
  auto labels = Make<vtkUnsignedCharArray, unsigned char>({ 1, 1, 1, 0, 0, 0, 0, 0, 0, 0 });
  auto found = Make<vtkUnsignedCharArray, unsigned char>({ 1, 1, 0, 1, 0, 0, 0, 0, 0, 0 });
  FP_CHECK(e->EvaluateLabels(found, labels), "%s", e->GetErrorText().c_str());
  FP_CHECK(Near(e->GetPrecision(), 2.0 / 3.0) && Near(e->GetRecall(), 2.0 / 3.0),
    "labels: precision %g recall %g", e->GetPrecision(), e->GetRecall());
  FP_CHECK(Near(e->GetMCC(), 11.0 / 21.0), "labels: MCC %g", e->GetMCC());
  FP_CHECK(Near(e->GetPr(), 1.0) && e->GetPt() == -1.0, "labels: Pr %g Pt %g", e->GetPr(), e->GetPt());

  // Perfect and inverted detections: MCC +1 and -1; nothing detected: MCC 0, precision 0.
  e->EvaluateLabels(labels, labels);
  FP_CHECK(Near(e->GetMCC(), 1.0) && Near(e->GetF1(), 1.0), "perfect: MCC %g F1 %g", e->GetMCC(), e->GetF1());
  auto inverted = Make<vtkUnsignedCharArray, unsigned char>({ 0, 0, 0, 1, 1, 1, 1, 1, 1, 1 });
  e->EvaluateLabels(inverted, labels);
  FP_CHECK(Near(e->GetMCC(), -1.0), "inverted: MCC %g", e->GetMCC());
  auto none = Make<vtkUnsignedCharArray, unsigned char>({ 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 });
  e->EvaluateLabels(none, labels);
  FP_CHECK(e->GetMCC() == 0.0 && e->GetPrecision() == 0.0 && e->GetRecall() == 0.0,
    "none: MCC %g precision %g", e->GetMCC(), e->GetPrecision());

  // Bad arguments: a clear error, no figures.
  auto shortMask = Make<vtkUnsignedCharArray, unsigned char>({ 1, 0 });
  FP_CHECK(!e->EvaluateLabels(shortMask, labels) &&
      e->GetErrorText().find("2 values") != std::string::npos,
    "length mismatch not reported: '%s'", e->GetErrorText().c_str());
  FP_CHECK(!e->EvaluateDistances(hit, delta, 0.0), "s = 0 accepted");
  FP_CHECK(!e->EvaluateDistances(nullptr, delta, 1.0), "missing array accepted");

  // PCEDNet's colours: (255,0,0) and (168,0,0) sharp, anything else flat.
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(4);
  const unsigned char rgba[5][4] = { { 255, 0, 0, 255 }, { 168, 0, 0, 255 }, { 255, 255, 255, 255 },
    { 255, 0, 1, 255 }, { 0, 0, 0, 255 } };
  for (const auto& c : rgba)
  {
    colors->InsertNextTypedTuple(c);
  }
  auto sharp = vtkFeaturePointEvaluation::LabelsFromColors(colors);
  FP_CHECK(sharp && sharp->GetValue(0) == 1 && sharp->GetValue(1) == 1 && sharp->GetValue(2) == 0 &&
      sharp->GetValue(3) == 0 && sharp->GetValue(4) == 0,
    "colour labels wrong");
  std::printf("evaluation: %d failure(s)\n", failures);
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
