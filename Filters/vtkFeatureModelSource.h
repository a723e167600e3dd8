/**
 * @class   vtkFeatureModelSource
 * @brief   Noisy point clouds of the paper's kind of test model, with exact ground truth.
 *
 * Generates one of the synthetic models of Huang et al. (2023), Section 3.3, as this project
 * reads their description (the paper shows them only in figures), or a smooth shape with no
 * feature:
 *
 * - MODEL_I ("a surface with a middle valley", 170,000 points by default): a square sheet of side
 *   Size with a V-shaped valley across its middle: flanks at ValleySlope (30 degrees) from the
 *   plane, 0.3 Size wide. Three straight creases: two convex shoulders (dihedral angle 30 degrees)
 *   and the concave valley floor (60 degrees).
 * - MODEL_II ("a flat top plane with gentle features in the middle", 220,000 points): a plateau
 *   0.5 Size wide standing 0.15 Size above a ground plane, with 60-degree walls, and on its top a
 *   low ridge whose flanks rise at 15 degrees. Seven straight creases: walls' foot (concave, 60)
 *   and top (convex, 60), the ridge's feet (concave, 15) and crest (convex, 30).
 * - MODEL_III ("intersecting surfaces", 130,000 points): a square sheet crossed by an open vertical
 *   cylinder of radius 0.25 Size and height 0.5 Size; both surfaces go through each other. One
 *   curved feature: the circle where they meet (dihedral angle 90 degrees), with the cylinder's
 *   curvature around it.
 * - SPHERE (100,000 points): a sphere of diameter Size, no feature at all.
 *
 * Sampling: points are drawn independently and uniformly over the surface area (a Poisson
 * sampling, like an unorganized scan), except that the band within DenseBandWidth nominal
 * spacings of a feature curve is sampled FeatureDensityFactor times as densely, as the paper's
 * re-scanned feature regions (1: uniform sampling). The nominal spacing is sqrt(area / number of
 * points). Then every point is moved by isotropic Gaussian noise of standard deviation
 * NoiseFactor * s, where s is the mean nearest-neighbour distance of the clean cloud
 * (EVALUATION.md: sigma = 0.5 s by default). Everything follows from Seed: the same parameters give
 * the same cloud on every run and every thread count.
 *
 * Output: a vtkPolyData with one vertex cell per point and the point arrays
 * - `FeatureDistance` (double): the clean (pre-noise) distance delta from the point to the
 *   nearest feature curve; VTK_FLOAT_MAX on a model without features.
 * - `GroundTruth` (uint8): 1 for the positives of EVALUATION.md, delta <= 2 s.
 * and the field data `CleanMeanSpacing` (s) and `NoiseSigma`.
 *
 * @sa vtkFeaturePointEvaluation vtkFeaturePointExtraction
 */
#ifndef vtkFeatureModelSource_h
#define vtkFeatureModelSource_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FEATUREPOINTSFILTERS_EXPORT vtkFeatureModelSource : public vtkPolyDataAlgorithm
{
public:
  static vtkFeatureModelSource* New();
  vtkTypeMacro(vtkFeatureModelSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Models
  {
    MODEL_I = 0,   ///< sheet with a middle valley
    MODEL_II = 1,  ///< plateau with a gentle ridge on its flat top
    MODEL_III = 2, ///< sheet crossed by a cylinder
    SPHERE = 3,    ///< no feature
  };

  ///@{
  /** Which model. Default MODEL_I. */
  vtkSetClampMacro(Model, int, MODEL_I, SPHERE);
  vtkGetMacro(Model, int);
  void SetModelToModelI() { this->SetModel(MODEL_I); }
  void SetModelToModelII() { this->SetModel(MODEL_II); }
  void SetModelToModelIII() { this->SetModel(MODEL_III); }
  void SetModelToSphere() { this->SetModel(SPHERE); }
  ///@}

  /** The model's name ("Model I", ...), and its default number of points. */
  static const char* GetModelName(int model);
  static vtkIdType GetDefaultNumberOfPoints(int model);

  ///@{
  /**
   * Number of points; 0 (default) takes the model's own count (170,000, 220,000, 130,000 for
   * Models I-III as in the paper's Table 1; 100,000 for the sphere).
   */
  vtkSetClampMacro(NumberOfPoints, vtkIdType, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * How many times denser the band around the feature curves is sampled than the rest. Default 3;
   * 1 samples the model uniformly.
   */
  vtkSetClampMacro(FeatureDensityFactor, double, 1.0, 100.0);
  vtkGetMacro(FeatureDensityFactor, double);
  ///@}

  ///@{
  /** Half-width of the denser band around each feature curve, in nominal spacings. Default 5. */
  vtkSetClampMacro(DenseBandWidth, double, 0.0, 1000.0);
  vtkGetMacro(DenseBandWidth, double);
  ///@}

  ///@{
  /** Standard deviation of the Gaussian noise, in mean spacings s of the clean cloud. Default 0.5. */
  vtkSetClampMacro(NoiseFactor, double, 0.0, 100.0);
  vtkGetMacro(NoiseFactor, double);
  ///@}

  ///@{
  /** Size of the model (sheet side, sphere diameter) in the output's units. Default 100. */
  vtkSetClampMacro(Size, double, 1e-12, 1e12);
  vtkGetMacro(Size, double);
  ///@}

  ///@{
  /** Where the model's centre lies. Default (0, 0, 0). */
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  ///@}

  ///@{
  /** Seed of the random sampling and noise. Default 1. */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /** Slope of Model I's valley flanks, in degrees. Default 30. */
  vtkSetClampMacro(ValleySlope, double, 1.0, 80.0);
  vtkGetMacro(ValleySlope, double);
  ///@}

  ///@{
  /** vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) output points. */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkFeatureModelSource();
  ~vtkFeatureModelSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Model = MODEL_I;
  vtkIdType NumberOfPoints = 0;
  double FeatureDensityFactor = 3.0;
  double DenseBandWidth = 5.0;
  double NoiseFactor = 0.5;
  double Size = 100.0;
  double Center[3] = { 0.0, 0.0, 0.0 };
  unsigned int Seed = 1;
  double ValleySlope = 30.0;
  int OutputPointsPrecision = DOUBLE_PRECISION;

private:
  vtkFeatureModelSource(const vtkFeatureModelSource&) = delete;
  void operator=(const vtkFeatureModelSource&) = delete;
};

#endif
