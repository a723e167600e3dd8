/**
 * @class   vtkFeaturePointExtraction
 * @brief   Feature points (sharp edges, creases, corners) of a noisy, unorganized point cloud:
 *          the method of Huang, Chen, Zhang and Lu (CAD & Applications 20(5), 2023).
 *
 * For each point P_i and its k nearest other points P_j (nearest first; one k-nearest query per
 * point, with the largest k any quantity needs, reused for all of them):
 *
 * - Normal n_i (Eq. 3): eigenvector of the smallest eigenvalue of the covariance of the
 *   NormalNeighbors nearest points, oriented away from the bounding box's centre.
 * - Mean neighbour distance m(i) (Eq. 7) over the DensityNeighbors nearest points, and the Point
 *   Density Index D(i) = 1 / m(i) (Eq. 9: the paper reuses Eq. 7's mean distance, with m = 15).
 * - Weighted centroid P^w_i = sum g_j m(j) P_j / sum g_j m(j) over the SSINeighbors nearest
 *   points, g_j = exp(-(|P_j - P_i| / r)^2), r = GaussianRadiusFactor * d (Eqs. 4-5), where d is
 *   the cloud's mean spacing (mean distance to the nearest other point).
 * - Centre: with SSICenter DENSITY_WEIGHTED_MEAN (default, Eq. 6) the point is replaced by
 *   Pbar_i = sum m(j) P_j / sum m(j) over the CenterNeighbors nearest points and the point itself;
 *   with SSICenter POINT it stays P_i (Nie 2016, Eq. 2).
 * - Smooth Shrink Index L(i) = |(centre - P^w_i) . n_i| (Eqs. 2, 8).
 * - F(i) = alpha * L(i) / d + (1 - alpha) * d / m(i) (Eq. 1 on dimensionless terms, see below).
 *
 * A point is a feature point when F(i) > threshold. Only the candidates of the voxel pre-filter
 * (vtkVoxelDensityContrastFilter, Section 3.2) are scored when UseVoxelFilter is on; the other
 * points get 0 in every score array and are never feature points. When the pre-filter finds no
 * density contrast at all (a uniformly sampled cloud), every point is scored, so features are not
 * lost. With the project's BLOCK_SPACING rule, a cloud of 65536 points or more is first screened
 * on a spatial sample of about one point in 8 (vtkVoxelDensityContrastFilter::
 * SampleShowsContrast); when the sample shows no contrast the full test and its 1-nearest pass
 * over every point are skipped and every point is scored, so that uniform clouds pay about 2 %
 * for the pre-filter instead of about 15 %. The paper's VOXEL_COUNTS rule is always run in full.
 *
 * Choices the paper leaves open, made here (each changeable where another reading is reasonable):
 * - Neighbourhoods exclude the point itself ("the k nearest other points"), except the centre of
 *   Eq. 6, which averages the point with its CenterNeighbors nearest points.
 * - k of Eq. 7: the paper says 5 there and 15 in its experiments; DensityNeighbors = 15 is used for
 *   m(i) in Eqs. 4, 6 and 9 alike, as Section 3.1.2 says the value is computed once and reused.
 * - r: "5 times the average distance" (Section 3.3), the average distance being the mean spacing d.
 * - Eq. 4's weights are written g(i) m(i) in the paper; g_j m(j) (the neighbour's) is meant. They
 *   are evaluated as exp(-(|P_j - P_i|^2 - |P_1 - P_i|^2) / r^2), which differs from Eq. 5 by a
 *   factor common to all j and so leaves P^w unchanged, but never underflows to 0/0 for isolated
 *   points.
 * - Normalization of Eq. 1: L is a length and D an inverse length, so they are made dimensionless
 *   with the cloud's own mean spacing d: L/d and D*d = d/m(i). F is then unchanged when the cloud is
 *   scaled or moved. The SSI and PDI arrays hold the raw L(i) and D(i), in the cloud's units.
 * - Threshold (the paper gives none). AUTOMATIC (default): the scores of the scored points are
 *   treated as a background distribution with a minority of outliers; its centre mu and scale s
 *   are the median and the normalized median absolute deviation (1.4826 MAD), re-estimated after
 *   discarding the values above mu + z s until they settle (at most 50 rounds); the threshold is
 *   mu + z s with z = ThresholdSigmas. s is never taken below 1% of mu, so that a noise-free plane,
 *   whose scores are all equal, yields no features. ABSOLUTE: the value of Threshold.
 *   With the voxel pre-filter the candidates alone are a feature-rich population, so the AUTOMATIC
 *   threshold also sees a sample of the other points: whole cubic blocks of side 16 d, one block
 *   in 8 (fewer when more than 8 x 65536 points are not candidates) chosen by a hash of the
 *   block's grid coordinates from the bounding box's corner, so that the sample does not depend on
 *   the points' order, scale or offset. Each sampled point counts for the non-candidates of the
 *   unsampled blocks; its scores are computed but cleared from the output, and it is never marked.
 *   Blocks rather than scattered points, because a point's SSI needs m(j) of its SSINeighbors
 *   neighbours: a block's neighbourhoods overlap, scattered ones would need nearly every point's.
 *   A cloud with fewer than 512 sampled points scores every non-candidate instead.
 * - m(i) is floored at 0.001 d so that stacks of coincident points give a large but finite D(i).
 *
 * Input: any vtkPointSet (points only are used). Output: a vtkPolyData with the input points in
 * input order, all input point data, one vertex cell per point and the point arrays
 * `Normals` (float, 3), `SSI`, `PDI`, `F` (float), `Candidate` and `FeatureMask` (uint8). With
 * OutputFeaturesOnly the output holds the feature points only, with the same arrays and
 * `vtkOriginalPointIds`. The field data holds `MeanSpacing` and `FeatureThreshold`.
 *
 * Bad input never crashes the filter or puts NaN in an output: points with NaN or infinite
 * coordinates are skipped (warning, scores 0); an empty input, fewer valid points than the largest
 * neighbour count plus one, or points that all coincide give a warning and all-zero scores;
 * duplicates, and clouds whose points all lie on a line or a plane, are processed with a warning.
 *
 * @warning The per-point work runs under vtkSMPTools and depends on the point only: the output is
 * identical whatever the number of threads and the SMP backend.
 *
 * @sa vtkFeaturePointDetector vtkVoxelDensityContrastFilter vtkPointCloudNeighborhoods
 * vtkSmoothShrinkIndexFeatures vtkPCANormalEstimation
 */
#ifndef vtkFeaturePointExtraction_h
#define vtkFeaturePointExtraction_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkFeaturePointDetector.h"

#include <algorithm> // For std::max

class FEATUREPOINTSFILTERS_EXPORT vtkFeaturePointExtraction : public vtkFeaturePointDetector
{
public:
  static vtkFeaturePointExtraction* New();
  vtkTypeMacro(vtkFeaturePointExtraction, vtkFeaturePointDetector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SSICenters
  {
    POINT = 0,                 ///< Eq. 2 (Nie 2016): the point itself
    DENSITY_WEIGHTED_MEAN = 1, ///< Eq. 6: the density-weighted mean of the point's neighbourhood
  };

  ///@{
  /**
   * alpha of Eq. 1, the weight of the SSI term against the density term; the paper's range is
   * [0.5, 1], larger for noisier clouds. Default 0.75 (the middle of that range).
   */
  vtkSetClampMacro(Alpha, double, 0.0, 1.0);
  vtkGetMacro(Alpha, double);
  ///@}

  ///@{
  /** k for the PCA normal (Eq. 3). Default 15 (the paper's experiments). */
  vtkSetClampMacro(NormalNeighbors, int, 3, 1000);
  vtkGetMacro(NormalNeighbors, int);
  ///@}

  ///@{
  /**
   * k for the weighted centroid P^w of the SSI (Eq. 4). The paper sets the SSI's neighbourhood by
   * its search radius r = 5 d rather than by a count; a disc of radius 5 d holds about 20 points
   * of a randomly (Poisson) sampled surface and 78 of a regular grid. Default 50, between the two.
   */
  vtkSetClampMacro(SSINeighbors, int, 1, 1000);
  vtkGetMacro(SSINeighbors, int);
  ///@}

  ///@{
  /** k for the mean distance m(i) (Eq. 7) and the density index (Eq. 9). Default 15. */
  vtkSetClampMacro(DensityNeighbors, int, 1, 1000);
  vtkGetMacro(DensityNeighbors, int);
  ///@}

  ///@{
  /**
   * k for the density-weighted centre Pbar_i of Eq. 6 (the point and its k nearest points).
   * Default 15, the k of the paper's experiments. Only used with SSICenter DENSITY_WEIGHTED_MEAN.
   */
  vtkSetClampMacro(CenterNeighbors, int, 0, 1000);
  vtkGetMacro(CenterNeighbors, int);
  ///@}

  ///@{
  /** What the SSI measures from: DENSITY_WEIGHTED_MEAN (Eq. 6, default) or POINT (Eq. 2). */
  vtkSetClampMacro(SSICenter, int, POINT, DENSITY_WEIGHTED_MEAN);
  vtkGetMacro(SSICenter, int);
  void SetSSICenterToPoint() { this->SetSSICenter(POINT); }
  void SetSSICenterToDensityWeightedMean() { this->SetSSICenter(DENSITY_WEIGHTED_MEAN); }
  ///@}

  ///@{
  /** r of Eq. 5 in units of the mean spacing d. Default 5 (Section 3.3). */
  vtkSetClampMacro(GaussianRadiusFactor, double, 0.01, 1000.0);
  vtkGetMacro(GaussianRadiusFactor, double);
  ///@}

  ///@{
  /** Score only the candidates of the voxel pre-filter (Section 3.2). Default on. */
  vtkSetMacro(UseVoxelFilter, bool);
  vtkGetMacro(UseVoxelFilter, bool);
  vtkBooleanMacro(UseVoxelFilter, bool);
  ///@}

  ///@{
  /** beta of Eq. 11: voxel side in units of the mean spacing. Default 2.5 (the paper's value). */
  vtkSetClampMacro(VoxelSizeFactor, double, 0.1, 1000.0);
  vtkGetMacro(VoxelSizeFactor, double);
  ///@}

  ///@{
  /**
   * epsilon of the voxel pre-filter (see vtkVoxelDensityContrastFilter): the relative density
   * excess of a contrast voxel. Default 0.5 (a block half as dense again as the typical one).
   */
  vtkSetClampMacro(DensityContrast, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DensityContrast, double);
  ///@}

  ///@{
  /**
   * What the voxel pre-filter compares (vtkVoxelDensityContrastFilter::ContrastRules). Default
   * BLOCK_SPACING; VOXEL_COUNTS is the paper's rule.
   */
  vtkSetClampMacro(VoxelContrastRule, int, 0, 1);
  vtkGetMacro(VoxelContrastRule, int);
  ///@}

  /** The score array: "F". ABSOLUTE thresholds are on F (dimensionless; default 1). */
  const char* GetScoreArrayName() const override { return "F"; }

  /**
   * Distributed runs: the largest k of the method around each own point, and the neighbours'
   * own DensityNeighbors nearest (m(j) of Eqs. 4 and 6), so two generations.
   */
  bool GetHaloExtent(int& neighbors, int& levels) const override
  {
    neighbors = std::max(std::max(this->NormalNeighbors, this->SSINeighbors),
      std::max(this->DensityNeighbors,
        this->SSICenter == DENSITY_WEIGHTED_MEAN ? this->CenterNeighbors : 0));
    levels = 2;
    return true;
  }

  /**
   * Distributed runs with the voxel pre-filter: the voxels 3 each way around an own point's
   * voxel, and the nearest point of each of their points, are in the piece
   * (featurepoints::DensityContrast::HaloWidthFor: about 10.9 voxel sides, 27 spacings at the
   * default VoxelSizeFactor). The quick screen's voxels follow its sample's spacing, which may
   * be a little larger than the cloud's: the run asks for more when it is (see the superclass).
   */
  double GetHaloWidthFor(double spacing) const override;

protected:
  void ListParameters(std::vector<std::pair<const char*, double>>& parameters) const override;
  vtkFeaturePointExtraction();
  ~vtkFeaturePointExtraction() override;

  int Run(vtkPointSet* input, vtkPolyData* output) override;
  int GetLengthPower(const char* name) const override; // SSI: 1 (a length), PDI: -1

  /**
   * The non-candidates scored for the AUTOMATIC threshold (see the class comment): the points of
   * the sampled blocks, in point order. Returns how many non-candidates each of them stands for.
   * Distributed runs: the own points of the sampled blocks, the counts over all processes.
   */
  int SampleBackground(vtkPoints* points, const unsigned char* valid,
    const unsigned char* isCandidate, double spacing, const double bounds[6],
    std::vector<vtkIdType>& background);

  ///@{
  /**
   * The stages of RequestData before the scores (Section 3.2): the mean spacing (after the voxel
   * pre-filter's quick screen, or from every point's k-nearest table without it), the voxel
   * pre-filter's candidates, the k nearest of every scored point, and m(j) (Eq. 7) for the scored
   * points and the neighbours they weigh. A stage that returns false ends the run (aborted, or no
   * usable spacing).
   */
  struct ScoredPoints;
  bool MeasureSpacing(vtkPointCloudNeighborhoods* neighborhoods, int k, ScoredPoints& scored);
  bool MarkCandidates(
    vtkPointCloudNeighborhoods* neighborhoods, ScoredPoints& scored, unsigned char* isCandidate);
  // Distributed runs: the own points and reductions the voxel pre-filter takes.
  void PrepareProcesses(ScoredPoints& scored);
  // Keeps the halo width a stage needed; false when the piece's is narrower (the run stops).
  bool HaloSuffices(double required);
  bool FindScoredNeighbors(vtkPointCloudNeighborhoods* neighborhoods, int k,
    const unsigned char* isCandidate, ScoredPoints& scored);
  bool ComputeMeanDistances(vtkPointCloudNeighborhoods* neighborhoods, int k,
    const ScoredPoints& scored, std::vector<double>& meanDistance);
  ///@}

  double Alpha = 0.75;
  int NormalNeighbors = 15;
  int SSINeighbors = 50;
  int DensityNeighbors = 15;
  int CenterNeighbors = 15;
  int SSICenter = DENSITY_WEIGHTED_MEAN;
  double GaussianRadiusFactor = 5.0;
  bool UseVoxelFilter = true;
  double VoxelSizeFactor = 2.5;
  double DensityContrast = 0.5;
  int VoxelContrastRule = 1;

private:
  vtkFeaturePointExtraction(const vtkFeaturePointExtraction&) = delete;
  void operator=(const vtkFeaturePointExtraction&) = delete;
};

#endif
