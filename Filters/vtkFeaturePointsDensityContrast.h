// Private header of FeaturePoints::Filters (not installed): the voxel density-contrast test of
// Huang et al. 2023 (Section 3.2) on bare arrays. vtkVoxelDensityContrastFilter runs it as a
// pipeline filter, vtkFeaturePointExtraction as its pre-filter; the rules, the parameters and
// their defaults are documented in vtkVoxelDensityContrastFilter.h.
#ifndef vtkFeaturePointsDensityContrast_h
#define vtkFeaturePointsDensityContrast_h

#include "vtkType.h" // For vtkIdType

#include <cstdint> // For int32_t

class vtkObject;
class vtkPoints;
class vtkPointCloudNeighborhoods;

namespace featurepoints
{
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
  ///@}
};
} // namespace featurepoints

#endif
