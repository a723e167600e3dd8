/**
 * @class   vtkSmoothShrinkIndexFeatures
 * @brief   Baseline: feature points by the Smooth Shrink Index alone (Nie 2016), the "SSI" of the
 *          paper's Table 1.
 *
 * Exactly vtkFeaturePointExtraction with alpha = 1 (no density term), no voxel pre-filter and
 * the SSI measured from the point itself (Eq. 2) rather than from Eq. 6's density-weighted
 * centre: F(i) = L(i) / d with L(i) = |(P_i - P^w_i) . n_i|, P^w_i the weighted centroid of
 * Eq. 4. The constructor sets those three properties; everything else (neighbour counts, the
 * Gaussian radius, the threshold) is inherited with the same defaults, so the comparison with the
 * proposed method isolates what the paper adds. The properties stay settable; changing those
 * three makes it the proposed method again.
 *
 * Output: as vtkFeaturePointExtraction (`SSI` holds L(i), `F` the thresholded score L(i) / d).
 *
 * @sa vtkFeaturePointExtraction vtkFeaturePointDetector
 */
#ifndef vtkSmoothShrinkIndexFeatures_h
#define vtkSmoothShrinkIndexFeatures_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkFeaturePointExtraction.h"

class FEATUREPOINTSFILTERS_EXPORT vtkSmoothShrinkIndexFeatures : public vtkFeaturePointExtraction
{
public:
  static vtkSmoothShrinkIndexFeatures* New();
  vtkTypeMacro(vtkSmoothShrinkIndexFeatures, vtkFeaturePointExtraction);

protected:
  vtkSmoothShrinkIndexFeatures();
  ~vtkSmoothShrinkIndexFeatures() override;

private:
  vtkSmoothShrinkIndexFeatures(const vtkSmoothShrinkIndexFeatures&) = delete;
  void operator=(const vtkSmoothShrinkIndexFeatures&) = delete;
};

#endif
