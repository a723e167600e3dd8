#include "vtkFeatureCurveExtraction.h"
#include "vtkFeaturePointsStatistics.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudGridLocator.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkFeatureCurveExtraction);

namespace
{
using V3 = Eigen::Vector3d;

// Shape constants: angles and ratios. Lengths are parameters, in mean spacings.
const double MaxTurnPerStep = std::cos(vtkMath::RadiansFromDegrees(35.0)); // a trace stops at a sharper turn
constexpr double MaxFlatness = 0.6;   // lambda2 / lambda1 of a line fit above this: not a line
constexpr int MinFitPoints = 4;       // fewer trace points in a fit: nothing to follow
// The fit radius grows where trace points are sparse (AdaptFitRadius), up to this many times
// FitRadius: about 8 times sparser than a one-point-wide mask on a random sampling.
constexpr double MaximumFitRadiusGrowth = 4.0;
// A fit reads at most this many times the points of a disk of FitRadius at the mean spacing, the
// nearest (a dense cluster of feature points would otherwise put thousands in every fit).
constexpr double FitCapDisks = 4.0;
// A curve more than this many resampling steps long per vertex keeps its vertices (Resample).
constexpr double MaximumStepsPerVertex = 1024.0;
constexpr double CollisionRadius = 1.5; // s: a trace joins a vertex of another this close
constexpr double CoverRadius = 2.5;     // s: trace points this close to a vertex seed no trace
constexpr double AssignRadius = 3.0;    // s: feature points this close to a curve get its id
// Ends further apart across their parallel lines than this many band widths (the trace points'
// RMS distance from their lines) lie on two curves.
constexpr double SideBySideWidths = 4.0;
// The normals around x span a plane (a crease's) when their least variance is below this share of
// the middle one; a trace's direction further off that plane's normal than AcrossNormals crosses
// the crease's faces instead of following it.
constexpr double NormalPlaneRatio = 0.2;
constexpr double RidgeRadius = 2.0; // s: a crease point's score against those this close
const double AcrossNormals = std::cos(vtkMath::RadiansFromDegrees(30.0));
const double CornerTurn = std::cos(vtkMath::RadiansFromDegrees(45.0)); // a sharper turn within CornerWindow splits
constexpr double CornerWindow = 3.0;    // s
constexpr double CornerNear = 2.0;      // s: a vertex this near a point typed corner is at one
constexpr double CornerSupport = 2.0;   // s: a junction needs a feature point this near (the band)
const double BridgeCone = std::cos(vtkMath::RadiansFromDegrees(30.0)); // an end joins what lies in this cone
constexpr int BridgeProposals = 3; // the facing ends an end may be bridged to, nearest first
constexpr int SmoothingPasses = 20;
constexpr double SectionRadius = 1.5; // in FitRadius: the cross-section's points
// In FitRadius: the wider cross-section a gap's bend is measured on where the faces stay planes
// that far (the slopes' error falls as the width to the power 1.5).
constexpr double WideSectionRadius = 3.0;
constexpr double SectionLength = 0.75; // in FitRadius: how far along the curve they may lie
constexpr double MovedBand = 2.0; // s: the moved crease points that place a vertex (the detector's band)
// In FitRadius: how far along the fitted curve the second fit takes its points, either side (a
// vertex fit's slab holds about 20 points per face, from which a crease whose faces differ by
// 30 degrees is placed along them within about 0.8 s only). The reference quadratic spans
// twice it and must follow the curve's bend.
constexpr double AlongLength = 2.5;
constexpr double SectionCore = 1.0; // s: points this near the vertex do not fit the faces' lines
const double MinimumCreaseAngle = std::sin(vtkMath::RadiansFromDegrees(10.0)); // flatter faces: no intersection
// A feature point whose score is below this share of the detector's threshold was not voted for
// (added by a rule other than the vote: unexplained fits, growth); a free branch or a piece
// whose points are mostly such is not a crease.
constexpr double SupportShare = 0.5;
constexpr double MinimumSupport = 0.25; // share of supported points a free branch needs
const double ThroughCone = std::cos(vtkMath::RadiansFromDegrees(150.0)); // a curve goes on through a junction
// Two faces' slopes further apart than this many standard errors (from the faces' own residuals,
// the cloud's noise) are a bend, not noise.
constexpr double CreaseSignificance = 3.0;
// Two faces (4 parameters) explain a cross-section better than one quadratic face (3) when their
// residual is lower by more than 2 noise variances (Akaike's criterion: 2 per parameter).
constexpr double KinkAIC = 2.0;

enum Types
{
  NONE = 0,
  CONVEX = 1,
  CONCAVE = 2,
  CORNER = 3,
  BORDER = 4,
};

// PointSearch's limit on the mean number of points in a point's own bin of VTK's locator.
constexpr double CrowdedBins = 100.0;

// Radius queries over a fixed set of points (serial).
class PointSearch
{
public:
  void Build(const std::vector<V3>& points)
  {
    this->Count = static_cast<vtkIdType>(points.size());
    this->Source = &points;
    vtkNew<vtkPoints> p;
    p->SetDataTypeToDouble();
    p->SetNumberOfPoints(this->Count);
    for (vtkIdType i = 0; i < this->Count; ++i)
    {
      p->SetPoint(i, points[i].data());
    }
    this->Data->SetPoints(p);
    this->Locator = this->Bins;
    if (this->Count > 0)
    {
      this->Bins->SetDataSet(this->Data);
      this->Bins->BuildLocator();
      // VTK's bins span the points' bounds: points along a curve (a wire, a cloud all features)
      // fill a few of them, and each query there reads thousands of points. The mean number of
      // points in a point's own bin says so; the grid locator (a k-d tree where even its finer
      // cells are that full) answers those.
      const int* d = this->Bins->GetDivisions();
      const vtkIdType bins = static_cast<vtkIdType>(d[0]) * d[1] * d[2];
      double pairs = 0.0;
      for (vtkIdType b = 0; b < bins; ++b)
      {
        const double inBin = static_cast<double>(this->Bins->GetNumberOfPointsInBucket(b));
        pairs += inBin * inBin;
      }
      if (pairs > CrowdedBins * static_cast<double>(this->Count))
      {
        this->Grid->SetDataSet(this->Data);
        this->Grid->BuildLocator();
        this->Locator = this->Grid;
      }
    }
  }
  void Within(const V3& x, double r, std::vector<vtkIdType>& out) const
  {
    out.clear();
    if (this->Count == 0)
    {
      return;
    }
    this->Locator->FindPointsWithinRadius(r, x.data(), this->Ids);
    out.assign(this->Ids->begin(), this->Ids->end());
    std::sort(out.begin(), out.end()); // the same sums whatever the locator's order
  }
  // The points within r of x, but at most `most` of them, the nearest (as Open3D's hybrid
  // search): where points crowd far beyond a surface's sampling (a dense cluster), a ball would
  // hold thousands and every query and fit through it would read them all.
  void NearestWithin(const V3& x, double r, vtkIdType most, std::vector<vtkIdType>& out) const
  {
    out.clear();
    if (this->Count == 0 || most <= 0)
    {
      return;
    }
    if (this->Locator == this->Grid)
    {
      // Crowded bins: the most nearest, of which those within r (all of the ball if it holds
      // fewer).
      this->Locator->FindClosestNPoints(static_cast<int>(std::min(most, this->Count)), x.data(), this->Ids);
      const double r2 = r * r;
      for (vtkIdType j = 0; j < this->Ids->GetNumberOfIds(); ++j)
      {
        const vtkIdType id = this->Ids->GetId(j);
        if (((*this->Source)[id] - x).squaredNorm() <= r2)
        {
          out.push_back(id);
        }
      }
    }
    else
    {
      this->Locator->FindPointsWithinRadius(r, x.data(), this->Ids);
      out.assign(this->Ids->begin(), this->Ids->end());
      if (static_cast<vtkIdType>(out.size()) > most)
      {
        const std::vector<V3>& p = *this->Source;
        std::nth_element(out.begin(), out.begin() + most, out.end(), [&](vtkIdType a, vtkIdType b) {
          const double da = (p[a] - x).squaredNorm(), db = (p[b] - x).squaredNorm();
          return da < db || (da == db && a < b);
        });
        out.resize(static_cast<size_t>(most));
      }
    }
    std::sort(out.begin(), out.end()); // the same sums whatever the locator's order
  }
  vtkIdType Nearest(const V3& x) const
  {
    return this->Count ? this->Locator->FindClosestPoint(x.data()) : -1;
  }
  // The distance from point i of the built points to its k-th nearest other one (-1: fewer).
  double KthDistance(const std::vector<V3>& points, vtkIdType i, int k) const
  {
    if (this->Count <= k)
    {
      return -1.0;
    }
    this->Locator->FindClosestNPoints(k + 1, points[i].data(), this->Ids);
    double d = 0.0;
    for (vtkIdType j = 0; j < this->Ids->GetNumberOfIds(); ++j)
    {
      d = std::max(d, (points[this->Ids->GetId(j)] - points[i]).norm());
    }
    return d;
  }

private:
  vtkIdType Count = 0;
  const std::vector<V3>* Source = nullptr; // the built points
  vtkNew<vtkPolyData> Data;
  vtkNew<vtkStaticPointLocator> Bins;
  vtkNew<vtkPointCloudGridLocator> Grid;
  vtkAbstractPointLocator* Locator = nullptr; // Bins or Grid
  vtkNew<vtkIdList> Ids;
};

struct LineFit
{
  V3 Centroid = V3::Zero();
  V3 Direction = V3::Zero();
  int Count = 0;
  double Flatness = 1.0; // lambda2 / lambda1
  double Width = 0.0;    // RMS distance of the points from the line
};

// PCA line through the listed points (coordinates taken relative to `origin`).
LineFit FitLine(const std::vector<V3>& points, const std::vector<vtkIdType>& ids, const V3& origin)
{
  LineFit fit;
  fit.Count = static_cast<int>(ids.size());
  if (fit.Count < 2)
  {
    return fit;
  }
  V3 mean = V3::Zero();
  for (vtkIdType i : ids)
  {
    mean += points[i] - origin;
  }
  mean /= fit.Count;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (vtkIdType i : ids)
  {
    const V3 v = points[i] - origin - mean;
    cov += v * v.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov / fit.Count);
  const V3 values = solver.eigenvalues();
  fit.Centroid = origin + mean;
  fit.Direction = solver.eigenvectors().col(2).normalized();
  fit.Flatness = values[2] > 0.0 ? std::max(values[1], 0.0) / values[2] : 1.0;
  fit.Width = std::sqrt(std::max(values[0], 0.0) + std::max(values[1], 0.0));
  return fit;
}

// Whether the listed points, whose line fit is `f`, lie on two lines side by side rather than
// on one: across the line (along the direction in which their offsets from it spread most), the
// best split into two groups (least squares, as 2-means) leaves each group of at least
// `minimum` points, the gap between the groups' means is wider than 2 sqrt(3) times their
// pooled spread (what splitting one band of any even width leaves), and each group has points
// in every third of the span along the line. `gap`: the distance between the groups' means.
bool TwoLinesSideBySide(const std::vector<V3>& points, const std::vector<vtkIdType>& ids,
  const LineFit& f, int minimum, double& gap)
{
  const size_t m = ids.size();
  if (m < static_cast<size_t>(2 * minimum))
  {
    return false;
  }
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  std::vector<V3> across(m);
  for (size_t k = 0; k < m; ++k)
  {
    const V3 r = points[ids[k]] - f.Centroid;
    across[k] = r - r.dot(f.Direction) * f.Direction;
    cov += across[k] * across[k].transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  const V3 e = solver.eigenvectors().col(2);
  // (across, along) per point, by across.
  std::vector<std::pair<double, double>> uv(m);
  for (size_t k = 0; k < m; ++k)
  {
    uv[k] = { across[k].dot(e), (points[ids[k]] - f.Centroid).dot(f.Direction) };
  }
  std::sort(uv.begin(), uv.end());
  std::vector<double> u(m);
  for (size_t k = 0; k < m; ++k)
  {
    u[k] = uv[k].first;
  }
  std::vector<double> prefix(m + 1, 0.0), squares(m + 1, 0.0);
  for (size_t k = 0; k < m; ++k)
  {
    prefix[k + 1] = prefix[k] + u[k];
    squares[k + 1] = squares[k] + u[k] * u[k];
  }
  double best = std::numeric_limits<double>::infinity();
  size_t split = 0;
  for (size_t k = static_cast<size_t>(minimum); k + static_cast<size_t>(minimum) <= m; ++k)
  {
    const double a = static_cast<double>(k), b = static_cast<double>(m - k);
    const double sa = prefix[k], sb = prefix[m] - prefix[k];
    const double within = squares[m] - sa * sa / a - sb * sb / b;
    if (within < best)
    {
      best = within;
      split = k;
    }
  }
  if (split == 0)
  {
    return false;
  }
  const double a = static_cast<double>(split), b = static_cast<double>(m - split);
  gap = (prefix[m] - prefix[split]) / b - prefix[split] / a;
  const double spread = std::sqrt(std::max(best, 0.0) / static_cast<double>(m));
  if (!(gap > 2.0 * std::sqrt(3.0) * spread))
  {
    return false;
  }
  // Side by side, each group runs along the whole span: a point of each in every third of it.
  // (A curved line splits too, across its chord: its middle from its two ends.)
  double lo = uv[0].second, hi = lo;
  for (const auto& p : uv)
  {
    lo = std::min(lo, p.second);
    hi = std::max(hi, p.second);
  }
  const double third = (hi - lo) / 3.0;
  if (!(third > 0.0))
  {
    return false;
  }
  int seen[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
  for (size_t k = 0; k < m; ++k)
  {
    const int part = std::min(2, static_cast<int>((uv[k].second - lo) / third));
    seen[k < split ? 0 : 1][part] = 1;
  }
  for (const auto& group : seen)
  {
    if (!(group[0] && group[1] && group[2]))
    {
      return false;
    }
  }
  return true;
}

V3 ProjectOnLine(const V3& x, const LineFit& f)
{
  return f.Centroid + (x - f.Centroid).dot(f.Direction) * f.Direction;
}

// The point nearest to lines through `points` along `directions` (least squares); false when the
// lines are (nearly) parallel.
bool NearestToLines(const std::vector<V3>& points, const std::vector<V3>& directions, V3& result)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  V3 b = V3::Zero();
  const V3 origin = points[0];
  for (size_t k = 0; k < points.size(); ++k)
  {
    const Eigen::Matrix3d m = Eigen::Matrix3d::Identity() - directions[k] * directions[k].transpose();
    a += m;
    b += m * (points[k] - origin);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
  if (solver.eigenvalues()[0] < 0.05 * static_cast<double>(points.size()))
  {
    return false;
  }
  result = origin + a.ldlt().solve(b);
  return result.allFinite();
}

// The curves' graph: vertices, undirected edges, and the vertices that must end curves.
struct Graph
{
  std::vector<V3> Vertices;
  std::vector<std::vector<int>> Adjacent;
  std::vector<unsigned char> Node; // forced end of curves (a corner)

  int Add(const V3& x, bool node = false)
  {
    this->Vertices.push_back(x);
    this->Adjacent.emplace_back();
    this->Node.push_back(node ? 1 : 0);
    return static_cast<int>(this->Vertices.size()) - 1;
  }
  void Link(int a, int b)
  {
    if (a == b || std::find(this->Adjacent[a].begin(), this->Adjacent[a].end(), b) !=
        this->Adjacent[a].end())
    {
      return;
    }
    this->Adjacent[a].push_back(b);
    this->Adjacent[b].push_back(a);
  }
  void Unlink(int a, int b)
  {
    auto& la = this->Adjacent[a];
    auto& lb = this->Adjacent[b];
    la.erase(std::remove(la.begin(), la.end(), b), la.end());
    lb.erase(std::remove(lb.begin(), lb.end(), a), lb.end());
  }
  int Degree(int a) const { return static_cast<int>(this->Adjacent[a].size()); }
  bool IsEnd(int a) const { return this->Degree(a) != 2 || this->Node[a]; }
};

// A curve of the graph: vertex ids from end to end (a closed one repeats its first id last).
struct Chain
{
  std::vector<int> Ids;
  bool Closed = false;
};

// Vertices of the traces by grid cell, for the "does a trace come near another" test.
class VertexHash
{
public:
  explicit VertexHash(double cell)
    : Cell(cell)
  {
  }
  void Insert(int id, const V3& x) { this->Cells[this->Key(x, 0, 0, 0)].push_back(id); }
  template <typename Accept>
  int Nearest(const V3& x, double radius, const std::vector<V3>& vertices, Accept accept) const
  {
    int best = -1;
    double bestDistance = radius * radius;
    for (int i = -1; i <= 1; ++i)
    {
      for (int j = -1; j <= 1; ++j)
      {
        for (int k = -1; k <= 1; ++k)
        {
          const auto found = this->Cells.find(this->Key(x, i, j, k));
          if (found == this->Cells.end())
          {
            continue;
          }
          for (int v : found->second)
          {
            const double d = (vertices[v] - x).squaredNorm();
            if (d <= bestDistance && accept(v) && (best < 0 || d < bestDistance || v < best))
            {
              best = v;
              bestDistance = d;
            }
          }
        }
      }
    }
    return best;
  }

private:
  int64_t Key(const V3& x, int i, int j, int k) const
  {
    const int64_t a = static_cast<int64_t>(std::floor(x[0] / this->Cell)) + i;
    const int64_t b = static_cast<int64_t>(std::floor(x[1] / this->Cell)) + j;
    const int64_t c = static_cast<int64_t>(std::floor(x[2] / this->Cell)) + k;
    return (a * 73856093) ^ (b * 19349663) ^ (c * 83492791);
  }
  double Cell;
  std::unordered_map<int64_t, std::vector<int>> Cells;
};

// One run of the filter: the stages of the class comment, in order.
class CurveRun
{
public:
  CurveRun(double s, double fitRadius, double step, double join, double minimumLength)
    : S(s)
    , R(fitRadius * s)
    , H(step * s)
    , J(join * s)
    , MinimumLength(minimumLength * s)
    , Hash(CollisionRadius * s)
  {
  }

  // Reads the cloud: all valid points, the feature points and the trace points among them.
  void SelectPoints(vtkPointSet* input, vtkDataArray* mask, vtkDataArray* types,
    vtkDataArray* normals, vtkDataArray* scores, double threshold, vtkDataArray* offsets);
  // Only the ridges of the score where the trace points are no line (a strip over close creases).
  void KeepRidges();
  // A fit radius that holds enough trace points where they are sparse (a one-point-wide mask).
  void AdaptFitRadius();
  // Line-likeness of each trace point's neighbourhood, and the seeding order.
  void OrderSeeds();
  // Stage 1: traces from every uncovered seed.
  void TraceAll();
  // Stage 2: corners, bridges and ends that point at a curve.
  void JoinEnds();
  // Stage 3: spurs and short pieces out, splits where a curve turns sharply.
  void RemoveSpurs();
  // Free branches and pieces made of points nobody voted for.
  void RemoveUnsupported();
  // Straight or short pieces on their own, off the borders, across which the cloud does not bend
  // (stray feature points on a smooth face).
  void RemoveFlatPieces();
  // Gaps in the feature points along a crease: two free ends that point at each other are
  // bridged where the cloud's cross-section shows the crease at every step between them.
  void BridgeAlongCreases();
  // Curves that go straight on through a junction are one curve; `through` gets, per chain end,
  // the chain on whose inner vertex it ends (-1: none).
  std::vector<Chain> MergeThrough(std::vector<Chain> chains,
    std::vector<std::array<int, 2>>& through) const;
  void SplitAtCorners();
  // A curve that runs along a border and then along a crease (a crease ending on a border that
  // goes on, traced round the junction) is two: split where the type of the feature points
  // around its vertices changes, each side for at least 2 CornerWindow s.
  void SplitAtTypeChanges();
  // Short curves between two junctions (a corner traced round as well as along its edges) are
  // collapsed into one corner.
  void CollapseShortLinks();
  // The curves of the graph.
  std::vector<Chain> ExtractChains() const;
  // Stage 4: vertices onto the cross-section's fit, smoothed, resampled.
  std::vector<std::vector<V3>> FitCurves(const std::vector<Chain>& chains);
  // The crease vertices of the fitted curves onto the median of the moved crease points around
  // them (where the input gives CreaseOffset).
  void OntoMovedPoints(const std::vector<Chain>& chains, std::vector<std::vector<V3>>& curves) const;

  double S, R, H, J, MinimumLength;
  double BandWidth = 0.0; // the trace points' RMS distance from their line fits (median)
  std::vector<V3> Points;           // all valid points
  std::vector<vtkIdType> PointIds;  // their input ids
  std::vector<V3> Normals;          // zero when the input has none
  std::vector<unsigned char> Type;  // FeatureType of the valid points (CONVEX when unknown)
  std::vector<unsigned char> Feature; // mask of the valid points
  std::vector<unsigned char> Supported; // per trace point: voted for, or on a border
  std::vector<double> Scores; // per feature point: the detector's score (KeepRidges)
  std::vector<V3> TracePoints;
  // Per trace point, its position moved by the detector's CreaseOffset (crease points, and
  // border points that carry one: a wall's rim; NaN elsewhere and where the input has no
  // offsets): where it is traced in a strip (KeepRidges).
  std::vector<V3> TraceMoved;
  // Per trace point (after KeepRidges): traced where it is moved to, in a strip of creases.
  std::vector<unsigned char> InStrip;
  // Half the median gap between lines of moved points side by side (0: none seen).
  double StripHalfGap = 0.0;
  // The fit `f` at a position x of a trace, on the trace points `ids`: where most of them lie in
  // a strip of lines side by side, refitted (twice) on those within StripHalfGap of the line
  // through x along the fit's direction (the trace's own line), `ids` cut to them; `own` tells
  // whether it was.
  LineFit OwnLine(const V3& x, const LineFit& f, std::vector<vtkIdType>& ids,
    bool* own = nullptr) const;
  // Per graph vertex of the traces: placed on its own line of a strip (OwnLine); the vertices
  // added after the traces have none.
  std::vector<unsigned char> StripVertex;
  bool IsStripVertex(int v) const
  {
    return v >= 0 && static_cast<size_t>(v) < this->StripVertex.size() && this->StripVertex[v];
  }
  // The crease points moved by the detector's CreaseOffset onto the line their voters agree on.
  std::vector<V3> Moved;
  PointSearch MovedSearch;
  std::vector<vtkIdType> TraceIndex; // index in Points of each trace point
  // Points at the position of a point already selected (exact copies, the same mask): input id
  // and the index in Points of that point. A copy adds no shape, and a stack of thousands made
  // every search around it return them all (the time grew with the square of the copies).
  std::vector<std::pair<vtkIdType, vtkIdType>> Copies;
  PointSearch AllSearch, TraceSearch;

private:
  vtkIdType FitCap(double radius) const; // the most points a fit within radius reads
  LineFit FitAt(const V3& x, std::vector<vtkIdType>& ids) const;
  void TraceFrom(vtkIdType seed, int trace);
  void Walk(int start, V3 x, V3 d, int trace, int sign);
  void Cover(const V3& x);
  int NearbyEnd(int v, int steps) const;
  // The direction a free end points in, from `reach` back along its curve.
  V3 EndDirection(int end, double reach, bool skipHook) const;
  std::vector<int> Components() const;
  // Whether direction t at x runs along the crease that the normals of the points around x
  // show (true where they show none: one face, or a corner).
  bool AlongNormals(const V3& x, const V3& t) const;
  // Whether the gap from a along t (length long) is a border's: both ends on one, and the
  // detector's border points along all of it.
  bool BorderAlong(const V3& a, const V3& t, double length) const;
  // Whether a trace point that the detector typed CORNER lies within CornerNear s of x (ids:
  // scratch).
  bool NearCorner(const V3& x, std::vector<vtkIdType>& ids) const;
  // Whether most of the trace points `ids` are border points.
  bool MostlyBorder(const std::vector<vtkIdType>& ids) const;
  // The crease direction c that the normals of the points around x show; false where they show
  // none.
  bool NormalsCrease(const V3& x, V3& c) const;
  // Whether two ends (at xa, xb, pointing along da, db) lie on two neighbouring curves: their
  // lines run side by side further apart than the band's width.
  bool SideBySide(const V3& xa, const V3& da, const V3& xb, const V3& db) const;
  V3 FitSection(const V3& x, const V3& t) const;
  // The slab of all points within `radius` FitRadius of x across the curve's tangent t and
  // halfLength along it, and the frame across it.
  void Section(const V3& x, const V3& t, double halfLength, std::vector<vtkIdType>& ids, V3& e1,
    V3& e2, double radius = SectionRadius) const;
  // The points `ids` in the cross-section's frame (x; e1, e2), appended to q; returns their sum.
  Eigen::Vector2d Project(const std::vector<vtkIdType>& ids, const V3& x, const V3& e1,
    const V3& e2, std::vector<Eigen::Vector2d>& q) const;
  // How the cross-section bends at x, over a slab halfLength either side along t: two faces
  // hinged at x (the line of the section's plane u, fitted unless `fixed`), the difference of
  // their slopes and its standard error.
  struct Bend
  {
    bool Valid = false;
    double Difference = 0.0, Error = 0.0, Angle = 0.0;
    // How much better the two faces fit than one quadratic face (an F statistic).
    double Kink = 0.0;
    // Each face's height is one line over its side: a quadratic there leaves no significantly
    // smaller residual (its F statistic at most CreaseSignificance^2).
    bool Planar = false;
  };
  // `radius`: the cross-section's, in FitRadius.
  Bend BendAt(const V3& x, const V3& t, double halfLength, Eigen::Vector2d& u, bool fixed,
    double radius = SectionRadius) const;
  // The crease in the cross-section (x itself when the points show none; `found` says which).
  V3 FitCrease(const V3& x, const V3& e1, const V3& e2, const std::vector<vtkIdType>& ids,
    bool* found = nullptr) const;
  V3 FitBorder(const V3& x, const V3& e1, const V3& e2, const std::vector<vtkIdType>& ids) const;
  // The same fits on points given in the cross-section's frame (and their normals there): the
  // crease's or the border's position p in that frame; false when the points show none.
  bool CreaseIn(const std::vector<Eigen::Vector2d>& section,
    const std::vector<Eigen::Vector2d>& sectionNormals, Eigen::Vector2d& p) const;
  bool BorderIn(const std::vector<Eigen::Vector2d>& section, Eigen::Vector2d& p) const;
  // The fit again at vertex k of a fitted curve c (arc lengths `arc`), over the points within
  // halfLength of it along the curve, each taken in the cross-section of the curve where it lies.
  V3 FitAlong(const std::vector<V3>& c, const std::vector<double>& arc, bool closed, int k,
    double halfLength) const;
  unsigned char LocalType(const V3& x) const;
  void RefitCorners(const std::vector<Chain>& chains, std::vector<std::vector<V3>>& curves) const;

  std::vector<vtkIdType> Seeds;
  std::vector<unsigned char> Covered;
  Graph G;
  VertexHash Hash;
  std::vector<int> TraceOf, ArcOf; // per graph vertex
  mutable std::vector<vtkIdType> Scratch;
};

void CurveRun::SelectPoints(vtkPointSet* input, vtkDataArray* mask, vtkDataArray* types,
  vtkDataArray* normals, vtkDataArray* scores, double threshold, vtkDataArray* offsets)
{
  const vtkIdType n = input->GetNumberOfPoints();
  // Selected positions and masks, by their bits, for the copies.
  struct PositionHash
  {
    size_t operator()(const std::array<uint64_t, 4>& k) const
    {
      return std::hash<uint64_t>()(k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^
        k[2] * 0x165667B19E3779F9ull ^ k[3]);
    }
  };
  std::unordered_map<std::array<uint64_t, 4>, vtkIdType, PositionHash> selected;
  // The first point of each position (its input id) and the copies of it.
  std::vector<vtkIdType> first;
  std::vector<V3> at;
  std::vector<std::pair<vtkIdType, vtkIdType>> copyOf; // input ids: copy, first point
  for (vtkIdType i = 0; i < n; ++i)
  {
    V3 x;
    input->GetPoint(i, x.data());
    if (!x.allFinite())
    {
      continue;
    }
    const bool feature = mask->GetTuple1(i) != 0.0;
    std::array<uint64_t, 4> key = { 0, 0, 0, feature ? 1u : 0u };
    for (int c = 0; c < 3; ++c)
    {
      const double v = x[c] == 0.0 ? 0.0 : x[c]; // -0 and 0 are one position
      std::memcpy(&key[c], &v, sizeof(double));
    }
    const auto found = selected.emplace(key, i);
    if (!found.second)
    {
      copyOf.emplace_back(i, found.first->second);
      continue;
    }
    first.push_back(i);
    at.push_back(x);
  }
  decltype(selected)().swap(selected);
  // Near copies (a scan merged with a copy of itself moved by a rounding): a point within a
  // hundredth of a spacing of an earlier position of the same mask is a copy of that position.
  std::vector<unsigned char> isCopy(first.size(), 0);
  std::unordered_map<vtkIdType, vtkIdType> nearOf; // input ids: near copy, first point
  {
    PointSearch search;
    search.Build(at);
    std::vector<vtkIdType> near;
    for (size_t p = 0; p < first.size(); ++p)
    {
      search.Within(at[p], 0.01 * this->S, near);
      const bool feature = mask->GetTuple1(first[p]) != 0.0;
      for (vtkIdType q : near) // ascending
      {
        if (static_cast<size_t>(q) < p && !isCopy[q] &&
          (mask->GetTuple1(first[q]) != 0.0) == feature)
        {
          isCopy[p] = 1;
          copyOf.emplace_back(first[p], first[q]);
          nearOf.emplace(first[p], first[q]);
          break;
        }
      }
    }
  }
  std::unordered_map<vtkIdType, vtkIdType> indexOf; // input id of a kept point -> its index
  for (size_t p = 0; p < first.size(); ++p)
  {
    if (isCopy[p])
    {
      continue;
    }
    const vtkIdType i = first[p];
    const V3& x = at[p];
    const bool feature = mask->GetTuple1(i) != 0.0;
    indexOf.emplace(i, static_cast<vtkIdType>(this->Points.size()));
    unsigned char type = feature ? CONVEX : NONE;
    if (feature && types)
    {
      const double t = types->GetTuple1(i);
      type = (t == CONCAVE || t == CORNER || t == BORDER) ? static_cast<unsigned char>(t) : CONVEX;
    }
    V3 normal = V3::Zero();
    if (normals)
    {
      normals->GetTuple(i, normal.data());
      if (!normal.allFinite())
      {
        normal.setZero();
      }
    }
    if (feature)
    {
      V3 moved = V3::Constant(std::numeric_limits<double>::quiet_NaN());
      if (offsets && (type == CONVEX || type == CONCAVE || type == BORDER))
      {
        V3 offset;
        offsets->GetTuple(i, offset.data());
        if (offset.allFinite() && offset.squaredNorm() > 0.0)
        {
          moved = x + offset;
          this->Moved.push_back(moved);
        }
      }
      // Without a score, every feature point supports a curve. A crease point that no fit voted
      // for (the detector's rule for points no fit explains at any scale) lies between features
      // as often as on one: it carries no trace, which would hop through such points from one
      // crease to the next across the face between them. Corners and borders carry traces.
      const double score = scores ? scores->GetTuple1(i) : threshold;
      const bool supported = type == BORDER || !(score < SupportShare * threshold);
      if (supported || type == CORNER)
      {
        this->TraceIndex.push_back(static_cast<vtkIdType>(this->Points.size()));
        this->TracePoints.push_back(x);
        this->TraceMoved.push_back(moved);
        this->Supported.push_back(supported);
        this->Scores.push_back(score);
      }
    }
    this->Points.push_back(x);
    this->PointIds.push_back(i);
    this->Normals.push_back(normal);
    this->Type.push_back(type);
    this->Feature.push_back(feature ? 1 : 0);
  }
  for (const auto& copy : copyOf)
  {
    // An exact copy of a near copy: a copy of the position that one is a copy of.
    auto kept = indexOf.find(copy.second);
    if (kept == indexOf.end())
    {
      kept = indexOf.find(nearOf.at(copy.second));
    }
    if (kept != indexOf.end())
    {
      this->Copies.emplace_back(copy.first, kept->second);
    }
  }
  this->AllSearch.Build(this->Points);
  this->TraceSearch.Build(this->TracePoints);
  this->MovedSearch.Build(this->Moved);
  if (scores)
  {
    this->KeepRidges();
  }
  this->Covered.assign(this->TracePoints.size(), 0);
}

vtkIdType CurveRun::FitCap(double radius) const
{
  // Four times the points of a whole disk of this radius sampled at the mean spacing: a band, a
  // corner's neighbourhood and a denser patch of a surface stay far below it.
  const double disk = 3.14159265358979323846 * (radius / this->S) * (radius / this->S);
  return static_cast<vtkIdType>(std::min(std::ceil(FitCapDisks * disk), 1e7));
}

LineFit CurveRun::OwnLine(
  const V3& x, const LineFit& f, std::vector<vtkIdType>& ids, bool* own) const
{
  if (own)
  {
    *own = false;
  }
  if (this->StripHalfGap <= 0.0 || f.Count < MinFitPoints || this->InStrip.empty())
  {
    return f;
  }
  size_t strip = 0;
  for (vtkIdType i : ids)
  {
    strip += this->InStrip[i];
  }
  if (2 * strip <= ids.size())
  {
    return f;
  }
  LineFit line = f;
  std::vector<vtkIdType> near;
  for (int round = 0; round < 2; ++round)
  {
    near.clear();
    for (vtkIdType i : ids)
    {
      const V3 r = this->TracePoints[i] - x;
      if ((r - r.dot(line.Direction) * line.Direction).norm() <= this->StripHalfGap)
      {
        near.push_back(i);
      }
    }
    if (static_cast<int>(near.size()) < MinFitPoints)
    {
      return f;
    }
    line = FitLine(this->TracePoints, near, x);
  }
  ids.swap(near);
  if (own)
  {
    *own = true;
  }
  return line;
}

LineFit CurveRun::FitAt(const V3& x, std::vector<vtkIdType>& ids) const
{
  this->TraceSearch.NearestWithin(x, this->R, this->FitCap(this->R), ids);
  return FitLine(this->TracePoints, ids, x);
}

void CurveRun::KeepRidges()
{
  // Where the trace points around a crease point are no line but the normals there show one
  // crease direction (a strip of feature points over two or more close parallel creases; not a
  // corner, where the normals spread in three dimensions), only the points on the ridges of the
  // detector's score are kept: those whose score reaches the median of the crease points within
  // RidgeRadius. Where the normals show one crease direction but the trace points moved by the
  // detector's CreaseOffset (onto the line their voters agree on) form no line, whether the
  // points themselves do or not, the neighbourhood holds creases side by side: the crease points
  // within FitRadius of such a point are traced where they are moved to, every one of them (the
  // moved points of a strip lie on its creases, not between them). Where the moved points form
  // one line, a strip is the wide band of one crease and keeps its ridges. Where they form two
  // lines side by side (TwoLinesSideBySide, over 1.5 FitRadius, further apart than
  // CollisionRadius, and so for a quarter of the trace points within FitRadius), the strip is
  // traced on the moved points too, each trace on its own line (OwnLine).
  const vtkIdType n = static_cast<vtkIdType>(this->TracePoints.size());
  std::vector<vtkIdType> ids, withMoved, wide;
  std::vector<double> around;
  std::vector<unsigned char> ridge(n, 1), parallel(n, 0);
  std::vector<double> gapOf(n, 0.0); // between the lines of moved points side by side
  std::vector<unsigned char> twoLines(n, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const unsigned char type = this->Type[this->TraceIndex[i]];
    if (type != CONVEX && type != CONCAVE && !(type == BORDER && this->TraceMoved[i].allFinite()))
    {
      continue;
    }
    const LineFit f = this->FitAt(this->TracePoints[i], ids);
    if (f.Count < MinFitPoints)
    {
      continue;
    }
    withMoved.clear();
    for (vtkIdType j : ids)
    {
      if (this->TraceMoved[j].allFinite())
      {
        withMoved.push_back(j);
      }
    }
    const LineFit moved = FitLine(this->TraceMoved, withMoved, this->TracePoints[i]);
    const bool movedNoLine = moved.Count >= MinFitPoints && moved.Flatness > MaxFlatness;
    // Moved points on two lines side by side closer than the fit radius (two creases a few
    // spacings apart, a rim face between its two edges) make one line of the fit's width.
    // Tested over the wider ball of the walk's second try (1.5 FitRadius): a line of moved
    // points holds about one per spacing.
    double gap = 0.0;
    bool movedTwoLines = false;
    if (moved.Count >= MinFitPoints && !movedNoLine)
    {
      this->TraceSearch.Within(this->TracePoints[i], 1.5 * this->R, wide);
      wide.erase(std::remove_if(wide.begin(), wide.end(),
                   [this](vtkIdType j) { return !this->TraceMoved[j].allFinite(); }),
        wide.end());
      const LineFit both = FitLine(this->TraceMoved, wide, this->TracePoints[i]);
      // Lines closer than CollisionRadius could not be traced apart (a trace joins a vertex of
      // another that close); the moved points of one crease split at any scale (a clean
      // crease's by 1e-8 s).
      movedTwoLines = both.Flatness <= MaxFlatness &&
        TwoLinesSideBySide(this->TraceMoved, wide, both, MinFitPoints, gap) &&
        gap > CollisionRadius * this->S;
    }
    const bool noLine = f.Flatness > MaxFlatness;
    // The normals' test (the costliest) only where either answer depends on it.
    V3 c;
    if ((!movedNoLine && !movedTwoLines && !noLine) ||
      !this->NormalsCrease(this->TracePoints[i], c))
    {
      continue;
    }
    parallel[i] = movedNoLine;
    if (movedTwoLines)
    {
      twoLines[i] = 1;
      gapOf[i] = gap;
    }
    if (!noLine || type == BORDER) // borders carry traces whatever their score
    {
      continue;
    }
    this->TraceSearch.Within(this->TracePoints[i], RidgeRadius * this->S, ids);
    around.clear();
    for (vtkIdType j : ids)
    {
      if (this->Type[this->TraceIndex[j]] != BORDER)
      {
        around.push_back(this->Scores[j]);
      }
    }
    if (around.empty())
    {
      continue;
    }
    const size_t middle = around.size() / 2;
    std::nth_element(around.begin(), around.begin() + middle, around.end());
    ridge[i] = !(this->Scores[i] < around[middle]);
  }
  // Lines side by side where MinFitPoints trace points within FitRadius (this one included) see
  // them: a strip runs along its lines, a lone split is noise (at a junction, a cut end).
  std::vector<double> gaps;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!twoLines[i])
    {
      continue;
    }
    this->TraceSearch.Within(this->TracePoints[i], this->R, ids);
    int seen = 0;
    for (vtkIdType j : ids)
    {
      seen += twoLines[j];
    }
    if (seen >= MinFitPoints && 4 * static_cast<size_t>(seen) >= ids.size())
    {
      parallel[i] = 1;
      gaps.push_back(gapOf[i]);
    }
  }
  // The crease points within FitRadius of a strip of parallel creases.
  std::vector<unsigned char> inStrip(n, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (parallel[i])
    {
      this->TraceSearch.Within(this->TracePoints[i], this->R, ids);
      for (vtkIdType j : ids)
      {
        inStrip[j] = this->TraceMoved[j].allFinite() ? 1 : 0;
      }
    }
  }
  std::vector<V3> points;
  std::vector<vtkIdType> index;
  std::vector<unsigned char> supported, strip;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!inStrip[i] && !ridge[i])
    {
      continue;
    }
    points.push_back(inStrip[i] ? this->TraceMoved[i] : this->TracePoints[i]);
    index.push_back(this->TraceIndex[i]);
    supported.push_back(this->Supported[i]);
    strip.push_back(inStrip[i]);
  }
  this->TracePoints.swap(points);
  this->TraceIndex.swap(index);
  this->Supported.swap(supported);
  this->InStrip.swap(strip);
  // A trace among lines side by side follows the points nearer to its own line than to the
  // next: within half the median gap between them.
  this->StripHalfGap = gaps.empty() ? 0.0 : 0.5 * featurepoints::UpperMedian(gaps);
  std::vector<V3>().swap(this->TraceMoved); // indexed as the trace points were
  this->TraceSearch.Build(this->TracePoints);
}

void CurveRun::AdaptFitRadius()
{
  // A fit needs MinFitPoints trace points and 2 ahead of the step; along a one-point-wide mask
  // on a random sampling there are about 0.5 per spacing, so that a ball of FitRadius s (4 s)
  // holds 4 on average and the traces stopped at every sparser stretch (a clean 10K cube with
  // --thin: traces along 4.6 of its 12 edge lengths). The radius grows to 1.5 times the median
  // distance from a trace point to its 4th nearest (2 per side along a row: 6 in the ball on
  // average); a band's trace points are denser, and keep FitRadius.
  const vtkIdType n = static_cast<vtkIdType>(this->TracePoints.size());
  std::vector<double> reach;
  const vtkIdType stride = std::max<vtkIdType>(1, n / 20000);
  for (vtkIdType i = 0; i < n; i += stride)
  {
    const double d = this->TraceSearch.KthDistance(this->TracePoints, i, MinFitPoints);
    if (d > 0.0)
    {
      reach.push_back(d);
    }
  }
  if (!reach.empty())
  {
    // At most MaximumFitRadiusGrowth times the given radius: trace points sparser than that are
    // not a curve sampled by the cloud (outliers scattered far from a part, whose median reach
    // would make the fits, and every length derived from them, as wide as the scatter).
    this->R = std::min(std::max(this->R, 1.5 * featurepoints::UpperMedian(reach)),
      MaximumFitRadiusGrowth * this->R);
  }
}

void CurveRun::OrderSeeds()
{
  const vtkIdType n = static_cast<vtkIdType>(this->TracePoints.size());
  std::vector<double> flatness(n, 1.0);
  std::vector<double> widths;
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const LineFit f = this->FitAt(this->TracePoints[i], ids);
    if (f.Count >= MinFitPoints)
    {
      flatness[i] = f.Flatness;
      if (f.Flatness <= MaxFlatness)
      {
        widths.push_back(f.Width);
      }
    }
  }
  // The band's width: the trace points' RMS distance from their line, over the line-like fits.
  if (!widths.empty())
  {
    const size_t middle = widths.size() / 2;
    std::nth_element(widths.begin(), widths.begin() + middle, widths.end());
    this->BandWidth = widths[middle];
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (flatness[i] <= MaxFlatness && this->Type[this->TraceIndex[i]] != CORNER)
    {
      this->Seeds.push_back(i);
    }
  }
  std::stable_sort(this->Seeds.begin(), this->Seeds.end(),
    [&](vtkIdType a, vtkIdType b) { return flatness[a] < flatness[b]; });
}

void CurveRun::Cover(const V3& x)
{
  this->TraceSearch.Within(x, CoverRadius * this->S, this->Scratch);
  for (vtkIdType i : this->Scratch)
  {
    this->Covered[i] = 1;
  }
}

void CurveRun::TraceAll()
{
  int trace = 0;
  for (vtkIdType seed : this->Seeds)
  {
    if (!this->Covered[seed])
    {
      this->TraceFrom(seed, trace++);
    }
  }
}

void CurveRun::TraceFrom(vtkIdType seed, int trace)
{
  this->Covered[seed] = 1;
  std::vector<vtkIdType> ids;
  V3 x = this->TracePoints[seed];
  LineFit f = this->FitAt(x, ids);
  bool own = false;
  f = this->OwnLine(x, f, ids, &own);
  for (int round = 0; round < 2 && f.Count >= MinFitPoints; ++round)
  {
    x = ProjectOnLine(x, f);
    f = this->FitAt(x, ids);
    f = this->OwnLine(x, f, ids, &own);
  }
  // A seed among stray feature points beside a crease would trace across it.
  if (f.Count < MinFitPoints || f.Flatness > MaxFlatness ||
    (!this->MostlyBorder(ids) && !this->AlongNormals(x, f.Direction)))
  {
    return;
  }
  x = ProjectOnLine(x, f);
  // Already traced: a vertex of another trace is near.
  if (this->Hash.Nearest(x, CollisionRadius * this->S, this->G.Vertices, [](int) { return true; }) >= 0)
  {
    return;
  }
  const int start = this->G.Add(x);
  this->StripVertex.resize(this->G.Vertices.size(), 0);
  this->StripVertex[start] = own;
  this->TraceOf.push_back(trace);
  this->ArcOf.push_back(0);
  this->Hash.Insert(start, x);
  this->Cover(x);
  this->Walk(start, x, f.Direction, trace, 1);
  this->Walk(start, x, -f.Direction, trace, -1);
}

void CurveRun::Walk(int start, V3 x, V3 d, int trace, int sign)
{
  // Vertices of the same trace closer than this along it are its own neighbourhood, not a loop.
  const int ownReach = static_cast<int>(std::ceil(2.0 * this->R / this->H)) + 2;
  std::vector<vtkIdType> ids;
  int previous = start;
  const size_t maxSteps = 4 * this->TracePoints.size() + 16;
  for (size_t step = 1; step <= maxSteps; ++step)
  {
    V3 y = x + this->H * d;
    // The fit at y; where the trace points are sparse or noisy, again over a wider ball.
    LineFit f;
    V3 t;
    bool found = false, border = false, own = false;
    for (const double radius : { this->R, 1.5 * this->R })
    {
      this->TraceSearch.Within(y, radius, ids);
      f = FitLine(this->TracePoints, ids, y);
      f = this->OwnLine(y, f, ids, &own);
      int ahead = 0;
      for (vtkIdType i : ids)
      {
        ahead += (this->TracePoints[i] - x).dot(d) > 0.5 * this->H;
      }
      t = f.Direction.dot(d) >= 0.0 ? f.Direction : V3(-f.Direction);
      border = this->MostlyBorder(ids);
      if (ahead >= 2 && f.Count >= MinFitPoints && f.Flatness <= MaxFlatness &&
        t.dot(d) >= MaxTurnPerStep && (border || this->AlongNormals(y, t)))
      {
        found = true;
        break;
      }
      if (ahead < 2 && radius == this->R && !own)
      {
        break; // an end: nothing ahead (on a strip's own line, try the wider ball first)
      }
    }
    // Stray feature points beside the crease (or a neighbouring crease's band) turned the fit:
    // again on the trace points near the line along the crease that the normals show.
    V3 c;
    if (!found && !border && this->BandWidth > 0.0 && this->NormalsCrease(y, c) &&
      std::abs(c.dot(d)) >= MaxTurnPerStep)
    {
      c = c.dot(d) >= 0.0 ? c : V3(-c);
      this->TraceSearch.Within(y, this->R, ids);
      std::vector<vtkIdType> tube;
      int ahead = 0;
      for (vtkIdType i : ids)
      {
        const V3 r = this->TracePoints[i] - y;
        if ((r - r.dot(c) * c).norm() <= SideBySideWidths * this->BandWidth)
        {
          tube.push_back(i);
          ahead += (this->TracePoints[i] - x).dot(d) > 0.5 * this->H;
        }
      }
      f = FitLine(this->TracePoints, tube, y);
      own = false;
      t = f.Direction.dot(d) >= 0.0 ? f.Direction : V3(-f.Direction);
      found = ahead >= 2 && f.Count >= MinFitPoints && f.Flatness <= MaxFlatness &&
        t.dot(d) >= MaxTurnPerStep && std::abs(t.dot(c)) >= AcrossNormals;
    }
    if (!found)
    {
      return;
    }
    y = ProjectOnLine(y, f);
    if ((y - x).norm() < 0.25 * this->H)
    {
      return; // stalled
    }
    const int arc = sign * static_cast<int>(step);
    const int hit = this->Hash.Nearest(y, CollisionRadius * this->S, this->G.Vertices,
      [&](int v) { return this->TraceOf[v] != trace || std::abs(this->ArcOf[v] - arc) > ownReach; });
    if (hit >= 0)
    {
      this->G.Link(previous, this->NearbyEnd(hit, ownReach / 2));
      return;
    }
    const int v = this->G.Add(y);
    this->StripVertex.resize(this->G.Vertices.size(), 0);
    this->StripVertex[v] = own;
    this->TraceOf.push_back(trace);
    this->ArcOf.push_back(arc);
    this->Hash.Insert(v, y);
    this->G.Link(previous, v);
    this->Cover(y);
    previous = v;
    x = y;
    d = t;
  }
}

int CurveRun::NearbyEnd(int v, int steps) const
{
  // Breadth-first along the curves: the nearest free end within `steps` edges, else v itself.
  std::vector<std::pair<int, int>> queue{ { v, 0 } };
  std::set<int> seen{ v };
  for (size_t k = 0; k < queue.size(); ++k)
  {
    const int a = queue[k].first;
    if (this->G.Degree(a) == 1)
    {
      return a;
    }
    if (queue[k].second >= steps)
    {
      continue;
    }
    for (int b : this->G.Adjacent[a])
    {
      if (seen.insert(b).second)
      {
        queue.emplace_back(b, queue[k].second + 1);
      }
    }
  }
  return v;
}

std::vector<Chain> CurveRun::ExtractChains() const
{
  std::vector<Chain> chains;
  const int n = static_cast<int>(this->G.Vertices.size());
  std::set<std::pair<int, int>> used;
  auto edge = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  auto walk = [&](int from, int next, Chain& chain) {
    chain.Ids = { from };
    int previous = from, current = next;
    used.insert(edge(from, next));
    while (true)
    {
      chain.Ids.push_back(current);
      if (this->G.IsEnd(current) || current == from)
      {
        break;
      }
      const auto& a = this->G.Adjacent[current];
      const int following = a[0] == previous ? a[1] : a[0];
      used.insert(edge(current, following));
      previous = current;
      current = following;
    }
    // A loop through a corner is a curve from the corner back to it, not a closed curve.
    chain.Closed = chain.Ids.front() == chain.Ids.back() && !this->G.IsEnd(from);
  };
  for (int v = 0; v < n; ++v)
  {
    if (!this->G.IsEnd(v) || this->G.Degree(v) == 0)
    {
      continue;
    }
    for (int w : this->G.Adjacent[v])
    {
      if (!used.count(edge(v, w)))
      {
        Chain chain;
        walk(v, w, chain);
        chains.push_back(chain);
      }
    }
  }
  // Loops without an end.
  for (int v = 0; v < n; ++v)
  {
    if (this->G.Degree(v) == 2 && !used.count(edge(v, this->G.Adjacent[v][0])))
    {
      Chain chain;
      walk(v, this->G.Adjacent[v][0], chain);
      chains.push_back(chain);
    }
  }
  return chains;
}

double ChainLength(const Chain& chain, const std::vector<V3>& vertices)
{
  double length = 0.0;
  for (size_t k = 1; k < chain.Ids.size(); ++k)
  {
    length += (vertices[chain.Ids[k]] - vertices[chain.Ids[k - 1]]).norm();
  }
  return length;
}

void CurveRun::RemoveSpurs()
{
  for (int round = 0; round < 4; ++round)
  {
    bool changed = false;
    for (const Chain& chain : this->ExtractChains())
    {
      if (ChainLength(chain, this->G.Vertices) >= this->MinimumLength)
      {
        continue;
      }
      const bool freeStart = this->G.Degree(chain.Ids.front()) == 1;
      const bool freeEnd = this->G.Degree(chain.Ids.back()) == 1;
      // A short piece on its own, a short loop, or a short branch that ends freely.
      if (chain.Closed || freeStart || freeEnd)
      {
        for (size_t k = 1; k < chain.Ids.size(); ++k)
        {
          this->G.Unlink(chain.Ids[k - 1], chain.Ids[k]);
        }
        changed = true;
      }
    }
    // A vertex left with two curves is no longer a junction (unless a corner).
    if (!changed)
    {
      return;
    }
  }
}

void CurveRun::RemoveUnsupported()
{
  std::vector<vtkIdType> ids;
  for (const Chain& chain : this->ExtractChains())
  {
    // A curve between two junctions is not a branch: its points may lack votes where two
    // creases run close together.
    const bool freeStart = this->G.Degree(chain.Ids.front()) == 1;
    const bool freeEnd = this->G.Degree(chain.Ids.back()) == 1;
    if ((!chain.Closed && !freeStart && !freeEnd) ||
      ChainLength(chain, this->G.Vertices) >= 2.0 * this->R)
    {
      continue;
    }
    // A piece on its own no longer than one line fit's window: nothing the fits resolve.
    if (freeStart && freeEnd)
    {
      for (size_t k = 1; k < chain.Ids.size(); ++k)
      {
        this->G.Unlink(chain.Ids[k - 1], chain.Ids[k]);
      }
      continue;
    }
    // The feature points along the chain, each once.
    std::set<vtkIdType> near;
    for (int v : chain.Ids)
    {
      this->TraceSearch.Within(this->G.Vertices[v], CollisionRadius * this->S, ids);
      near.insert(ids.begin(), ids.end());
    }
    size_t supported = 0;
    for (vtkIdType i : near)
    {
      supported += this->Supported[i];
    }
    if (static_cast<double>(supported) >= MinimumSupport * static_cast<double>(near.size()))
    {
      continue;
    }
    for (size_t k = 1; k < chain.Ids.size(); ++k)
    {
      this->G.Unlink(chain.Ids[k - 1], chain.Ids[k]);
    }
  }
}

void CurveRun::RemoveFlatPieces()
{
  std::vector<vtkIdType> ids;
  for (const Chain& chain : this->ExtractChains())
  {
    const int first = chain.Ids.front(), last = chain.Ids.back();
    auto freeEnd = [&](int v) { return this->G.Degree(v) == 1 && !this->G.Node[v]; };
    if (chain.Closed || (!freeEnd(first) && !freeEnd(last)))
    {
      continue;
    }
    // A straight piece on its own or a straight branch from a junction (every vertex within one
    // spacing of its chord), on a crease; or one no longer along its path than the slab across
    // its chord (2 FitRadius), whatever its wiggle: the slab holds it whole (a spur of a clump
    // of stray points on a smooth face, 4.6 s between its ends).
    const V3 a = this->G.Vertices[first];
    const V3 chord = this->G.Vertices[last] - a;
    const double length = chord.norm();
    if (!(length > 0.0))
    {
      continue;
    }
    const V3 t = chord / length;
    bool straight = true;
    std::set<vtkIdType> near;
    for (int v : chain.Ids)
    {
      const V3 r = this->G.Vertices[v] - a;
      straight = straight && (r - r.dot(t) * t).norm() <= this->S;
      this->TraceSearch.Within(this->G.Vertices[v], CollisionRadius * this->S, ids);
      near.insert(ids.begin(), ids.end());
    }
    double path = 0.0;
    for (size_t k = 1; k < chain.Ids.size(); ++k)
    {
      path += (this->G.Vertices[chain.Ids[k]] - this->G.Vertices[chain.Ids[k - 1]]).norm();
    }
    straight = straight || path <= 2.0 * this->R; // short: the slab below covers it
    if (!straight || this->MostlyBorder(std::vector<vtkIdType>(near.begin(), near.end())))
    {
      continue;
    }
    // The cloud across it, as for a bridge: a crease bends by a crease's angle, significantly.
    Eigen::Vector2d u;
    const Bend whole = this->BendAt(a + 0.5 * chord, t, 0.5 * length + this->R, u, false);
    if (!whole.Valid ||
      (whole.Angle >= std::asin(MinimumCreaseAngle) &&
        std::abs(whole.Difference) > CreaseSignificance * whole.Error &&
        whole.Kink > KinkAIC))
    {
      continue;
    }
    for (size_t k = 1; k < chain.Ids.size(); ++k)
    {
      this->G.Unlink(chain.Ids[k - 1], chain.Ids[k]);
    }
  }
}

std::vector<Chain> CurveRun::MergeThrough(
  std::vector<Chain> chains, std::vector<std::array<int, 2>>& through) const
{
  // The outward direction of a chain at one of its ends, over 2 FitRadius: a join's hook at the
  // very end does not turn the curve.
  const int w = std::max(1, static_cast<int>(std::lround(2.0 * this->R / this->H)));
  auto outward = [&](const Chain& chain, bool atStart) {
    const int count = static_cast<int>(chain.Ids.size());
    const int k = std::min(w, count - 1);
    const int j = k / 4; // the last quarter aside: where a join or a corner placed the end
    const V3& end = this->G.Vertices[atStart ? chain.Ids[j] : chain.Ids[count - 1 - j]];
    const V3& back = this->G.Vertices[atStart ? chain.Ids[k] : chain.Ids[count - 1 - k]];
    const V3 d = end - back;
    return d.norm() > 0.0 ? V3(d.normalized()) : V3(V3::Zero());
  };
  std::vector<unsigned char> alive(chains.size(), 1);
  for (bool changed = true; changed;)
  {
    changed = false;
    // Chain ends at each vertex where two or more curves meet (corners too: the straightness test
    // leaves true corners alone).
    std::map<int, std::vector<std::pair<size_t, bool>>> atJunction;
    for (size_t c = 0; c < chains.size(); ++c)
    {
      if (!alive[c] || chains[c].Closed)
      {
        continue;
      }
      for (const bool atStart : { true, false })
      {
        const int v = atStart ? chains[c].Ids.front() : chains[c].Ids.back();
        if (this->G.Degree(v) >= 2)
        {
          atJunction[v].emplace_back(c, atStart);
        }
      }
    }
    // Each chain merged at most once a pass (its ends move); the next pass takes the rest.
    std::vector<unsigned char> touched(chains.size(), 0);
    for (const auto& entry : atJunction)
    {
      const auto& ends = entry.second;
      bool stale = false;
      for (const auto& end : ends)
      {
        stale = stale || touched[end.first];
      }
      if (stale)
      {
        changed = true;
        continue;
      }
      // The most nearly opposite pair, if straight enough.
      double best = ThroughCone;
      size_t a = 0, b = 0;
      for (size_t i = 0; i < ends.size(); ++i)
      {
        for (size_t j = i + 1; j < ends.size(); ++j)
        {
          const double d = outward(chains[ends[i].first], ends[i].second)
                             .dot(outward(chains[ends[j].first], ends[j].second));
          if (d < best)
          {
            best = d;
            a = i;
            b = j;
          }
        }
      }
      if (best >= ThroughCone)
      {
        continue;
      }
      const size_t ca = ends[a].first, cb = ends[b].first;
      if (ca == cb)
      {
        chains[ca].Closed = true; // the curve comes round to itself
        touched[ca] = 1;
        changed = true;
        continue;
      }
      // chains[ca] ending at the junction, then chains[cb] from it.
      std::vector<int> first = chains[ca].Ids, second = chains[cb].Ids;
      if (ends[a].second)
      {
        std::reverse(first.begin(), first.end());
      }
      if (!ends[b].second)
      {
        std::reverse(second.begin(), second.end());
      }
      first.insert(first.end(), second.begin() + 1, second.end());
      chains[ca].Ids = first;
      chains[ca].Closed = false;
      alive[cb] = 0;
      touched[ca] = touched[cb] = 1;
      changed = true;
    }
  }
  std::vector<Chain> merged;
  for (size_t c = 0; c < chains.size(); ++c)
  {
    if (alive[c])
    {
      merged.push_back(chains[c]);
    }
  }
  // The chains that end on a merged curve's inner vertex: which curve, which end.
  std::map<int, int> passesThrough; // vertex -> chain
  for (size_t c = 0; c < merged.size(); ++c)
  {
    const size_t count = merged[c].Ids.size();
    for (size_t k = 1; k + 1 < count; ++k)
    {
      passesThrough.emplace(merged[c].Ids[k], static_cast<int>(c));
    }
  }
  through.assign(merged.size(), { -1, -1 });
  for (size_t c = 0; c < merged.size(); ++c)
  {
    if (merged[c].Closed)
    {
      continue;
    }
    for (int e = 0; e < 2; ++e)
    {
      const auto found = passesThrough.find(e == 0 ? merged[c].Ids.front() : merged[c].Ids.back());
      if (found != passesThrough.end() && found->second != static_cast<int>(c))
      {
        through[c][e] = found->second;
      }
    }
  }
  return merged;
}

void CurveRun::BridgeAlongCreases()
{
  // Each free end and the direction it points in, over 2 FitRadius back along its curve (the
  // last quarter aside, as in MergeThrough): the line the gap continues; and the vertex where
  // that direction starts (its anchor).
  const int w = std::max(1, static_cast<int>(std::lround(2.0 * this->R / this->H)));
  const int n = static_cast<int>(this->G.Vertices.size());
  std::vector<int> ends;
  std::vector<V3> directions, anchors;
  for (int v = 0; v < n; ++v)
  {
    if (this->G.Degree(v) != 1)
    {
      continue;
    }
    std::vector<int> path{ v };
    for (int previous = -1, current = v; static_cast<int>(path.size()) <= w;)
    {
      const auto& a = this->G.Adjacent[current];
      const int next = a[0] != previous ? a[0] : (a.size() > 1 ? a[1] : -1);
      if (next < 0 || next == v)
      {
        break;
      }
      path.push_back(next);
      if (this->G.Degree(next) != 2)
      {
        break;
      }
      previous = current;
      current = next;
    }
    const int k = static_cast<int>(path.size()) - 1;
    if (k < 4)
    {
      continue;
    }
    const V3 d = this->G.Vertices[path[k / 4]] - this->G.Vertices[path[k]];
    if (d.norm() > 0.0)
    {
      ends.push_back(v);
      directions.push_back(d.normalized());
      anchors.push_back(this->G.Vertices[path[k / 4]]);
    }
  }
  // Pairs that point at each other, nearest first; each end bridged once. An end proposes its
  // BridgeProposals nearest facing ends only (on the benchmarks' parts no farther bridge was
  // taken): testing every pair along a curve broken into many pieces took the cube of their
  // number (each test reads the points along its gap).
  struct Gap
  {
    double Length;
    size_t A, B;
  };
  std::vector<Gap> gaps;
  for (size_t a = 0; a < ends.size(); ++a)
  {
    for (size_t b = a + 1; b < ends.size(); ++b)
    {
      const V3 ab = this->G.Vertices[ends[b]] - this->G.Vertices[ends[a]];
      const double length = ab.norm();
      // Facing from the ends, or from where their directions were taken: a trace's last
      // vertices hook towards the side of the band where its points run out, and the two
      // pieces of one crease across a hole in the sampling may hook apart.
      const double facing = std::min(ab.dot(directions[a]), -ab.dot(directions[b]));
      const V3 anchored = anchors[b] - anchors[a];
      const double span = anchored.norm();
      const double anchoredFacing =
        std::min(anchored.dot(directions[a]), -anchored.dot(directions[b]));
      if (length > 0.0 &&
        (facing >= BridgeCone * length || (span > 0.0 && anchoredFacing >= BridgeCone * span)))
      {
        gaps.push_back({ length, a, b });
      }
    }
  }
  std::sort(gaps.begin(), gaps.end(), [](const Gap& x, const Gap& y) {
    return x.Length < y.Length || (x.Length == y.Length && (x.A < y.A || (x.A == y.A && x.B < y.B)));
  });
  std::vector<int> rank(ends.size(), 0);
  size_t proposed = 0;
  for (const Gap& gap : gaps)
  {
    if (rank[gap.A] < BridgeProposals || rank[gap.B] < BridgeProposals)
    {
      gaps[proposed++] = gap;
    }
    ++rank[gap.A];
    ++rank[gap.B];
  }
  gaps.resize(proposed);
  std::vector<unsigned char> used(ends.size(), 0);
  std::vector<vtkIdType> ids;
  for (const Gap& gap : gaps)
  {
    if (used[gap.A] || used[gap.B])
    {
      continue;
    }
    const V3 a = this->G.Vertices[ends[gap.A]];
    const V3 t = (this->G.Vertices[ends[gap.B]] - a) / gap.Length;
    // The gap's line is a crease when the cloud bends across it: over the whole gap, two faces
    // hinged on the line whose slopes differ significantly and by a crease's angle (within 3
    // errors); and in every
    // stretch of 2 FitRadius along it, no sign of a flat stretch: a bend nearer to none than to
    // the whole gap's and apart from the latter by more than its own error allows.
    const int steps = static_cast<int>(std::ceil(gap.Length / this->H));
    const V3 middle = a + 0.5 * gap.Length * t;
    Eigen::Vector2d u;
    const Bend whole = this->BendAt(middle, t, 0.5 * gap.Length + this->R, u, false);
    // The angle only as closely as the points tell it (the slopes' error bounds the angle's):
    // a gap is where the detector found too little of the crease, and there the noise may well
    // have made it look shallower, as it did to the detector (15 degrees measured as 8 over a
    // 36 s gap on Model II at 200,000 points, 4 of its errors off).
    auto creaseAngle = [](const Bend& bend) {
      return bend.Valid &&
        bend.Angle + CreaseSignificance * bend.Error >= std::asin(MinimumCreaseAngle) &&
        std::abs(bend.Difference) > CreaseSignificance * bend.Error;
    };
    bool crease = creaseAngle(whole);
    if (!crease && whole.Valid) // the windows below read its plane and its bend
    {
      // A shallow crease under noise, over a short gap, bends less than 3 errors of the section
      // at 1.5 FitRadius (15 degrees on Model II at 200,000 points over 20 s: 2.9 errors): the
      // section twice as wide, where each face stays one plane across it, tells the bend with
      // a third of the error.
      Eigen::Vector2d wideU;
      const Bend wide =
        this->BendAt(middle, t, 0.5 * gap.Length + this->R, wideU, false, WideSectionRadius);
      crease = wide.Planar && creaseAngle(wide);
    }
    const int tests = static_cast<int>(std::ceil(gap.Length / this->R));
    // One flat-looking window among many is what the noise gives: the significance of each of
    // the tests + 1 windows is raised so that all of them together mistake a crease for flat as
    // rarely as one test at CreaseSignificance (a Gaussian tail divided by m adds 2 ln m to z^2).
    const double significance =
      std::sqrt(CreaseSignificance * CreaseSignificance + 2.0 * std::log(tests + 1.0));
    for (int k = 0; crease && k <= tests; ++k)
    {
      const V3 x = a + (gap.Length * k / tests) * t;
      const Bend local = this->BendAt(x, t, this->R, u, true);
      const double offCrease = std::abs(local.Difference - whole.Difference);
      crease = local.Valid &&
        !(offCrease > std::abs(local.Difference) && offCrease > significance * local.Error);
    }
    const bool border = !crease && this->BorderAlong(a, t, gap.Length);
    std::vector<V3> bridge;
    for (int k = 1; k < steps; ++k)
    {
      bridge.push_back(a + (gap.Length * k / steps) * t);
    }
    if (!crease && !border)
    {
      continue;
    }
    int previous = ends[gap.A];
    for (const V3& x : bridge)
    {
      const int v = this->G.Add(x);
      this->G.Link(previous, v);
      previous = v;
    }
    this->G.Link(previous, ends[gap.B]);
    used[gap.A] = used[gap.B] = 1;
  }
}

bool CurveRun::BorderAlong(const V3& a, const V3& t, double length) const
{
  // Both ends on a border, and the cloud ends at the gap's line all along it: at every FitRadius
  // along it, the points within 2 FitRadius lie on one side of the line in their tangent plane,
  // the same side throughout, none beyond it by more than FitRadius (the border's band and the
  // trace's place in it). A sampling that recedes from the edge leaves the detector's
  // empty-sector test without border points there; a surface that goes on has points far out on
  // both sides.
  if (this->LocalType(a) != BORDER || this->LocalType(a + length * t) != BORDER)
  {
    return false;
  }
  const double beyond = this->R;
  const int tests = static_cast<int>(std::ceil(length / this->R));
  V3 empty = V3::Zero(); // the direction across the line in which no point lies
  for (int k = 0; k <= tests; ++k)
  {
    const V3 x = a + (length * k / tests) * t;
    this->AllSearch.Within(x, 2.0 * this->R, this->Scratch);
    if (this->Scratch.size() < 10)
    {
      return false;
    }
    V3 mean = V3::Zero();
    for (vtkIdType i : this->Scratch)
    {
      mean += this->Points[i];
    }
    mean /= static_cast<double>(this->Scratch.size());
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    for (vtkIdType i : this->Scratch)
    {
      const V3 r = this->Points[i] - mean;
      c += r * r.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(c);
    const V3 across = solver.eigenvectors().col(0).cross(t);
    if (!(across.norm() > 0.5))
    {
      return false; // the line runs across the surface, not along it
    }
    const V3 u = across.normalized();
    int plus = 0, minus = 0;
    for (vtkIdType i : this->Scratch)
    {
      const double offset = (this->Points[i] - x).dot(u);
      plus += offset > beyond ? 1 : 0;
      minus += offset < -beyond ? 1 : 0;
    }
    if ((plus == 0) == (minus == 0))
    {
      return false; // points far out on both sides (the surface goes on), or on neither
    }
    const V3 side = plus == 0 ? u : V3(-u);
    if (k > 0 && side.dot(empty) <= 0.0)
    {
      return false;
    }
    empty = side;
  }
  return true;
}

V3 CurveRun::EndDirection(int end, double reach, bool skipHook) const
{
  // Back along the curve `reach` (not past a junction or a corner), then the direction towards
  // the end; with skipHook, the last quarter of that stretch aside: a trace's last vertices hook
  // towards the side of the band where its points run out.
  std::vector<int> path{ end };
  int previous = end, current = this->G.Adjacent[end][0];
  path.push_back(current);
  const int steps = std::max(1, static_cast<int>(std::lround(reach / this->H)));
  for (int k = 1; k < steps && this->G.Degree(current) == 2 && !this->G.Node[current]; ++k)
  {
    const auto& a = this->G.Adjacent[current];
    const int following = a[0] == previous ? a[1] : a[0];
    if (following == end)
    {
      break;
    }
    previous = current;
    current = following;
    path.push_back(current);
  }
  const int k = static_cast<int>(path.size()) - 1;
  const V3 d = this->G.Vertices[path[skipHook ? k / 4 : 0]] - this->G.Vertices[path[k]];
  return d.norm() > 0.0 ? V3(d.normalized()) : V3(V3::Zero());
}

bool CurveRun::NormalsCrease(const V3& x, V3& c) const
{
  // Around a crease the normals lie in the plane across it: the direction in which they vary
  // least is the crease's.
  this->AllSearch.NearestWithin(x, this->R, this->FitCap(this->R), this->Scratch);
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  int count = 0;
  for (vtkIdType i : this->Scratch)
  {
    const V3& n = this->Normals[i];
    if (n.squaredNorm() > 0.0)
    {
      m += n.normalized() * n.normalized().transpose();
      ++count;
    }
  }
  if (count < 10)
  {
    return false;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m / count);
  const V3 values = solver.eigenvalues();
  if (!(values[1] > 0.0) || values[0] > NormalPlaneRatio * values[1])
  {
    return false;
  }
  c = solver.eigenvectors().col(0);
  return true;
}

bool CurveRun::MostlyBorder(const std::vector<vtkIdType>& ids) const
{
  size_t border = 0;
  for (vtkIdType i : ids)
  {
    border += this->Type[this->TraceIndex[i]] == BORDER;
  }
  return 2 * border > ids.size();
}

bool CurveRun::AlongNormals(const V3& x, const V3& t) const
{
  V3 c;
  return !this->NormalsCrease(x, c) || std::abs(t.dot(c)) >= AcrossNormals;
}

bool CurveRun::SideBySide(const V3& xa, const V3& da, const V3& xb, const V3& db) const
{
  if (std::abs(da.dot(db)) < BridgeCone)
  {
    return false;
  }
  // The distance between the two lines, across their mean direction.
  const V3 mean = da.dot(db) >= 0.0 ? V3(da + db) : V3(da - db);
  if (!(mean.norm() > 0.0))
  {
    return false;
  }
  const V3 m = mean.normalized();
  const V3 ab = xb - xa;
  return (ab - ab.dot(m) * m).norm() > SideBySideWidths * this->BandWidth;
}

std::vector<int> CurveRun::Components() const
{
  const int n = static_cast<int>(this->G.Vertices.size());
  std::vector<int> component(n, -1);
  int count = 0;
  for (int v = 0; v < n; ++v)
  {
    if (component[v] >= 0)
    {
      continue;
    }
    std::vector<int> stack{ v };
    component[v] = count;
    while (!stack.empty())
    {
      const int a = stack.back();
      stack.pop_back();
      for (int b : this->G.Adjacent[a])
      {
        if (component[b] < 0)
        {
          component[b] = count;
          stack.push_back(b);
        }
      }
    }
    ++count;
  }
  return component;
}

void CurveRun::JoinEnds()
{
  const int n = static_cast<int>(this->G.Vertices.size());
  // Each free end's direction just behind it (where a corner's edges meet), and along its curve
  // over 2 FitRadius, the hook at the end aside (whether two ends continue one line).
  std::vector<int> ends;
  std::vector<V3> directions, lineDirections;
  for (int v = 0; v < n; ++v)
  {
    if (this->G.Degree(v) == 1)
    {
      const V3 d = this->EndDirection(v, CornerWindow * this->S, false);
      const V3 line = this->EndDirection(v, 2.0 * this->R, true);
      if (d.squaredNorm() > 0.0 && line.squaredNorm() > 0.0)
      {
        ends.push_back(v);
        directions.push_back(d);
        lineDirections.push_back(line);
      }
    }
  }
  const std::vector<int> component = this->Components();
  std::vector<int> componentSize(n, 0);
  for (int v = 0; v < n; ++v)
  {
    componentSize[component[v]] += this->G.Degree(v) > 0;
  }
  // Pairs of ends near each other, facing each other's side, nearest first.
  const size_t m = ends.size();
  std::vector<unsigned char> borderEnd(m, 0);
  for (size_t a = 0; a < m; ++a)
  {
    borderEnd[a] = this->LocalType(this->G.Vertices[ends[a]]) == BORDER;
  }
  struct Pair
  {
    double Distance;
    size_t A, B;
    bool Facing;
  };
  std::vector<Pair> pairs;
  for (size_t a = 0; a < m; ++a)
  {
    for (size_t b = a + 1; b < m; ++b)
    {
      const V3 ab = this->G.Vertices[ends[b]] - this->G.Vertices[ends[a]];
      const double distance = ab.norm();
      // Two ends that face each other along one line (within BridgeCone, the hooks aside) are
      // bridged from twice as far.
      const bool facing = ab.dot(lineDirections[a]) >= BridgeCone * distance &&
        -ab.dot(lineDirections[b]) >= BridgeCone * distance;
      if (distance > (facing ? 2.0 : 1.0) * this->J ||
        (!facing && (ab.dot(directions[a]) < 0.0 || -ab.dot(directions[b]) < 0.0)))
      {
        continue;
      }
      if (!borderEnd[a] && !borderEnd[b] &&
        this->SideBySide(this->G.Vertices[ends[a]], lineDirections[a], this->G.Vertices[ends[b]],
          lineDirections[b]))
      {
        continue;
      }
      // The two ends of one short piece are not a corner.
      if (component[ends[a]] == component[ends[b]] &&
        componentSize[component[ends[a]]] * this->H < 4.0 * this->J)
      {
        continue;
      }
      pairs.push_back({ distance, a, b, facing });
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return x.Distance < y.Distance ||
      (x.Distance == y.Distance && (x.A < y.A || (x.A == y.A && x.B < y.B)));
  });
  // Clusters by complete linkage: two clusters meet only when all their ends lie within
  // JoinDistance of each other (a bridge between two facing ends aside), so that a chain of
  // near pairs along a row of ends does not make one junction of them all.
  std::vector<int> cluster(m, -1);
  std::vector<std::vector<size_t>> clusters;
  for (const Pair& pair : pairs)
  {
    const int ca = cluster[pair.A], cb = cluster[pair.B];
    if (ca >= 0 && ca == cb)
    {
      continue;
    }
    const std::vector<size_t> one{ pair.A }, other{ pair.B };
    const std::vector<size_t>& first = ca >= 0 ? clusters[ca] : one;
    const std::vector<size_t>& second = cb >= 0 ? clusters[cb] : other;
    bool compact = true;
    for (size_t x : first)
    {
      for (size_t y : second)
      {
        compact = compact &&
          (this->G.Vertices[ends[x]] - this->G.Vertices[ends[y]]).norm() <= this->J;
      }
    }
    const bool bridge = pair.Facing && ca < 0 && cb < 0;
    if (!compact && !bridge)
    {
      continue;
    }
    if (ca < 0 && cb < 0)
    {
      cluster[pair.A] = cluster[pair.B] = static_cast<int>(clusters.size());
      clusters.push_back({ pair.A, pair.B });
    }
    else if (ca < 0 || cb < 0)
    {
      const int c = ca >= 0 ? ca : cb;
      const size_t added = ca >= 0 ? pair.B : pair.A;
      cluster[added] = c;
      clusters[c].push_back(added);
    }
    else
    {
      for (size_t x : clusters[cb])
      {
        cluster[x] = ca;
        clusters[ca].push_back(x);
      }
      clusters[cb].clear();
    }
  }
  std::vector<unsigned char> paired(m, 0);
  for (const std::vector<size_t>& members : clusters)
  {
    if (members.empty())
    {
      continue;
    }
    for (size_t a : members)
    {
      paired[a] = 1;
    }
    std::vector<V3> points, lines;
    for (size_t a : members)
    {
      points.push_back(this->G.Vertices[ends[a]]);
      lines.push_back(directions[a]);
    }
    if (members.size() == 2 &&
      lineDirections[members[0]].dot(lineDirections[members[1]]) < -BridgeCone)
    {
      this->G.Link(ends[members[0]], ends[members[1]]); // a gap along one curve
      continue;
    }
    V3 corner;
    bool valid = NearestToLines(points, lines, corner);
    for (size_t k = 0; valid && k < points.size(); ++k)
    {
      valid = (corner - points[k]).norm() <= this->J && (corner - points[k]).dot(lines[k]) > -this->H;
    }
    // A corner with no feature point within CornerSupport s lies beyond what the points show:
    // ends that hook the same way (two pieces of one border where its points thin out) put the
    // point nearest to their lines outside the band.
    if (valid)
    {
      this->TraceSearch.Within(corner, CornerSupport * this->S, this->Scratch);
      valid = !this->Scratch.empty();
    }
    if (!valid)
    {
      corner = V3::Zero();
      for (const V3& p : points)
      {
        corner += p;
      }
      corner /= static_cast<double>(points.size());
    }
    const int c = this->G.Add(corner, true);
    for (size_t a : members)
    {
      this->G.Link(ends[a], c);
    }
  }
  // Single ends that point at a curve nearby join it.
  PointSearch vertices;
  vertices.Build(this->G.Vertices);
  std::vector<vtkIdType> near;
  for (size_t a = 0; a < m; ++a)
  {
    if (paired[a])
    {
      continue;
    }
    const V3& x = this->G.Vertices[ends[a]];
    vertices.Within(x, this->J, near);
    int best = -1;
    double bestDistance = 0.0;
    for (vtkIdType v : near)
    {
      const V3 to = this->G.Vertices[v] - x;
      const double distance = to.norm();
      if (v == ends[a] || this->G.Degree(static_cast<int>(v)) == 0 || distance <= 0.0 ||
        to.dot(directions[a]) < BridgeCone * distance ||
        (component[v] == component[ends[a]] && componentSize[component[v]] * this->H < 4.0 * this->J))
      {
        continue;
      }
      const auto& around = this->G.Adjacent[v];
      const V3 along = this->G.Vertices[around.front()] - this->G.Vertices[around.back()];
      const V3 tangent = around.size() > 1 && along.norm() > 0.0
        ? V3(along.normalized())
        : V3((this->G.Vertices[around.front()] - this->G.Vertices[v]).normalized());
      if (!borderEnd[a] && this->SideBySide(x, lineDirections[a], this->G.Vertices[v], tangent))
      {
        continue;
      }
      if (best < 0 || distance < bestDistance)
      {
        best = static_cast<int>(v);
        bestDistance = distance;
      }
    }
    if (best >= 0)
    {
      this->G.Link(ends[a], best);
    }
  }
}

void CurveRun::CollapseShortLinks()
{
  for (int round = 0; round < 100000; ++round)
  {
    bool changed = false;
    for (const Chain& chain : this->ExtractChains())
    {
      const int a = chain.Ids.front(), b = chain.Ids.back();
      auto junction = [&](int v) { return this->G.Degree(v) >= 3 || this->G.Node[v]; };
      if (chain.Closed || !junction(a) || !junction(b) ||
        ChainLength(chain, this->G.Vertices) >= this->J)
      {
        continue;
      }
      for (size_t k = 1; k < chain.Ids.size(); ++k)
      {
        this->G.Unlink(chain.Ids[k - 1], chain.Ids[k]);
      }
      if (a != b)
      {
        const std::vector<int> moved = this->G.Adjacent[b];
        for (int w : moved)
        {
          this->G.Unlink(b, w);
          this->G.Link(a, w);
        }
        this->G.Vertices[a] = 0.5 * (this->G.Vertices[a] + this->G.Vertices[b]);
      }
      this->G.Node[a] = 1;
      changed = true;
      break; // the chains changed
    }
    if (!changed)
    {
      return;
    }
  }
}

bool CurveRun::NearCorner(const V3& x, std::vector<vtkIdType>& ids) const
{
  this->TraceSearch.Within(x, CornerNear * this->S, ids);
  return std::any_of(
    ids.begin(), ids.end(), [&](vtkIdType i) { return this->Type[this->TraceIndex[i]] == CORNER; });
}

void CurveRun::SplitAtCorners()
{
  const int w = std::max(1, static_cast<int>(std::lround(CornerWindow * this->S / this->H)));
  const int wide = 2 * w;
  std::vector<vtkIdType> ids;
  for (const Chain& chain : this->ExtractChains())
  {
    const int count = static_cast<int>(chain.Ids.size()) - (chain.Closed ? 1 : 0);
    if (count < 2 * w + 1)
    {
      continue;
    }
    auto at = [&](int k) -> const V3& {
      if (chain.Closed)
      {
        k = ((k % count) + count) % count;
      }
      return this->G.Vertices[chain.Ids[k]];
    };
    std::vector<double> turn(count, 1.0);
    const int first = chain.Closed ? 0 : w, last = chain.Closed ? count : count - w;
    for (int k = first; k < last; ++k)
    {
      const V3 a = at(k) - at(k - w), b = at(k + w) - at(k);
      if (a.norm() > 0.0 && b.norm() > 0.0)
      {
        turn[k] = a.normalized().dot(b.normalized());
      }
      // Where the detector typed a corner point within CornerNear s of the vertex, the turn
      // across twice the window too: a trace that went round a corner rounds it over the
      // corner's zone, where the fits of neither edge hold (the detector's own corner test looks
      // twice its smallest scale's radius away for the same reason), so that within one window
      // either side it turns less than it does from edge to edge.
      if (wide < count && (chain.Closed || (k >= wide && k < count - wide)) &&
        this->NearCorner(at(k), ids))
      {
        const V3 a2 = at(k) - at(k - wide), b2 = at(k + wide) - at(k);
        if (a2.norm() > 0.0 && b2.norm() > 0.0)
        {
          turn[k] = std::min(turn[k], a2.normalized().dot(b2.normalized()));
        }
      }
    }
    for (int k = first; k < last; ++k)
    {
      bool sharpest = turn[k] < CornerTurn;
      for (int j = k - w; sharpest && j <= k + w; ++j)
      {
        const int i = chain.Closed ? ((j % count) + count) % count : j;
        if (i >= 0 && i < count && i != k && (turn[i] < turn[k] || (turn[i] == turn[k] && i < k)))
        {
          sharpest = false;
        }
      }
      if (sharpest)
      {
        this->G.Node[chain.Ids[k]] = 1;
      }
    }
  }
}

void CurveRun::SplitAtTypeChanges()
{
  const int w = std::max(1, static_cast<int>(std::lround(2.0 * CornerWindow * this->S / this->H)));
  for (const Chain& chain : this->ExtractChains())
  {
    const int count = static_cast<int>(chain.Ids.size());
    if (chain.Closed || count < 2 * w)
    {
      continue;
    }
    // Border or not at each vertex, then the majority over w vertices either side (a stray
    // vertex of the other type is noise).
    std::vector<int> border(count + 1, 0); // running count
    for (int k = 0; k < count; ++k)
    {
      border[k + 1] = border[k] + (this->LocalType(this->G.Vertices[chain.Ids[k]]) == BORDER);
    }
    std::vector<unsigned char> type(count);
    for (int k = 0; k < count; ++k)
    {
      const int lo = std::max(0, k - w), hi = std::min(count, k + w + 1);
      type[k] = 2 * (border[hi] - border[lo]) > hi - lo ? 1 : 0;
    }
    // The changes between runs of at least w vertices each.
    int start = 0, previous = -1;
    for (int k = 1; k <= count; ++k)
    {
      if (k < count && type[k] == type[start])
      {
        continue;
      }
      if (k - start >= w)
      {
        if (previous >= 0 && type[previous] != type[start])
        {
          this->G.Node[chain.Ids[start]] = 1;
        }
        previous = start;
      }
      start = k;
    }
  }
}

unsigned char CurveRun::LocalType(const V3& x) const
{
  this->AllSearch.Within(x, 2.0 * this->S, this->Scratch);
  int counts[5] = { 0, 0, 0, 0, 0 };
  for (vtkIdType i : this->Scratch)
  {
    ++counts[this->Type[i]];
  }
  return counts[BORDER] > counts[CONVEX] + counts[CONCAVE] ? BORDER : CONVEX;
}

V3 CurveRun::FitCrease(const V3& x, const V3& e1, const V3& e2,
  const std::vector<vtkIdType>& ids, bool* found) const
{
  std::vector<Eigen::Vector2d> q, nq;
  for (vtkIdType i : ids)
  {
    const V3 r = this->Points[i] - x;
    q.emplace_back(r.dot(e1), r.dot(e2));
    nq.emplace_back(this->Normals[i].dot(e1), this->Normals[i].dot(e2));
  }
  Eigen::Vector2d p;
  const bool crease = this->CreaseIn(q, nq, p);
  if (found)
  {
    *found = crease;
  }
  return crease ? V3(x + p[0] * e1 + p[1] * e2) : x;
}

bool CurveRun::CreaseIn(const std::vector<Eigen::Vector2d>& section,
  const std::vector<Eigen::Vector2d>& sectionNormals, Eigen::Vector2d& p) const
{
  // The faces: points split by the direction in which their normals, seen along the curve, vary
  // most; then one 2D line per face, and their intersection.
  std::vector<Eigen::Vector2d> q, nq;
  for (size_t k = 0; k < section.size(); ++k)
  {
    if (section[k].norm() >= SectionCore * this->S && sectionNormals[k].norm() > 0.0)
    {
      q.push_back(section[k]);
      nq.push_back(sectionNormals[k].normalized());
    }
  }
  if (q.size() < 10)
  {
    return false;
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& nn : nq)
  {
    mean += nn;
  }
  mean /= static_cast<double>(nq.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& nn : nq)
  {
    cov += (nn - mean) * (nn - mean).transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> split(cov);
  const Eigen::Vector2d axis = split.eigenvectors().col(1);
  Eigen::Vector2d c[2] = { Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero() };
  int count[2] = { 0, 0 };
  std::vector<int> side(q.size());
  for (size_t k = 0; k < q.size(); ++k)
  {
    side[k] = (nq[k] - mean).dot(axis) >= 0.0 ? 1 : 0;
  }
  // Then, as k-means with lines, each point to the nearer line (the normals near the crease mix
  // both faces'), until the split settles.
  Eigen::Vector2d u[2];
  for (int round = 0; round < 6; ++round)
  {
    for (int g = 0; g < 2; ++g)
    {
      Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
      c[g] = Eigen::Vector2d::Zero();
      count[g] = 0;
      for (size_t k = 0; k < q.size(); ++k)
      {
        if (side[k] == g)
        {
          c[g] += q[k];
          ++count[g];
        }
      }
      if (count[g] < 5)
      {
        return false;
      }
      c[g] /= count[g];
      for (size_t k = 0; k < q.size(); ++k)
      {
        if (side[k] == g)
        {
          m += (q[k] - c[g]) * (q[k] - c[g]).transpose();
        }
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> line(m);
      u[g] = line.eigenvectors().col(1);
    }
    bool changed = false;
    for (size_t k = 0; k < q.size(); ++k)
    {
      const Eigen::Vector2d a = q[k] - c[0], b = q[k] - c[1];
      const double da = std::abs(a[0] * u[0][1] - a[1] * u[0][0]);
      const double db = std::abs(b[0] * u[1][1] - b[1] * u[1][0]);
      const int g = da <= db ? 0 : 1;
      changed = changed || g != side[k];
      side[k] = g;
    }
    if (!changed)
    {
      break;
    }
  }
  // c0 + a u0 = c1 + b u1
  auto intersect = [&](Eigen::Vector2d& p) {
    const double det = u[0][0] * (-u[1][1]) - u[0][1] * (-u[1][0]);
    if (std::abs(det) < MinimumCreaseAngle)
    {
      return false;
    }
    const Eigen::Vector2d r = c[1] - c[0];
    const double a = (r[0] * (-u[1][1]) - r[1] * (-u[1][0])) / det;
    p = c[0] + a * u[0];
    return p.allFinite();
  };
  if (!intersect(p))
  {
    return false;
  }
  // Then as a hinge: each point to the face on its side of the bisector of the two half-lines
  // from the crease. The nearest-line split takes the noise of one face near the crease for the
  // other's, which tilts both lines towards each other and pulls the crease inside the bend.
  for (int round = 0; round < 3; ++round)
  {
    Eigen::Vector2d h[2];
    for (int g = 0; g < 2; ++g)
    {
      h[g] = (c[g] - p).dot(u[g]) >= 0.0 ? u[g] : Eigen::Vector2d(-u[g]);
    }
    const Eigen::Vector2d bisector = (h[0] + h[1]).normalized();
    auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a[0] * b[1] - a[1] * b[0];
    };
    const double side0 = cross(bisector, h[0]);
    if (!bisector.allFinite() || side0 == 0.0)
    {
      break;
    }
    for (size_t k = 0; k < q.size(); ++k)
    {
      side[k] = (cross(bisector, q[k] - p) >= 0.0) == (side0 > 0.0) ? 0 : 1;
    }
    bool valid = true;
    for (int g = 0; g < 2 && valid; ++g)
    {
      Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
      Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
      int n = 0;
      for (size_t k = 0; k < q.size(); ++k)
      {
        if (side[k] == g)
        {
          centroid += q[k];
          ++n;
        }
      }
      if (n < 5)
      {
        valid = false;
        break;
      }
      centroid /= n;
      for (size_t k = 0; k < q.size(); ++k)
      {
        if (side[k] == g)
        {
          m += (q[k] - centroid) * (q[k] - centroid).transpose();
        }
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> line(m);
      c[g] = centroid;
      u[g] = line.eigenvectors().col(1);
    }
    Eigen::Vector2d moved;
    if (!valid || !intersect(moved))
    {
      break;
    }
    p = moved;
  }
  return p.allFinite() && p.norm() <= 2.0 * this->S;
}

CurveRun::Bend CurveRun::BendAt(const V3& x, const V3& t, double halfLength, Eigen::Vector2d& u,
  bool fixed, double radius) const
{
  // The slab's points in the cross-section; the plane through them (its line u, unless given);
  // on each side of x along u, the face's height over u by least squares; the slopes'
  // difference and its standard error from the faces' residuals.
  std::vector<vtkIdType> ids;
  V3 e1, e2;
  this->Section(x, t, halfLength, ids, e1, e2, radius);
  Bend result;
  std::vector<Eigen::Vector2d> q;
  Eigen::Vector2d c = this->Project(ids, x, e1, e2, q);
  if (q.size() < 10)
  {
    return result;
  }
  if (!fixed)
  {
    c /= static_cast<double>(q.size());
    Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
    for (const auto& p : q)
    {
      m += (p - c) * (p - c).transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> plane(m);
    u = plane.eigenvectors().col(1);
  }
  const Eigen::Vector2d v(-u[1], u[0]);
  // The residual of a quadratic height over u (about (ma, mh)) through the points of one side
  // (side 0 or 1, along u) or all of them (side -1); `finite`: whether its fit is.
  auto quadraticResidual = [&](int side, double ma, double mh, bool& finite) {
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d right = Eigen::Vector3d::Zero();
    for (const auto& p : q)
    {
      if (side < 0 || (p.dot(u) >= 0.0) == (side == 1))
      {
        const double a = p.dot(u) - ma;
        const Eigen::Vector3d row(1.0, a, a * a);
        normal += row * row.transpose();
        right += row * (p.dot(v) - mh);
      }
    }
    const Eigen::Vector3d coefficients = normal.ldlt().solve(right);
    finite = coefficients.allFinite();
    double rss = 0.0;
    for (const auto& p : q)
    {
      if (side < 0 || (p.dot(u) >= 0.0) == (side == 1))
      {
        const double a = p.dot(u) - ma;
        const double e = p.dot(v) - mh - coefficients.dot(Eigen::Vector3d(1.0, a, a * a));
        rss += e * e;
      }
    }
    return rss;
  };
  double slope[2], variance[2], hinge = 0.0;
  bool planar = true;
  for (int g = 0; g < 2; ++g)
  {
    double sa = 0.0, sh = 0.0;
    int n = 0;
    for (const auto& p : q)
    {
      if ((p.dot(u) >= 0.0) == (g == 1))
      {
        sa += p.dot(u);
        sh += p.dot(v);
        ++n;
      }
    }
    if (n < 5)
    {
      return result;
    }
    const double ma = sa / n, mh = sh / n;
    double saa = 0.0, sah = 0.0;
    for (const auto& p : q)
    {
      if ((p.dot(u) >= 0.0) == (g == 1))
      {
        saa += (p.dot(u) - ma) * (p.dot(u) - ma);
        sah += (p.dot(u) - ma) * (p.dot(v) - mh);
      }
    }
    if (!(saa > 0.0))
    {
      return result;
    }
    slope[g] = sah / saa;
    double residual = 0.0;
    for (const auto& p : q)
    {
      if ((p.dot(u) >= 0.0) == (g == 1))
      {
        const double e = p.dot(v) - mh - slope[g] * (p.dot(u) - ma);
        residual += e * e;
      }
    }
    variance[g] = residual / std::max(1, n - 2) / saa;
    hinge += residual;
    // The same side's height as a quadratic over u: a bend within the side (another feature in
    // the section, a curved face) leaves significantly less.
    bool finite = false;
    const double curved = quadraticResidual(g, ma, mh, finite);
    planar = planar && n > 3 && finite &&
      (residual - curved) * (n - 3) <=
        CreaseSignificance * CreaseSignificance * std::max(curved, 0.0);
  }
  // One smooth face instead: a quadratic height over u through all the points. Where it leaves
  // no more than the two faces (F of its one parameter fewer), the section bends smoothly.
  bool finite = false;
  const double smooth = quadraticResidual(-1, 0.0, 0.0, finite);
  const double perPoint = hinge / std::max(1, static_cast<int>(q.size()) - 4);
  result.Kink = perPoint > 0.0
    ? (smooth - hinge) / perPoint
    : (smooth > 0.0 ? std::numeric_limits<double>::infinity() : 0.0); // exact faces
  result.Valid = true;
  result.Planar = planar;
  result.Difference = slope[1] - slope[0];
  result.Error = std::sqrt(variance[0] + variance[1]);
  result.Angle = std::abs(std::atan(slope[1]) - std::atan(slope[0]));
  return result;
}

V3 CurveRun::FitBorder(
  const V3& x, const V3& e1, const V3& e2, const std::vector<vtkIdType>& ids) const
{
  // The face's line in the cross-section; along it, the points fill [b, ...) evenly: over a window
  // [b, a0 + W] their mean is the window's middle, which gives b.
  std::vector<Eigen::Vector2d> q;
  this->Project(ids, x, e1, e2, q);
  Eigen::Vector2d p;
  return this->BorderIn(q, p) ? V3(x + p[0] * e1 + p[1] * e2) : x;
}

bool CurveRun::BorderIn(const std::vector<Eigen::Vector2d>& q, Eigen::Vector2d& p) const
{
  if (q.size() < 10)
  {
    return false;
  }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& a : q)
  {
    c += a;
  }
  c /= static_cast<double>(q.size());
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (const auto& a : q)
  {
    m += (a - c) * (a - c).transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> line(m);
  Eigen::Vector2d u = line.eigenvectors().col(1);
  if (c.dot(u) < 0.0)
  {
    u = -u; // into the face
  }
  const double window = this->R;
  double b = -c.dot(u); // the vertex, along the line
  for (int round = 0; round < 3; ++round)
  {
    double sum = 0.0;
    int count = 0;
    for (const auto& p : q)
    {
      const double a = (p - c).dot(u);
      if (a <= b + window)
      {
        sum += a;
        ++count;
      }
    }
    if (count < 5)
    {
      return false;
    }
    b = 2.0 * sum / count - (b + window);
  }
  p = c + b * u;
  return p.allFinite() && p.norm() <= 2.0 * this->S;
}

Eigen::Vector2d CurveRun::Project(const std::vector<vtkIdType>& ids, const V3& x, const V3& e1,
  const V3& e2, std::vector<Eigen::Vector2d>& q) const
{
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (vtkIdType i : ids)
  {
    const V3 r = this->Points[i] - x;
    q.emplace_back(r.dot(e1), r.dot(e2));
    sum += q.back();
  }
  return sum;
}

void CurveRun::Section(const V3& x, const V3& t, double halfLength, std::vector<vtkIdType>& ids,
  V3& e1, V3& e2, double radius) const
{
  ids.clear();
  const double across2 = std::pow(radius * this->R, 2);
  this->AllSearch.Within(x, std::sqrt(across2 + halfLength * halfLength), this->Scratch);
  for (vtkIdType i : this->Scratch)
  {
    const V3 r = this->Points[i] - x;
    const double along = r.dot(t);
    if (std::abs(along) <= halfLength && (r - along * t).squaredNorm() <= across2)
    {
      ids.push_back(i);
    }
  }
  e1 = t.unitOrthogonal();
  e2 = t.cross(e1);
}

V3 CurveRun::FitSection(const V3& x, const V3& t) const
{
  std::vector<vtkIdType> ids;
  V3 e1, e2;
  this->Section(x, t, SectionLength * this->R, ids, e1, e2);
  return this->LocalType(x) == BORDER ? this->FitBorder(x, e1, e2, ids)
                                      : this->FitCrease(x, e1, e2, ids);
}

V3 CurveRun::FitAlong(const std::vector<V3>& c, const std::vector<double>& arc, bool closed,
  int k, double halfLength) const
{
  const int n = static_cast<int>(c.size()) - (closed ? 1 : 0); // distinct vertices
  const double perimeter = arc.back();
  if (n < 5)
  {
    return c[k];
  }
  // The reference: a quadratic in arc length, r(a) = r0 + r1 a + r2 a^2, through the curve's
  // vertices within twice the window. The points are taken relative to it, so the fit gives
  // the crease's mean offset from r over the window: r's own wander does not come back (a
  // vertex-by-vertex reference would add its wander to the result), and r's bend follows the
  // curve's (a straight slab would cut a bent curve's chord).
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();
  int count = 0;
  // The vertices within the window: arc lengths grow along the curve, so they are index ranges
  // (three on a closed curve: the window, and it a perimeter earlier and later), found by
  // bisection, a little wider than the window and then tested one by one, in increasing order
  // (the sums as a scan of every vertex would add them). A scan of every vertex for every vertex
  // took 9 s on a curve of 100,000 points.
  const double reach = 2.0 * halfLength;
  const double margin = 1e-9 * (std::abs(arc[k]) + perimeter + reach) + VTK_DBL_MIN;
  std::vector<std::pair<int, int>> ranges;
  for (const double shift : { -perimeter, 0.0, perimeter })
  {
    if (shift != 0.0 && !closed)
    {
      continue;
    }
    const auto from =
      std::lower_bound(arc.begin(), arc.begin() + n, arc[k] + shift - reach - margin);
    const auto to = std::upper_bound(from, arc.begin() + n, arc[k] + shift + reach + margin);
    if (from < to)
    {
      ranges.emplace_back(static_cast<int>(from - arc.begin()), static_cast<int>(to - arc.begin()));
    }
  }
  std::sort(ranges.begin(), ranges.end());
  int next = 0; // the first index not yet tested: ranges may overlap
  for (const auto& range : ranges)
  {
    for (int j = std::max(range.first, next); j < range.second; ++j)
    {
      double offset = arc[j] - arc[k];
      if (closed)
      {
        offset -= perimeter * std::round(offset / perimeter);
      }
      if (std::abs(offset) <= reach)
      {
        const V3 basis(1.0, offset, offset * offset);
        normal += basis * basis.transpose();
        rhs += basis * (c[j] - c[k]).transpose();
        ++count;
      }
    }
    next = std::max(next, range.second);
  }
  Eigen::LDLT<Eigen::Matrix3d> solver(normal);
  const Eigen::Matrix3d coefficients = solver.solve(rhs);
  if (count < 5 || solver.info() != Eigen::Success || !coefficients.allFinite())
  {
    return c[k];
  }
  const V3 r0 = c[k] + coefficients.row(0).transpose();
  const V3 r1 = coefficients.row(1).transpose();
  const V3 r2 = coefficients.row(2).transpose();
  if (!(r1.squaredNorm() > 0.25))
  {
    return c[k];
  }
  const V3 t = r1.normalized();
  const V3 e1 = t.unitOrthogonal();
  const V3 e2 = t.cross(e1);
  // Where an open curve ends, its points end: the window stops there.
  const double first = closed ? -VTK_DOUBLE_MAX : arc[0] - arc[k] - 0.5 * this->H;
  const double last = closed ? VTK_DOUBLE_MAX : arc[n - 1] - arc[k] + 0.5 * this->H;
  const double across = SectionRadius * this->R;
  std::vector<vtkIdType> ids;
  this->AllSearch.NearestWithin(r0, across + halfLength, this->FitCap(across + halfLength), ids);
  std::vector<Eigen::Vector2d> q, nq;
  for (vtkIdType i : ids)
  {
    const V3& p = this->Points[i];
    double a = (p - r0).dot(r1) / r1.squaredNorm();
    for (int round = 0; round < 2; ++round) // Newton steps to the nearest point of r
    {
      const V3 d = r1 + 2.0 * a * r2;
      a += (p - (r0 + a * r1 + a * a * r2)).dot(d) / d.squaredNorm();
    }
    if (std::abs(a) > halfLength || a < first || a > last)
    {
      continue;
    }
    const V3 ta = (r1 + 2.0 * a * r2).normalized();
    V3 r = p - (r0 + a * r1 + a * a * r2);
    r -= r.dot(ta) * ta;
    if (r.squaredNorm() > across * across)
    {
      continue;
    }
    const V3 f1 = (e1 - e1.dot(ta) * ta).normalized();
    const V3 f2 = ta.cross(f1);
    q.emplace_back(r.dot(f1), r.dot(f2));
    nq.emplace_back(this->Normals[i].dot(f1), this->Normals[i].dot(f2));
  }
  Eigen::Vector2d p;
  const bool found =
    this->LocalType(r0) == BORDER ? this->BorderIn(q, p) : this->CreaseIn(q, nq, p);
  return found ? V3(r0 + p[0] * e1 + p[1] * e2) : c[k];
}

void Smooth(std::vector<V3>& x, bool closed, int passes)
{
  const size_t n = x.size();
  if (n < 3)
  {
    return;
  }
  for (int pass = 0; pass < passes; ++pass)
  {
    std::vector<V3> y = x;
    for (size_t k = 0; k < n; ++k)
    {
      if (!closed && (k == 0 || k + 1 == n))
      {
        continue;
      }
      if (closed && k + 1 == n)
      {
        y[k] = y[0];
        continue;
      }
      const V3& a = closed && k == 0 ? x[n - 2] : x[k - 1];
      const V3& b = x[k + 1];
      y[k] = 0.5 * x[k] + 0.25 * (a + b);
    }
    if (closed)
    {
      y[n - 1] = y[0];
    }
    x = y;
  }
}

std::vector<V3> Resample(const std::vector<V3>& x, double step)
{
  std::vector<double> arc(x.size(), 0.0);
  for (size_t k = 1; k < x.size(); ++k)
  {
    arc[k] = arc[k - 1] + (x[k] - x[k - 1]).norm();
  }
  const double length = arc.back();
  // A curve's vertices lie a trace step or a bridged gap apart: pieces far more than that many
  // steps long only come from degenerate input (points scattered over 1e38 spacings), where the
  // resampled curve would not fit in memory. Such a curve keeps its vertices.
  const double wanted = length / step;
  if (!(wanted <= MaximumStepsPerVertex * static_cast<double>(x.size())))
  {
    return x;
  }
  const int segments = std::max(1, static_cast<int>(std::lround(wanted)));
  std::vector<V3> y{ x.front() };
  size_t j = 1;
  for (int k = 1; k < segments; ++k)
  {
    const double a = length * k / segments;
    while (j + 1 < x.size() && arc[j] < a)
    {
      ++j;
    }
    const double span = arc[j] - arc[j - 1];
    const double f = span > 0.0 ? (a - arc[j - 1]) / span : 0.0;
    y.push_back(x[j - 1] + f * (x[j] - x[j - 1]));
  }
  y.push_back(x.back());
  return y;
}

void CurveRun::RefitCorners(
  const std::vector<Chain>& chains, std::vector<std::vector<V3>>& curves) const
{
  // Each corner again, from the fitted curves: the point nearest to their end lines.
  std::map<int, std::vector<std::pair<size_t, bool>>> atCorner; // vertex -> (curve, at its start)
  for (size_t c = 0; c < chains.size(); ++c)
  {
    if (chains[c].Closed)
    {
      continue;
    }
    if (this->G.Node[chains[c].Ids.front()])
    {
      atCorner[chains[c].Ids.front()].emplace_back(c, true);
    }
    if (this->G.Node[chains[c].Ids.back()])
    {
      atCorner[chains[c].Ids.back()].emplace_back(c, false);
    }
  }
  for (const auto& entry : atCorner)
  {
    std::vector<V3> points, lines;
    for (const auto& end : entry.second)
    {
      const std::vector<V3>& x = curves[end.first];
      // The stretch from 2 to 6 s from the corner.
      std::vector<vtkIdType> ids;
      std::vector<V3> stretch;
      const V3 corner = end.second ? x.front() : x.back();
      for (const V3& p : x)
      {
        const double d = (p - corner).norm();
        if (d >= 2.0 * this->S && d <= 6.0 * this->S)
        {
          ids.push_back(static_cast<vtkIdType>(stretch.size()));
          stretch.push_back(p);
        }
      }
      if (ids.size() < 3)
      {
        continue;
      }
      const LineFit f = FitLine(stretch, ids, corner);
      points.push_back(f.Centroid);
      lines.push_back(f.Direction);
    }
    V3 corner;
    if (points.size() < 2 || !NearestToLines(points, lines, corner))
    {
      continue;
    }
    bool near = true;
    for (const auto& end : entry.second)
    {
      const std::vector<V3>& x = curves[end.first];
      near = near && (corner - (end.second ? x.front() : x.back())).norm() <= 3.0 * this->S;
    }
    for (const auto& end : entry.second)
    {
      std::vector<V3>& x = curves[end.first];
      (end.second ? x.front() : x.back()) = near ? corner : (end.second ? x.front() : x.back());
    }
  }
}

void CurveRun::OntoMovedPoints(
  const std::vector<Chain>& chains, std::vector<std::vector<V3>>& curves) const
{
  // Each inner crease vertex onto the median, across the curve, of the moved crease points in
  // the slab of the cross-section fits (SectionLength FitRadius along the curve either side) and
  // within the detector's band (2 s) of it: the median of many voters' lines places the crease
  // better than one section's fit (mean distance to the true curves at sigma 0.5 s: see
  // FeaturePointsCurveBenchmark). Borders, corners and vertices with fewer than MinFitPoints
  // such points keep their fit.
  if (this->Moved.empty())
  {
    return;
  }
  const double halfLength = SectionLength * this->R;
  const double reach = std::max(MovedBand * this->S, this->StripHalfGap);
  std::vector<vtkIdType> ids;
  std::vector<double> a, b;
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const bool closed = chains[c].Closed;
    const std::vector<V3>& x = curves[c];
    std::vector<V3> y = x;
    const int n = static_cast<int>(x.size()) - (closed ? 1 : 0); // distinct vertices
    for (int k = closed ? 0 : 1; k < (closed ? n : n - 1); ++k)
    {
      const bool strip = this->IsStripVertex(chains[c].Ids[k]);
      if (this->G.Node[chains[c].Ids[k]] || (!strip && this->LocalType(x[k]) == BORDER))
      {
        continue;
      }
      // A strip vertex: only its own line's moved points.
      const double across = strip ? this->StripHalfGap : MovedBand * this->S;
      const V3 chord = x[(k + 1) % n] - x[(k + n - 1) % n];
      if (!(chord.norm() > 0.0))
      {
        continue;
      }
      const V3 t = chord.normalized();
      const V3 e1 = t.unitOrthogonal(), e2 = t.cross(e1);
      this->MovedSearch.Within(x[k], std::sqrt(halfLength * halfLength + reach * reach), ids);
      a.clear();
      b.clear();
      for (vtkIdType i : ids)
      {
        const V3 r = this->Moved[i] - x[k];
        const double along = r.dot(t);
        if (std::abs(along) <= halfLength && (r - along * t).norm() <= across)
        {
          a.push_back(r.dot(e1));
          b.push_back(r.dot(e2));
        }
      }
      if (static_cast<int>(a.size()) < MinFitPoints)
      {
        continue;
      }
      const size_t middle = a.size() / 2;
      std::nth_element(a.begin(), a.begin() + middle, a.end());
      std::nth_element(b.begin(), b.begin() + middle, b.end());
      y[k] = x[k] + a[middle] * e1 + b[middle] * e2;
    }
    if (closed)
    {
      y.back() = y.front();
    }
    curves[c] = y;
  }
}

std::vector<std::vector<V3>> CurveRun::FitCurves(const std::vector<Chain>& chains)
{
  // Fitted positions of the graph's vertices: every vertex once, so that curves sharing an end
  // still share it.
  const int n = static_cast<int>(this->G.Vertices.size());
  std::vector<V3> fitted = this->G.Vertices;
  std::vector<V3> tangent(n, V3::Zero());
  for (const Chain& chain : chains)
  {
    const int count = static_cast<int>(chain.Ids.size());
    for (int k = 0; k < count; ++k)
    {
      const int a = chain.Ids[std::max(0, k - 2)];
      const int b = chain.Ids[std::min(count - 1, k + 2)];
      const V3 t = this->G.Vertices[b] - this->G.Vertices[a];
      if (t.norm() > 0.0 && tangent[chain.Ids[k]].squaredNorm() == 0.0)
      {
        tangent[chain.Ids[k]] = t.normalized();
      }
    }
  }
  for (int v = 0; v < n; ++v)
  {
    // A strip vertex lies on its own line of moved points already; the cross-section holds the
    // lines beside it too.
    if (this->G.Degree(v) > 0 && !this->G.Node[v] && tangent[v].squaredNorm() > 0.0 &&
      !this->IsStripVertex(v))
    {
      fitted[v] = this->FitSection(this->G.Vertices[v], tangent[v]);
    }
  }
  std::vector<std::vector<V3>> curves;
  for (const Chain& chain : chains)
  {
    std::vector<V3> x;
    for (int id : chain.Ids)
    {
      x.push_back(fitted[id]);
    }
    Smooth(x, chain.Closed, SmoothingPasses);
    curves.push_back(x);
  }
  // Again, each inner vertex from the points along the fitted curve, over AlongLength either side:
  // one vertex fit's slab holds too few points to place a shallow crease within the noise.
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const bool closed = chains[c].Closed;
    std::vector<V3>& x = curves[c];
    std::vector<double> arc(x.size(), 0.0);
    for (size_t k = 1; k < x.size(); ++k)
    {
      arc[k] = arc[k - 1] + (x[k] - x[k - 1]).norm();
    }
    std::vector<V3> y = x;
    const int n = static_cast<int>(x.size()) - (closed ? 1 : 0);
    for (int k = closed ? 0 : 1; k < (closed ? n : n - 1); ++k)
    {
      if (!this->G.Node[chains[c].Ids[k]] && !this->IsStripVertex(chains[c].Ids[k]))
      {
        y[k] = this->FitAlong(x, arc, closed, k, AlongLength * this->R);
      }
    }
    if (closed)
    {
      y.back() = y.front();
    }
    Smooth(y, closed, SmoothingPasses);
    x = y;
  }
  this->OntoMovedPoints(chains, curves);
  this->RefitCorners(chains, curves);
  for (size_t c = 0; c < curves.size(); ++c)
  {
    Smooth(curves[c], chains[c].Closed, 1);
    curves[c] = Resample(curves[c], this->H);
  }
  return curves;
}
} // namespace

vtkFeatureCurveExtraction::vtkFeatureCurveExtraction()
{
  this->SetNumberOfOutputPorts(2);
}

vtkFeatureCurveExtraction::~vtkFeatureCurveExtraction() = default;

vtkPolyData* vtkFeatureCurveExtraction::GetCurves()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkFeatureCurveExtraction::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

namespace
{
// The mean spacing: the detector's, else the points' own.
double MeanSpacingOf(vtkPointSet* input)
{
  vtkDataArray* given = input->GetFieldData()->GetArray("MeanSpacing");
  if (given && given->GetNumberOfTuples() > 0)
  {
    const double s = given->GetTuple1(0);
    if (std::isfinite(s) && s > 0.0)
    {
      return s;
    }
  }
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  return input->GetNumberOfPoints() > 1 && neighborhoods->Build(input->GetPoints())
    ? neighborhoods->ComputeMeanSpacing()
    : 0.0;
}

// Output port 0: the input points with their arrays and vertex cells.
void CopyPoints(vtkPointSet* input, vtkPolyData* output)
{
  vtkPolyData* poly = vtkPolyData::SafeDownCast(input);
  if (poly)
  {
    output->ShallowCopy(poly);
  }
  else
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->ShallowCopy(input->GetPointData());
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
  }
  if (output->GetNumberOfCells() == 0 && input->GetNumberOfPoints() > 0)
  {
    output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(input->GetNumberOfPoints()));
  }
}

// Whether a point array has one tuple of `components` values per point.
bool Shaped(vtkDataArray* array, int components, vtkIdType n)
{
  return array && array->GetNumberOfComponents() == components && array->GetNumberOfTuples() == n;
}

// A point array the curves may use: the array when it has one tuple of `components` values per
// point, else nullptr (the curves do without it), with a warning from `self`.
vtkDataArray* Usable(vtkAlgorithm* self, vtkDataArray* array, int components, vtkIdType n)
{
  if (!array || Shaped(array, components, n))
  {
    return array;
  }
  vtkWarningWithObjectMacro(self, << "The input's point array '"
                                  << (array->GetName() ? array->GetName() : "(no name)")
                                  << "' has " << array->GetNumberOfTuples() << " tuples of "
                                  << array->GetNumberOfComponents() << " values for " << n
                                  << " points, not " << components << " per point: not used.");
  return nullptr;
}
} // namespace

int vtkFeatureCurveExtraction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* curvesOutput = vtkPolyData::GetData(outputVector, 1);
  this->MeanSpacing = 0.0;
  this->NumberOfCurves = 0;
  this->TotalLength = 0.0;
  if (!input || !output || !curvesOutput)
  {
    return 0;
  }
  if (const char* nan = featurepoints::FirstNaN({ { "FitRadius", this->FitRadius },
        { "StepLength", this->StepLength }, { "JoinDistance", this->JoinDistance },
        { "MinimumLength", this->MinimumLength } }))
  {
    vtkErrorMacro(<< nan << " is NaN: give it a number. The outputs are empty.");
    output->Initialize();
    curvesOutput->Initialize();
    return 1;
  }
  vtkDataArray* mask = input->GetPointData()->GetArray("FeatureMask");
  if (!mask && input->GetNumberOfPoints() > 0)
  {
    vtkErrorMacro("The input has no FeatureMask point array: give it a feature point detector's "
                  "output (vtkCreaseVotingFeatures).");
    return 0;
  }
  if (mask && !Shaped(mask, 1, input->GetNumberOfPoints()))
  {
    vtkErrorMacro(<< "The input's FeatureMask has " << mask->GetNumberOfTuples() << " tuples of "
                  << mask->GetNumberOfComponents() << " values for "
                  << input->GetNumberOfPoints()
                  << " points: give it a feature point detector's output, one value per point.");
    return 0;
  }
  CopyPoints(input, output);
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkIntArray> curveIds;
  curveIds->SetName("CurveId");
  curveIds->SetNumberOfValues(n);
  curveIds->FillValue(-1);
  output->GetPointData()->AddArray(curveIds);

  vtkNew<vtkPoints> linePoints;
  linePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("CurveId");
  vtkNew<vtkUnsignedCharArray> cellTypes;
  cellTypes->SetName("FeatureType");
  vtkNew<vtkFloatArray> cellAngles;
  cellAngles->SetName("CreaseAngle");
  vtkNew<vtkDoubleArray> cellLengths;
  cellLengths->SetName("Length");
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangent");
  tangents->SetNumberOfComponents(3);
  curvesOutput->SetPoints(linePoints);
  curvesOutput->SetLines(lines);
  curvesOutput->GetCellData()->AddArray(cellIds);
  curvesOutput->GetCellData()->AddArray(cellTypes);
  curvesOutput->GetCellData()->AddArray(cellAngles);
  curvesOutput->GetCellData()->AddArray(cellLengths);
  curvesOutput->GetPointData()->AddArray(tangents);
  if (n == 0)
  {
    return 1;
  }
  const double s = MeanSpacingOf(input);
  this->MeanSpacing = s;
  if (!(s > 0.0))
  {
    vtkWarningMacro("No two points apart: no mean spacing, no curve.");
    return 1;
  }

  CurveRun run(s, this->FitRadius, this->StepLength, this->JoinDistance, this->MinimumLength);
  // The detector's score (its active scalars) and threshold, when it gives them.
  vtkDataArray* scores = Usable(this, input->GetPointData()->GetScalars(), 1, n);
  vtkDataArray* types = Usable(this, input->GetPointData()->GetArray("FeatureType"), 1, n);
  vtkDataArray* normals = Usable(this, input->GetPointData()->GetArray("Normals"), 3, n);
  vtkDataArray* thresholdArray = input->GetFieldData()->GetArray("FeatureThreshold");
  const double threshold = thresholdArray && thresholdArray->GetNumberOfTuples() > 0
    ? thresholdArray->GetTuple1(0)
    : 0.0;
  vtkDataArray* offsets = input->GetPointData()->GetArray("CreaseOffset");
  if (offsets && (offsets->GetNumberOfComponents() != 3 ||
                   offsets->GetNumberOfTuples() != input->GetNumberOfPoints()))
  {
    offsets = nullptr;
  }
  run.SelectPoints(input, mask, types, normals,
    scores && scores != mask && std::isfinite(threshold) && threshold > 0.0 ? scores : nullptr,
    threshold, offsets);
  this->UpdateProgress(0.1);
  run.AdaptFitRadius();
  run.OrderSeeds();
  this->UpdateProgress(0.3);
  run.TraceAll();
  this->UpdateProgress(0.6);
  run.RemoveSpurs();
  run.JoinEnds();
  run.RemoveSpurs();
  run.CollapseShortLinks();
  run.RemoveSpurs();
  run.RemoveUnsupported();
  run.RemoveSpurs();
  // The spurs' removal frees ends that were junctions: join those too.
  run.JoinEnds();
  run.RemoveSpurs();
  run.BridgeAlongCreases();
  run.RemoveFlatPieces();
  run.SplitAtCorners();
  // A corner that a trace went round can be split twice (two turns of 45 degrees or more, more
  // than a CornerWindow apart): the piece between is a short link too.
  run.CollapseShortLinks();
  run.SplitAtTypeChanges();
  std::vector<std::array<int, 2>> through;
  const std::vector<Chain> chains = run.MergeThrough(run.ExtractChains(), through);
  std::vector<std::vector<V3>> curves = run.FitCurves(chains);
  // An end on a curve that goes on through the junction: onto that curve's nearest vertex.
  std::vector<std::array<std::pair<int, size_t>, 2>> endOn(
    curves.size(), { std::make_pair(-1, size_t(0)), std::make_pair(-1, size_t(0)) });
  for (size_t c = 0; c < curves.size(); ++c)
  {
    for (int e = 0; e < 2; ++e)
    {
      const int t = through[c][e];
      if (t < 0)
      {
        continue;
      }
      V3& end = e == 0 ? curves[c].front() : curves[c].back();
      size_t nearest = 0;
      for (size_t k = 1; k < curves[t].size(); ++k)
      {
        if ((curves[t][k] - end).squaredNorm() < (curves[t][nearest] - end).squaredNorm())
        {
          nearest = k;
        }
      }
      end = curves[t][nearest];
      endOn[c][e] = std::make_pair(t, nearest);
    }
  }
  this->UpdateProgress(0.9);

  // Curves out, junctions shared: an end within a hundredth of a spacing of an earlier end is it.
  std::vector<std::pair<V3, vtkIdType>> endPoints;
  auto endPoint = [&](const V3& x) {
    for (const auto& e : endPoints)
    {
      if ((e.first - x).norm() <= 0.01 * s)
      {
        return e.second;
      }
    }
    const vtkIdType id = linePoints->InsertNextPoint(x.data());
    endPoints.emplace_back(x, id);
    return id;
  };
  std::vector<V3> samples;
  std::vector<int> sampleCurve;
  std::vector<V3> tangentValues;
  // The point ids of each curve's vertices; ends on another curve's inner vertex are resolved
  // once every curve has its ids.
  std::vector<std::vector<vtkIdType>> vertexIds(curves.size());
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const std::vector<V3>& x = curves[c];
    const bool closed = chains[c].Closed;
    std::vector<vtkIdType>& ids = vertexIds[c];
    for (size_t k = 0; k < x.size(); ++k)
    {
      const bool end = k == 0 || k + 1 == x.size();
      if (closed && k + 1 == x.size())
      {
        ids.push_back(ids.front());
      }
      else if (end && endOn[c][k == 0 ? 0 : 1].first >= 0)
      {
        ids.push_back(-1);
      }
      else if (end)
      {
        ids.push_back(endPoint(x[k]));
      }
      else
      {
        ids.push_back(linePoints->InsertNextPoint(x[k].data()));
      }
    }
  }
  for (size_t round = 0; round <= curves.size(); ++round) // an end may land on another's end
  {
    for (size_t c = 0; c < curves.size(); ++c)
    {
      for (int e = 0; e < 2; ++e)
      {
        const auto& on = endOn[c][e];
        vtkIdType& id = e == 0 ? vertexIds[c].front() : vertexIds[c].back();
        if (on.first >= 0 && id < 0)
        {
          id = vertexIds[on.first][on.second];
          if (id < 0 && round == curves.size())
          {
            id = endPoint(e == 0 ? curves[c].front() : curves[c].back());
          }
        }
      }
    }
  }
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const std::vector<V3>& x = curves[c];
    const std::vector<vtkIdType>& ids = vertexIds[c];
    for (size_t k = 0; k < x.size(); ++k)
    {
      samples.push_back(V3(linePoints->GetPoint(ids[k])));
      sampleCurve.push_back(static_cast<int>(c));
    }
    for (size_t k = 0; k < x.size(); ++k)
    {
      const V3 t = x[std::min(k + 1, x.size() - 1)] - x[k > 0 ? k - 1 : 0];
      if (static_cast<vtkIdType>(tangentValues.size()) <= ids[k])
      {
        tangentValues.resize(ids[k] + 1, V3::Zero());
      }
      if (tangentValues[ids[k]].squaredNorm() == 0.0 && t.norm() > 0.0)
      {
        tangentValues[ids[k]] = t.normalized();
      }
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    double length = 0.0;
    for (size_t k = 1; k < x.size(); ++k)
    {
      length += (x[k] - x[k - 1]).norm();
    }
    cellIds->InsertNextValue(static_cast<int>(c));
    cellLengths->InsertNextValue(length);
    this->TotalLength += length;
  }
  tangents->SetNumberOfTuples(linePoints->GetNumberOfPoints());
  for (vtkIdType i = 0; i < linePoints->GetNumberOfPoints(); ++i)
  {
    const V3 t = i < static_cast<vtkIdType>(tangentValues.size()) ? tangentValues[i] : V3::Zero();
    tangents->SetTuple3(i, t[0], t[1], t[2]);
  }
  this->NumberOfCurves = static_cast<vtkIdType>(curves.size());

  // CurveId of the feature points; each curve's type and angle from its points.
  PointSearch sampleSearch;
  sampleSearch.Build(samples);
  vtkDataArray* angles =
    Usable(this, input->GetPointData()->GetArray("CreaseAngle"), 1, input->GetNumberOfPoints());
  std::vector<std::array<int, 5>> typeCounts(curves.size(), { 0, 0, 0, 0, 0 });
  std::vector<double> angleSum(curves.size(), 0.0);
  std::vector<int> angleCount(curves.size(), 0);
  for (size_t r = 0; r < run.Points.size(); ++r)
  {
    if (!run.Feature[r] || samples.empty())
    {
      continue;
    }
    const vtkIdType nearest = sampleSearch.Nearest(run.Points[r]);
    if (nearest < 0 || (samples[nearest] - run.Points[r]).norm() > AssignRadius * s)
    {
      continue;
    }
    const int c = sampleCurve[nearest];
    const vtkIdType i = run.PointIds[r];
    curveIds->SetValue(i, c);
    const int type = types ? static_cast<int>(types->GetTuple1(i)) : CONVEX;
    if (type >= 0 && type < 5)
    {
      ++typeCounts[c][type];
    }
    const double angle = angles ? angles->GetTuple1(i) : 0.0;
    if (std::isfinite(angle) && angle > 0.0)
    {
      angleSum[c] += angle;
      ++angleCount[c];
    }
  }
  for (const auto& copy : run.Copies)
  {
    curveIds->SetValue(copy.first, curveIds->GetValue(run.PointIds[copy.second]));
  }
  for (size_t c = 0; c < curves.size(); ++c)
  {
    const auto& k = typeCounts[c];
    unsigned char type = CONVEX;
    if (k[CONCAVE] > k[CONVEX] && k[CONCAVE] >= k[BORDER])
    {
      type = CONCAVE;
    }
    else if (k[BORDER] > k[CONVEX] && k[BORDER] > k[CONCAVE])
    {
      type = BORDER;
    }
    cellTypes->InsertNextValue(type);
    cellAngles->InsertNextValue(
      angleCount[c] ? static_cast<float>(angleSum[c] / angleCount[c]) : 0.0f);
  }
  return 1;
}

void vtkFeatureCurveExtraction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FitRadius: " << this->FitRadius << "\n";
  os << indent << "StepLength: " << this->StepLength << "\n";
  os << indent << "JoinDistance: " << this->JoinDistance << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "MeanSpacing: " << this->MeanSpacing << "\n";
  os << indent << "NumberOfCurves: " << this->NumberOfCurves << "\n";
  os << indent << "TotalLength: " << this->TotalLength << "\n";
}
