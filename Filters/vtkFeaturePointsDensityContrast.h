// Private header of FeaturePoints::Filters (not installed): the voxel density-contrast test of
// Huang et al. 2023 (Section 3.2) on bare arrays. vtkVoxelDensityContrastFilter runs it as a
// pipeline filter, vtkFeaturePointExtraction as its pre-filter; the rules, the parameters and
// their defaults are documented in vtkVoxelDensityContrastFilter.h.
#ifndef vtkFeaturePointsDensityContrast_h
#define vtkFeaturePointsDensityContrast_h

#include "vtkType.h" // For vtkIdType

#include <cstdint>    // For int32_t
#include <functional> // For the reductions of a distributed run
#include <vector>     // For the reductions of a distributed run

class vtkObject;
class vtkPoints;
class vtkPointCloudNeighborhoods;

namespace featurepoints
{
/**
 * What a distributed run (docs/design.md, "Distributed runs") gives the test: which points of the
 * piece are its own, and the reductions over the processes (every process calls them in the same
 * order). The piece must hold every point within HaloWidth (on each axis) of each own point; the
 * test needs RequiredHaloWidth() and does nothing with less.
 */
struct DensityContrastProcesses
{
  const unsigned char* Owned = nullptr;    // 1 for the piece's own points
  const int32_t* InputOrder = nullptr;     // each point's index in the piece (global id order)
  const double* Bounds = nullptr;          // the valid points' bounds over the whole cloud
  double HaloWidth = 0.0;
  std::function<vtkIdType(vtkIdType)> Sum;
  std::function<double(std::vector<double>&)> UpperMedian; // the union's, on every process
  std::function<void(double lo[3], double hi[3])> MinMax;   // in place
  std::function<double(std::vector<double>&)> MeanWithoutOutliers; // factor 10, exact sum
  std::function<void(std::vector<uint64_t>&)> AllGather;   // every process's keys, on every one
};

class DensityContrast
{
public:
  enum ContrastRules
  {
    VOXEL_COUNTS = 0,  ///< the paper: N(i) against N(j)
    BLOCK_SPACING = 1, ///< 5x5x5 block nearest-point spacing against the cloud's median
  };

  ///@{
  /** The parameters (vtkVoxelDensityContrastFilter's of the same names). */
  double VoxelSizeFactor = 2.5;
  double DensityContrast = 0.5;
  double ContrastSigmas = 4.0;
  double MinimumContrastFraction = 0.01;
  int ContrastRule = BLOCK_SPACING;
  ///@}

  /** The object whose warnings the test's warnings are (points clamped to the grid's border). */
  vtkObject* Reporter = nullptr;

  /**
   * A distributed run: the piece's own points and the reductions (null: one process). Every
   * figure below is then the whole cloud's, and the candidates of the own points are those of a
   * single process; the halo's points are never candidates.
   */
  const DensityContrastProcesses* Processes = nullptr;

  /**
   * The halo width, on each axis, that a piece needs around its own points for voxels of side a:
   * the own point's voxel and 3 more each way (the 5x5x5 blocks of the voxels next to it), and
   * the nearest other point of every point in them, within 4 sqrt(3) a.
   */
  static double HaloWidthFor(double a) { return 4.0 * (1.0 + 1.7320508075688772) * a * (1.0 + 1e-9); }

  /**
   * Marks candidate[i] = 1 for the candidates among the points with valid[i] != 0 (all points
   * when valid is null), 0 for the others, with voxels of side VoxelSizeFactor * spacing
   * (spacing > 0). `nearest` holds each point's distance to its nearest other point (needed by
   * BLOCK_SPACING only). `voxelCount`, when not null, receives N of each point's voxel (0 for
   * invalid points). Returns the number of candidates.
   */
  vtkIdType MarkCandidates(vtkPoints* points, const unsigned char* valid, double spacing,
    const double* nearest, unsigned char* candidate, int32_t* voxelCount = nullptr);

  /**
   * The quick screen of vtkVoxelDensityContrastFilter::SampleShowsContrast(): the BLOCK_SPACING
   * test on a spatial sample of the cloud. False when the sample shows no density contrast.
   */
  bool SampleShowsContrast(vtkPointCloudNeighborhoods* neighborhoods);

  ///@{
  /** Figures of the last MarkCandidates() (vtkVoxelDensityContrastFilter's getters). */
  double VoxelSize = 0.0;
  vtkIdType NumberOfOccupiedVoxels = 0;
  vtkIdType NumberOfContrastVoxels = 0;
  vtkIdType NumberOfCandidates = 0;
  vtkIdType NumberOfClampedPoints = 0;
  double ReferenceLevel = 0.0;
  /** Distributed runs: the halo width the last call needed (VTK_DOUBLE_MAX: the whole cloud). */
  double RequiredHaloWidth = 0.0;
  ///@}
};
} // namespace featurepoints

#endif
