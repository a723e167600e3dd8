/**
 * @class   vtkPointCloudNeighborhoods
 * @brief   k-nearest-neighbour tables and the mean point spacing of a point cloud, shared by the
 *          feature filters of this module.
 *
 * vtkPointCloudNeighborhoods validates a cloud's coordinates once, builds one search structure
 * over its finite points (its own uniform grid by default, or a vtkStaticPointLocator: see
 * SearchMethod), and answers the two questions every score of this module needs:
 *
 * - the mean spacing d: the mean, over all points, of the distance to the nearest *distinct* point
 *   (for a point stacked on duplicates, the nearest point at a nonzero distance), leaving out
 *   isolated outliers whose distance exceeds 10 times the median (one far point would otherwise
 *   set the unit of the whole cloud). It is the unit in which the filters express radii and voxel
 *   sizes, so that results do not depend on the cloud's units.
 * - for a set of points, the k nearest other points of each (the point itself excluded), nearest
 *   first, as a table of 32-bit ids. One query per point serves every quantity that needs a
 *   neighbourhood: a filter asks for the largest k it needs and uses prefixes of each row.
 *
 * Points with a NaN or infinite coordinate are left out of the locator: they are never anyone's
 * neighbour and their own rows are filled with -1.
 *
 * @warning The queries run in parallel with vtkSMPTools; each row depends on its point only, so the
 * tables are identical whatever the number of threads or the SMP backend. Clouds of more than
 * 2^31 - 1 points are refused (the tables hold 32-bit ids).
 *
 * Python: the methods on std::vector<int32_t> tables and bare pointers are C++ only; each has a
 * wrapped counterpart on VTK arrays (vtkIdList of point ids, a k-component vtkIntArray table).
 *
 * @sa vtkFeaturePointExtraction vtkStaticPointLocator
 */
#ifndef vtkPointCloudNeighborhoods_h
#define vtkPointCloudNeighborhoods_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For ivars

#include <cstdint> // For int32_t
#include <memory>  // For the search grid
#include <string>  // For error text
#include <vector>  // For tables

class vtkAlgorithm;
class vtkCellArray;
class vtkDoubleArray;
class vtkIdList;
class vtkIntArray;
class vtkPoints;
class vtkPolyData;
class vtkStaticPointLocator;
class vtkUnsignedCharArray;

class FEATUREPOINTSFILTERS_EXPORT vtkPointCloudNeighborhoods : public vtkObject
{
public:
  static vtkPointCloudNeighborhoods* New();
  vtkTypeMacro(vtkPointCloudNeighborhoods, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SearchMethods
  {
    GRID = 0,                 ///< this class's uniform grid (default)
    STATIC_POINT_LOCATOR = 1, ///< vtkStaticPointLocator::FindClosestNPoints
  };

  ///@{
  /**
   * How the k nearest points are found; both give the same tables (ties in distance aside, which
   * GRID breaks by the smaller point id). GRID, the default, sorts the points into a uniform grid
   * of about two cells per point over the cloud's robust bounding box and searches rings of cells
   * around each query, the queries themselves taken cell by cell: about 3 times faster than
   * STATIC_POINT_LOCATOR here (docs/design.md, "Neighbourhoods"). Set before Build().
   */
  void SetSearchMethod(int method) { this->SearchMethod = method == STATIC_POINT_LOCATOR ? method : GRID; }
  int GetSearchMethod() const { return this->SearchMethod; }
  ///@}

  /** The grid of the GRID search (opaque). */
  struct SearchGrid;

  /**
   * Validate the points and build the locator. Returns false, with a message in GetErrorText(),
   * when nothing can be computed: no points, no finite point, more than 2^31 - 1 points.
   * Non-finite coordinates and duplicates are not errors: they are counted (see the getters).
   */
  bool Build(vtkPoints* points);

  /** The ids of the valid points, ascending. */
  std::vector<vtkIdType> GetValidIds() const;

  /**
   * Renumber the cloud in a spatially coherent order, right after Build() (GRID only): the valid
   * points in the grid's cell order (ascending ids within a cell), then the invalid ones in their
   * given order. From then on GetPoints() is the cloud in that order (the grid's own copy of the
   * coordinates, in double precision, not a new one), every id this object takes or returns is a
   * position in it, and `originalIds[i]` is the id, in the cloud given to Build(), of point i.
   *
   * Why: a filter that scores points reads, for each, the coordinates and per-point values of its
   * neighbours. In a cloud stored in random order (a scanner's, a sampler's, a shuffled file's)
   * these reads are scattered over the whole cloud; in this order neighbours sit near each other
   * in memory and consecutive queries share them, which makes the whole filter faster
   * (docs/design.md, "Neighbourhoods"). The order depends on the points only, not on the number
   * of threads.
   *
   * Returns false, and changes nothing, with STATIC_POINT_LOCATOR, before a successful Build(), or
   * once a spacing or a neighbour table has been computed.
   * C++ only; the wrapped counterpart fills `originalIds` (a vtkIntArray) instead.
   */
  VTK_WRAPEXCLUDE bool ReorderSpatially(std::vector<int32_t>& originalIds);
  bool ReorderSpatially(vtkIntArray* originalIds);

  /**
   * Compute the mean spacing d (see the class comment) with one nearest-neighbour query per valid
   * point. Returns 0 when no two valid points are apart (all coincide, or a single point).
   * The result is cached until the next Build().
   */
  double ComputeMeanSpacing();

  /**
   * The same mean spacing, taken from a k-nearest table that FindNearestNeighbors() has already
   * filled for every valid point (`ids` lists them, row r for ids[r]), so that a caller that needs
   * every point's neighbourhood anyway does not search twice. Returns the same value as
   * ComputeMeanSpacing(). C++ only; the wrapped counterpart takes the table as FindNearestNeighbors'
   * wrapped counterpart fills it (k = its number of components).
   */
  VTK_WRAPEXCLUDE double ComputeMeanSpacing(
    const std::vector<vtkIdType>& ids, const std::vector<int32_t>& table, int k);
  double ComputeMeanSpacing(vtkIdList* ids, vtkIntArray* table);

  /**
   * Distance from each listed point to its nearest other point (`distances[r]` for `ids[r]`, 0
   * for an invalid point or one that coincides with another), found with one 1-nearest query each.
   * The values are kept, so that a later ComputeMeanSpacing() does not search these points again
   * (the voxel screen's sample, for instance).
   */
  void FindNearestDistances(const std::vector<vtkIdType>& ids, std::vector<double>& distances);

  /**
   * The k nearest other valid points of each point in `ids` (ascending point ids or any order),
   * nearest first, written to `table` (ids.size() * k entries, row r for ids[r]). Rows of invalid
   * points, and the tail of rows when fewer than k other valid points exist, hold -1.
   * If `nearestDistances` is given it receives, per row, the distance to the nearest other point.
   * Progress is reported through `progressAlg` between `progressStart` and `progressEnd`; returns
   * false when that algorithm's AbortExecute flag is raised.
   * C++ only; the wrapped counterpart fills `table` (a vtkIntArray of k components, one tuple
   * per id) and, when given, `nearestDistances` (one value per id).
   */
  VTK_WRAPEXCLUDE bool FindNearestNeighbors(int k, const std::vector<vtkIdType>& ids,
    std::vector<int32_t>& table, std::vector<double>* nearestDistances = nullptr,
    vtkAlgorithm* progressAlg = nullptr, double progressStart = 0.0, double progressEnd = 1.0);
  bool FindNearestNeighbors(int k, vtkIdList* ids, vtkIntArray* table,
    vtkDoubleArray* nearestDistances = nullptr);

  ///@{
  /**
   * Statistics of the points given to Build(). A point is valid when its three coordinates are
   * finite. GetFirstInvalidPoint() is -1 when all are valid. GetValidMask(): 1 per valid point,
   * 0 per invalid one (C++: a pointer into this object; Python: into the array given).
   */
  vtkIdType GetNumberOfPoints() const { return this->NumberOfPoints; }
  vtkIdType GetNumberOfValidPoints() const { return this->NumberOfValidPoints; }
  vtkIdType GetFirstInvalidPoint() const { return this->FirstInvalidPoint; }
  VTK_WRAPEXCLUDE const unsigned char* GetValidMask() const { return this->Valid.data(); }
  void GetValidMask(vtkUnsignedCharArray* mask) const;
  ///@}

  /**
   * Distance of each point to its nearest distinct point, filled by ComputeMeanSpacing() (0 for
   * invalid points and for points that coincide with all others).
   */
  const std::vector<double>& GetNearestDistances() const { return this->NearestDistances; }

  /**
   * Number of valid points that coincide with another point (after ComputeMeanSpacing()).
   */
  vtkIdType GetNumberOfDuplicatePoints() const { return this->NumberOfDuplicatePoints; }

  /**
   * Centre of the bounding box of the valid points (Eq. 10 of the paper) and the box itself
   * (xmin, xmax, ymin, ymax, zmin, zmax).
   */
  const double* GetCenter() const VTK_SIZEHINT(3) { return this->Center; }
  const double* GetBounds() const VTK_SIZEHINT(6) { return this->Bounds; }

  /** Why Build() failed. */
  const std::string& GetErrorText() const { return this->ErrorText; }

  /** The points given to Build(), or their renumbered copy after ReorderSpatially(). */
  vtkPoints* GetPoints() const;

  /**
   * One vertex cell per point (0 .. n-1), with 32-bit storage when n allows (nullptr when the
   * memory cannot be had): how the filters of this module make a cloud render as is. C++ only (a
   * smart pointer); the wrapped counterpart fills `cells` and returns false when the memory cannot
   * be had.
   */
  VTK_WRAPEXCLUDE static vtkSmartPointer<vtkCellArray> MakeVertexCells(vtkIdType n);
  static bool MakeVertexCells(vtkIdType n, vtkCellArray* cells);

protected:
  vtkPointCloudNeighborhoods();
  ~vtkPointCloudNeighborhoods() override;

  vtkSmartPointer<vtkPoints> Points;
  vtkSmartPointer<vtkPolyData> LocatorData; // the valid points only
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  std::unique_ptr<SearchGrid> Grid;
  int SearchMethod = GRID;
  bool Searchable = false; // Build() succeeded
  std::vector<vtkIdType> LocatorToPoint; // empty when all points are valid
  std::vector<unsigned char> Valid;
  std::vector<double> NearestDistances;
  std::vector<unsigned char> NearestKnown; // FindNearestDistances() filled NearestDistances here
  vtkIdType NumberOfPoints = 0;
  vtkIdType NumberOfValidPoints = 0;
  vtkIdType FirstInvalidPoint = -1;
  vtkIdType NumberOfDuplicatePoints = 0;
  double MeanSpacing = -1.0;
  double Center[3] = { 0, 0, 0 };
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::string ErrorText;

  void BuildGrid();
  // The distinct positions of each cell of the grid and their points, when some points coincide.
  void BuildSites();
  // `distinct` (k = 1 only): the nearest point at a nonzero distance.
  bool FindNearestNeighborsOnGrid(int k, const std::vector<vtkIdType>& ids,
    std::vector<int32_t>& table, std::vector<double>* nearestDistances, vtkAlgorithm* progressAlg,
    double progressStart, double progressEnd, bool distinct = false);

  // Completes NearestDistances for duplicates and averages them (shared by both spacing methods).
  double FinishMeanSpacing();

private:
  vtkPointCloudNeighborhoods(const vtkPointCloudNeighborhoods&) = delete;
  void operator=(const vtkPointCloudNeighborhoods&) = delete;
};

#endif
