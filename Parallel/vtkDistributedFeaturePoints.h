/**
 * @class   vtkDistributedFeaturePoints
 * @brief   Runs a feature point detector on a cloud split between MPI processes, with the
 *          results of a single process.
 *
 * Each process gives this filter its piece of the cloud (any vtkPointSet; a piece may be empty).
 * The pieces, in process order, form the cloud: the point ids of the whole cloud (its "global
 * ids") number process 0's points first, then process 1's, and so on. The filter:
 *
 * 1. Splits the cloud in space: a k-d split by point count along the longest axis of a sample of
 *    the cloud (one point in max(1, N / 100000), the same on every process), one box per process;
 *    each point is sent to the process of its box. Each process keeps its points in ascending
 *    global id order, so that ties in distance are broken as in one process.
 * 2. Builds each process's halo: the points of the other processes within reach of its own points.
 *    The detector says how far (vtkFeaturePointDetector::GetHaloExtent: k nearest over L
 *    generations). Measured on the process's own points, r_i (the distance to the k-th nearest
 *    point, or to the nearest point at a nonzero distance if further) bounds the true distance from
 *    above; a neighbour j of i lies within r_i and its own k nearest within 2 r_i of j, so the
 *    reach is (2^L - 1) r_i. The reaches, over the cells of an 8x8x8 grid on the process's box,
 *    give a list of boxes that every other process fills with its points that fall in them.
 *    A detector that also needs whole regions around its points (GetHaloWidthFor(): the paper's
 *    method's voxel blocks) gets boxes at least that wide, for a mean spacing estimated from
 *    above (a sample of each piece's distances to the nearest own point, plus 25 %); when the
 *    run finds the width short (GetRequiredHaloWidth()), the halo is built again that wide and
 *    the detector runs again.
 * 3. Runs the detector on its own points and the halo (ordered by global id, the halo flagged in
 *    `vtkGhostType`, each point's global id in `vtkPieceGlobalIds`), with the Controller set: the
 *    detector takes every cloud-wide figure over all processes' own points, and exchanges the
 *    halo's values with the points' owners where it needs them (the default detector's growth
 *    and border components). The result's `vtkPieceGlobalIds` is dropped.
 * 4. Output: the process's own points (in global id order, with a `GlobalPointIds` array), or with
 *    GatherOutput the whole cloud on process 0 in the input's order (other processes: empty).
 *
 * A detector whose GetHaloExtent() returns false (settings whose cloud-wide figures are not
 * reduced yet), or a cloud too small for the split (fewer than 4 (k + 1) points per process), is
 * run on process 0 alone on the gathered cloud: the same result, without the speed-up; then the
 * whole result is on process 0 whatever GatherOutput says.
 *
 * The input's point arrays travel with the points (vtkDataArray only); a process with points must
 * hold the same arrays as process 0.
 *
 * With one process, or no controller, the detector runs on the input as it is.
 *
 * @warning Exact ties in distance between points at different places (points on a lattice) may be
 * broken otherwise than in one process, whose search grid orders the points by cell first; ties
 * between coincident points are not affected. docs/design.md, "Distributed runs".
 *
 * @sa vtkFeaturePointDetector vtkDistributedPointCloudFilter
 */
#ifndef vtkDistributedFeaturePoints_h
#define vtkDistributedFeaturePoints_h

#include "FeaturePointsParallelModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For the replaced arrays
#include <vector> // For the counts of each process

class vtkFeaturePointDetector;
class vtkMultiProcessController;

class FEATUREPOINTSPARALLEL_EXPORT vtkDistributedFeaturePoints : public vtkPolyDataAlgorithm
{
public:
  static vtkDistributedFeaturePoints* New();
  vtkTypeMacro(vtkDistributedFeaturePoints, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The detector to run (its settings are used as they are). Required. */
  virtual void SetDetector(vtkFeaturePointDetector*);
  vtkGetObjectMacro(Detector, vtkFeaturePointDetector);
  ///@}

  ///@{
  /**
   * The processes. Default: vtkMultiProcessController::GetGlobalController() at construction.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /** Gather the whole result on process 0, in the input's order. Default off. */
  vtkSetMacro(GatherOutput, bool);
  vtkGetMacro(GatherOutput, bool);
  vtkBooleanMacro(GatherOutput, bool);
  ///@}

  ///@{
  /**
   * Figures of the last run: whether the cloud was split (false: run on process 0 alone), and for
   * each process the points it owned and the halo points it received (the same on every process).
   */
  vtkGetMacro(Distributed, bool);
  int GetNumberOfRanks() const { return static_cast<int>(this->OwnedCounts.size()); }
  vtkIdType GetNumberOfOwnedPoints(int rank) const { return this->OwnedCounts.at(rank); }
  vtkIdType GetNumberOfHaloPoints(int rank) const { return this->HaloCounts.at(rank); }
  ///@}

  ///@{
  /**
   * The input's point arrays that the detector replaced by its own of the same name in the last
   * run (the output holds the detector's).
   */
  int GetNumberOfReplacedArrays() const { return static_cast<int>(this->ReplacedArrays.size()); }
  const char* GetReplacedArray(int i) const { return this->ReplacedArrays.at(i).c_str(); }
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkDistributedFeaturePoints();
  ~vtkDistributedFeaturePoints() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkFeaturePointDetector* Detector = nullptr;
  vtkMultiProcessController* Controller = nullptr;
  bool GatherOutput = false;
  bool Distributed = false;
  std::vector<vtkIdType> OwnedCounts;
  std::vector<vtkIdType> HaloCounts;
  std::vector<std::string> ReplacedArrays;

  void FindReplacedArrays(vtkPolyData* input, vtkPolyData* result);

private:
  vtkDistributedFeaturePoints(const vtkDistributedFeaturePoints&) = delete;
  void operator=(const vtkDistributedFeaturePoints&) = delete;
};

#endif
