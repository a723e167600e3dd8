/**
 * @class   vtkFeaturePointEvaluation
 * @brief   Quality figures of a feature point detection, as docs/evaluation.md defines them.
 *
 * Two kinds of ground truth:
 *
 * - Synthetic clouds (EvaluateDistances): each point's clean distance delta to the nearest
 *   feature curve (vtkFeatureModelSource's `FeatureDistance`) and the clean cloud's mean
 *   nearest-neighbour distance s. Positives are the points with delta <= PositiveRadius s (2);
 *   a detection is correct when delta <= CorrectRadius s (4, a tolerance band).
 *   precision = correct detections / detections; recall = detected positives / positives;
 *   F1 = their harmonic mean. The paper's figures beside them: Pr = detections / positives
 *   (Eq. 13) and Pt = detections with delta <= PtRadius s / points with delta <= PtRadius s
 *   (Eq. 14, r = 1.3 s, the top of the paper's range). MCC is the Matthews correlation of the
 *   detections with the positives, point by point (no tolerance). FalsePerThousand counts the
 *   detections with delta > CorrectRadius s per 1000 points: on a shape with no feature, every
 *   detection.
 * - Labelled clouds (EvaluateLabels), such as PCEDNet's: a 0/1 label per point, no tolerance.
 *   precision = TP / (TP + FP), recall = TP / (TP + FN), F1, MCC, Pr = detections / positives;
 *   Pt does not apply (-1). LabelsFromColors() reads PCEDNet's colour coding.
 *
 * A ratio whose denominator is 0 is reported as 0 (precision with no detection, MCC when a row or
 * column of the confusion matrix is empty).
 *
 * @sa vtkFeatureModelSource vtkFeaturePointDetector
 */
#ifndef vtkFeaturePointEvaluation_h
#define vtkFeaturePointEvaluation_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For LabelsFromColors

#include <string> // For error text

class vtkDataArray;
class vtkUnsignedCharArray;

class FEATUREPOINTSFILTERS_EXPORT vtkFeaturePointEvaluation : public vtkObject
{
public:
  static vtkFeaturePointEvaluation* New();
  vtkTypeMacro(vtkFeaturePointEvaluation, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Radii in units of the clean mean spacing s (docs/evaluation.md: 2, 4; the paper's r: 1.3). */
  vtkSetClampMacro(PositiveRadius, double, 0.0, 1e6);
  vtkGetMacro(PositiveRadius, double);
  vtkSetClampMacro(CorrectRadius, double, 0.0, 1e6);
  vtkGetMacro(CorrectRadius, double);
  vtkSetClampMacro(PtRadius, double, 0.0, 1e6);
  vtkGetMacro(PtRadius, double);
  ///@}

  /**
   * Evaluate a detection (nonzero = detected, one value per point) against clean distances to
   * the feature curves, in the cloud's units, with the clean mean spacing s. Returns false (see
   * GetErrorText()) when the arrays are missing, of different lengths or s is not positive.
   */
  bool EvaluateDistances(vtkDataArray* detected, vtkDataArray* featureDistance, double spacing);

  /** Evaluate a detection against 0/1 labels (nonzero = feature). Returns false as above. */
  bool EvaluateLabels(vtkDataArray* detected, vtkDataArray* labels);

  /**
   * PCEDNet's colour labels: 1 where the colour (the first three components, 0-255) is
   * (255, 0, 0) or (168, 0, 0), else 0. Returns null when the array has fewer than 3 components.
   * C++ only (a smart pointer); the wrapped counterpart fills `labels` (named SharpLabel) and
   * returns false, `labels` untouched, when the array has fewer than 3 components.
   */
  VTK_WRAPEXCLUDE static vtkSmartPointer<vtkUnsignedCharArray> LabelsFromColors(
    vtkDataArray* colors);
  static bool LabelsFromColors(vtkDataArray* colors, vtkUnsignedCharArray* labels);

  ///@{
  /** Counts of the last evaluation. */
  vtkGetMacro(NumberOfPoints, vtkIdType);
  vtkGetMacro(Detections, vtkIdType);
  vtkGetMacro(Positives, vtkIdType);
  vtkGetMacro(TruePositives, vtkIdType);
  vtkGetMacro(FalsePositives, vtkIdType);
  vtkGetMacro(FalseNegatives, vtkIdType);
  vtkGetMacro(TrueNegatives, vtkIdType);
  vtkGetMacro(CorrectDetections, vtkIdType);
  ///@}

  ///@{
  /** Figures of the last evaluation (see the class comment). */
  vtkGetMacro(Precision, double);
  vtkGetMacro(Recall, double);
  vtkGetMacro(F1, double);
  vtkGetMacro(MCC, double);
  vtkGetMacro(Pr, double);
  vtkGetMacro(Pt, double);
  vtkGetMacro(FalsePerThousand, double);
  ///@}

  /** Why the last evaluation failed. */
  const std::string& GetErrorText() const { return this->ErrorText; }

protected:
  vtkFeaturePointEvaluation();
  ~vtkFeaturePointEvaluation() override;

  void Reset();
  // Precision-independent figures from the confusion matrix.
  void Finish();

  double PositiveRadius = 2.0;
  double CorrectRadius = 4.0;
  double PtRadius = 1.3;

  vtkIdType NumberOfPoints = 0;
  vtkIdType Detections = 0;
  vtkIdType Positives = 0;
  vtkIdType TruePositives = 0;
  vtkIdType FalsePositives = 0;
  vtkIdType FalseNegatives = 0;
  vtkIdType TrueNegatives = 0;
  vtkIdType CorrectDetections = 0;
  double Precision = 0, Recall = 0, F1 = 0, MCC = 0, Pr = 0, Pt = -1, FalsePerThousand = 0;
  std::string ErrorText;

private:
  vtkFeaturePointEvaluation(const vtkFeaturePointEvaluation&) = delete;
  void operator=(const vtkFeaturePointEvaluation&) = delete;
};

#endif
