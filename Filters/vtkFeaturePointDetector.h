/**
 * @class   vtkFeaturePointDetector
 * @brief   Abstract base of this module's feature point filters: one per-point score, a threshold
 *          on it, a `FeatureMask`, the same output conventions for every method.
 *
 * A subclass computes a score per point (the proposed method's F, PCA surface variation, ...);
 * this class supplies what all methods share, so that they can be compared on equal terms:
 *
 * - Input: any vtkPointSet; only its points are used. Points with NaN or infinite coordinates are
 *   skipped (warning; scores 0, never feature points).
 * - Neighbourhoods: one vtkPointCloudNeighborhoods per run over the point locator of
 *   SetLocator() (by default a vtkPointCloudGridLocator: one batched k-nearest query, the cloud
 *   renumbered in the grid's order while the method works) and the mean spacing d of the cloud,
 *   the unit of every radius.
 * - Threshold: AUTOMATIC (default) treats the scores as a background distribution with a
 *   minority of outliers: its centre mu and scale s are the median and the normalized median
 *   absolute deviation (1.4826 MAD), re-estimated after discarding the values above mu + z s until
 *   they settle (at most 50 rounds); the threshold is mu + z s with z = ThresholdSigmas, and s is
 *   never taken below 1% of mu, so that scores that are all equal yield no feature. ABSOLUTE: the
 *   value of Threshold, in the unit of the method's score.
 * - Output: a vtkPolyData with the input points in input order, all input point data, one vertex
 *   cell per point, the method's arrays and `FeatureMask` (uint8, 1 for a feature point); with
 *   OutputFeaturesOnly only the feature points, with the same arrays and `vtkOriginalPointIds`.
 *   The field data holds `MeanSpacing` and `FeatureThreshold`.
 * - Distributed runs: with a Controller of more than one process, each process gives the filter
 *   its piece of the cloud and a halo around it, the halo's points flagged in a `vtkGhostType`
 *   point array (vtkDataSetAttributes::DUPLICATEPOINT). The piece's points are scored as in a
 *   single process; every cloud-wide figure (bounds, mean spacing, medians, the threshold, the
 *   counts) is taken over the pieces' own points of all processes, so that a method whose
 *   GetHaloExtent() says so gives the own points exactly the results of one process on the whole
 *   cloud. vtkDistributedFeaturePoints (FeaturePoints::Parallel) splits the cloud, builds the halo
 *   and calls the filter that way. Without a Controller, or with one process, nothing changes.
 *
 * @sa vtkFeaturePointExtraction vtkSurfaceVariationFeatures vtkCurvatureDensityFeatures
 * vtkSmoothShrinkIndexFeatures vtkPointCloudNeighborhoods
 */
#ifndef vtkFeaturePointDetector_h
#define vtkFeaturePointDetector_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <chrono>     // For stage timing
#include <cstdint>    // For int32_t
#include <functional> // For the block consumer
#include <string>     // For stage names
#include <utility>    // For the halo layout
#include <vector>     // For AutomaticThreshold

class vtkAbstractPointLocator;
class vtkDataArray;
class vtkMultiProcessController;
class vtkPointCloudNeighborhoods;
class vtkPoints;
class vtkPointData;
class vtkPointSet;
class vtkPolyData;
class vtkUnsignedCharArray;

class FEATUREPOINTSFILTERS_EXPORT vtkFeaturePointDetector : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkFeaturePointDetector, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ThresholdModes
  {
    AUTOMATIC = 0, ///< robust rule on the score distribution (see the class comment)
    ABSOLUTE = 1,  ///< score > Threshold
  };

  ///@{
  /** AUTOMATIC (default) or ABSOLUTE threshold on the score. */
  vtkSetClampMacro(ThresholdMode, int, AUTOMATIC, ABSOLUTE);
  vtkGetMacro(ThresholdMode, int);
  void SetThresholdModeToAutomatic() { this->SetThresholdMode(AUTOMATIC); }
  void SetThresholdModeToAbsolute() { this->SetThresholdMode(ABSOLUTE); }
  ///@}

  ///@{
  /** The threshold of ABSOLUTE mode, in the unit of the method's score (see the subclass). */
  vtkSetMacro(Threshold, double);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * z of the AUTOMATIC rule: how many robust standard deviations above the median score a feature
   * point lies. Default 5: under a Gaussian background fewer than 1 point in a million exceeds
   * it; the real background (an absolute value, sampling irregularity) has heavier tails, and 5
   * keeps noisy smooth shapes below 2 false feature points per 1000 with the proposed method.
   */
  vtkSetClampMacro(ThresholdSigmas, double, 0.0, 1000.0);
  vtkGetMacro(ThresholdSigmas, double);
  ///@}

  ///@{
  /**
   * The point locator the neighbourhoods are searched with. By default a
   * vtkPointCloudGridLocator. Any vtkAbstractPointLocator gives the same feature points (ties in
   * distance aside), more slowly: it is asked for each point in turn (in parallel only when it is
   * a vtkStaticPointLocator), and the cloud is not renumbered. Each run gives it the input's
   * points and builds it, and releases its search structure at the end. nullptr: the default.
   */
  void SetLocator(vtkAbstractPointLocator* locator);
  vtkGetObjectMacro(Locator, vtkAbstractPointLocator);
  ///@}

  ///@{
  /** Output only the feature points, with `vtkOriginalPointIds`. Default off. */
  vtkSetMacro(OutputFeaturesOnly, bool);
  vtkGetMacro(OutputFeaturesOnly, bool);
  vtkBooleanMacro(OutputFeaturesOnly, bool);
  ///@}

  ///@{
  /**
   * Figures of the last run: the mean spacing d, the threshold applied to the score, the number
   * of points scored (candidates) and of feature points.
   */
  vtkGetMacro(MeanSpacing, double);
  vtkGetMacro(ThresholdUsed, double);
  vtkGetMacro(NumberOfCandidates, vtkIdType);
  vtkGetMacro(NumberOfFeaturePoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Wall-clock time of each stage of the last run, in order ("locator", "spacing",
   * "voxel filter", "neighbours", "scores", "threshold", "output"; a method reports the stages it
   * has), in seconds. An index outside 0 .. GetNumberOfStages() - 1 gives nullptr and 0.
   */
  int GetNumberOfStages() const { return static_cast<int>(this->StageNames.size()); }
  const char* GetStageName(int i) const
  {
    return i >= 0 && i < this->GetNumberOfStages() ? this->StageNames[i].c_str() : nullptr;
  }
  double GetStageTime(int i) const
  {
    return i >= 0 && i < static_cast<int>(this->StageTimes.size()) ? this->StageTimes[i] : 0.0;
  }
  ///@}

  /**
   * The feature points of a full output (`mask` is its FeatureMask): what OutputFeaturesOnly
   * gives, without running the filter again. `output` gets the points where the mask is set, all
   * point arrays, `vtkOriginalPointIds` and one vertex cell per point. `full` may be `output`'s
   * own earlier content only if it is another object.
   */
  static void SelectFeaturePoints(
    vtkPolyData* full, vtkUnsignedCharArray* mask, vtkPolyData* output);

  ///@{
  /**
   * The processes of a distributed run (see the class comment). Default nullptr: one process,
   * whatever vtkMultiProcessController::GetGlobalController() holds.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /**
   * What a distributed run must give each process so that its own points get the results of a
   * single process: the `neighbors` nearest points of every own point (and the nearest point at a
   * nonzero distance), and so on over `levels` generations (2: the neighbours' own neighbourhoods
   * too). Returns false (the default) when the method, with its present settings, takes figures
   * that the processes cannot yet reduce: vtkDistributedFeaturePoints then runs it on one process.
   */
  virtual bool GetHaloExtent(int& neighbors, int& levels) const
  {
    neighbors = 0;
    levels = 0;
    return false;
  }

  /**
   * Beyond GetHaloExtent(): the width, on each axis, around each own point within which a
   * distributed run's piece must hold every point, for a cloud of mean spacing `spacing` (the
   * paper's method's voxel blocks). 0 (the default): none. The method checks the width it is
   * given (HaloWidth) against the one it needs once it knows the cloud's figures, and does nothing
   * with less; GetRequiredHaloWidth() then says how much (see vtkDistributedFeaturePoints).
   */
  virtual double GetHaloWidthFor(double vtkNotUsed(spacing)) const { return 0.0; }

  ///@{
  /**
   * Distributed runs: the width (on each axis) around each own point within which the piece
   * holds every point of the cloud, set by vtkDistributedFeaturePoints. Default 0.
   */
  vtkSetClampMacro(HaloWidth, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(HaloWidth, double);
  ///@}

  /**
   * The power of the length unit of the output point array `name` (1: a length, -1: an inverse
   * length; 0, the default: no unit): how RequestData() scales it back from a scaled frame, and
   * how a caller that scales the cloud itself (the featurepoints command) does.
   */
  virtual int GetLengthPower(const char* vtkNotUsed(name)) const { return 0; }

  /**
   * Scales every array of `arrays` that has a length unit (GetLengthPower() p) by
   * 2^(p lengthExponent), exactly, into a double array of the same name and place (its values
   * may lie beyond float's range); the arrays that are `passedThrough`'s own are left alone.
   * RequestData() uses it after a run in a scaled frame; so does a caller that scales the
   * cloud itself.
   */
  void ScaleLengthArrays(
    vtkPointData* arrays, int lengthExponent, vtkPointData* passedThrough = nullptr) const;

  /**
   * The power of two by which to scale a cloud so that squares and products of its coordinate
   * differences, in double and in float, neither overflow nor underflow; 0 where its extent lies
   * within 2^-limit .. 2^limit (its results do not change). Others are scaled to a robust extent
   * near 1: the central half of the points on each axis, so that far points, even 1 % of them,
   * do not shrink the rest into underflow. A power of two scales every coordinate exactly.
   */
  static int ScaledFrameExponent(vtkPointSet* cloud, int limit = 64);

  /**
   * Distributed runs: the halo width the last run needed; larger than HaloWidth when the run
   * stopped for want of it (its output is then all zeros). VTK_DOUBLE_MAX: the whole cloud.
   */
  vtkGetMacro(RequiredHaloWidth, double);

  /**
   * Distributed runs: the name of the point array (vtkIdTypeArray) that holds each piece point's
   * global id, its index in the whole cloud. vtkDistributedFeaturePoints adds it to each piece;
   * a method that makes halo values agree across processes (ShareHaloValues) reads it.
   */
  static const char* GetPieceGlobalIdsArrayName() { return "vtkPieceGlobalIds"; }

  /** Name of the point array the threshold applies to ("F", "SurfaceVariation", ...). */
  virtual const char* GetScoreArrayName() const = 0;

  /**
   * The AUTOMATIC threshold rule on a set of scores (see the class comment). Returns 0 for an empty
   * set. The vector is reordered.
   */
  static double AutomaticThreshold(std::vector<double>& scores, double sigmas);

  /**
   * The same rule on weighted scores: score i counts weights[i] times (weights >= 1). Gives exactly
   * the threshold of AutomaticThreshold on the scores repeated by their weights, without repeating
   * them: one sort, then each round walks the kept scores once.
   */
  static double AutomaticThreshold(
    const std::vector<double>& scores, const std::vector<int>& weights, double sigmas);

protected:
  /**
   * The numeric parameters a run reads, by name: PrepareNeighborhoods() refuses a run where one
   * is NaN (vtkSetClampMacro lets NaN through), with an error naming it. Each class adds its own
   * to its superclass's.
   */
  virtual void ListParameters(std::vector<std::pair<const char*, double>>& parameters) const;

  vtkFeaturePointDetector();
  ~vtkFeaturePointDetector() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /** Clears the figures of the last run. */
  void ResetFigures();

  /**
   * Clears the figures and runs the detector (Run()). A cloud whose extent lies beyond
   * 2^-32 .. 2^32 units (squared lengths overflow or lose their precision in float, and beyond
   * 2^+-140 in the methods' float scores too) runs scaled by a power of two to a robust extent
   * near 1 (ScaledFrameExponent()), which scales every coordinate exactly; the output points
   * are the input's, and the lengths are scaled back: MeanSpacing, the point arrays of a length
   * unit (GetLengthPower(), then double arrays: their values may lie beyond float's range) and
   * the detector's own figures (ScaleFiguresBack()). Distributed runs keep their pieces' frame.
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** The detector on `input`, into `output` (RequestData's work, figures cleared). */
  virtual int Run(vtkPointSet* input, vtkPolyData* output) = 0;

  /** Scales the detector's own length figures by 2^exponent (RequestData(), scaled frame). */
  virtual void ScaleFiguresBack(int vtkNotUsed(exponent)) {}

private:
  // RequestData(), scaled frame: the output back in the input's units (`scaled`: the points
  // the run was given, scaled by 2^exponent).
  void ScaleBack(vtkPointSet* input, vtkPoints* scaled, int exponent, vtkPolyData* output);

protected:

  /**
   * Builds `neighborhoods` over the input's points and checks that neighbourhoods of k points
   * exist. Warns (naming the problem) and returns false when nothing can be scored.
   * On success the cloud is renumbered in a spatially coherent order
   * (vtkPointCloudNeighborhoods::ReorderSpatially): the method then reads its points from
   * `neighborhoods->GetPoints()` and fills its arrays in that numbering, and AssembleOutput()
   * puts them back in the input's order. The results do not depend on the input's order, except
   * where distances tie exactly (duplicates, lattices): the k-nearest tables break such ties by
   * the renumbering (grid cell, then input id).
   */
  bool PrepareNeighborhoods(vtkPoints* points, vtkIdType n, int k,
    vtkPointCloudNeighborhoods* neighborhoods);

  /**
   * Checks the mean spacing d found by `neighborhoods` (sets MeanSpacing) and warns about
   * duplicates and clouds that lie on a line or a plane. Returns false when all points coincide.
   */
  bool CheckSpacing(double d, vtkPointCloudNeighborhoods* neighborhoods);

  /**
   * The warnings CheckSpacing() gives about the cloud (points that coincide, a cloud on a line
   * or a plane), which it leaves to the method while DeferCloudWarnings is set: a method that
   * may run again on the cloud's distinct positions (FindSites()) warns once, about the cloud
   * it scores.
   */
  void WarnAboutCloud(vtkPointCloudNeighborhoods* neighborhoods);

  /** Sums the times of stages of one name into the first of them (a method that ran twice). */
  void MergeRepeatedStages();
  bool DeferCloudWarnings = false;

  /**
   * The positions that several points share: groups of valid points, each point within a
   * tolerance of another of its group, the tolerance 1 % of the median distance from a point
   * to its 8th nearest (exact copies; a scan merged with a copy of itself moved by a rounding or
   * a registration). `row(r, buffer, w)` gives row r of the k-nearest table of `ids` (its first w
   * entries, at most `width`, nearest first, -1 past its end), in the numbering the method works in.
   * Where at least 1 % of the valid points are not the first of their group, fills `site`
   * (input point id -> index of its group, the groups in the order of their first points; -1
   * for an invalid point), sets `tolerance` and returns the number of groups. Otherwise returns
   * 0 and leaves `site` empty: a few copies change a neighbourhood of many points little, and
   * running again on the groups would double the time. One process only (returns 0 when
   * distributed).
   */
  vtkIdType FindSites(vtkPointCloudNeighborhoods* neighborhoods,
    const std::vector<vtkIdType>& ids, int width,
    const std::function<const int32_t*(vtkIdType, int32_t*, int)>& row, std::vector<vtkIdType>& site,
    double& tolerance) const;

  /**
   * The usual path of a method that scores every valid point: prepare, find the k nearest of
   * every valid point (progress 0 to progressEnd) and the mean spacing from that table. Returns
   * false when nothing can be scored (after a warning) or on abort.
   */
  bool SearchAllPoints(vtkPoints* points, vtkIdType n, int k,
    vtkPointCloudNeighborhoods* neighborhoods, std::vector<vtkIdType>& ids,
    std::vector<int32_t>& table, double progressEnd);

  /**
   * The same, the table handed to `consume(firstRow, rows, block)` in blocks of consecutive rows
   * (rows firstRow to firstRow + rows - 1, k entries each, the rows of `ids` in order) instead of
   * kept whole: a method that stores the table in a form of its own never holds all of it in
   * 32-bit ids. The rows and the mean spacing are those of the other form.
   */
  bool SearchAllPoints(vtkPoints* points, vtkIdType n, int k,
    vtkPointCloudNeighborhoods* neighborhoods, std::vector<vtkIdType>& ids,
    const std::function<void(vtkIdType, vtkIdType, const int32_t*)>& consume,
    double progressEnd);

  /**
   * Sets ThresholdUsed (AUTOMATIC rule over the scores of `ids`, each counted `weights[r]` times
   * when weights are given, or Threshold) and the mask: 1 where eligible (all when null) and
   * score > threshold. Sets NumberOfFeaturePoints.
   */
  void ApplyThreshold(const float* score, const std::vector<vtkIdType>& ids,
    const std::vector<int>* weights, const unsigned char* eligible, unsigned char* mask);

  /**
   * Assembles the output (see the class comment) from the input, the method's arrays (n tuples
   * each) and the mask; the score array becomes the active scalars. After a renumbering (see
   * PrepareNeighborhoods) the arrays and the mask are first put back in the input's order, in
   * place.
   */
  int AssembleOutput(vtkPointSet* input, vtkPolyData* output,
    const std::vector<vtkDataArray*>& arrays, vtkUnsignedCharArray* mask);

  ///@{
  /**
   * Cloud-wide figures of a distributed run (see the class comment). IsDistributed(): a
   * Controller of more than one process. IsOwned(i): point i (in the numbering the method works
   * in) belongs to this process's piece, not to its halo; always true in one process. The
   * Global*() helpers reduce over all processes (every process must call them, in the same
   * order) and are the local figure in one process. GlobalUpperMedian() selects the value of rank
   * n / 2 by counts summed over the processes (no process gathers the values),
   * GlobalValueOfShare() that of rank floor(share n) (at most n - 1).
   * CloudBounds()/CloudCenter(): the bounds of the valid points of the whole cloud
   * (neighborhoods->GetBounds()/GetCenter() in one process).
   */
  bool IsDistributed() const;
  bool IsOwned(vtkIdType i) const { return this->Owned.empty() || this->Owned[i] != 0; }
  double GlobalSum(double value) const;
  vtkIdType GlobalSum(vtkIdType value) const;
  double GlobalUpperMedian(std::vector<double>& values) const;
  double GlobalValueOfShare(std::vector<double>& values, double share) const;
  const double* CloudBounds(vtkPointCloudNeighborhoods* neighborhoods) const;
  const double* CloudCenter(vtkPointCloudNeighborhoods* neighborhoods) const;
  /** The number of own points among `ids`. */
  vtkIdType CountOwned(const std::vector<vtkIdType>& ids) const;
  /**
   * The mean spacing as vtkPointCloudNeighborhoods::ComputeMeanSpacing() takes it, over the own
   * points of every process, from the nearest distances `neighborhoods` has measured. Returns
   * `local` in one process.
   */
  double GlobalMeanSpacing(vtkPointCloudNeighborhoods* neighborhoods, double local) const;
  /**
   * featurepoints::MeanWithoutOutliers(values, factor) over the `values` of every process (the
   * own points' values each).
   */
  double GlobalMeanWithoutOutliers(const std::vector<double>& values, double factor) const;
  ///@}

  enum HaloRules
  {
    HALO_FROM_OWNER = 0, ///< each halo copy takes its owner's value, bit for bit
    HALO_MAXIMUM = 1,    ///< the owner takes the largest of all copies, a halo copy the larger
                         ///< of its own and the owner's
    HALO_MINIMUM = 2,    ///< the same with the smallest
  };

  ///@{
  /**
   * Distributed runs: makes a per-point array (`components` values per point, by point id in the
   * numbering the method works in) agree across the processes that hold the point: where a
   * method's value of a halo point is not exact, HALO_FROM_OWNER replaces it with the value its
   * owner computed; a flood or a labelling that spreads across pieces exchanges with
   * HALO_MAXIMUM or HALO_MINIMUM, round after round, until no process changes (a value reaches
   * every copy within two rounds). Every process
   * must call it (collective). Returns whether any value changed on any process; in one process
   * changes nothing and returns false. Needs the piece's global ids
   * (GetPieceGlobalIdsArrayName()); without them, an error and false.
   */
  bool ShareHaloValues(unsigned char* values, int components, int rule);
  bool ShareHaloValues(float* values, int components, int rule);
  bool ShareHaloValues(long long* values, int components, int rule);
  ///@}

  /**
   * Distributed runs: HALO_FROM_OWNER for a record of `bytes` bytes a point that the method keeps
   * elsewhere than in a per-point array (a fit, a model): `read(i, record)` fills the record of
   * point i where this process owns a point that others hold, `write(i, record)` takes the
   * owner's record for a halo point i. Only the halo's records are buffered. Collective, as
   * ShareHaloValues(); returns false in one process or without global ids.
   */
  bool ShareHaloRecords(int bytes, const std::function<void(vtkIdType, unsigned char*)>& read,
    const std::function<void(vtkIdType, const unsigned char*)>& write);

  /**
   * Distributed runs: the global id of point i (the numbering the method works in); i in one
   * process or when the piece carries no global ids.
   */
  long long GlobalId(vtkIdType i) const
  {
    return !this->PieceGlobalIds ? static_cast<long long>(i)
      : this->PieceGlobalIds[this->OriginalIds.empty() ? i : this->OriginalIds[i]];
  }

  /**
   * For each of `labels` (one per own point of this process), how many own points of all
   * processes carry that label, in `counts` (collective; the labels are gathered everywhere).
   */
  void GlobalLabelCounts(const std::vector<long long>& labels, std::vector<long long>& counts) const;

  /**
   * Distributed runs: every process's `values` one after the other, in the order of the
   * processes, on every process (collective). Alone: `values` as they are.
   */
  void GatherAll(std::vector<double>& values) const;
  void GatherAll(std::vector<long long>& values) const;

  // Distributed runs: the own points (from the input's vtkGhostType) and the cloud's bounds, after
  // the renumbering of PrepareNeighborhoods.
  void PrepareOwnership(vtkPointCloudNeighborhoods* neighborhoods);
  // Distributed runs: the scores (and weights) of every process, on the first process.
  void GatherScores(std::vector<double>& scores, std::vector<int>* weights) const;
  /**
   * Where each process's values lie in a gathered array: `lengths` from the processes' `counts`,
   * `offsets` their running sum. Returns the total.
   */
  static vtkIdType GatherLayout(const std::vector<long long>& counts,
    std::vector<vtkIdType>& lengths, std::vector<vtkIdType>& offsets);

  // Closes the running stage (if any) and starts timing the next one; nullptr only closes.
  void BeginStage(const char* name);

  // Warns when all valid points lie on a line or on a plane, within what coordinates of
  // `dataType` (that of the input points) resolve and closer than the mean spacing (which must
  // be set).
  void WarnIfDegenerate(vtkPoints* points, const unsigned char* valid, int dataType);

  int ThresholdMode = AUTOMATIC;
  double Threshold = 1.0;
  double ThresholdSigmas = 5.0;
  bool OutputFeaturesOnly = false;
  vtkAbstractPointLocator* Locator = nullptr;

  double MeanSpacing = 0.0;
  double ThresholdUsed = 0.0;
  vtkIdType NumberOfCandidates = 0;
  vtkIdType NumberOfFeaturePoints = 0;
  double HaloWidth = 0.0;
  double RequiredHaloWidth = 0.0;
  // Input id of each point of the renumbered cloud (empty: not renumbered).
  std::vector<int32_t> OriginalIds;
  vtkMultiProcessController* Controller = nullptr;
  // Distributed runs: 1 for the piece's own points, 0 for the halo, in the numbering the method
  // works in (empty: every point is own); the bounds of the whole cloud's valid points.
  std::vector<unsigned char> Owned;
  // Distributed runs: the input's global ids (the piece's array, in input order; null without it).
  const vtkIdType* PieceGlobalIds = nullptr;
  // ShareHaloValues' layout, built at its first call in a run: every process's halo points'
  // global ids gathered in one list of entries; (entry, point) of this process's halo points and
  // of the entries that name its own points.
  bool HaloLayoutReady = false;
  vtkIdType HaloEntries = 0;
  std::vector<std::pair<vtkIdType, vtkIdType>> HaloRequests;
  std::vector<std::pair<vtkIdType, vtkIdType>> HaloAnswers;
  bool BuildHaloLayout();
  template <typename T>
  bool ShareHalo(T* values, int components, int rule);
  template <typename T>
  void GatherValues(std::vector<T>& values) const;
  double GlobalBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double GlobalCenter[3] = { 0, 0, 0 };
  std::vector<std::string> StageNames;
  std::vector<double> StageTimes;
  std::chrono::steady_clock::time_point StageStart;
  bool StageRunning = false;

private:
  vtkFeaturePointDetector(const vtkFeaturePointDetector&) = delete;
  void operator=(const vtkFeaturePointDetector&) = delete;
};

#endif
