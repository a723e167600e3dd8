/**
 * @class   vtkSurfaceVariationFeatures
 * @brief   Baseline: feature points by PCA surface variation (Pauly, Keiser and Gross 2003).
 *
 * For each point, the covariance of the point and its NumberOfNeighbors nearest other points has
 * eigenvalues lambda0 <= lambda1 <= lambda2; the surface variation
 * sigma = lambda0 / (lambda0 + lambda1 + lambda2) is 0 on a plane and up to 1/3 where the
 * neighbourhood spreads isotropically (a corner, noise). A point is a feature point when sigma
 * exceeds the threshold (vtkFeaturePointDetector: AUTOMATIC by default; ABSOLUTE thresholds are on
 * sigma itself, default 0.05). This is the "PCA" of the paper's Table 1, with the paper's k = 15.
 *
 * Output (see vtkFeaturePointDetector): `Normals` (float, 3: the eigenvector of lambda0, oriented
 * away from the bounding box's centre), `SurfaceVariation` (float) and `FeatureMask`.
 *
 * @warning The per-point work runs under vtkSMPTools; results do not depend on the thread count.
 *
 * @sa vtkFeaturePointDetector vtkPCACurvatureEstimation vtkFeaturePointExtraction
 */
#ifndef vtkSurfaceVariationFeatures_h
#define vtkSurfaceVariationFeatures_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkFeaturePointDetector.h"

class FEATUREPOINTSFILTERS_EXPORT vtkSurfaceVariationFeatures : public vtkFeaturePointDetector
{
public:
  static vtkSurfaceVariationFeatures* New();
  vtkTypeMacro(vtkSurfaceVariationFeatures, vtkFeaturePointDetector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** k: the number of nearest other points in each neighbourhood. Default 15. */
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 1000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  /** The score array: "SurfaceVariation". */
  const char* GetScoreArrayName() const override { return "SurfaceVariation"; }

  /** Distributed runs: each own point's NumberOfNeighbors nearest (see the superclass). */
  bool GetHaloExtent(int& neighbors, int& levels) const override
  {
    neighbors = this->NumberOfNeighbors;
    levels = 1;
    return true;
  }

protected:
  vtkSurfaceVariationFeatures();
  ~vtkSurfaceVariationFeatures() override;

  int Run(vtkPointSet* input, vtkPolyData* output) override;

  int NumberOfNeighbors = 15;

private:
  vtkSurfaceVariationFeatures(const vtkSurfaceVariationFeatures&) = delete;
  void operator=(const vtkSurfaceVariationFeatures&) = delete;
};

#endif
