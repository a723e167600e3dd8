#include "vtkFeaturePointEvaluation.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkFeaturePointEvaluation);

namespace
{
double Ratio(double a, double b)
{
  return b > 0.0 ? a / b : 0.0;
}

bool CheckArrays(vtkDataArray* detected, vtkDataArray* truth, const char* what, std::string& error)
{
  std::ostringstream os;
  if (!detected)
  {
    os << "no detection array";
  }
  else if (!truth)
  {
    os << "no " << what << " array";
  }
  else if (detected->GetNumberOfTuples() != truth->GetNumberOfTuples())
  {
    os << "the detection array has " << detected->GetNumberOfTuples() << " values and the "
       << what << " array " << truth->GetNumberOfTuples();
  }
  error = os.str();
  return error.empty();
}
} // namespace

vtkFeaturePointEvaluation::vtkFeaturePointEvaluation() = default;
vtkFeaturePointEvaluation::~vtkFeaturePointEvaluation() = default;

void vtkFeaturePointEvaluation::Reset()
{
  this->NumberOfPoints = this->Detections = this->Positives = 0;
  this->TruePositives = this->FalsePositives = this->FalseNegatives = this->TrueNegatives = 0;
  this->CorrectDetections = 0;
  this->Precision = this->Recall = this->F1 = this->MCC = this->Pr = this->FalsePerThousand = 0;
  this->Pt = -1;
  this->ErrorText.clear();
}

void vtkFeaturePointEvaluation::Finish()
{
  this->F1 = Ratio(2.0 * this->Precision * this->Recall, this->Precision + this->Recall);
  this->Pr = Ratio(double(this->Detections), double(this->Positives));
  const double tp = double(this->TruePositives), fp = double(this->FalsePositives);
  const double fn = double(this->FalseNegatives), tn = double(this->TrueNegatives);
  const double denominator = (tp + fp) * (tp + fn) * (tn + fp) * (tn + fn);
  this->MCC = denominator > 0.0 ? (tp * tn - fp * fn) / std::sqrt(denominator) : 0.0;
}

bool vtkFeaturePointEvaluation::EvaluateDistances(
  vtkDataArray* detected, vtkDataArray* featureDistance, double spacing)
{
  this->Reset();
  if (!CheckArrays(detected, featureDistance, "feature distance", this->ErrorText))
  {
    return false;
  }
  if (!(spacing > 0.0) || !std::isfinite(spacing))
  {
    this->ErrorText = "the mean spacing s must be positive and finite";
    return false;
  }
  const vtkIdType n = detected->GetNumberOfTuples();
  vtkIdType near = 0, nearDetected = 0, far = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool hit = detected->GetComponent(i, 0) != 0.0;
    const double delta = featureDistance->GetComponent(i, 0);
    const bool positive = delta <= this->PositiveRadius * spacing;
    this->Detections += hit;
    this->Positives += positive;
    this->TruePositives += hit && positive;
    this->FalsePositives += hit && !positive;
    this->FalseNegatives += !hit && positive;
    this->TrueNegatives += !hit && !positive;
    this->CorrectDetections += hit && delta <= this->CorrectRadius * spacing;
    far += hit && !(delta <= this->CorrectRadius * spacing);
    if (delta <= this->PtRadius * spacing)
    {
      ++near;
      nearDetected += hit;
    }
  }
  this->NumberOfPoints = n;
  this->Precision = Ratio(double(this->CorrectDetections), double(this->Detections));
  this->Recall = Ratio(double(this->TruePositives), double(this->Positives));
  this->Pt = Ratio(double(nearDetected), double(near));
  this->FalsePerThousand = Ratio(1000.0 * double(far), double(n));
  this->Finish();
  return true;
}

bool vtkFeaturePointEvaluation::EvaluateLabels(vtkDataArray* detected, vtkDataArray* labels)
{
  this->Reset();
  if (!CheckArrays(detected, labels, "label", this->ErrorText))
  {
    return false;
  }
  const vtkIdType n = detected->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool hit = detected->GetComponent(i, 0) != 0.0;
    const bool positive = labels->GetComponent(i, 0) != 0.0;
    this->Detections += hit;
    this->Positives += positive;
    this->TruePositives += hit && positive;
    this->FalsePositives += hit && !positive;
    this->FalseNegatives += !hit && positive;
    this->TrueNegatives += !hit && !positive;
  }
  this->NumberOfPoints = n;
  this->CorrectDetections = this->TruePositives;
  this->Precision = Ratio(double(this->TruePositives), double(this->Detections));
  this->Recall = Ratio(double(this->TruePositives), double(this->Positives));
  this->FalsePerThousand = Ratio(1000.0 * double(this->FalsePositives), double(n));
  this->Finish();
  return true;
}

vtkSmartPointer<vtkUnsignedCharArray> vtkFeaturePointEvaluation::LabelsFromColors(
  vtkDataArray* colors)
{
  if (!colors || colors->GetNumberOfComponents() < 3)
  {
    return nullptr;
  }
  auto labels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  labels->SetName("SharpLabel");
  labels->SetNumberOfValues(colors->GetNumberOfTuples());
  for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); ++i)
  {
    const double r = colors->GetComponent(i, 0);
    const double g = colors->GetComponent(i, 1);
    const double b = colors->GetComponent(i, 2);
    labels->SetValue(i, (r == 255.0 || r == 168.0) && g == 0.0 && b == 0.0 ? 1 : 0);
  }
  return labels;
}

bool vtkFeaturePointEvaluation::LabelsFromColors(vtkDataArray* colors, vtkUnsignedCharArray* labels)
{
  vtkSmartPointer<vtkUnsignedCharArray> made = labels ? LabelsFromColors(colors) : nullptr;
  if (!made)
  {
    return false;
  }
  labels->DeepCopy(made);
  labels->SetName(made->GetName());
  return true;
}

void vtkFeaturePointEvaluation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PositiveRadius: " << this->PositiveRadius << "\n";
  os << indent << "CorrectRadius: " << this->CorrectRadius << "\n";
  os << indent << "PtRadius: " << this->PtRadius << "\n";
  os << indent << "Precision: " << this->Precision << " Recall: " << this->Recall
     << " F1: " << this->F1 << " MCC: " << this->MCC << "\n";
}
