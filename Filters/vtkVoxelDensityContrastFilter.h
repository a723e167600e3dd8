/**
 * @class   vtkVoxelDensityContrastFilter
 * @brief   Marks the points of a cloud that lie where the sampling density changes: the voxel
 *          pre-filter of Huang et al. 2023 (Section 3.2).
 *
 * The cloud is cut into cubic voxels of side a = VoxelSizeFactor * d, where d is the mean spacing
 * (mean distance to the nearest other point; Eq. 11, beta = 2.5) or the value of Spacing when set.
 * The points of each voxel are counted. A voxel C(i) shows *density contrast* when some occupied
 * voxel C(j) of its 26-neighbourhood has (N(i) - N(j)) / N(j) > DensityContrast (epsilon). The
 * points of every contrast voxel and of its 26 neighbours become candidates (Filter_Algorithm of
 * the paper); the feature score is then computed for candidates only.
 *
 * Choices the paper leaves open, made here:
 * - Empty neighbours (N(j) = 0) are ignored: a surface's voxels always have empty neighbours, and
 *   counting them would make every voxel a contrast voxel.
 * - epsilon, which the paper does not give, defaults to 0.5: one and a half times the density.
 * - When fewer than MinimumContrastFraction (1 %) of the occupied voxels show contrast, the
 *   contrast is taken for the clumping of random sampling and no voxel is kept: the caller then
 *   knows that the cloud has no usable density contrast (vtkFeaturePointExtraction scores every
 *   point). A dense region smaller than that is scored all the same, only not faster.
 * - ContrastRule VOXEL_COUNTS compares the raw counts N(i), N(j) of neighbouring voxels, as
 *   published. On real surfaces it finds "contrast" almost everywhere: a voxel that the surface only
 *   grazes holds few points whatever the density, so nearly every voxel has a much emptier occupied
 *   neighbour and every point becomes a candidate (the paper notes that with uniform sampling the
 *   method becomes plain SSI).
 * - ContrastRule BLOCK_SPACING (the default) measures each voxel's density by the mean distance
 *   to the nearest other point over the points of its 5x5x5 block (two passes of a 3x3x3 box sum,
 *   so tent weights), h(i), as the areal density 1 / h(i)^2, and calls it a contrast voxel when
 *   that density exceeds the cloud's median block density both by the relative margin epsilon and
 *   by ContrastSigmas robust deviations of the lower half of the block densities (so that the clumps of random
 *   sampling, which a block of a few dozen points shows, are not taken for denser regions). Then,
 *   as a denser region is contiguous, the blocks connected to contrast voxels through blocks that
 *   clear half that margin join them (hysteresis), which keeps a band's edges and thinner
 *   stretches. Counts per voxel depend on how the surface crosses the
 *   voxel (a face-aligned sheet fills fewer voxels with more points than an oblique one, by up to
 *   a factor 1.7), nearest distances do not; they come for free from the pass that measures the
 *   mean spacing. Blocks holding fewer than half the median block's points (a surface's rim, a
 *   stray cluster) measure no density and are never contrast voxels. The comparison is with the cloud's typical density rather than with the next
 *   block, because neighbouring blocks share two thirds of their points and never differ much.
 * - The grid starts at the bounding box's minimum corner (Eqs. 10-12). Only occupied voxels are
 *   stored (sorted 63-bit keys), so memory grows with the number of points, never with the box's
 *   volume. When an outlier makes the box wider than 2^21 voxels along an axis, the grid is centred
 *   on the coordinate-wise median instead and the points farther than 2^20 voxels from it are
 *   clamped to the grid's border (a warning says how many).
 *
 * Output: the input points in input order, all point data passed through, one vertex cell per
 * point, and the point arrays `Candidate` (uint8, 1 for candidates) and `VoxelPointCount` (int32,
 * N of the point's voxel). Points with non-finite coordinates are never candidates.
 *
 * @warning The work is parallel (vtkSMPTools) and deterministic: the same candidates whatever the
 * thread count or SMP backend.
 *
 * @sa vtkFeaturePointExtraction vtkPointCloudNeighborhoods
 */
#ifndef vtkVoxelDensityContrastFilter_h
#define vtkVoxelDensityContrastFilter_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint> // For int32_t

class vtkDoubleArray;
class vtkIntArray;
class vtkPoints;
class vtkPointCloudNeighborhoods;
class vtkUnsignedCharArray;
namespace featurepoints
{
class DensityContrast;
}

class FEATUREPOINTSFILTERS_EXPORT vtkVoxelDensityContrastFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkVoxelDensityContrastFilter* New();
  vtkTypeMacro(vtkVoxelDensityContrastFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ContrastRules
  {
    VOXEL_COUNTS = 0,      ///< the paper: N(i) against N(j)
    BLOCK_SPACING = 1, ///< 5x5x5 block nearest-point spacing against the cloud's median
  };

  ///@{
  /**
   * beta of Eq. 11: the voxel side in units of the mean spacing. Default 2.5 (the paper's value).
   */
  vtkSetClampMacro(VoxelSizeFactor, double, 0.1, 1000.0);
  vtkGetMacro(VoxelSizeFactor, double);
  ///@}

  ///@{
  /**
   * The point spacing d in the cloud's units. 0 (default): computed as the cloud's mean distance
   * to the nearest other point.
   */
  vtkSetClampMacro(Spacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * epsilon: the relative excess of density that makes a voxel a contrast voxel (of its count over
   * an occupied neighbour's for VOXEL_COUNTS, of its block density over the cloud's median block
   * density for BLOCK_SPACING). Default 0.5 (half as dense again). The paper gives no value.
   */
  vtkSetClampMacro(DensityContrast, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DensityContrast, double);
  ///@}

  ///@{
  /**
   * BLOCK_SPACING only: a contrast block's density must also exceed the median block density by
   * this many robust standard deviations of the block densities (1.4826 times the median distance
   * to the median of the blocks below the median, which denser regions do not reach): the spread
   * that random sampling alone gives blocks of a few dozen points. Default 4.
   */
  vtkSetClampMacro(ContrastSigmas, double, 0.0, 1000.0);
  vtkGetMacro(ContrastSigmas, double);
  ///@}

  ///@{
  /**
   * The smallest fraction of the occupied voxels that must show contrast for any to count (see the
   * class comment). Default 0.01.
   */
  vtkSetClampMacro(MinimumContrastFraction, double, 0.0, 1.0);
  vtkGetMacro(MinimumContrastFraction, double);
  ///@}

  ///@{
  /**
   * What is compared between neighbouring voxels: VOXEL_COUNTS (as published) or BLOCK_SPACING
   * (default; see the class comment).
   */
  vtkSetClampMacro(ContrastRule, int, VOXEL_COUNTS, BLOCK_SPACING);
  vtkGetMacro(ContrastRule, int);
  void SetContrastRuleToVoxelCounts() { this->SetContrastRule(VOXEL_COUNTS); }
  void SetContrastRuleToBlockSpacing() { this->SetContrastRule(BLOCK_SPACING); }
  ///@}

  /**
   * The work of the filter on bare arrays, outside the pipeline (the module's filters share the
   * private helper that does it, featurepoints::DensityContrast): marks candidate[i] = 1 for the
   * candidates among the points with valid[i] != 0 (all points when valid is null), 0 for the
   * others, using the given spacing (> 0). `nearest` holds each point's distance to its nearest
   * other point (vtkPointCloudNeighborhoods::GetNearestDistances(); needed by BLOCK_SPACING only).
   * `voxelCount`, when not null, receives N of each point's voxel (0 for invalid points). Returns
   * the number of candidates. C++ only (bare pointers); the wrapped counterpart takes VTK arrays
   * of one value per point (`valid` and `nearest` may be null as above) and sizes `candidate`
   * and `voxelCount` itself; it returns -1 when an input array has the wrong size.
   */
  VTK_WRAPEXCLUDE vtkIdType MarkCandidates(vtkPoints* points, const unsigned char* valid,
    double spacing, const double* nearest, unsigned char* candidate, int32_t* voxelCount = nullptr);
  vtkIdType MarkCandidates(vtkPoints* points, vtkUnsignedCharArray* valid, double spacing,
    vtkDoubleArray* nearest, vtkUnsignedCharArray* candidate, vtkIntArray* voxelCount = nullptr);

  /**
   * A quick screen for BLOCK_SPACING before MarkCandidates: the same test on a spatial sample of
   * the cloud, about one point in SampleModulus. The sample is made of whole cubic regions of side
   * 20 L / sqrt(n) (L the diagonal of the bounding box, n the number of valid points; that is 25
   * to 50 spacings on a surface), one in 8 chosen by a hash of the region's grid coordinates from
   * the box's corner, so that it does not depend on the points' order, scale or offset. Only the
   * sampled points are searched for their nearest neighbour, and the voxel side comes from their
   * mean spacing. Returns false when the sample shows no density contrast: the caller may then
   * skip the full test, whose 1-nearest pass over every point costs as much as the rest of a
   * cloud's scoring saves on uniform clouds. Returns true when the sample shows contrast, when
   * it has fewer than 8192 points (a small cloud: test it whole) or when ContrastRule is
   * VOXEL_COUNTS (the paper's rule is always run in full). A denser region that no sampled region
   * reaches is missed: the caller then scores every point, which is slower, never worse.
   */
  bool SampleShowsContrast(vtkPointCloudNeighborhoods* neighborhoods);

  ///@{
  /**
   * Figures of the last run: the voxel side used, the number of occupied voxels, of contrast voxels,
   * of candidates, and of points clamped to the grid's border.
   */
  vtkGetMacro(VoxelSize, double);
  vtkGetMacro(NumberOfOccupiedVoxels, vtkIdType);
  vtkGetMacro(NumberOfContrastVoxels, vtkIdType);
  vtkGetMacro(NumberOfCandidates, vtkIdType);
  vtkGetMacro(NumberOfClampedPoints, vtkIdType);
  /** BLOCK_SPACING: the cloud's median block density 1/h^2 (0 for VOXEL_COUNTS). */
  vtkGetMacro(ReferenceLevel, double);
  ///@}

protected:
  vtkVoxelDensityContrastFilter();
  ~vtkVoxelDensityContrastFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double VoxelSizeFactor = 2.5;
  double Spacing = 0.0;
  double DensityContrast = 0.5;
  double ContrastSigmas = 4.0;
  double MinimumContrastFraction = 0.01;
  int ContrastRule = BLOCK_SPACING;

  double VoxelSize = 0.0;
  vtkIdType NumberOfOccupiedVoxels = 0;
  vtkIdType NumberOfContrastVoxels = 0;
  vtkIdType NumberOfCandidates = 0;
  vtkIdType NumberOfClampedPoints = 0;
  double ReferenceLevel = 0.0;

private:
  // The figures of the last run of the test, as the getters give them.
  void KeepFigures(const featurepoints::DensityContrast& test);

  vtkVoxelDensityContrastFilter(const vtkVoxelDensityContrastFilter&) = delete;
  void operator=(const vtkVoxelDensityContrastFilter&) = delete;
};

#endif
