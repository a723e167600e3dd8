/**
 * @class   vtkPointCloudNeighborhoods
 * @brief   k-nearest-neighbour tables and the mean point spacing of a point cloud, shared by the
 *          feature filters of this module.
 *
 * vtkPointCloudNeighborhoods validates a cloud's coordinates once, builds one point locator over
 * its finite points (a vtkPointCloudGridLocator by default, or any vtkAbstractPointLocator: see
 * SetLocator()), and answers the two questions every score of this module needs:
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
 * @warning The queries run in parallel with vtkSMPTools when the locator is a
 * vtkPointCloudGridLocator or a vtkStaticPointLocator (their queries are thread safe once built),
 * one after the other with any other locator; each row depends on its point only, so the tables
 * are identical whatever the number of threads or the SMP backend. Clouds of more than
 * 2^31 - 1 points are refused (the tables hold 32-bit ids).
 *
 * Python: the methods on std::vector<int32_t> tables and bare pointers are C++ only; each has a
 * wrapped counterpart on VTK arrays (vtkIdList of point ids, a k-component vtkIntArray table).
 *
 * @sa vtkPointCloudGridLocator vtkFeaturePointExtraction vtkStaticPointLocator
 */
#ifndef vtkPointCloudNeighborhoods_h
#define vtkPointCloudNeighborhoods_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For ivars

#include <cstdint> // For int32_t
#include <string>  // For error text
#include <vector>  // For tables

class vtkAbstractPointLocator;
class vtkAlgorithm;
class vtkCellArray;
class vtkDoubleArray;
class vtkIdList;
class vtkIntArray;
class vtkPoints;
class vtkPointCloudGridLocator;
class vtkPolyData;
class vtkUnsignedCharArray;

class FEATUREPOINTSFILTERS_EXPORT vtkPointCloudNeighborhoods : public vtkObject
{
public:
  static vtkPointCloudNeighborhoods* New();
  vtkTypeMacro(vtkPointCloudNeighborhoods, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The point locator the k nearest points are found with; Build() gives it its data set (the
   * cloud's finite points) and builds it. The default, a vtkPointCloudGridLocator, answers a
   * whole table in one batched query, its queries taken cell by cell: about 3 times faster than
   * vtkStaticPointLocator here (docs/design.md, "Neighbourhoods"), and the only one with which
   * ReorderSpatially() works. Any other locator is asked for each point in turn
   * (FindClosestNPoints); all give the same tables, ties in distance aside (the grid breaks them
   * by the smaller point id). nullptr restores the default. Set before Build(). The next Build(),
   * and the destruction of this object, release the locator's search structure and data set, so
   * that a locator a filter keeps holds no cloud between runs.
   */
  void SetLocator(vtkAbstractPointLocator* locator);
  vtkAbstractPointLocator* GetLocator() const;
  ///@}

  enum SearchMethods
  {
    GRID = 0,                 ///< a vtkPointCloudGridLocator (default)
    STATIC_POINT_LOCATOR = 1, ///< a vtkStaticPointLocator
    OTHER_LOCATOR = 2,        ///< another locator given to SetLocator()
  };

  ///@{
  /**
   * A shortcut to SetLocator(): GRID sets a new vtkPointCloudGridLocator, STATIC_POINT_LOCATOR a
   * new vtkStaticPointLocator (unless the locator already is one). GetSearchMethod() tells which
   * kind the locator is (OTHER_LOCATOR for any other class).
   */
  void SetSearchMethod(int method);
  int GetSearchMethod() const;
  ///@}

  /**
   * Validate the points and build the locator. Returns false, with a message in GetErrorText(),
   * when nothing can be computed: no points, no finite point, more than 2^31 - 1 points.
   * Non-finite coordinates and duplicates are not errors: they are counted (see the getters).
   */
  bool Build(vtkPoints* points);

  /** The ids of the valid points, ascending. */
  std::vector<vtkIdType> GetValidIds() const;

  /**
   * Renumber the cloud in a spatially coherent order, right after Build(), with a
   * vtkPointCloudGridLocator only (vtkPointCloudGridLocator::ReorderSpatially()): the valid
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
   * Returns false, and changes nothing, with another locator, before a successful Build(), or
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
   * The valid points at the position of another valid point that comes first (all copies of a
   * position but one), sorted (after ComputeMeanSpacing()): the mean spacing counts a position
   * once, whatever its copies.
   */
  const std::vector<vtkIdType>& GetExtraCopies() const { return this->ExtraCopies; }

  /**
   * Centre of the bounding box of the valid points (Eq. 10 of the paper) and the box itself
   * (xmin, xmax, ymin, ymax, zmin, zmax).
   */
  const double* GetCenter() const VTK_SIZEHINT(3) { return this->Center; }
  const double* GetBounds() const VTK_SIZEHINT(6) { return this->Bounds; }

  /**
   * The data type of the points given to Build() (VTK_FLOAT, VTK_DOUBLE, ...): their precision.
   * GetPoints() is a double copy once ReorderSpatially() has run.
   */
  int GetInputDataType() const { return this->InputDataType; }

  /** Why Build() failed. */
  const std::string& GetErrorText() const { return this->ErrorText; }

  /**
   * Why a mean spacing came out 0 or not finite (no final period): distinct points whose squared
   * distances underflow or overflow in double precision (coordinates near 1e-160 or 1e160), or
   * else "All points coincide".
   */
  std::string DescribeZeroSpacing(double spacing) const;

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
  // The locator's data set: all points for the grid (it leaves the non-finite ones out itself),
  // the finite points only for another locator.
  vtkSmartPointer<vtkPolyData> LocatorData;
  vtkSmartPointer<vtkAbstractPointLocator> Locator;
  vtkPointCloudGridLocator* GridLocator = nullptr; // Locator, when it is the grid, after Build()
  bool Searchable = false; // Build() succeeded
  std::vector<vtkIdType> LocatorToPoint; // empty when all points are valid or with the grid
  std::vector<unsigned char> Valid;
  std::vector<double> NearestDistances;
  std::vector<unsigned char> NearestKnown; // FindNearestDistances() filled NearestDistances here
  int InputDataType = VTK_DOUBLE;
  std::vector<vtkIdType> Unreached;        // valid points the nearest search found no point for
  // Adds to Unreached the rows of `table` (k wide, for `ids`) without a neighbour.
  void NoteUnreached(const std::vector<vtkIdType>& ids, const int32_t* table, int k);
  vtkIdType NumberOfPoints = 0;
  vtkIdType NumberOfValidPoints = 0;
  vtkIdType FirstInvalidPoint = -1;
  vtkIdType NumberOfDuplicatePoints = 0;
  std::vector<vtkIdType> ExtraCopies;
  double MeanSpacing = -1.0;
  double Center[3] = { 0, 0, 0 };
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::string ErrorText;

  // Releases the locator's search structure and data set (they are this object's cloud).
  void ReleaseLocator();

  // Completes NearestDistances for duplicates and averages them (shared by both spacing methods).
  double FinishMeanSpacing();

private:
  vtkPointCloudNeighborhoods(const vtkPointCloudNeighborhoods&) = delete;
  void operator=(const vtkPointCloudNeighborhoods&) = delete;
};

#endif
