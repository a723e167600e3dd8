/**
 * @class   vtkPointCloudGridLocator
 * @brief   exact nearest-point queries on a uniform grid sized for point clouds, with a batched,
 *          grid-ordered k-nearest query over the cloud's own points.
 *
 * vtkPointCloudGridLocator sorts the points of its data set into a uniform grid of cubic cells,
 * about two cells per point, over the points' *robust* bounding box: when a few far outliers
 * stretch the bounds more than four times the central 99 % of the points, the box is that central
 * part widened by half its size, and the points beyond it are kept in the border cells (which
 * reach to infinity). Where the central 80 % is less than a quarter of that box on some axis,
 * the central 95 % and 80 % (widened alike) are tried too, and the box whose cells hold the
 * fewest pairs of points on a sample of 100,000 wins (needed only when it halves them): a few
 * per cent of the points spread far around a dense part no longer put that part in a handful
 * of cells. The box changes how fast the queries are, never what they return. A query searches rings of cells around the cell of its position, nearest
 * first, and stops when the best distances found are below the distance to the unsearched cells,
 * so every answer is exact. Candidates are ordered by (distance, point id): where distances tie
 * exactly, the smaller id comes first, whatever the order the cells are read in.
 *
 * Besides the queries of vtkAbstractPointLocator, FindNearestNeighbors() answers "the k nearest
 * other points of each of these points of the data set" in one call: the queries are taken cell
 * by cell, in parallel (vtkSMPTools), so that consecutive queries read the same cells. This is
 * the query vtkPointCloudNeighborhoods builds its k-nearest tables with. ReorderSpatially()
 * renumbers the data set's points in the grid's cell order.
 *
 * Points with a NaN or infinite coordinate are left out of the grid: no query returns them.
 * Coincident points are grouped once per position, so that stacks of copies do not slow the
 * queries down; points that differ by less than 2^-540 (about 2.8e-163) in every coordinate,
 * whose squared distance underflows to 0, count as coincident (a query within about 1e-146 of
 * them gets one distance for all, exact only to a relative 2^-40). Where no box can spread the points over the cells (clusters far apart relative
 * to their size), a k-d tree (nanoflann) answers the queries instead, with the same results
 * (see SetSearchStructure()).
 *
 * @warning The queries are thread safe once BuildLocator() has been called from a single thread
 * (as vtkStaticPointLocator's). Data sets of more than 2^31 - 1 points are refused (an error, and
 * an empty grid). The grid keeps its own copy of the coordinates in double precision.
 *
 * Python: the methods on std::vector tables are C++ only; each has a wrapped counterpart on VTK
 * arrays (vtkIdList of point ids, a k-component vtkIntArray table).
 *
 * @sa vtkStaticPointLocator vtkPointCloudNeighborhoods
 */
#ifndef vtkPointCloudGridLocator_h
#define vtkPointCloudGridLocator_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkAbstractPointLocator.h"
#include "vtkSmartPointer.h" // For ivars

#include <cstdint> // For int32_t
#include <memory>  // For the grid
#include <vector>  // For tables

class vtkAlgorithm;
class vtkDoubleArray;
class vtkIdList;
class vtkIntArray;
class vtkPoints;

class FEATUREPOINTSFILTERS_EXPORT vtkPointCloudGridLocator : public vtkAbstractPointLocator
{
public:
  static vtkPointCloudGridLocator* New();
  vtkTypeMacro(vtkPointCloudGridLocator, vtkAbstractPointLocator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Re-use the superclass's x, y, z overloads.
  using vtkAbstractPointLocator::FindClosestNPoints;
  using vtkAbstractPointLocator::FindClosestPoint;
  using vtkAbstractPointLocator::FindPointsWithinRadius;

  ///@{
  /**
   * The queries of vtkAbstractPointLocator. FindClosestNPoints() and FindPointsWithinRadius()
   * return their points nearest first (ties: the smaller id first). A position with a NaN or
   * infinite coordinate finds nothing (-1, an empty list).
   */
  vtkIdType FindClosestPoint(const double x[3]) override;
  vtkIdType FindClosestPointWithinRadius(double radius, const double x[3], double& dist2) override;
  void FindClosestNPoints(int N, const double x[3], vtkIdList* result) override;
  void FindPointsWithinRadius(double R, const double x[3], vtkIdList* result) override;
  ///@}

  ///@{
  /**
   * Build the grid over the data set's points (nothing is done when it is newer than both this
   * object and the data set), or free it.
   */
  void BuildLocator() override;
  void FreeSearchStructure() override;
  ///@}

  /**
   * The outline of the grid's box (12 lines; `level` is ignored: the grid has one level). The
   * border cells also hold the points beyond it (see the class comment).
   */
  void GenerateRepresentation(int level, vtkPolyData* pd) override;

  ///@{
  /**
   * The bounds of the points in the grid (xmin, xmax, ymin, ymax, zmin, zmax), after a build.
   * (Overridden for the size hint only: Python gets a tuple of 6.)
   */
  double* GetBounds() VTK_SIZEHINT(6) override { return this->Bounds; }
  void GetBounds(double* bounds) override { this->Superclass::GetBounds(bounds); }
  ///@}

  ///@{
  /**
   * The grid of the last build: the number of cells along x, y, z, the side of a cell, the corner
   * of the box and the number of points it holds (the finite points of the data set).
   */
  void GetDivisions(int divisions[3]) const;
  double GetCellSize() const;
  void GetOrigin(double origin[3]) const;
  vtkIdType GetNumberOfGridPoints() const;
  ///@}

  ///@{
  /**
   * The structure that answers the queries. AUTO (the default): the grid, unless its cells are
   * so uneven that a query would read more than 3,000 positions of its own cell on average
   * (GetCellOccupancy(): clusters lying far apart relative to their size, each in a handful of
   * cells, where the grid's time grows with the square of the points); then a k-d tree
   * (nanoflann) over the same points, which costs 1.5 to 2.5 times the grid on an even cloud. GRID and KD_TREE force one. Both give the same answers (the same points, the
   * same order, the same ties); only the time differs. Takes effect at the next build.
   */
  enum SearchStructures
  {
    AUTO = 0,
    GRID = 1,
    KD_TREE = 2
  };
  vtkSetClampMacro(SearchStructure, int, AUTO, KD_TREE);
  vtkGetMacro(SearchStructure, int);
  ///@}

  /**
   * After a build: the mean number of positions in a query's own cell (each distinct position
   * weighted by the count of its cell), and whether the k-d tree answers the queries.
   */
  double GetCellOccupancy() const { return this->CellOccupancy; }
  bool GetUsesTree() const;

  /**
   * The k nearest *other* points of each listed point of the data set (ids: any order; the same
   * id twice gets the same row twice), nearest first, ties broken by the smaller id, written to
   * `table` (ids.size() * k entries, row r for ids[r]). The rows of points not in the grid
   * (non-finite coordinates), and the tail of rows when fewer than k other points exist, hold -1.
   * `nearestDistances`, when given, receives per row the distance to the nearest point found
   * (0 when none). `distinct` (k = 1 only): the nearest point at a nonzero distance, copies of
   * the query being skipped. Progress is reported through `progressAlg` between `progressStart`
   * and `progressEnd`; returns false when that algorithm's AbortExecute flag is raised.
   * Builds the grid first if needed (call BuildLocator() beforehand to query from several
   * threads). C++ only; the wrapped counterpart fills `table` (a vtkIntArray of k components, one
   * tuple per id) and, when given, `nearestDistances`.
   */
  VTK_WRAPEXCLUDE bool FindNearestNeighbors(int k, const std::vector<vtkIdType>& ids,
    std::vector<int32_t>& table, std::vector<double>* nearestDistances = nullptr,
    bool distinct = false, vtkAlgorithm* progressAlg = nullptr, double progressStart = 0.0,
    double progressEnd = 1.0);
  bool FindNearestNeighbors(
    int k, vtkIdList* ids, vtkIntArray* table, vtkDoubleArray* nearestDistances = nullptr);

  /**
   * Renumber the points in the grid's cell order (ascending ids within a cell), the points left
   * out of the grid (non-finite) last, in their given order. `originalIds[i]` receives the id, in
   * the data set, of new point i, and the return value is the renumbered points: the grid's own
   * copy of the coordinates (double precision, shared, not copied). From then on the locator's
   * data set is a vtkPolyData of these points and every id it takes or returns is a position in
   * them. Returns nullptr, and changes nothing, before a build. The order depends on the points
   * only, not on the number of threads. C++ only; the wrapped counterpart fills `originalIds` (a
   * vtkIntArray) and returns the points.
   */
  VTK_WRAPEXCLUDE vtkPoints* ReorderSpatially(std::vector<int32_t>& originalIds);
  vtkPoints* ReorderSpatially(vtkIntArray* originalIds);

  /** The grid (opaque; defined in the .cxx file). */
  struct SearchGrid;

protected:
  vtkPointCloudGridLocator();
  ~vtkPointCloudGridLocator() override;

  std::unique_ptr<SearchGrid> Grid;

  // The grid over the m points of `points` whose valid[i] is set (the finite ones; `bounds`:
  // their bounding box).
  void BuildGrid(vtkPoints* points, const std::vector<unsigned char>& valid,
    const double bounds[6], vtkIdType m);
  // The distinct positions of each cell and their points, when some points coincide.
  void BuildSites();
  // The k-d tree, where SearchStructure asks for it (see SetSearchStructure()).
  void BuildTree();

  int SearchStructure = AUTO;
  double CellOccupancy = 0.0;

private:
  vtkPointCloudGridLocator(const vtkPointCloudGridLocator&) = delete;
  void operator=(const vtkPointCloudGridLocator&) = delete;
};

#endif
