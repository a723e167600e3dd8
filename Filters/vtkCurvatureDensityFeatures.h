/**
 * @class   vtkCurvatureDensityFeatures
 * @brief   Baseline: feature points from curvature, normal angles and density, after Wang and
 *          Yuan (2011).
 *
 * Wang, L. and Yuan, B.: "Curvature and density based feature point detection for point cloud
 * data", IET 3rd International Conference on Wireless, Mobile and Multimedia Networks, 2010
 * (published 2011), is the "method in [17]" of the paper's Table 1. Its full text is not openly
 * available; the paper describes it as combining "neighborhood average normal vector angle,
 * curvature and density". This class implements that description, with these choices made here:
 *
 * - Curvature c(i): the PCA surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the point
 *   and its NumberOfNeighbors nearest other points (the usual curvature estimate of point clouds).
 * - Average normal angle theta(i): the mean over the same neighbours of the angle between the
 *   point's PCA normal and theirs, taken without orientation (acos |n_i . n_j|, in radians).
 * - Density rho(i) = 1 / m(i), m(i) the mean distance to the same neighbours (as the paper's Eq. 9).
 * - The three indicators have different units, so each is divided by its median over the cloud,
 *   and the score is their weighted mean:
 *   CurvatureDensity(i) = (w_c c/med(c) + w_t theta/med(theta) + w_d rho/med(rho)) / (w_c+w_t+w_d),
 *   with the three weights 1 by default. A point is a feature point when the score exceeds the
 *   threshold (vtkFeaturePointDetector: AUTOMATIC by default; ABSOLUTE thresholds are on the score,
 *   which is about 1 on a smooth region; default 2).
 *
 * Output (see vtkFeaturePointDetector): `Normals` (float, 3), `Curvature`, `NormalAngle`,
 * `Density` (raw indicators, float), `CurvatureDensity` (the score, float) and `FeatureMask`.
 *
 * @warning The per-point work runs under vtkSMPTools; results do not depend on the thread count.
 *
 * @sa vtkFeaturePointDetector vtkSurfaceVariationFeatures vtkFeaturePointExtraction
 */
#ifndef vtkCurvatureDensityFeatures_h
#define vtkCurvatureDensityFeatures_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkFeaturePointDetector.h"

class FEATUREPOINTSFILTERS_EXPORT vtkCurvatureDensityFeatures : public vtkFeaturePointDetector
{
public:
  static vtkCurvatureDensityFeatures* New();
  vtkTypeMacro(vtkCurvatureDensityFeatures, vtkFeaturePointDetector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** k: the number of nearest other points in each neighbourhood. Default 15. */
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 1000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /** Weights of the curvature, normal-angle and density terms of the score. Default 1 each. */
  vtkSetClampMacro(CurvatureWeight, double, 0.0, 1000.0);
  vtkGetMacro(CurvatureWeight, double);
  vtkSetClampMacro(NormalAngleWeight, double, 0.0, 1000.0);
  vtkGetMacro(NormalAngleWeight, double);
  vtkSetClampMacro(DensityWeight, double, 0.0, 1000.0);
  vtkGetMacro(DensityWeight, double);
  ///@}

  /** The score array: "CurvatureDensity". */
  const char* GetScoreArrayName() const override { return "CurvatureDensity"; }

  /**
   * Distributed runs: each own point's NumberOfNeighbors nearest and their normals, so their
   * neighbourhoods too (see the superclass).
   */
  bool GetHaloExtent(int& neighbors, int& levels) const override
  {
    neighbors = this->NumberOfNeighbors;
    levels = 2;
    return true;
  }

protected:
  void ListParameters(std::vector<std::pair<const char*, double>>& parameters) const override;
  // The upper median of `values` over `ids` (the own points of every process).
  double MedianOf(const float* values, const std::vector<vtkIdType>& ids);
  vtkCurvatureDensityFeatures();
  ~vtkCurvatureDensityFeatures() override;

  int Run(vtkPointSet* input, vtkPolyData* output) override;
  int GetLengthPower(const char* name) const override; // Density: -1 (points per length)

  int NumberOfNeighbors = 15;
  double CurvatureWeight = 1.0;
  double NormalAngleWeight = 1.0;
  double DensityWeight = 1.0;

private:
  vtkCurvatureDensityFeatures(const vtkCurvatureDensityFeatures&) = delete;
  void operator=(const vtkCurvatureDensityFeatures&) = delete;
};

#endif
