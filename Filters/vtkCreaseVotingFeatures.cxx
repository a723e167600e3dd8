#include "vtkCreaseVotingFeatures.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <tuple>
#include <vector>

vtkStandardNewMacro(vtkCreaseVotingFeatures);

namespace
{
// sigma is never taken below this fraction of the mean spacing (noise-free clouds).
constexpr double NoiseFloor = 0.05;
// Outliers (see RemoveOutliers): a point off the plane of its nearest by more than this many
// standard errors. Student's t with 12 degrees of freedom (15 neighbours, less the plane's 3)
// exceeds 12 with a probability of about 5e-8.
constexpr double OutlierDistance = 12.0;
// Over the plane of the nearest point's nearest, the standard error of a height is at least
// this many mean spacings (over the point's own, at least the noise floor 0.05 d): the point
// can lie just across a crease from all of them (on the clean box at 30,000 points, a point
// 0.86 d below the top face's plane, beside the edge, lay 14.6 errors off it at 0.05 d). At a
// quarter spacing, the point must lie 3 d off that plane. Its own nearest always hold its face.
constexpr double OutlierFloor = 0.25;
constexpr double OnPlane = 3.0; // within this many errors of its own nearest's plane: on it
constexpr int OutlierNeighbors = 8; // fewer nearest: no plane to measure against
// Isolated points: Tukey's far fence (3 interquartile ranges past the third quartile) on the
// logarithm of each point's distance to its nearest other position.
constexpr double IsolatedFence = 3.0;
// The interquartile range is taken as at least a random sampling's: the nearest distance of a
// uniform random (Poisson) sampling of a surface has quartiles 0.605 and 1.328 times its mean,
// log(1.328 / 0.605) = 0.786. A grid's is 0, which would call every point a spacing and a
// rounding away isolated; no sampling of a surface leaves its points more isolated than a
// random one.
constexpr double RandomSpread = 0.786;
// Nearest points that are a surface: their RMS thickness across their plane is less than half
// their RMS spread along it (a scatter through a volume spreads about as much every way).
constexpr double SurfaceThickness = 0.5;
constexpr int MaxOutlierRuns = 3;   // runs on the kept points, the first included
// A neighbourhood is two sheets (the sides of a wall thinner than it) where the two-means split
// of its heights along its plane's normal (SplitHeights) puts the groups' means more than
// SheetSplitSigmas times their pooled RMS apart (the best split of 16 heights of pure Gaussian
// noise exceeds 6 with probability about 1e-3, a curved patch's about 1e-2; two-means finds
// that split or a worse one) and the groups lie over each other: their centroids,
// projected on the plane, less than SheetOverlap times the projected RMS radius apart. A step's
// two levels lie side by side (about 1.2 at a step through the point), a wall's sides about 0.3.
constexpr double SheetSplitSigmas = 6.0;
constexpr double SheetOverlap = 0.6;
// Rounds of the two-plane assignment.
constexpr int MaximumRounds = 8;
// Rounds of the refit by side of the crease line.
constexpr int SideRounds = 3;
// A model explains a neighbourhood when its residual, in noise variances, stays within
// MisfitSigmas standard deviations of what noise alone leaves: a chi-square over the degrees of
// freedom, dof + MisfitSigmas sqrt(2 dof) (exceeded by pure noise with probability about 1e-3).
// A fixed multiple of dof would let a wrong model (one hinge through two creases a few
// spacings apart, a crease cut by a wall's other side) explain 150 noisy points: there the
// misfit of the few points it does not fit hides in a bound twice the noise.
constexpr double MisfitSigmas = 3.0;
inline double MisfitBound(int dof)
{
  const double n = std::max(dof, 1);
  return n + MisfitSigmas * std::sqrt(2.0 * n);
}
// The vote's band is widened by this many noise widths (in quadrature with BandWidth d): a point
// is moved across a crease line by the noise within two of them in 86 % of draws under isotropic
// noise (the Rayleigh law of its 2-D displacement in the cross-section), 95 % under noise along
// the normals.
constexpr double BandNoiseSigmas = 2.0;
// The cubic height field (10 coefficients) stands for a smooth surface only where the points are
// at least CubicPointsPerTerm per coefficient: with fewer it bends into a crease (at 10 points it
// interpolates them; at 20-37 it explains most creases).
constexpr int CubicPointsPerTerm = 10;
// Two planes of the nearest-plane fit within 10 degrees of parallel and more than 4 times their
// residual's RMS apart at the fitted point are two sheets (a thin wall), not a crease: a split of
// pure Gaussian noise puts its planes 2.7 RMS apart.
const double SheetCosine = std::cos(10.0 * 3.14159265358979323846 / 180.0);
constexpr double SheetSeparation = 4.0;
// The noise figure's trimmed median (TrimmedMedian): the rows at most the 95 % point of the
// pure-noise law (chi-square over its degrees of freedom) scaled to the current estimate; their
// median is that law's 47.5 % point. The standard normal's quantiles at both shares, for Wilson
// and Hilferty's approximation (ChiSquareShare).
constexpr double NoiseTrimZ = 1.6448536;      // 0.95
constexpr double NoiseTrimHalfZ = -0.0627068; // 0.475
constexpr int NoiseTrimRounds = 100;
// The noise figure across the surface (MeasureNoiseAcross): the search ball reaches the radius
// of the point's nearest across the surface widened by this many standard deviations of a
// height difference between two points (sqrt 2 sigma), so that it misses none of them; at most
// NoiseSearchPasses searches, each from the figure of the one before.
constexpr double NoiseHeightSpread = 3.0 * 1.4142135623730951;
constexpr int NoiseSearchPasses = 3;
// The nearest-plane fit stands for two surfaces crossing (four half-planes at the line) only where
// each of its planes holds at least CrossingShare of the neighbourhood on either side of the line,
// counting only points more than CrossingSigmas noise widths from the other plane: points that the
// noise cannot have handed to the nearer plane. Elsewhere the nearest-plane assignment fits the
// noise itself (two planes a noise width apart above and below a face leave about a third of its
// residual) and would "explain" any neighbourhood.
constexpr double CrossingShare = 0.05;
constexpr double CrossingSigmas = 3.0;
// Links of the one-sheet neighbourhoods: each point to its 5 nearest. On a randomly sampled
// surface these reach about 2.5 mean spacings: walls thicker than about 5 spacings keep their
// sides apart (4 links split noisy single sheets; 6 join the walls of PCEDNet's abc/7010).
constexpr int SheetLinks = 5;
// Where those 5 lie on one line with the point (sampling in scan lines: a terrestrial or mobile
// lidar's rows, a line scanner's profiles, rows farther apart than 5 points along them), two links
// more join it to the nearest points of its KNear nearest off that line, on either side: else
// every row is a sheet of its own, a line that no plane or crease model fits. One line: the
// second principal spread of the 6 points under CollinearSpread of the first (a random sampling
// of a surface leaves about a third).
constexpr int LinkSlots = SheetLinks + 2;
constexpr double CollinearSpread = 0.05;
// Where the KNear nearest hold no point of the next row on one side (rows more than about 6 points
// apart), the links across are taken from this many nearest: rows up to about 20 points apart.
constexpr int AcrossRowsNeighbors = 50;
// A fit votes only where its hinge explains more than this many noise variances beyond one plane.
// The gate used to be the cloud's median gain, taken as what a fit gains by chance; with 150
// neighbours (the default) the angle and the line decide: gates of 1, 4, 10 and 25 give the same
// F1 within 0.003 on every part and smooth shape of the quality probes. The median
// failed where most points lie within a neighbourhood of a crease (features sampled denser, small
// clouds): it was then a crease's gain, and the shallow creases fell below it.
constexpr double MinimumGain = 1.0;
// Neighbours through which the hysteresis step connects points, and among which the thinning
// compares points across a curve.
constexpr int ConnectionNeighbors = 8;
// A point that one plane explains is fitted all the same when one of its ViewNeighbors nearest on
// its sheet is not: a feature in view, about 7 spacings away or nearer (the 150 nearest reach
// about 14). On Model I at 160,000 points the mask is the same with 40, 75 and 150 (3 points
// differ with 20), and 40 takes 15 % off the detector's CPU time against 150.
constexpr int ViewNeighbors = 40;
// The smallest neighbourhood of the scale per point (a hinge of 2 x 3 parameters through noise).
constexpr int SmallestScale = 20;
// A side of the curved hinge is a face when its quadric turns by at most a radian over the
// side's radius (largest principal curvature times the radius): a cylinder's side, a large fillet.
// A quadric that bends more is fitting a rib, a groove or a small fillet, which are features.
// (On parallel creases 3 and 5 s apart at sigma 0.25 s, the share of the points within 1 s of a
// crease that are found falls by at most 0.025 against no curved hinge with this bound, 0.032 with
// 2 radians, 0.11 with 4 and 0.12 with none.)
constexpr double MaximumFaceBend = 1.0;
constexpr double Pi = 3.14159265358979323846;
// Borders: the point's BorderNeighbors nearest leave an empty sector wider than BorderGap in the
// tangent plane. n random directions around an interior point leave a gap above 90 degrees with
// probability about n (3/4)^(n-1): 4e-5 for n = 50, fifty times below the 2 per 1000 allowed on
// smooth shapes. The strip between a point and the border holds points too, so the sector is
// empty only for the outermost row, about 1-2 spacings wide whatever n (measured with 120
// degrees: 93 % of the points within 1 s of the border, 60 % between 1 and 2 s); the band is
// then the points within BandWidth d of that row. The gaps of a random sampling are not
// independent: the rim of a void in the sampling shows a gap too (0.7 points per 1000 on a
// noisy plane at 120 degrees). Such a rim is a small closed ring inside one neighbourhood, a
// border a curve that runs on: connected border points (each linked to the border points among
// its BorderNeighbors / 2 nearest) fewer than BorderNeighbors / 2 are dropped.
constexpr int BorderNeighbors = 50;
constexpr double BorderGap = 2.0 * Pi / 3.0;
// Corners: the directions t of the feature points around a point spread: the share of the mean
// of t t^T (trace 1) off its main direction, 1 minus its largest eigenvalue, above CornerSpread,
// over at least MinimumCornerDirections feature points. Two curves at an angle theta holding
// shares f and 1 - f of the points give (1 - sqrt(1 - 4 f (1 - f) sin^2 theta)) / 2: min(f, 1 - f)
// at 90 degrees, 0.25 for equal shares at 60 degrees; three curves at right angles with shares
// f1 >= f2 >= f3, 1 - f1 (2/3 for equal shares); one curve bending by +-a across the
// neighbourhood about a^2 / 3 (0.18 needs a bend of +-42 degrees). The middle eigenvalue alone,
// used before, is f2 at a three-curve corner: the corners of boxes and brackets, where one crease
// near the corner has most of the directions (f1 0.7, f2 and f3 0.15), went untyped.
constexpr double CornerSpread = 0.18;
constexpr int MinimumCornerDirections = 6;
// The directions come from the feature points within CornerReachScales radii of the point's
// SmallestScale nearest (on its sheet). Around a corner no fit of even the smallest scale is
// explained within about that radius, so the creases that meet there give no direction there;
// a point near the corner must reach past that zone along each of them by as much again to
// collect comparable samples of each.
constexpr double CornerReachScales = 2.0;

// Moments of a set of points: count, sum, sum of outer products (upper triangle). The points are
// relative to the fitted point, a few spacings long, so the one-pass covariance loses nothing.
// Tukey's far fence of the logarithms of the points' distances to their nearest other position
// (`gap`, -1 for none): the third quartile plus IsolatedFence interquartile ranges, the range at
// least RandomSpread. Infinite with fewer than 4 figures.
double IsolationFence(const std::vector<float>& gap)
{
  std::vector<float> logs;
  logs.reserve(gap.size());
  std::copy_if(
    gap.begin(), gap.end(), std::back_inserter(logs), [](float g) { return g != -1.0f; });
  if (logs.size() < 4)
  {
    return std::numeric_limits<double>::infinity();
  }
  auto quartile = [&logs](size_t at) {
    std::nth_element(logs.begin(), logs.begin() + at, logs.end());
    return static_cast<double>(logs[at]);
  };
  const double q1 = quartile(logs.size() / 4), q3 = quartile(3 * logs.size() / 4);
  return q3 + IsolatedFence * std::max(q3 - q1, RandomSpread);
}

struct Moments
{
  int Count = 0;
  double S[3] = { 0.0, 0.0, 0.0 };
  double SS[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }; // xx xy xz yy yz zz

  void Add(const Eigen::Vector3d& p)
  {
    ++this->Count;
    this->S[0] += p[0];
    this->S[1] += p[1];
    this->S[2] += p[2];
    this->SS[0] += p[0] * p[0];
    this->SS[1] += p[0] * p[1];
    this->SS[2] += p[0] * p[2];
    this->SS[3] += p[1] * p[1];
    this->SS[4] += p[1] * p[2];
    this->SS[5] += p[2] * p[2];
  }
};

// Least-squares plane of a set of points from its moments: centroid, unit normal, residual sum of
// squares. Returns false with fewer than 3 points.
bool FitPlane(const Moments& m, Eigen::Vector3d& centroid, Eigen::Vector3d& normal, double& rss)
{
  if (m.Count < 3)
  {
    return false;
  }
  centroid = Eigen::Vector3d(m.S[0], m.S[1], m.S[2]) / m.Count;
  Eigen::Matrix3d cov;
  cov(0, 0) = m.SS[0] - m.S[0] * centroid[0];
  cov(0, 1) = m.SS[1] - m.S[0] * centroid[1];
  cov(0, 2) = m.SS[2] - m.S[0] * centroid[2];
  cov(1, 1) = m.SS[3] - m.S[1] * centroid[1];
  cov(1, 2) = m.SS[4] - m.S[1] * centroid[2];
  cov(2, 2) = m.SS[5] - m.S[2] * centroid[2];
  cov(1, 0) = cov(0, 1);
  cov(2, 0) = cov(0, 2);
  cov(2, 1) = cov(1, 2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov);
  normal = solver.eigenvectors().col(0);
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  normal /= length;
  rss = std::max(solver.eigenvalues()[0], 0.0);
  return true;
}

// Residual of the least-squares polynomial height field over the plane (c, n) (u, v along the
// plane, h along n): Terms = 6, the quadric h = a u^2 + b uv + c v^2 + d u + e v + f, what a
// smooth surface explains; Terms = 10 adds the cubic terms u^3, u^2 v, u v^2, v^3 (a free-form
// face whose curvature changes across the neighbourhood). A crease is a bend that no smooth
// surface of the neighbourhood's size explains; a cylinder or a sphere is explained by the quadric
// however strongly curved. Falls back on `planeRss` when singular.
// `across`: each height residual divided by sqrt(1 + |grad h|^2), the first-order distance to the
// surface across it (Sampson's), as the planes' residuals are measured; the height alone counts
// the noise of a steep patch 1 + slope^2 times (see Explains and the gain).
template <int Terms = 6>
double FitHeights(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& c,
  const Eigen::Vector3d& n, double planeRss, double* bend = nullptr, bool across = true)
{
  static_assert(Terms == 6 || Terms == 10, "a quadric or a cubic height field");
  using Row = Eigen::Matrix<double, Terms, 1>;
  if (bend)
  {
    *bend = 0.0;
  }
  const Eigen::Vector3d e1 = n.unitOrthogonal();
  const Eigen::Vector3d e2 = n.cross(e1);
  // The largest squared distance, then its root: the root of each (norm()) is the same maximum,
  // since the square root is monotone.
  double radius2 = 0.0;
  for (const Eigen::Vector3d& q : p)
  {
    radius2 = std::max(radius2, (q - c).squaredNorm());
  }
  const double radius = std::sqrt(radius2);
  if (!(radius > 0.0))
  {
    return planeRss;
  }
  // Coordinates in units of the neighbourhood's radius: the normal equations stay conditioned.
  auto row = [&](const Eigen::Vector3d& q, double& h) {
    const Eigen::Vector3d w = (q - c) / radius;
    const double u = w.dot(e1), v = w.dot(e2);
    h = w.dot(n);
    Row a;
    if constexpr (Terms == 6)
    {
      a << u * u, u * v, v * v, u, v, 1.0;
    }
    else
    {
      a << u * u, u * v, v * v, u, v, 1.0, u * u * u, u * u * v, u * v * v, v * v * v;
    }
    return a;
  };
  // The rows are kept for the residual's pass (this thread's scratch: no allocation per fit).
  // Read through a pointer taken once: each use of a thread_local of a shared library is a call
  // (__tls_get_addr), which the compiler repeats inside the loops (450 calls per fit).
  thread_local std::vector<Eigen::Matrix<double, Terms + 1, 1>> threadRows;
  threadRows.resize(p.size());
  Eigen::Matrix<double, Terms + 1, 1>* const rows = threadRows.data();
  Eigen::Matrix<double, Terms, Terms> ata = Eigen::Matrix<double, Terms, Terms>::Zero();
  Row ath = Row::Zero();
  double h = 0.0;
  for (size_t j = 0; j < p.size(); ++j)
  {
    const Row a = row(p[j], h);
    rows[j] << a, h;
    // The lower triangle of a a^T, as Eigen's rankUpdate adds it, written out to be inlined.
    for (int c = 0; c < Terms; ++c)
    {
      for (int l = c; l < Terms; ++l)
      {
        ata(l, c) += a[c] * a[l];
      }
    }
    ath += h * a;
  }
  const Eigen::LDLT<Eigen::Matrix<double, Terms, Terms>> solver(
    ata.template selfadjointView<Eigen::Lower>());
  if (solver.info() != Eigen::Success || !(solver.vectorD().minCoeff() > 1e-12 * p.size()))
  {
    return planeRss;
  }
  const Row x = solver.solve(ath);
  if (bend)
  {
    // The largest principal curvature at the fitted point times the radius (coordinates are in
    // radii).
    Eigen::Matrix2d hessian;
    hessian << 2.0 * x[0], x[1], x[1], 2.0 * x[2];
    *bend = hessian.eigenvalues().cwiseAbs().maxCoeff();
  }
  double rss = 0.0;
  for (size_t j = 0; j < p.size(); ++j)
  {
    const Eigen::Matrix<double, Terms + 1, 1>& a = rows[j];
    const double r = a.template head<Terms>().dot(x) - a[Terms];
    if (across)
    {
      // a = (u^2, uv, v^2, u, v, 1[, u^3, u^2 v, u v^2, v^3]): the gradient of the fitted height
      // at (u, v).
      const double u = a[3], v = a[4];
      double gu = 2.0 * x[0] * u + x[1] * v + x[3];
      double gv = x[1] * u + 2.0 * x[2] * v + x[4];
      if constexpr (Terms == 10)
      {
        gu += 3.0 * x[6] * u * u + 2.0 * x[7] * u * v + x[8] * v * v;
        gv += x[7] * u * u + 2.0 * x[8] * u * v + 3.0 * x[9] * v * v;
      }
      rss += r * r / (1.0 + gu * gu + gv * gv);
    }
    else
    {
      rss += r * r;
    }
  }
  rss *= radius * radius;
  return std::isfinite(rss) ? std::min(rss, planeRss) : planeRss;
}

// The quadric height field's residual (FitHeights<6>).
double FitQuadric(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& c,
  const Eigen::Vector3d& n, double planeRss, double* bend = nullptr, bool across = true)
{
  return FitHeights<6>(p, c, n, planeRss, bend, across);
}

// The scale of a stored ray's components (CreaseLine::Rays).
constexpr double RayUnit = 32767.0;

// One two-plane model of a neighbourhood: its residual and the line where its planes meet.
struct CreaseLine
{
  double RSS2 = 0.0;  // residual of the two planes
  float Angle = 0.0f; // degrees
  bool HasLine = false;
  float LinePoint[3] = { 0.0f, 0.0f, 0.0f }; // relative to the point
  float LineDirection[3] = { 0.0f, 0.0f, 0.0f };
  // Unit directions from the line into each half-plane, across the line (towards the centroid
  // of each half's points): with the line, the hinge's cross-section. Components in units of
  // 1/RayUnit (a fit is stored for every point near a feature: 12 bytes, not 24).
  int16_t Rays[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
  // The planes' centroids lie on the inner side of the line (against the fitted point's normal):
  // a convex crease. False for a concave one.
  bool Convex = true;
};

struct CreaseFit
{
  double RSS1 = 0.0; // residual of one plane
  double RSSQ = 0.0; // residual of one smooth quadric height field over that plane
  CreaseLine Hinge;  // two half-planes, points split by the side of the line they lie on
  CreaseLine Cross;  // two whole planes, points split by the nearer plane
  int Points = 0;    // points fitted
  int Sheet = -1;    // two parallel sheets (a thin wall): the fitted point's sheet (0, 1)
  bool Crossing = false; // the nearest planes cross within the neighbourhood (see CrossingShare)
  bool Explained = true; // a quadric or the hinge explains the points within the noise
};

// The line where the planes (ca, na) and (cb, nb) meet: its point nearest the origin x, its unit
// direction t and the sine of the planes' angle. False when they are (nearly) parallel.
bool MeetingLine(const Eigen::Vector3d& ca, const Eigen::Vector3d& na, const Eigen::Vector3d& cb,
  const Eigen::Vector3d& nb, Eigen::Vector3d& x, Eigen::Vector3d& t, double& sine)
{
  t = na.cross(nb);
  sine = t.norm();
  if (!(sine > 1e-6))
  {
    return false;
  }
  t /= sine;
  // na.x = na.ca, nb.x = nb.cb, t.x = 0.
  Eigen::Matrix3d a;
  a.row(0) = na.transpose();
  a.row(1) = nb.transpose();
  a.row(2) = t.transpose();
  x = a.colPivHouseholderQr().solve(Eigen::Vector3d(na.dot(ca), nb.dot(cb), 0.0));
  return x.allFinite();
}

void StoreLine(CreaseLine& line, double rss2, double sine, bool hasLine, const Eigen::Vector3d& x,
  const Eigen::Vector3d& t, const Eigen::Vector3d& ca, const Eigen::Vector3d& cb,
  const Eigen::Vector3d& normal)
{
  line.RSS2 = rss2;
  // Convex when the faces fall away from the line on the inner side of the point's normal.
  Eigen::Vector3d inward = 0.5 * (ca + cb) - x;
  inward -= inward.dot(t) * t;
  line.Convex = !hasLine || inward.dot(normal) <= 0.0;
  line.Angle = static_cast<float>(std::asin(std::min(sine, 1.0)) * 180.0 / 3.14159265358979323846);
  line.HasLine = hasLine;
  for (int c = 0; c < 3; ++c)
  {
    line.LinePoint[c] = hasLine ? static_cast<float>(x[c]) : 0.0f;
    line.LineDirection[c] = hasLine ? static_cast<float>(t[c]) : 0.0f;
  }
  const Eigen::Vector3d* centroids[2] = { &ca, &cb };
  for (int k = 0; k < 2; ++k)
  {
    Eigen::Vector3d ray = *centroids[k] - x;
    ray -= ray.dot(t) * t;
    const double length = ray.norm();
    for (int c = 0; c < 3; ++c)
    {
      line.Rays[k][c] =
        hasLine && length > 0.0 ? static_cast<int16_t>(std::lround(RayUnit * ray[c] / length)) : 0;
    }
  }
}

// Whether the nearest planes (ca, na), (cb, nb), meeting on the line (x, t), cross: each holds
// points on both sides of the line beyond the noise of the other plane (see CrossingShare).
bool Crosses(const std::vector<Eigen::Vector3d>& p, const std::vector<unsigned char>& label,
  const Eigen::Vector3d& ca, const Eigen::Vector3d& na, const Eigen::Vector3d& cb,
  const Eigen::Vector3d& nb, const Eigen::Vector3d& x, const Eigen::Vector3d& t, double variance)
{
  int sides[2][2] = { { 0, 0 }, { 0, 0 } };
  const Eigen::Vector3d along[2] = { na.cross(t), nb.cross(t) };
  const double oa = ca.dot(na), ob = cb.dot(nb);
  const double beyond = CrossingSigmas * CrossingSigmas * variance;
  for (size_t j = 0; j < p.size(); ++j)
  {
    const int k = label[j];
    const double other = k == 0 ? p[j].dot(nb) - ob : p[j].dot(na) - oa;
    if (other * other > beyond)
    {
      ++sides[k][(p[j] - x).dot(along[k]) >= 0.0 ? 0 : 1];
    }
  }
  const double least = CrossingShare * static_cast<double>(p.size());
  return std::min(std::min(sides[0][0], sides[0][1]), std::min(sides[1][0], sides[1][1])) >= least;
}

// Moments of the points on each side of the plane through x with normal `across`.
void SplitMoments(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& x,
  const Eigen::Vector3d& across, Moments half[2])
{
  half[0] = Moments();
  half[1] = Moments();
  for (const Eigen::Vector3d& q : p)
  {
    half[(q - x).dot(across) >= 0.0 ? 0 : 1].Add(q);
  }
}

// A hinge: the planes of two halves of the points and the line where they meet.
struct Hinge
{
  Eigen::Vector3d A, NA, B, NB, X, T;
  double Sine = 0.0;
  double RSS = -1.0; // negative: no hinge formed
};

// The hinge refined from a first partition `half`: the planes of both halves, their line, and
// the points split again by the bisector through the line that separates the two faces (normal
// na - nb, both normals turned to `up`), SideRounds times. Splitting by position across the line
// and never by height keeps the fit off the noise: a split into the points above and below a face
// would gain a share of the noise. Where a split leaves a side too few points for a plane, the
// last hinge stands; where the planes turn parallel, no hinge forms (RSS negative).
Hinge RefineHinge(const std::vector<Eigen::Vector3d>& p, Moments half[2], const Eigen::Vector3d& up)
{
  Hinge best, h;
  for (int round = 0; round <= SideRounds; ++round)
  {
    double qa = 0.0, qb = 0.0;
    if (!FitPlane(half[0], h.A, h.NA, qa) || !FitPlane(half[1], h.B, h.NB, qb))
    {
      break;
    }
    h.NA = h.NA.dot(up) < 0.0 ? Eigen::Vector3d(-h.NA) : h.NA;
    h.NB = h.NB.dot(up) < 0.0 ? Eigen::Vector3d(-h.NB) : h.NB;
    if (!MeetingLine(h.A, h.NA, h.B, h.NB, h.X, h.T, h.Sine))
    {
      return Hinge();
    }
    h.RSS = qa + qb;
    best = h;
    if (round == SideRounds)
    {
      break;
    }
    Eigen::Vector3d across = h.NA - h.NB;
    if ((h.A - h.X).dot(across) < 0.0)
    {
      across = -across; // face a's side is where its centroid lies
    }
    SplitMoments(p, h.X, across, half);
  }
  return best;
}

// The hinge started from the cut through the centroid c of the points p, across the direction e
// in which their normals vary most (less its part along the plane's normal n), refined by
// position (RefineHinge); none (RSS negative) where e is along n.
Hinge CutHinge(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& c,
  const Eigen::Vector3d& n, const Eigen::Vector3d& e)
{
  const Eigen::Vector3d cut = e - e.dot(n) * n;
  if (!(cut.squaredNorm() > 0.0))
  {
    return Hinge();
  }
  Moments half[2];
  SplitMoments(p, c, cut, half);
  return RefineHinge(p, half, n);
}

// Whether the hinge h formed and its line passes within the neighbourhood p (no farther from the
// fitted point than its farthest point): a line outside it is no crease of it, but two nearly
// parallel planes through the noise.
bool HingeWithin(const Hinge& h, const std::vector<Eigen::Vector3d>& p)
{
  double reach = 0.0;
  for (const Eigen::Vector3d& q : p)
  {
    reach = std::max(reach, q.squaredNorm());
  }
  return h.RSS >= 0.0 && h.X.squaredNorm() <= reach;
}

// The split of the points p in two groups by their heights along n: two-means in one dimension
// (a threshold halfway between the groups' means, from the mean height, until the groups hold
// still), label[j] 0 for the lower group, 1 for the upper. Returns the squared distance of the
// groups' mean heights over their pooled variance (0 where one group is empty). A linear pass
// per round: a sort of the heights was a tenth of the two-plane fit's time.
double SplitHeights(
  const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& n, std::vector<unsigned char>& label)
{
  const size_t m = p.size();
  label.assign(m, 0);
  if (m < 3)
  {
    return 0.0;
  }
  thread_local std::vector<double> threadHeights; // read through a pointer (see FitHeights)
  threadHeights.resize(m);
  double* const heights = threadHeights.data();
  double total = 0.0;
  for (size_t j = 0; j < m; ++j)
  {
    heights[j] = p[j].dot(n);
    total += heights[j];
  }
  double threshold = total / m;
  double sum[2] = { 0.0, 0.0 }, sum2[2] = { 0.0, 0.0 };
  size_t count[2] = { 0, 0 };
  for (int round = 0; round < MaximumRounds; ++round)
  {
    sum[0] = sum[1] = sum2[0] = sum2[1] = 0.0;
    count[0] = count[1] = 0;
    bool changed = false;
    for (size_t j = 0; j < m; ++j)
    {
      const unsigned char g = heights[j] > threshold ? 1 : 0;
      changed = changed || g != label[j];
      label[j] = g;
      sum[g] += heights[j];
      sum2[g] += heights[j] * heights[j];
      ++count[g];
    }
    if (count[0] == 0 || count[1] == 0)
    {
      return 0.0;
    }
    const double next = 0.5 * (sum[0] / count[0] + sum[1] / count[1]);
    if ((!changed && round > 0) || next == threshold)
    {
      break;
    }
    threshold = next;
  }
  const double apart = sum[1] / count[1] - sum[0] / count[0];
  const double within =
    sum2[0] - sum[0] * sum[0] / count[0] + sum2[1] - sum[1] * sum[1] / count[1];
  const double variance = std::max(within, 0.0) / (m - 2);
  return variance > 0.0 ? apart * apart / variance : std::numeric_limits<double>::infinity();
}

// Whether SplitHeights()' groups (label) of p, with squared separation `separation`, are the two
// sides of a wall: far apart for their spread and lying over each other (see SheetOverlap).
bool TwoSheets(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& n,
  const std::vector<unsigned char>& label, double separation)
{
  if (!(separation > SheetSplitSigmas * SheetSplitSigmas))
  {
    return false;
  }
  Eigen::Vector3d sum[2] = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() };
  int count[2] = { 0, 0 };
  double spread = 0.0;
  for (size_t j = 0; j < p.size(); ++j)
  {
    const Eigen::Vector3d t = p[j] - p[j].dot(n) * n;
    sum[label[j]] += t;
    ++count[label[j]];
    spread += t.squaredNorm();
  }
  if (count[0] == 0 || count[1] == 0)
  {
    return false;
  }
  const double m = static_cast<double>(p.size());
  const Eigen::Vector3d center = (sum[0] + sum[1]) / m;
  spread = spread / m - center.squaredNorm();
  const Eigen::Vector3d offset = sum[0] / count[0] - sum[1] / count[1];
  return offset.squaredNorm() < SheetOverlap * SheetOverlap * spread;
}

// Whether planes a (ca, na) and b (cb, nb) are two sheets, not a crease: within 10 degrees of
// parallel and more than SheetSeparation times `rms` apart at the origin (the fitted point);
// `nearer` gets the one the origin lies nearer to.
bool ParallelApart(const Eigen::Vector3d& ca, const Eigen::Vector3d& na, const Eigen::Vector3d& cb,
  const Eigen::Vector3d& nb, double rms, int& nearer)
{
  if (!(std::abs(na.dot(nb)) > SheetCosine))
  {
    return false;
  }
  // Signed offsets of the fitted point (the origin) from the planes, both normals one way.
  const double sa = -ca.dot(na), sb = -cb.dot(na.dot(nb) < 0.0 ? -nb : nb);
  nearer = std::abs(sa) <= std::abs(sb) ? 0 : 1;
  return std::abs(sa - sb) > SheetSeparation * rms;
}

// Whether p holds the two sides of a wall that SplitHeights() separates but TwoSheets() does
// not take: the far side a few points off to one side of the fitted point (p[0]), as where the
// wall is about as thick as the links reach and the smaller scales gather a few of its points.
// Two rounds of heights (the first `label`, across the plane of all; the second across the
// plane of the point's group, which the far side's points tilt in the first), more than
// SheetSplitSigmas apart for their spread, and the groups' planes ParallelApart() at their
// residual's RMS (as FitCrease() tells two sheets from a crease). `sheets` gets the second
// round's groups.
bool ParallelSheets(const std::vector<Eigen::Vector3d>& p, const std::vector<unsigned char>& label,
  std::vector<unsigned char>& sheets)
{
  Moments own;
  for (size_t j = 0; j < p.size(); ++j)
  {
    if (label[j] == label[0])
    {
      own.Add(p[j]);
    }
  }
  Eigen::Vector3d c, n;
  double rss = 0.0;
  if (!FitPlane(own, c, n, rss) ||
    !(SplitHeights(p, n, sheets) > SheetSplitSigmas * SheetSplitSigmas))
  {
    return false;
  }
  Moments group[2];
  for (size_t j = 0; j < p.size(); ++j)
  {
    group[sheets[j]].Add(p[j]);
  }
  Eigen::Vector3d ca, na, cb, nb;
  double ra = 0.0, rb = 0.0;
  int nearer = 0;
  return FitPlane(group[0], ca, na, ra) && FitPlane(group[1], cb, nb, rb) &&
    ParallelApart(ca, na, cb, nb, std::sqrt((ra + rb) / static_cast<double>(p.size())), nearer);
}

// The least-squares plane of all the points p (FitPlane); false with fewer than 8.
bool PlaneOfAll(
  const std::vector<Eigen::Vector3d>& p, Eigen::Vector3d& c, Eigen::Vector3d& n, double& rss)
{
  Moments all;
  for (const Eigen::Vector3d& q : p)
  {
    all.Add(q);
  }
  return p.size() >= 8 && FitPlane(all, c, n, rss);
}

// The direction in which the normals nr, turned to the side of n, vary most: the principal axis of
// their spread. oriented: the turned normals less their mean (this thread's scratch, valid until
// the next call).
Eigen::Vector3d NormalsSpread(const std::vector<Eigen::Vector3d>& nr, const Eigen::Vector3d& n,
  const Eigen::Vector3d** oriented = nullptr)
{
  const size_t m = nr.size();
  thread_local std::vector<Eigen::Vector3d> threadOriented; // through a pointer (FitHeights)
  threadOriented.resize(m);
  Eigen::Vector3d* const turned = threadOriented.data();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < m; ++j)
  {
    turned[j] = nr[j].dot(n) < 0.0 ? -nr[j] : nr[j];
    mean += turned[j];
  }
  mean /= static_cast<double>(m);
  featurepoints::OuterSum sum;
  for (size_t j = 0; j < m; ++j)
  {
    turned[j] -= mean;
    sum.Add(turned[j]);
  }
  const Eigen::Matrix3d spread = sum.Matrix();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(spread);
  if (oriented)
  {
    *oriented = turned;
  }
  return solver.eigenvectors().col(2);
}

// Two-plane fit of one neighbourhood: p[0] is the point (the origin), nr the normals, variance
// the noise variance.
CreaseFit FitCrease(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& nr,
  double variance, std::vector<unsigned char>& label, std::vector<unsigned char>& next, bool cubic)
{
  CreaseFit fit;
  fit.Points = static_cast<int>(p.size());
  const size_t m = p.size();
  label.assign(m, 0);
  Eigen::Vector3d c1, n1;
  double rss1 = 0.0;
  if (!PlaneOfAll(p, c1, n1, rss1))
  {
    return fit;
  }
  // Split by the direction in which the (consistently oriented) normals vary most.
  const Eigen::Vector3d* oriented = nullptr;
  const Eigen::Vector3d e = NormalsSpread(nr, n1, &oriented);
  Moments side[2];
  for (size_t j = 0; j < m; ++j)
  {
    label[j] = oriented[j].dot(e) >= 0.0 ? 0 : 1;
  }
  // Two sheets (a wall thinner than the neighbourhood) have no direction in which the normals
  // vary: there the split starts from the sheets (else the rounds settle on two planes crossing
  // between them, a crease that is not there).
  thread_local std::vector<unsigned char> sheets, apart;
  if (TwoSheets(p, n1, sheets, SplitHeights(p, n1, sheets)))
  {
    label = sheets;
  }
  else if (ParallelSheets(p, sheets, apart))
  {
    label = apart;
  }
  for (size_t j = 0; j < m; ++j)
  {
    side[label[j]].Add(p[j]);
  }
  // Planes and nearest-plane assignment until the split settles; each pass over the points
  // assigns them and gathers the moments of the next round's planes.
  Eigen::Vector3d ca, na, cb, nb;
  double ra = 0.0, rb = 0.0, rss2 = rss1;
  bool fitted = false;
  next.resize(m);
  for (int round = 0; round < MaximumRounds; ++round)
  {
    if (!FitPlane(side[0], ca, na, ra) || !FitPlane(side[1], cb, nb, rb))
    {
      break;
    }
    fitted = true;
    double rss = 0.0;
    bool changed = false;
    Moments nextSide[2];
    const double oa = ca.dot(na), ob = cb.dot(nb);
    for (size_t j = 0; j < m; ++j)
    {
      const double da = p[j].dot(na) - oa;
      const double db = p[j].dot(nb) - ob;
      next[j] = da * da <= db * db ? 0 : 1;
      rss += std::min(da * da, db * db);
      changed = changed || next[j] != label[j];
      nextSide[next[j]].Add(p[j]);
    }
    rss2 = rss;
    if (!changed)
    {
      break;
    }
    label.swap(next);
    side[0] = nextSide[0];
    side[1] = nextSide[1];
  }
  fit.RSS1 = rss1;
  fit.RSSQ = FitQuadric(p, c1, n1, rss1);
  if (!fitted)
  {
    fit.Hinge.RSS2 = fit.Cross.RSS2 = rss1;
    return fit;
  }
  // Two parallel sheets a few noise widths apart, the fitted point on one of them: both sides
  // of a thin wall are in the neighbourhood. The caller fits the point's sheet alone.
  int nearer = 0;
  if (ParallelApart(ca, na, cb, nb, std::sqrt(rss2 / static_cast<double>(m)), nearer))
  {
    fit.Sheet = nearer;
  }
  Eigen::Vector3d t, x;
  double sine = 0.0;
  bool hasLine = MeetingLine(ca, na, cb, nb, x, t, sine);
  StoreLine(fit.Cross, rss2, sine, hasLine, x, t, ca, cb, nr[0]);
  fit.Crossing = hasLine && Crosses(p, label, ca, na, cb, nb, x, t, variance);
  // The nearest-plane assignment fits noise too: each point picks the plane nearer to it, so on a
  // flat noisy patch two planes "gain" a large share of the residual, and a shallow crease hides
  // in that. The hinge model is fitted on a partition by position instead (RefineHinge), from two
  // starts: the nearest-plane halves, and a cut through the centroid across the direction in
  // which the normals vary. The lower residual wins. On pure noise it gains what a hinge gains by
  // chance (a few sigma^2); on a crease of any angle it keeps the whole bend. Where surfaces cross
  // (four half-planes at the line) it cannot fit, and the caller falls back on the crossing
  // planes.
  Moments half[2];
  for (size_t j = 0; j < m; ++j)
  {
    half[label[j]].Add(p[j]);
  }
  const Hinge fromPlanes = RefineHinge(p, half, n1);
  const Hinge fromCut = CutHinge(p, c1, n1, e);
  const Hinge& h = fromCut.RSS >= 0.0 && (fromPlanes.RSS < 0.0 || fromCut.RSS < fromPlanes.RSS)
    ? fromCut
    : fromPlanes;
  hasLine = HingeWithin(h, p);
  if (hasLine)
  {
    rss2 = h.RSS;
    ca = h.A;
    cb = h.B;
    x = h.X;
    t = h.T;
    sine = h.Sine;
  }
  else
  {
    rss2 = rss1;
  }
  StoreLine(fit.Hinge, rss2, sine, hasLine, x, t, ca, cb, nr[0]);
  // A free-form face (a blend, a turbine blade, a car's body panel): its curvature changes across
  // a wide neighbourhood, so that neither the quadric nor the planes explain it within the noise
  // and the hinge gains on the quadric as on a crease. Where nothing else explains the points, a
  // cubic height field that does (within the bound of its 10 parameters) stands for the smooth
  // surface. Only where asked (the widest scale): a crease seen from a neighbourhood small enough
  // to be explained by a cubic would be lost.
  if (cubic && fit.Points >= CubicPointsPerTerm * 10)
  {
    const double crossing = fit.Crossing ? fit.Cross.RSS2 : fit.RSSQ;
    if (std::min(std::min(fit.RSSQ, fit.Hinge.RSS2), crossing) >
      MisfitBound(fit.Points - 6) * variance)
    {
      const double rssc = FitHeights<10>(p, c1, n1, rss1);
      if (rssc <= MisfitBound(fit.Points - 10) * variance)
      {
        fit.RSSQ = std::min(fit.RSSQ, rssc);
      }
    }
  }
  return fit;
}

// The hinge of a neighbourhood that one plane explains (a point with a feature in view, see
// FitInView()). Its points are one sheet and the hinge explains them: neither the sheets' split
// nor the crossing planes (chosen only where the hinge does not explain) apply, so that the
// nearest-plane rounds of FitCrease() and the hinge started from their halves are left out. The
// hinge comes from FitCrease()'s other start, the cut through the centroid across the direction
// in which the normals vary most, refined by position (RefineHinge); the quadric gives the gain.
// (Against the full fit, FeaturePointsScalingBenchmark at 160,000 points: the default detector's
// extract 0.82x; every line of the quality and curve benchmarks within 0.004.)
CreaseFit FitViewHinge(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& nr)
{
  CreaseFit fit;
  fit.Points = static_cast<int>(p.size());
  Eigen::Vector3d c1, n1;
  double rss1 = 0.0;
  if (!PlaneOfAll(p, c1, n1, rss1))
  {
    return fit;
  }
  const Eigen::Vector3d e = NormalsSpread(nr, n1);
  fit.RSS1 = fit.Cross.RSS2 = rss1;
  fit.RSSQ = FitQuadric(p, c1, n1, rss1);
  const Hinge h = CutHinge(p, c1, n1, e);
  if (HingeWithin(h, p))
  {
    StoreLine(fit.Hinge, h.RSS, h.Sine, true, h.X, h.T, h.A, h.B, nr[0]);
  }
  else
  {
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    StoreLine(fit.Hinge, rss1, 0.0, false, zero, zero, c1, c1, nr[0]);
  }
  return fit;
}

// Residual of the curved hinge: each side of the hinge's line gets its own quadric height field
// (over its own plane), so that a crease between curved faces (a cylinder's rim, a fillet meeting
// a face) is explained where two planes leave the faces' curvature. The sides are split across
// the line by the mean direction of the points from it. Returns a negative value when a side has
// too few points for a quadric.
double FitCurvedHinge(const std::vector<Eigen::Vector3d>& p, const CreaseLine& line,
  std::vector<Eigen::Vector3d> side[2])
{
  if (!line.HasLine)
  {
    return -1.0;
  }
  const Eigen::Vector3d x(line.LinePoint[0], line.LinePoint[1], line.LinePoint[2]);
  const Eigen::Vector3d t(line.LineDirection[0], line.LineDirection[1], line.LineDirection[2]);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : p)
  {
    Eigen::Vector3d w = q - x;
    w -= w.dot(t) * t;
    const double length = w.norm();
    if (length > 0.0)
    {
      mean += w / length;
    }
  }
  const Eigen::Vector3d across = t.cross(mean);
  side[0].clear();
  side[1].clear();
  for (const Eigen::Vector3d& q : p)
  {
    side[(q - x).dot(across) >= 0.0 ? 0 : 1].push_back(q);
  }
  double rss = 0.0;
  for (int k = 0; k < 2; ++k)
  {
    Moments m;
    for (const Eigen::Vector3d& q : side[k])
    {
      m.Add(q);
    }
    Eigen::Vector3d c, n;
    double planeRss = 0.0;
    if (side[k].size() < 3)
    {
      continue; // a plane passes through them
    }
    if (!FitPlane(m, c, n, planeRss))
    {
      return -1.0;
    }
    double bend = 0.0;
    rss += side[k].size() < 6 ? planeRss : FitQuadric(side[k], c, n, planeRss, &bend);
    if (bend > MaximumFaceBend)
    {
      return -1.0; // not a face at this scale: a rib, a groove or a fillet fills the side
    }
  }
  return rss;
}

// The neighbours of a point on its own sheet: the neighbourhood's points joined to it through
// links, a link joining each point to its SheetLinks nearest (and, on a sampling in lines, to the
// next rows: LinkSlots), either way round. A wall thinner than the neighbourhood but thicker than
// the links then keeps its two sides apart.
struct SheetReach
{
  std::vector<int16_t> LocalOf; // by point id: its local index in the current neighbourhood, or -1
  std::vector<int16_t> Out;     // by local index: the local indices of its links, -1 outside
  std::vector<unsigned char> In;
  std::vector<int16_t> Stack;

  // Marks the reached neighbours in the bit mask `reached` (local indices); returns their count.
  // `links` holds, by point id, each point's LinkSlots links (its SheetLinks nearest and any
  // across rows; -1 where none).
  int Reach(vtkIdType id, const int32_t* row, int count, const std::vector<int32_t>& links,
    uint64_t* reached)
  {
    const size_t n = links.size() / LinkSlots;
    if (this->LocalOf.size() != n)
    {
      this->LocalOf.assign(n, -1);
    }
    auto idOf = [&](int j) { return j == 0 ? id : static_cast<vtkIdType>(row[j - 1]); };
    const size_t points = static_cast<size_t>(count) + 1;
    for (int j = 0; j <= count; ++j)
    {
      this->LocalOf[idOf(j)] = static_cast<int16_t>(j);
    }
    this->Out.resize(points * LinkSlots);
    for (int j = 0; j <= count; ++j)
    {
      const int32_t* linked = links.data() + idOf(j) * LinkSlots;
      for (int e = 0; e < LinkSlots; ++e)
      {
        this->Out[j * LinkSlots + e] = linked[e] >= 0 ? this->LocalOf[linked[e]] : int16_t(-1);
      }
    }
    for (int j = 0; j <= count; ++j)
    {
      this->LocalOf[idOf(j)] = -1;
    }
    // The component of the point in the graph whose edges are the links taken either way round:
    // a search along the links from the point, then sweeps that add the points linking to a
    // reached point (and what their links reach) until a sweep adds none. Most points are
    // reached by the first search.
    this->In.assign(points, 0);
    int members = 0;
    auto spread = [&](int start) {
      this->In[start] = 1;
      ++members;
      this->Stack.assign(1, static_cast<int16_t>(start));
      while (!this->Stack.empty())
      {
        const int j = this->Stack.back();
        this->Stack.pop_back();
        for (int e = 0; e < LinkSlots; ++e)
        {
          const int other = this->Out[j * LinkSlots + e];
          if (other >= 0 && !this->In[other])
          {
            this->In[other] = 1;
            ++members;
            this->Stack.push_back(static_cast<int16_t>(other));
          }
        }
      }
    };
    spread(0);
    for (bool added = true; added && members < static_cast<int>(points);)
    {
      added = false;
      for (int j = 1; j <= count; ++j)
      {
        if (this->In[j])
        {
          continue;
        }
        for (int e = 0; e < LinkSlots; ++e)
        {
          const int other = this->Out[j * LinkSlots + e];
          if (other >= 0 && this->In[other])
          {
            spread(j);
            added = true;
            break;
          }
        }
      }
    }
    for (int j = 0; j <= count; ++j)
    {
      if (this->In[j])
      {
        reached[j / 64] |= uint64_t(1) << (j % 64);
      }
    }
    return members;
  }
};

inline bool Reached(const uint64_t* reached, int j)
{
  return (reached[j / 64] >> (j % 64)) & 1u;
}

// The k-nearest table of a run in 16 bits an entry: each row as offsets from its smallest id
// (the cloud is in the grid's cell order, so that a row's ids lie close together), the few rows
// that span more ids kept whole. 32-bit ids were most of the detector's memory (600 bytes a
// point at k = 150).
class NeighborTable
{
public:
  void Reset(vtkIdType rows, int k)
  {
    this->K = k;
    this->Base.assign(static_cast<size_t>(rows), 0);
    this->Offsets.assign(static_cast<size_t>(rows) * k, None);
    this->Spilled.clear();
  }

  // Stores rows first to first + count - 1 given as 32-bit ids (-1: none).
  void Store(vtkIdType first, vtkIdType count, const int32_t* block)
  {
    std::vector<unsigned char> wide(static_cast<size_t>(count), 0);
    vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType r = begin; r < end; ++r)
      {
        const int32_t* in = block + r * this->K;
        int32_t lo = std::numeric_limits<int32_t>::max(), hi = -1;
        for (int j = 0; j < this->K; ++j)
        {
          if (in[j] >= 0)
          {
            lo = std::min(lo, in[j]);
            hi = std::max(hi, in[j]);
          }
        }
        if (hi >= 0 && hi - lo >= None)
        {
          wide[r] = 1;
          continue;
        }
        this->Base[first + r] = hi >= 0 ? lo : 0;
        uint16_t* out = this->Offsets.data() + (first + r) * this->K;
        for (int j = 0; j < this->K; ++j)
        {
          out[j] = in[j] >= 0 ? static_cast<uint16_t>(in[j] - lo) : None;
        }
      }
    });
    for (vtkIdType r = 0; r < count; ++r)
    {
      if (wide[r])
      {
        this->Base[first + r] = -1 - static_cast<int32_t>(this->Spilled.size() / this->K);
        this->Spilled.insert(this->Spilled.end(), block + r * this->K, block + (r + 1) * this->K);
      }
    }
  }

  // Row r as 32-bit ids, -1 past its end: its first `width` entries written to `buffer`, or the
  // row kept whole.
  const int32_t* Row(vtkIdType r, int32_t* buffer, int width) const
  {
    const int32_t base = this->Base[r];
    if (base < 0)
    {
      return this->Spilled.data() + static_cast<size_t>(-1 - base) * this->K;
    }
    const uint16_t* in = this->Offsets.data() + r * this->K;
    for (int j = 0; j < width; ++j)
    {
      buffer[j] = in[j] == None ? -1 : base + in[j];
    }
    return buffer;
  }

private:
  static constexpr uint16_t None = 0xffff;
  int K = 0;
  std::vector<int32_t> Base; // per row: its smallest id, or -1 - its index in Spilled
  std::vector<uint16_t> Offsets;
  std::vector<int32_t> Spilled;
};

// The fit of a row that one plane explains, where no feature is in view (see OnePlane): no line,
// explained.
const CreaseFit OnePlaneFit{};

// The fits of a run, by row. Most rows (a part's faces) have OnePlaneFit and store nothing; the
// others store theirs, 128 bytes each.
class FitTable
{
public:
  void Reset(vtkIdType rows)
  {
    this->Of.assign(static_cast<size_t>(rows), -1);
    this->Stored.clear();
  }
  bool Has(vtkIdType r) const { return this->Of[r] >= 0; }
  const CreaseFit& operator[](vtkIdType r) const
  {
    return this->Of[r] < 0 ? OnePlaneFit : this->Stored[this->Of[r]];
  }
  // A stored fit, to change in place (rows apart may be changed in parallel).
  CreaseFit& Edit(vtkIdType r) { return this->Stored[this->Of[r]]; }
  // Stores row r's fit: one thread at a time.
  void Add(vtkIdType r, const CreaseFit& fit)
  {
    this->Of[r] = static_cast<int32_t>(this->Stored.size());
    this->Stored.push_back(fit);
  }

private:
  std::vector<int32_t> Of;
  std::deque<CreaseFit> Stored;
};

// A crease point's hinge as a frame for the sides of the normals around it: the line (point,
// relative to the crease point, and direction t), the rays into its two half-planes and their
// normals turned away from each other's ray. A convex crease's outward normals; both inward on
// a concave one: the two faces take one side together either way.
struct HingeFrame
{
  Eigen::Vector3d Point, T, Ray[2], Face[2];
  bool Valid = false;

  explicit HingeFrame(const CreaseLine& f)
  {
    this->Point = Eigen::Vector3d(f.LinePoint[0], f.LinePoint[1], f.LinePoint[2]);
    this->T = Eigen::Vector3d(f.LineDirection[0], f.LineDirection[1], f.LineDirection[2]);
    for (int k = 0; k < 2; ++k)
    {
      this->Ray[k] = Eigen::Vector3d(f.Rays[k][0], f.Rays[k][1], f.Rays[k][2]) / RayUnit;
    }
    this->Valid = f.HasLine;
    for (int k = 0; k < 2; ++k)
    {
      const Eigen::Vector3d& other = this->Ray[1 - k];
      this->Face[k] = this->Ray[k].dot(other) * this->Ray[k] - other;
      const double length = this->Face[k].norm();
      this->Valid = this->Valid && length > 1e-3;
      this->Face[k] /= length > 0.0 ? length : 1.0;
    }
  }

  // The side of the normal m of a point at y (relative to the crease point) against the face
  // it belongs to, and how sure that is. Where m turns to the same side of both faces' normals,
  // that side (|m . normal|, the nearer). Otherwise the face the point lies on (nearer one
  // half-plane than the other by more than `clear`) when its normal is nearer that face's
  // normal too (|m . its normal|); else not sure at all (an acute crease's blended normals fit
  // both faces alike, and a point on one face near the line may see mostly the other).
  int Side(const Eigen::Vector3d& y, const Eigen::Vector3d& m, double clear, double& sure) const
  {
    const double along[2] = { m.dot(this->Face[0]), m.dot(this->Face[1]) };
    const int nearer = std::abs(along[0]) >= std::abs(along[1]) ? 0 : 1;
    if ((along[0] < 0.0) == (along[1] < 0.0))
    {
      sure = std::abs(along[nearer]);
      return along[0] < 0.0 ? -1 : 1;
    }
    Eigen::Vector3d w = y - this->Point;
    w -= w.dot(this->T) * this->T;
    double distance[2];
    for (int k = 0; k < 2; ++k)
    {
      distance[k] = w.dot(this->Ray[k]) > 0.0 ? std::abs(w.dot(this->Face[k])) : w.norm();
    }
    const int on = distance[0] <= distance[1] ? 0 : 1;
    sure = on == nearer && distance[1 - on] - distance[on] > clear ? std::abs(along[nearer]) : 0.0;
    return along[nearer] < 0.0 ? -1 : 1;
  }

  // Whether another crease point's frame takes the same side (+1) or the other (-1): its faces
  // matched to these by their planes (a face between two creases has its rays turned against
  // each other), by the sign of their normals' agreement; how sure that is (none where the
  // planes match either way alike or the lines cross).
  int Relation(const HingeFrame& o, double& sure) const
  {
    const double straight[2] = { this->Face[0].dot(o.Face[0]), this->Face[1].dot(o.Face[1]) };
    const double swapped[2] = { this->Face[0].dot(o.Face[1]), this->Face[1].dot(o.Face[0]) };
    const double a = std::abs(straight[0]) + std::abs(straight[1]);
    const double b = std::abs(swapped[0]) + std::abs(swapped[1]);
    const double agree = a >= b ? straight[0] + straight[1] : swapped[0] + swapped[1];
    sure = std::min({ std::abs(agree) / 2.0, std::abs(a - b), std::abs(this->T.dot(o.T)) });
    return agree < 0.0 ? -1 : 1;
  }
};

// The orientation's links: no link.
constexpr uint8_t NoLink = 255;

// Asks memory for the cache line at p, to be read (or written) shortly; nothing where the
// compiler has no such hint.
inline void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}
inline void PrefetchForWrite(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p, 1);
#else
  (void)p;
#endif
}

// Union-find of signed sets: each element's side relative to its set's root (union by rank,
// path halving). Which element is the root does not matter: a tree's sides are set by its
// links, up to one sign that OrientNormals() chooses by the volume.
class SignedSets
{
public:
  explicit SignedSets(size_t n)
    : Parent(n)
    , Turn(n, 0)
    , Rank(n, 0)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), int32_t(0));
  }
  // The root of i's set, and whether i's side is turned against it.
  int32_t Find(int32_t i, int& turn)
  {
    int t = 0;
    while (this->Parent[i] != i)
    {
      // Halving: i's parent becomes its grandparent, and i's turn the sum of both steps.
      const int32_t p = this->Parent[i];
      if (this->Parent[p] != p)
      {
        this->Turn[i] = static_cast<unsigned char>(this->Turn[i] ^ this->Turn[p]);
        this->Parent[i] = this->Parent[p];
      }
      t ^= this->Turn[i];
      i = this->Parent[i];
    }
    turn = t;
    return i;
  }
  // Asks memory for element i's parent, to be read shortly.
  void PrefetchParent(int32_t i) const { Prefetch(this->Parent.data() + i); }
  // Joins the sets of a and b, b's side turned against a's where `turned`; false where they are
  // one set already.
  bool Join(int32_t a, int32_t b, bool turned)
  {
    int ta = 0, tb = 0;
    int32_t ra = this->Find(a, ta), rb = this->Find(b, tb);
    if (ra == rb)
    {
      return false;
    }
    if (this->Rank[ra] < this->Rank[rb])
    {
      std::swap(ra, rb);
    }
    this->Parent[rb] = ra;
    this->Turn[rb] = static_cast<unsigned char>(ta ^ tb ^ (turned ? 1 : 0));
    if (this->Rank[ra] == this->Rank[rb])
    {
      ++this->Rank[ra];
    }
    return true;
  }

private:
  std::vector<int32_t> Parent;
  std::vector<unsigned char> Turn, Rank;
};

struct Scratch
{
  std::vector<int32_t> Row;
  std::vector<double> Q;
  std::vector<Eigen::Vector3d> P, N, Side[2];
  std::vector<unsigned char> Label, Next;
  SheetReach Sheet;
};

// Rows of the wide neighbour search taken at a time (see CreaseRun::Stream()).
constexpr vtkIdType BlockRows = 8192;

// Everything one run of the detector shares between its stages: the neighbour tables (renumbered
// cloud, one row of nearest points per scored point), the fits, and the output arrays' storage.
// Each stage is one member function; RequestData calls them in order. The K nearest of every
// row, which the fits and the vote read, are never held for the whole cloud (300 bytes a point
// at K = 150): Stream() searches them block by block and drops each block once the stages that
// read it have run; the last stages search again the few rows they need (LoadRows()). The
// narrow table holds the KNear nearest of every row (NormalNeighbors), for the stages that
// read no more.
struct CreaseRun
{
  const featurepoints::PointReader& Reader;
  const std::vector<vtkIdType>& Ids;
  const NeighborTable& Table; // the KNear nearest of every row
  const int K;       // width of a row: the widest neighbourhood a stage reads
  const int KNear;   // width of Table's rows
  const int KFit;    // the widest fit (NumberOfNeighbors)
  const double D;    // mean spacing
  const vtkIdType N; // points
  vtkIdType Rows = 0;
  std::vector<vtkIdType> RowOf;
  // The order in which Stream() takes the rows (Order[i] is a row, Rank[Order[i]] = i): along
  // the longest side of the cloud's bounding box, so that the rows a block of them reads lie
  // in a slab about two neighbourhoods thick.
  std::vector<int32_t> Order, Rank;
  // The K nearest: by block of BlockRows rows of Order while Stream() runs, and the rows
  // LoadRows() found (SubsetSlot[r] >= 0) after it.
  std::vector<std::unique_ptr<NeighborTable>> Blocks;
  NeighborTable Subset;
  std::vector<int32_t> SubsetSlot;
  // By point id: its SheetLinks nearest (-1 where fewer), one plane explains its sheet (see
  // OnePlane), its fit votes (these three while Stream() runs); a border point (before the short
  // borders are dropped) lies within the band among its kb nearest on its sheet.
  std::vector<int32_t> Links;
  // By point id: on a sampling in scan lines, half the distance across to the next row (its
  // nearest link across, see LinkAcrossRows); 0 elsewhere. The vote's band reaches at least that
  // far in units of BandWidth: a crease between two rows passes up to half their gap from both.
  std::vector<float> Across;
  std::vector<unsigned char> Flat, Voter, NearBorder;
  // Distributed runs (see RequestData): the halo's rows are never fitted (their owners' values
  // replace whatever an own row would read of them), and the passes of Stream() leave out the
  // own rows that read a halo value before the halo has its owners' values (exchanged once
  // Stream() is through); RunDeferred() runs them then. By row: DeferFits, the halo's rows
  // (their voter flags) and the rows with a halo point among their ViewNeighbors nearest (what
  // FitInView() reads), for passes 1 and 2; DeferVotes, those and the rows with a DeferFits row
  // among their K nearest (the voters CastVotes() reads), for pass 2. Deferring: RunDeferred()
  // is running.
  bool Distributed = false;
  bool Deferring = false;
  std::vector<unsigned char> DeferFits, DeferVotes;
  vtkSMPThreadLocal<Scratch> Scratches;
  // One bit per neighbour (and the point) of each row: on the point's sheet.
  size_t Words = 0;
  std::vector<uint64_t> Sheets;
  FitTable Fits;
  // Per row: how many of the row's sheet members the chosen fit and the vote use (the point's
  // scale), and the model's gain in noise variances.
  std::vector<int32_t> Scale;
  // Squared distance from each row's point to the farthest point of its fit (infinite where the
  // fit spans the widest neighbourhood): the reach within which its line says anything.
  std::vector<float> Reach2;
  std::vector<double> Gain;
  double Variance = 0.0;
  // Whether the run makes the one-point-wide mask (ThinFeatures): only then are Offset and
  // Spread kept.
  bool Thinning = false;
  // Per point: the median distance across the crease from the lines that vote for it (along the
  // nearer half-plane of each: the consensus distance to the crease, which no single noisy fit
  // gives), -1 where none does; and the standard error of that median (1.2533 x 1.4826 x the
  // median absolute deviation of the distances over the square root of their number). Set by
  // CastVotes() when Thinning.
  std::vector<float> Offset;
  std::vector<float> Spread;
  // Per point (3 floats, null: not asked for): the component-wise median of its feet on the
  // lines that vote for it, from the point. Set by CastVotes().
  float* Foot = nullptr;
  // Distributed runs (see RequestData): by point id, 1 for the piece's own points (null: all);
  // the value of rank floor(share n) of the n per-row values over the own rows of every process
  // (a negative value: the row has none), and their count n; labels made to agree across the
  // pieces (the smallest of each point's copies), true while any changes; how many own points
  // of all processes carry each label.
  const unsigned char* Own = nullptr;
  std::function<double(std::vector<double>&, double)> RowQuantile =
    [](std::vector<double>& values, double share) {
      values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return v < 0.0; }),
        values.end());
      return featurepoints::ValueOfShare(values, share);
    };
  // How many rows have a figure (>= 0), over every process.
  std::function<long long(const std::vector<double>&)> CountRows =
    [](const std::vector<double>& values) {
      return static_cast<long long>(
        std::count_if(values.begin(), values.end(), [](double v) { return v >= 0.0; }));
    };
  std::function<bool(long long*)> ShareMinimum;
  std::function<void(const std::vector<long long>&, std::vector<long long>&)> CountLabels =
    [](const std::vector<long long>& labels, std::vector<long long>& counts) {
      std::vector<long long> sorted(labels);
      std::sort(sorted.begin(), sorted.end());
      counts.resize(labels.size());
      for (size_t j = 0; j < labels.size(); ++j)
      {
        const auto range = std::equal_range(sorted.begin(), sorted.end(), labels[j]);
        counts[j] = static_cast<long long>(range.second - range.first);
      }
    };
  std::function<long long(vtkIdType)> GlobalId = [](vtkIdType id) {
    return static_cast<long long>(id);
  };
  // A point's key, the same whatever the pieces and the numbering (the input's order): the
  // orientation's order among equal weights.
  std::function<long long(vtkIdType)> Key = [](vtkIdType id) { return static_cast<long long>(id); };
  // Distributed runs: the halo's values of a per-point array (`bytes` bytes a point) replaced by
  // their owners', so that a stage reads its neighbours' exact values, not their neighbours'.
  std::function<void(void*, int)> FromOwners;
  // The same for a record kept by row (see vtkFeaturePointDetector::ShareHaloRecords()).
  std::function<void(int, const std::function<void(vtkIdType, unsigned char*)>&,
    const std::function<void(vtkIdType, const unsigned char*)>&)>
    RecordsFromOwners;
  // Distributed runs: every process's values one after the other.
  std::function<void(std::vector<double>&)> GatherAll = [](std::vector<double>&) {};
  bool IsOwn(vtkIdType id) const { return !this->Own || this->Own[id] != 0; }
  // Whether the current pass leaves row r out: a halo row (whose values come from its owner),
  // or pass 1 or 2 of Stream() on a deferred row.
  bool Defers(vtkIdType r, int pass) const
  {
    if (!this->IsOwn(this->Ids[r]))
    {
      return true;
    }
    if (pass == 0)
    {
      return false;
    }
    const std::vector<unsigned char>& deferred = pass == 1 ? this->DeferFits : this->DeferVotes;
    return !this->Deferring && !deferred.empty() && deferred[r];
  }

  CreaseRun(const featurepoints::PointReader& reader, const std::vector<vtkIdType>& ids,
    const NeighborTable& table, int k, int knear, int kfit, double d, vtkIdType n)
    : Reader(reader)
    , Ids(ids)
    , Table(table)
    , K(k)
    , KNear(knear)
    , KFit(kfit)
    , D(d)
    , N(n)
  {
    this->Rows = static_cast<vtkIdType>(ids.size());
    this->RowOf.assign(static_cast<size_t>(n), -1);
    for (vtkIdType r = 0; r < this->Rows; ++r)
    {
      this->RowOf[ids[r]] = r;
    }
    this->Words = (static_cast<size_t>(kfit) + 1 + 63) / 64;
  }

  // The first `width` entries of row r (all by default), in `buffer` (K entries) or elsewhere.
  // Wider than KNear: only for the rows of a block Stream() holds, or that LoadRows() found.
  const int32_t* Row(vtkIdType r, int32_t* buffer, int width = -1) const
  {
    width = width < 0 ? this->K : std::min(width, this->K);
    if (width <= this->KNear)
    {
      return this->Table.Row(r, buffer, width);
    }
    if (!this->SubsetSlot.empty() && this->SubsetSlot[r] >= 0)
    {
      return this->Subset.Row(this->SubsetSlot[r], buffer, width);
    }
    return this->Blocks[this->Rank[r] / BlockRows]->Row(this->Rank[r] % BlockRows, buffer, width);
  }
  const uint64_t* Sheet(vtkIdType r) const { return this->Sheets.data() + r * this->Words; }

  // Step 1a: PCA normals of the `kn` nearest, turned away from the cloud's centre, and sigma^2
  // from their quadric's residual per degree of freedom, on the point's side of a wall thinner
  // than them (NoiseResidual, NoiseVariance).
  void ComputeNormals(int kn, const double center[3], float* normal);
  // Step 1a, again where the noise is large for the kn nearest: in space, the kn nearest of a
  // point favour the neighbours near its own height, whose heights spread less than the noise,
  // and their plane tilts into the noise (its normal is the direction where the draw happened
  // to spread least); on a noisy plane the figure read 0.95 of the noise at sigma = 0.5 and
  // 0.61 at 1.5 (in units of the 16 nearest's radius r / 2.26). Instead the noise is measured
  // on the kn nearest across the surface (distances in the tangent plane) among the point's
  // nearest in space, in the frame of these (a plane of more points), reaching the radius r of
  // the kn nearest across widened by 3 standard deviations of a height difference (3 sqrt(2)
  // sigma): (kn + 1) (1 + 18 sigma^2 / r^2) points, at most K. On the noisy plane that reads
  // 0.99-1.01 of the noise from 0.25 to 2. It runs where the ball holds more than twice the kn
  // nearest (sigma > r / 4.24), from the last figure until the ball stops growing; below, the
  // figure reads at least about 0.95 of the noise and one more search of every row would cost
  // about a tenth of the detector.
  void MeasureNoiseAcross(vtkPointCloudNeighborhoods* neighborhoods, int kn);
  // The median over the rows of the squared tangent-plane distance from the point to the
  // farthest of its kn nearest (ComputeNormals(), then MeasureNoiseAcross()).
  double NoiseReach2 = 0.0;
  // sigma^2 from the rows' residuals per degree of freedom (dof: a whole neighbourhood's), each
  // sigma^2 chi2(dof) / dof where only noise is in view, larger where a feature is. The median
  // holds while most neighbourhoods see no feature. On a part whose details lie a few spacings
  // apart nearly all of them see one (an extruded pixel font at 20,000 points: 74 % of the
  // points within 2 spacings of an edge), and the median measured the creases: sigma 0.62
  // spacing on a clean cloud, so loose that a wrong model explained three faces. Every quantile
  // of pure noise is a known multiple of its median (chi-square, by Wilson and Hilferty), so the
  // lower quantiles 1/4, 1/10 and 1/20 give estimates too, the smallest of them the one the
  // features touch least (each where at least 100 rows lie below it). It replaces the median
  // only past the median's breakdown point: where fewer than a quarter of the rows lie below the
  // median it implies, that is fewer than half of the rows are noise alone. Below that point
  // the median stays: the sides of a wall too thin to split (a plate one spacing thick under
  // noise of a quarter spacing) raise the residual of some rows and not of others, and the
  // lower quantile then reads the noise without the thickness the fits cannot resolve (F1 0.964
  // -> 0.940 on that plate, a noisy ABC plate 2 spacings thick 0.22 -> 0.04 in thin MCC). On pure
  // noise (a sphere and a plane, 30,000 points, Gaussian noise) the lower estimates agree with
  // the median within 1 %; the 1/50 quantile reads 1-4 % low there, so 1/20 is the last.
  // A sheet of fewer points (one side of a thin wall) has fewer degrees of freedom (`rowDof`, 0:
  // no figure), and its figure (`raw`: per degree of freedom) spreads wider: chi2(2) / 2 has a
  // twentieth of its median at its 1/20 quantile, chi2(10) / 10 two fifths. So for each
  // quantile every row's figure is scaled to that quantile of the whole neighbourhood's law (the
  // median's, `residual`, to its median), and rows of fewer than 4 degrees of freedom, where the
  // approximation is too coarse, are left out of the lower quantiles.
  double NoiseVariance(std::vector<double>& residual, const std::vector<double>& raw,
    const std::vector<signed char>& rowDof, int dof) const;
  // The median of the rows' figures (`residual`, negative: none) that features leave alone: the
  // rows at most the 95 % point of the pure-noise law of `dof` degrees of freedom at the
  // current estimate, their median scaled to the whole law's (the 47.5 % point's), from the
  // median of all until it settles. A crease, a second sheet or a detail raises the figure of
  // the rows that see it, and only theirs: on a part whose details lie a few spacings apart
  // they are a third to a half of the rows, and the plain median read 1.2 to 1.8 times the
  // noise. A wall thinner than the noise fit resolves raises most rows alike and stays in.
  double TrimmedMedian(
    const std::vector<double>& residual, int dof, std::vector<double>& scratch) const;
  struct NoiseScratch
  {
    std::vector<Eigen::Vector3d> P;
    std::vector<unsigned char> Label;
  };
  // The noise figure of one neighbourhood (q: its count neighbours relative to the point; nrm
  // and lambda: its normal and smallest eigenvalue): the residual variance of a quadric height
  // field over the point's sheet, scaled to the median of a whole neighbourhood's; negative
  // where it has none. `raw`: unscaled; `dof`: its degrees of freedom (0: none).
  static double NoiseResidual(const double* q, int count, const double nrm[3], double lambda,
    NoiseScratch& s, double& raw, int& dof);
  // Step 8b: one consistent orientation of the normals (Hoppe et al. 1992), once the creases
  // are typed: a minimum spanning forest over the `kn` nearest carries each normal's side to
  // the next across the gentlest bends, along the surface, never across a thin wall. Across a
  // crease the normals of the kn nearest blend the two faces, and across an acute one (faces
  // less than 90 degrees apart) the gentlest bend turns the wrong way: the crease points whose
  // hinge explains their points stand for their hinge (see HingeFrame), and their links carry
  // its side to the normals around them by the face each belongs to. Each tree then takes the
  // side that encloses a positive volume (divergence theorem): Sum a (x - c).n over its points,
  // a each point's share of the surface (pi r^2 / kn, r the distance to its kn-th nearest, so
  // that the density does not weigh), c the cloud's centre; on a closed surface the outward
  // side wherever the centre lies, on an open one the side away from the centre's, a
  // convention. By row: side, +1 or -1 against the normal as ComputeNormals() turned it (for a
  // hinge's point, against the hinge: +1 a convex crease); own, the side of a hinge point's
  // normal in its hinge (0 for the other rows). The fits read the normals up to their sign:
  // only convex or concave turns on it. Frees Gain, which nothing reads after MarkFrames().
  void OrientNormals(int kn, const double center[3], const float* normal,
    const unsigned char* type, double minAngle, std::vector<signed char>& side,
    std::vector<signed char>& own);
  // Whether both half-planes of row r's hinge hold points of its fit (within 3 sigma of the
  // half-plane) nearer the line than two local spacings (of the ks nearest): a hinge whose
  // half-plane starts further out spans a gap (a slot narrower than the neighbourhood), two
  // faces that do not meet.
  bool HingeMeets(vtkIdType r, const HingeFrame& frame, int ks) const;
  // The crease points that stand for their hinge (type CONVEX or CONCAVE, whose fitted line
  // votes, explains the points within the noise and meets), as their owners decide.
  void MarkFrames(int kn, const unsigned char* type, double minAngle, std::vector<int32_t>& frameOf,
    std::vector<HingeFrame>& frames) const;
  // The links from each own row to its kn nearest (slot r kn + j): the row they reach (~row
  // where the link turns the side over) and their weight, 1 - how sure the relation is, in
  // 1/127 (NoLink where it carries nothing). Two normals: 1 - |cos| of their angle plus the
  // step's sine out of the tangent plane; the other side of a wall thinner than the
  // neighbourhood has the same normal up to its sign, so a step that leaves either tangent plane
  // by more than 30 degrees and more than 3 sigma is no link, nor are normals more than 60
  // degrees apart. A hinge and a normal, or two hinges: see HingeFrame. Also own and each own
  // row's share of the volume on the side of its normal (hinge points: of their hinge).
  void WeighLinks(int kn, const double center[3], const float* normal,
    const std::vector<int32_t>& frameOf, const std::vector<HingeFrame>& frames,
    const std::vector<int32_t>& place, const std::vector<long long>& key,
    std::vector<int32_t>& target, std::vector<uint8_t>& weight, std::vector<signed char>& own,
    std::vector<double>& share) const;
  // Drops (weight NoLink) the links that Kruskal's pass would leave out in any case: each the
  // heaviest, in SpanForest()'s order, of a triangle or a pair of links found in the rows of its
  // two ends. In parallel, a block of rows at a time; SpanForest() then orders and joins the rest.
  // Returns the number of links before.
  size_t DropCycleMaxima(int kn, const std::vector<int32_t>& rows,
    const std::vector<int32_t>& place, const std::vector<int32_t>& target,
    std::vector<uint8_t>& weight) const;
  // Kruskal over the own rows' links in a strict order (weight, then the keys of both ends), into
  // sets of rows; into `forest` (unless null) the links it keeps, 4 numbers each (weight, key
  // from, key to, 1 if turning).
  void SpanForest(int kn, const std::vector<int32_t>& rows, const std::vector<int32_t>& target,
    const std::vector<uint8_t>& weight, const std::vector<long long>& key, size_t weighed,
    SignedSets& sets, std::vector<double>* forest) const;
  // Storage of the fits, the sheets and the per-point flags of Stream()'s passes.
  void PrepareFits(vtkPointCloudNeighborhoods* neighborhoods);
  // Links of point id (its row of KNear nearest) across to the neighbouring rows of a sampling in
  // lines (see LinkSlots), into links[SheetLinks...].
  // Returns true where the 5 nearest are collinear and fewer than two links across were found
  // among `row`: a wider row may find them.
  bool LinkAcrossRows(vtkIdType id, const int32_t* row, int count, int32_t* links);
  // Runs the passes over the rows in turn, each over a block of rows (positions begin to end - 1
  // of Order) once every row the block's rows read has been through the pass before: passes[0]
  // as soon as the block's K nearest are found, then passes[1] and passes[2]; the block is
  // dropped after passes[2]. The K nearest are searched BlockRows rows at a time (progress from
  // progressStart to progressEnd of `algorithm`); returns false when it is aborted.
  bool Stream(vtkPointCloudNeighborhoods* neighborhoods, vtkAlgorithm* algorithm,
    double progressStart, double progressEnd,
    const std::function<void(vtkIdType, vtkIdType)> passes[3]);
  // The K nearest of the rows r with wanted(r), kept from now on (see Row()).
  bool LoadRows(vtkPointCloudNeighborhoods* neighborhoods, const std::function<bool(vtkIdType)>& wanted);
  // Distributed runs: DeferFits of the rows begin to end - 1 (in pass 0), DeferVotes (in pass 2,
  // after pass 0 on every row they read).
  void MarkDeferredFits(vtkIdType begin, vtkIdType end);
  void MarkDeferredVotes(vtkIdType begin, vtkIdType end);
  // Distributed runs, once Stream() is through and the halo has its owners' one-plane flags:
  // the K nearest of the own deferred rows (kept, see Row()), then passes[0] (the models) over
  // the DeferFits rows, ShareModels(), passes[1] (the voters) over the DeferFits rows and
  // passes[2] (the votes) over the DeferVotes rows (positions in Order), each a block of rows at
  // a time as in Stream().
  bool RunDeferred(vtkPointCloudNeighborhoods* neighborhoods,
    const std::function<void(vtkIdType, vtkIdType)> passes[3]);
  // Steps 1b-3 at the widest scale, rows begin to end - 1: the sheet of every point, its
  // two-plane fit.
  void FitCreases(const float* normal, vtkIdType begin, vtkIdType end);
  // The fits of the one-plane points with a feature in view (after FitCreases() on every row
  // they read).
  void FitInView(const float* normal, vtkIdType begin, vtkIdType end);
  // Scale per point: where the widest hinge does not explain the neighbourhood, the largest
  // smaller scale whose hinge does. Sets detail[id] where not even the smallest is explained
  // and its fit bends by minAngle (degrees) or more.
  void ChooseScales(const float* normal, int smallest, double minAngle, unsigned char* detail,
    vtkIdType begin, vtkIdType end);
  // The model of each fit (hinge or crossing planes) and its gain.
  void ChooseModels(float* gain, float* angle, vtkIdType begin, vtkIdType end);
  // Distributed runs: the halo's models (what the votes and the directions read) from their
  // owners (after ChooseModels() on every row).
  void ShareModels();
  // Whether each fit votes (Voter).
  void MarkVoters(double minAngle, vtkIdType begin, vtkIdType end);
  // Step 4: the vote fraction of every point, and its Offset (after MarkVoters() on every row
  // they read).
  void CastVotes(double bandWidth, float* vote, vtkIdType begin, vtkIdType end);
  // Step 6: hysteresis growth of the mask through points voting above growAt, stepping from own
  // points only (a distributed run repeats it after each exchange of the halo's mask).
  vtkIdType Grow(const float* vote, double growAt, unsigned char* mask) const;
  // Open borders: an empty sector of the tangent plane. Sets border[id] and its outward
  // direction (unit, in the tangent plane) in `outward`. DropShortBorders() follows, once every
  // row has been through.
  void FindBorders(int kb, unsigned char* border, float* outward, vtkIdType begin, vtkIdType end) const;
  // Drops the connected sets of border points smaller than `shortest` (rims of sampling voids).
  void DropShortBorders(int shortest, unsigned char* border) const;
  // NearBorder of the rows begin to end - 1 (after FindBorders() on every row they read).
  void MarkNearBorders(int kb, double bandWidth, const unsigned char* border, vtkIdType begin, vtkIdType end);
  // The border band: points within bandWidth d of a border point (among their kb nearest)
  // join it, as the crease band does. Only NearBorder points can (DropShortBorders() only takes
  // border points away).
  void WidenBorders(int kb, double bandWidth, unsigned char* border) const;
  // Whether one of row r's kb nearest on its sheet is a border point within sqrt(band2).
  bool BorderWithin(vtkIdType r, int kb, double band2, const unsigned char* border,
    int32_t* buffer) const;
  // FeatureType of the mask's points; minAngle as for the vote, kb as for the borders.
  void ClassifyFeatures(const unsigned char* mask, const unsigned char* border,
    const float* outward, double minAngle, int kb, unsigned char* type) const;
  // One point wide: keeps the crease and corner points whose consensus distance to the crease
  // (Offset, across the face) is within half their local spacing (of the ks nearest), widened by
  // the noise, and whose vote reaches `trusted` (enough voters for the distance to be a
  // consensus), and across each border the outermost points (among their kt nearest).
  vtkIdType Thin(const unsigned char* type, const float* outward, const float* vote,
    double trusted, int kt, int ks, unsigned char* mask) const;
  // The thin mask's gaps: a crease or corner point of the band with no kept point among its kt
  // nearest is kept where its consensus distance is the least of the candidates (band points
  // whose vote reaches `trusted`) among them, within its standard error (Spread): two rows the
  // same distance from the line, as far as the voters tell, are both kept. Two creases closer
  // than a fit can tell apart (a narrow chamfer's two edges) put the consensus line between
  // their rows, and noise pushes stretches of a row past the limit: both left the curve without
  // a point there.
  // band: the mask before Thin(); mask: after it, on return with the gaps' points added (their
  // number). In a distributed run the halo's mask, Offset and Spread must be their owners'.
  vtkIdType FillThinGaps(const unsigned char* type, const float* vote, double trusted, int kt,
    const unsigned char* band, unsigned char* mask) const;

private:
  // Whether one plane explains row r's point and all `count` of its neighbours (row) within the
  // noise (see OnePlane): then they are one sheet. Where the links split such a neighbourhood,
  // the split is a seam of a random sampling (the 5 nearest of the points on either side of a
  // line all on their own side), not the sides of a wall, which lie a wall's thickness apart
  // along the normal.
  bool OnePlaneRow(vtkIdType r, const int32_t* row, int count) const;
  // The members of row r's sheet (row: its neighbours), nearest first, at most `count` of them besides the point,
  // as coordinates relative to the point (P[0] = 0) with their normals.
  void GatherSheet(vtkIdType r, const int32_t* row, int count, const float* normal, Scratch& s) const;
  // The spacing of a uniform sampling as dense as row r's ks nearest: sqrt(pi r_ks^2 / ks).
  double LocalSpacing(vtkIdType r, int ks) const;
  // Distance from a point at offset v of the fitted point to row r's line.
  double LineDistance(vtkIdType r, const double v[3]) const;
  // How far from row r's line, along the nearer of its half-planes, the point at offset v of the
  // fitted point lies (0 beyond the line): its distance from the crease across the face it lies
  // on, which noise along that face's normal does not change.
  double HingeAcross(vtkIdType r, const double v[3]) const;
  // The unit direction of row r's feature point: its fit's crease line, or along its border (the
  // tangent plane of its kb nearest); false where it has none.
  bool Direction(vtkIdType r, const unsigned char* type, const float* outward, double minAngle,
    int kb, std::vector<double>& q, double t[3]) const;
  // How far from row r's point the corner test looks: CornerReachScales times the radius of its
  // SmallestScale nearest on its sheet.
  double CornerReach(vtkIdType r) const;
  // The kb nearest members of row r's sheet (the point excluded), as x, y, z relative to the
  // point in q; `buffer` holds K ids.
  void GatherSheetNearest(vtkIdType r, int kb, int32_t* buffer, std::vector<double>& q) const;
};

void CreaseRun::ComputeNormals(int kn, const double center[3], float* normal)
{
  std::vector<double> residual(static_cast<size_t>(this->Rows), 0.0);
  std::vector<double> raw(static_cast<size_t>(this->Rows), -1.0);
  std::vector<signed char> rowDof(static_cast<size_t>(this->Rows), 0);
  std::vector<double> reach(static_cast<size_t>(this->Rows), -1.0);
  vtkSMPThreadLocal<std::vector<double>> normalScratch;
  vtkSMPThreadLocal<NoiseScratch> noiseScratch;
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double>& q = normalScratch.Local();
    NoiseScratch& s = noiseScratch.Local();
    q.resize(3 * static_cast<size_t>(kn));
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    double x[3], lambda[3], nrm[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      const int32_t* row = this->Row(r, buffer.data(), kn);
      const int count = featurepoints::RowLength(row, kn);
      featurepoints::GatherRelative(this->Reader, id, row, count, q.data(), x);
      const double away[3] = { x[0] - center[0], x[1] - center[1], x[2] - center[2] };
      featurepoints::LocalPCA(q.data(), count, true, away, lambda, nrm);
      for (int c = 0; c < 3; ++c)
      {
        normal[3 * id + c] = static_cast<float>(nrm[c]);
      }
      // The noise: what a smooth surface leaves of the smallest neighbourhood on the point's
      // sheet. Curvature is explained by the quadric; NoiseVariance() keeps the creases out.
      int dof = 0;
      residual[r] = NoiseResidual(q.data(), count, nrm, lambda[0], s, raw[r], dof);
      rowDof[r] = static_cast<signed char>(std::min(dof, 127));
      reach[r] = count > 0 ? 0.0 : -1.0;
      for (int j = 0; j < count; ++j)
      {
        const double* y = q.data() + 3 * j;
        const double h = y[0] * nrm[0] + y[1] * nrm[1] + y[2] * nrm[2];
        reach[r] = std::max(reach[r], y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - h * h);
      }
    }
  });
  const double floor = NoiseFloor * NoiseFloor * this->D * this->D;
  this->Variance = std::max(this->NoiseVariance(residual, raw, rowDof, kn + 1 - 6), floor);
  this->NoiseReach2 = this->RowQuantile(reach, 0.5);
}

void CreaseRun::MeasureNoiseAcross(vtkPointCloudNeighborhoods* neighborhoods, int kn)
{
  const double floor = NoiseFloor * NoiseFloor * this->D * this->D;
  int used = kn;
  for (int pass = 0; pass < NoiseSearchPasses && neighborhoods && kn > 0; ++pass)
  {
    const double ratio = NoiseHeightSpread * NoiseHeightSpread * this->Variance / this->NoiseReach2;
    if (!(this->NoiseReach2 > 0.0) || !std::isfinite(ratio) || (pass == 0 && ratio <= 1.0))
    {
      return;
    }
    // The same on every process of a distributed run (global figures only): rows with fewer
    // points than that hold -1 past their last.
    const int want =
      static_cast<int>(std::min<double>(this->K, std::ceil((kn + 1) * (1.0 + ratio)) - 1.0));
    if (want <= used)
    {
      return;
    }
    used = want;
    std::vector<double> residual(static_cast<size_t>(this->Rows), -1.0);
    std::vector<double> raw(static_cast<size_t>(this->Rows), -1.0);
    std::vector<double> reach(static_cast<size_t>(this->Rows), -1.0);
    std::vector<signed char> rowDof(static_cast<size_t>(this->Rows), 0);
    std::vector<int32_t> table;
    vtkSMPThreadLocal<NoiseScratch> noiseScratch;
    for (vtkIdType start = 0; start < this->Rows; start += BlockRows)
    {
      const std::vector<vtkIdType> block(this->Ids.begin() + start,
        this->Ids.begin() + std::min<vtkIdType>(this->Rows, start + BlockRows));
      if (!neighborhoods->FindNearestNeighbors(want, block, table))
      {
        table.assign(block.size() * static_cast<size_t>(want), -1); // no figure from these rows
      }
      vtkSMPTools::For(0, static_cast<vtkIdType>(block.size()), [&](vtkIdType begin, vtkIdType end) {
        NoiseScratch& s = noiseScratch.Local();
        std::vector<double> q(3 * static_cast<size_t>(want)), across(3 * static_cast<size_t>(kn));
        std::vector<std::pair<double, int>> order;
        double x[3], lambda[3], nrm[3];
        const double any[3] = { 0.0, 0.0, 0.0 }; // the residual does not read the normal's sign
        for (vtkIdType b = begin; b < end; ++b)
        {
          const vtkIdType r = start + b;
          const int32_t* row = table.data() + b * want;
          const int count = featurepoints::RowLength(row, want);
          featurepoints::GatherRelative(this->Reader, block[b], row, count, q.data(), x);
          if (!featurepoints::LocalPCA(q.data(), count, true, any, lambda, nrm))
          {
            continue;
          }
          // The kn nearest across the surface, in a strict order (distance, then rank).
          order.clear();
          for (int j = 0; j < count; ++j)
          {
            const double* y = q.data() + 3 * j;
            const double h = y[0] * nrm[0] + y[1] * nrm[1] + y[2] * nrm[2];
            order.emplace_back(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - h * h, j);
          }
          const int m = std::min(kn, count);
          std::partial_sort(order.begin(), order.begin() + m, order.end());
          Eigen::Vector3d mean = Eigen::Vector3d::Zero();
          for (int j = 0; j < m; ++j)
          {
            const double* y = q.data() + 3 * order[j].second;
            std::copy_n(y, 3, across.data() + 3 * j);
            mean += Eigen::Vector3d(y[0], y[1], y[2]);
          }
          mean /= m + 1;
          // The plane of the wider neighbourhood's normal through the points kept: its residual
          // per point, as LocalPCA's smallest eigenvalue would be for their own plane.
          const Eigen::Vector3d n(nrm[0], nrm[1], nrm[2]);
          double plane = mean.dot(n) * mean.dot(n);
          for (int j = 0; j < m; ++j)
          {
            const double* y = across.data() + 3 * j;
            const double h = (Eigen::Vector3d(y[0], y[1], y[2]) - mean).dot(n);
            plane += h * h;
          }
          int dof = 0;
          residual[r] = NoiseResidual(across.data(), m, nrm, plane / (m + 1), s, raw[r], dof);
          rowDof[r] = static_cast<signed char>(std::min(dof, 127));
          reach[r] = m > 0 ? std::max(order[m - 1].first, 0.0) : -1.0;
        }
      });
    }
    if (this->CountRows(residual) == 0)
    {
      return; // no row has a figure: the one before stands
    }
    this->Variance = std::max(this->NoiseVariance(residual, raw, rowDof, kn + 1 - 6), floor);
    this->NoiseReach2 = this->RowQuantile(reach, 0.5);
  }
}

// Wilson and Hilferty: chi2(n) / n at the standard normal quantile z is about
// (1 - a + z sqrt(a))^3, a = 2 / (9 n); the median is z = 0.
double ChiSquareShare(int n, double z)
{
  const double a = 2.0 / (9.0 * std::max(n, 1));
  const double c = 1.0 - a + z * std::sqrt(a);
  return c > 0.0 ? c * c * c : 0.0;
}

double CreaseRun::TrimmedMedian(
  const std::vector<double>& residual, int dof, std::vector<double>& scratch) const
{
  scratch = residual;
  double estimate = this->RowQuantile(scratch, 0.5);
  const double upper = ChiSquareShare(dof, NoiseTrimZ) / ChiSquareShare(dof, 0.0);
  const double back = ChiSquareShare(dof, 0.0) / ChiSquareShare(dof, NoiseTrimHalfZ);
  for (int round = 0; round < NoiseTrimRounds && estimate > 0.0 && std::isfinite(estimate);
       ++round)
  {
    scratch.resize(residual.size()); // RowQuantile() drops the rows without a figure
    const double cut = upper * estimate;
    for (size_t r = 0; r < residual.size(); ++r)
    {
      scratch[r] = residual[r] >= 0.0 && residual[r] <= cut ? residual[r] : -1.0;
    }
    if (this->CountRows(scratch) < 100)
    {
      break;
    }
    const double next = this->RowQuantile(scratch, 0.5) * back;
    const bool settled = std::abs(next - estimate) <= 1e-9 * estimate;
    estimate = next;
    if (settled)
    {
      break;
    }
  }
  return estimate;
}

double CreaseRun::NoiseVariance(std::vector<double>& residual, const std::vector<double>& raw,
  const std::vector<signed char>& rowDof, int dof) const
{
  auto share = ChiSquareShare;
  std::vector<double> scaled(residual);
  const double median = this->TrimmedMedian(residual, dof, scaled);
  // The shares and the standard normal's quantiles at them.
  const std::array<std::pair<double, double>, 3> lower = { { { 0.25, -0.6744898 },
    { 0.1, -1.2815516 }, { 0.05, -1.6448536 } } };
  double smallest = median;
  for (const auto& q : lower)
  {
    const double whole = share(dof, q.second);
    if (whole <= 0.0)
    {
      continue;
    }
    scaled.resize(raw.size()); // RowQuantile() drops the rows without a figure
    for (size_t r = 0; r < raw.size(); ++r)
    {
      scaled[r] =
        raw[r] >= 0.0 && rowDof[r] >= 4 ? raw[r] * whole / share(rowDof[r], q.second) : -1.0;
    }
    if (q.first * static_cast<double>(this->CountRows(scaled)) >= 100.0)
    {
      smallest =
        std::min(smallest, this->RowQuantile(scaled, q.first) * share(dof, 0.0) / whole);
    }
  }
  // Past the median's breakdown: fewer than half of the rows that only noise would put below
  // the median it implies, so that most rows see a feature.
  scaled.resize(residual.size());
  for (size_t r = 0; r < residual.size(); ++r)
  {
    scaled[r] = residual[r] >= 0.0 && residual[r] <= smallest ? 0.0 : -1.0;
  }
  return 4 * this->CountRows(scaled) < this->CountRows(residual) ? smallest : median;
}

double CreaseRun::NoiseResidual(const double* q, int count, const double nrm[3], double lambda,
  NoiseScratch& s, double& raw, int& dof)
{
  raw = -1.0;
  dof = 0;
  // The point (first, at the origin) and its neighbours.
  const int all = count + 1;
  s.P.assign(1, Eigen::Vector3d::Zero());
  for (int j = 0; j < count; ++j)
  {
    s.P.emplace_back(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
  }
  Eigen::Vector3d normal(nrm[0], nrm[1], nrm[2]);
  double planeRss = all * lambda;
  if (all > 6)
  {
    // Two rounds: a neighbourhood across a wall with more points on one side tilts its plane,
    // which mixes the tilt into both groups' heights; the second splits by the plane of the
    // point's group.
    SplitHeights(s.P, normal, s.Label);
    Moments own;
    for (int j = 0; j < all; ++j)
    {
      if (s.Label[j] == s.Label[0])
      {
        own.Add(s.P[j]);
      }
    }
    Eigen::Vector3d c, n;
    double rss = 0.0;
    if (FitPlane(own, c, n, rss) && TwoSheets(s.P, n, s.Label, SplitHeights(s.P, n, s.Label)))
    {
      // The point's sheet alone.
      size_t kept = 0;
      for (int j = 0; j < all; ++j)
      {
        if (s.Label[j] == s.Label[0])
        {
          s.P[kept++] = s.P[j];
        }
      }
      s.P.resize(kept);
      Moments sheet;
      for (const Eigen::Vector3d& y : s.P)
      {
        sheet.Add(y);
      }
      if (!FitPlane(sheet, c, normal, planeRss))
      {
        return -1.0;
      }
    }
  }
  const int points = static_cast<int>(s.P.size());
  if (points <= 6)
  {
    return -1.0; // too few for the quadric: no figure
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& y : s.P)
  {
    mean += y;
  }
  mean /= points;
  // Heights, not distances across: the gradient of six coefficients fitted to 16 points is
  // noisy enough to shrink the residual (a torus at 0.5 s of noise: sigma -6 %). A sheet of
  // fewer points leaves fewer degrees of freedom: its figure is scaled to the median that the
  // whole neighbourhood's would have (the median of chi-square by Wilson and Hilferty).
  const double rss = FitQuadric(s.P, mean, normal, planeRss, nullptr, false);
  auto medianShare = [](int dof) {
    const double a = 1.0 - 2.0 / (9.0 * dof);
    return a * a * a;
  };
  raw = rss / (points - 6);
  dof = points - 6;
  return rss / (points - 6) * (medianShare(all - 6) / medianShare(points - 6));
}

bool CreaseRun::HingeMeets(vtkIdType r, const HingeFrame& frame, int ks) const
{
  if (!frame.Valid)
  {
    return false;
  }
  std::vector<int32_t> buffer(static_cast<size_t>(this->K));
  const int32_t* row = this->Row(r, buffer.data(), this->KFit);
  const int count = featurepoints::RowLength(row, this->KFit);
  const double noise = 3.0 * std::sqrt(this->Variance);
  const double gap = 2.0 * this->LocalSpacing(r, ks);
  double x[3], y[3];
  this->Reader.Get(this->Ids[r], x);
  double nearest[2] = { std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  for (int j = -1; j < count; ++j)
  {
    Eigen::Vector3d w = -frame.Point;
    if (j >= 0)
    {
      this->Reader.Get(row[j], y);
      w += Eigen::Vector3d(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
    }
    w -= w.dot(frame.T) * frame.T;
    for (int k = 0; k < 2; ++k)
    {
      const double on = w.dot(frame.Ray[k]);
      if (on > -noise && std::abs(w.dot(frame.Face[k])) <= noise)
      {
        nearest[k] = std::min(nearest[k], std::max(on, 0.0));
      }
    }
  }
  return nearest[0] <= gap && nearest[1] <= gap;
}

void CreaseRun::MarkFrames(int kn, const unsigned char* type, double minAngle,
  std::vector<int32_t>& frameOf, std::vector<HingeFrame>& frames) const
{
  // Only a hinge that explains its points within the noise (a corner's is two of its faces, and
  // the third's points fall on either) and whose faces meet (see HingeMeets()), as the owner of
  // the point fitted it.
  std::vector<unsigned char> framed(static_cast<size_t>(this->N), 0);
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      const CreaseFit& fit = this->Fits[r];
      const CreaseLine& f = fit.Hinge;
      const bool crossing = fit.Crossing && f.RSS2 == fit.Cross.RSS2;
      framed[id] = this->IsOwn(id) &&
          (type[id] == vtkCreaseVotingFeatures::CONVEX ||
            type[id] == vtkCreaseVotingFeatures::CONCAVE) &&
          f.HasLine && this->Gain[r] > MinimumGain && !(f.Angle < minAngle) && !crossing &&
          f.RSS2 <= MisfitBound(fit.Points - 6) * this->Variance &&
          this->HingeMeets(r, HingeFrame(f), kn)
        ? 1
        : 0;
    }
  });
  if (this->FromOwners)
  {
    this->FromOwners(framed.data(), 1);
  }
  frameOf.assign(static_cast<size_t>(this->Rows), -1);
  frames.clear();
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (framed[this->Ids[r]])
    {
      const HingeFrame frame(this->Fits[r].Hinge);
      if (frame.Valid)
      {
        frameOf[r] = static_cast<int32_t>(frames.size());
        frames.push_back(frame);
      }
    }
  }
}

void CreaseRun::WeighLinks(int kn, const double center[3], const float* normal,
  const std::vector<int32_t>& frameOf, const std::vector<HingeFrame>& frames,
  const std::vector<int32_t>& place, const std::vector<long long>& key,
  std::vector<int32_t>& target, std::vector<uint8_t>& weight, std::vector<signed char>& own,
  std::vector<double>& share) const
{
  const size_t placed = static_cast<size_t>(
    std::count_if(place.begin(), place.end(), [](int32_t p) { return p >= 0; }));
  const size_t slots = placed * static_cast<size_t>(kn);
  target.assign(slots, -1);
  weight.assign(slots, NoLink);
  own.assign(static_cast<size_t>(this->Rows), 0);
  share.assign(static_cast<size_t>(this->Rows), 0.0);
  const double clear = 2.0 * std::sqrt(this->Variance);
  auto quantized = [](double w) {
    return static_cast<uint8_t>(std::min(254.0, std::round(127.0 * std::max(w, 0.0))));
  };
  auto normalOf = [&](vtkIdType r) {
    const float* n = normal + 3 * this->Ids[r];
    return Eigen::Vector3d(n[0], n[1], n[2]);
  };
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    double x[3], y[3];
    std::vector<int32_t> nearest(static_cast<size_t>(this->K));
    std::vector<std::tuple<long long, int32_t, uint8_t>> links;
    for (vtkIdType r = begin; r < end; ++r)
    {
      // Only the own points' nearest: a halo point's are the nearest its piece holds, not the
      // cloud's.
      if (!this->IsOwn(this->Ids[r]))
      {
        continue;
      }
      // The next row's slots, which lie in the keys' order (anywhere in memory for a shuffled
      // input), asked of memory while this one is weighed.
      if (r + 1 < end && place[r + 1] >= 0)
      {
        const size_t next = static_cast<size_t>(place[r + 1]) * kn;
        PrefetchForWrite(weight.data() + next);
        PrefetchForWrite(target.data() + next);
        PrefetchForWrite(target.data() + next + kn - 1);
      }
      const Eigen::Vector3d n = normalOf(r);
      this->Reader.Get(this->Ids[r], x);
      const int32_t* row = this->Row(r, nearest.data(), kn);
      const int count = featurepoints::RowLength(row, kn);
      double sure = 0.0;
      if (count > 0)
      {
        this->Reader.Get(row[count - 1], y);
        const double area = vtkMath::Distance2BetweenPoints(x, y) / count;
        const Eigen::Vector3d away(x[0] - center[0], x[1] - center[1], x[2] - center[2]);
        share[r] = area * n.dot(away);
      }
      if (frameOf[r] >= 0)
      {
        own[r] = static_cast<signed char>(
          frames[frameOf[r]].Side(Eigen::Vector3d::Zero(), n, clear, sure));
        share[r] *= own[r];
      }
      for (int j = 0; j < count; ++j)
      {
        const vtkIdType to = this->RowOf[row[j]];
        if (to < 0)
        {
          continue;
        }
        const size_t slot = static_cast<size_t>(place[r]) * kn + j;
        this->Reader.Get(row[j], y);
        const Eigen::Vector3d step(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
        const Eigen::Vector3d m = normalOf(to);
        int relation = 1;
        if (frameOf[r] >= 0 && frameOf[to] >= 0)
        {
          // Two frames: their faces matched.
          relation = frames[frameOf[r]].Relation(frames[frameOf[to]], sure);
          weight[slot] = sure > 0.5 ? quantized(1.0 - sure) : NoLink;
        }
        else if (frameOf[r] >= 0 || frameOf[to] >= 0)
        {
          // A frame and a normal: the normal's side on the face it belongs to.
          const bool mine = frameOf[r] >= 0;
          const HingeFrame& frame = frames[frameOf[mine ? r : to]];
          relation = mine ? frame.Side(step, m, clear, sure) : frame.Side(-step, n, clear, sure);
          weight[slot] = sure > 0.5 ? quantized(1.0 - sure) : NoLink;
        }
        else
        {
          // Two normals: the bend and the step out of the tangent planes (see OrientNormals()).
          const double length = step.norm();
          const double height = std::max(std::abs(n.dot(step)), std::abs(m.dot(step)));
          const double bend = std::abs(n.dot(m));
          if ((height > 0.5 * length && height * height > 9.0 * this->Variance) || bend < 0.5)
          {
            continue;
          }
          const double across = length > 0.0 ? height / length : 0.0;
          weight[slot] = quantized(1.0 - bend + across);
          relation = n.dot(m) < 0.0 ? -1 : 1;
        }
        target[slot] = static_cast<int32_t>(relation < 0 ? ~to : to);
      }
      // The row's links in the order of their ends' keys (see SpanForest()).
      links.clear();
      for (int j = 0; j < kn; ++j)
      {
        const size_t slot = static_cast<size_t>(place[r]) * kn + j;
        if (weight[slot] < NoLink)
        {
          const int32_t t = target[slot];
          links.emplace_back(key[t < 0 ? ~t : t], t, weight[slot]);
        }
      }
      std::sort(links.begin(), links.end());
      for (int j = 0; j < kn; ++j)
      {
        const size_t slot = static_cast<size_t>(place[r]) * kn + j;
        const bool used = j < static_cast<int>(links.size());
        target[slot] = used ? std::get<1>(links[j]) : -1;
        weight[slot] = used ? std::get<2>(links[j]) : NoLink;
      }
    }
  });
}

size_t CreaseRun::DropCycleMaxima(int kn, const std::vector<int32_t>& rows,
  const std::vector<int32_t>& place, const std::vector<int32_t>& target,
  std::vector<uint8_t>& weight) const
{
  // The cycle property: a link that is the heaviest of a cycle (in a strict order) is in no
  // minimum spanning forest. Kruskal reaches it after the cycle's other links, which have joined
  // its ends by then, so it joins nothing: dropping it leaves the forest, link for link, and with
  // it the sides, as they were. The order is SpanForest()'s: by weight, then by slot (the rows in
  // the order of their keys, each row's links in the order of their ends' keys).
  const size_t links = static_cast<size_t>(
    std::count_if(weight.begin(), weight.end(), [](uint8_t w) { return w != NoLink; }));
  constexpr int MaskBits = 64;
  if (kn > MaskBits || rows.empty())
  {
    return links; // a row's links in one mask, or none dropped
  }
  auto end = [](int32_t t) { return t < 0 ? ~t : t; };
  // The rows in the cloud's (the grid's) order, where a row's ends were read shortly before: the
  // links lie in the keys' order, which for a shuffled input is anywhere in memory. Blocks of
  // rows: each block's links are dropped once all of its rows are read, so that a row is never
  // read while it changes. A later block reads the dropped links as no link and finds fewer
  // cycles through them, not wrong ones: every link it drops is the heaviest of a cycle of the
  // links as first weighed.
  const vtkIdType block = 65536;
  std::vector<uint64_t> dropped(static_cast<size_t>(std::min(block, this->Rows)));
  for (vtkIdType first = 0; first < this->Rows; first += block)
  {
    const vtkIdType last = std::min(this->Rows, first + block);
    vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType stop) {
      std::array<uint16_t, MaskBits> ranked;
      std::array<int32_t, MaskBits> seen;
      for (vtkIdType r = begin; r < stop; ++r)
      {
        dropped[r - first] = 0;
        if (place[r] < 0)
        {
          continue; // a halo row
        }
        const size_t base = static_cast<size_t>(place[r]) * kn;
        // The rows of its links' other ends, asked of memory at once rather than one by one.
        for (int j = 0; j < kn; ++j)
        {
          if (weight[base + j] != NoLink)
          {
            const int32_t q = place[end(target[base + j])];
            if (q >= 0)
            {
              Prefetch(weight.data() + static_cast<size_t>(q) * kn);
              Prefetch(target.data() + static_cast<size_t>(q) * kn);
              Prefetch(target.data() + static_cast<size_t>(q) * kn + kn - 1);
            }
          }
        }
        if (r + 1 < stop && place[r + 1] >= 0)
        {
          const size_t next = static_cast<size_t>(place[r + 1]) * kn;
          Prefetch(weight.data() + next);
          Prefetch(target.data() + next);
          Prefetch(target.data() + next + kn - 1);
        }
        // The row's links in their order: weight, then place in the row.
        int count = 0;
        for (int j = 0; j < kn; ++j)
        {
          if (weight[base + j] != NoLink)
          {
            const uint16_t order = static_cast<uint16_t>(weight[base + j] * MaskBits + j);
            int at = count++;
            for (; at > 0 && ranked[at - 1] > order; --at)
            {
              ranked[at] = ranked[at - 1];
            }
            ranked[at] = order;
          }
        }
        // Each link against the lighter links of both its ends: the link back from the other
        // end (a pair), or a third point that both ends link to (a triangle).
        uint64_t mask = 0, bloom = 0;
        for (int k = 0; k < count; ++k)
        {
          const int j = ranked[k] % MaskBits;
          const size_t e = base + j;
          const uint8_t we = weight[e];
          const int32_t q = place[end(target[e])];
          if (q >= 0) // a halo row has no links of its own here
          {
            const size_t other = static_cast<size_t>(q) * kn;
            bool cycle = false;
            for (int i = 0; i < kn && !cycle; ++i)
            {
              const size_t f = other + i;
              const uint8_t wf = weight[f];
              if (wf > we || (wf == we && f > e) || wf == NoLink)
              {
                continue;
              }
              const int32_t c = end(target[f]);
              cycle = c == r;
              if (!cycle && (bloom >> (c % MaskBits) & 1))
              {
                for (int m = 0; m < k && !cycle; ++m)
                {
                  cycle = seen[m] == c;
                }
              }
            }
            if (cycle)
            {
              mask |= uint64_t(1) << j;
            }
          }
          seen[k] = end(target[e]);
          bloom |= uint64_t(1) << (seen[k] % MaskBits);
        }
        dropped[r - first] = mask;
      }
    });
    vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType stop) {
      for (vtkIdType r = begin; r < stop; ++r)
      {
        uint64_t mask = dropped[r - first];
        for (size_t slot = static_cast<size_t>(place[r]) * kn; mask; mask >>= 1, ++slot)
        {
          if (mask & 1)
          {
            weight[slot] = NoLink;
          }
        }
      }
    });
  }
  return links;
}

void CreaseRun::SpanForest(int kn, const std::vector<int32_t>& rows,
  const std::vector<int32_t>& target, const std::vector<uint8_t>& weight,
  const std::vector<long long>& key, size_t weighed, SignedSets& sets,
  std::vector<double>* forest) const
{
  // Kruskal: the links by weight, then by their ends' keys (a strict order, the same in any
  // piece: the forest is then the cloud's one minimum spanning forest). The own rows' links lie
  // in the order of the rows' keys (rows), each row's in the order of their ends' keys.
  std::array<size_t, NoLink + 1> count{};
  for (uint8_t w : weight)
  {
    ++count[w];
  }
  // A few passes, each over a range of weights holding at most about a sixteenth of the links
  // as weighed (before DropCycleMaxima()), so that the order of only that many is held at a time.
  const size_t share = std::max<size_t>(weighed / 16, 1);
  auto end = [](int32_t t) { return t < 0 ? ~t : t; };
  if (forest)
  {
    forest->clear();
  }
  std::vector<uint64_t> order;
  for (int low = 0; low < NoLink;)
  {
    int high = low;
    size_t held = 0;
    while (high < NoLink && (held == 0 || held + count[high] <= share))
    {
      held += count[high++];
    }
    // Where each weight of the pass goes next; the other weights all go to one spare entry
    // past the end and stay there (no branch: a sixteenth of the links are taken in a pass).
    std::array<size_t, NoLink + 1> at, step{};
    at.fill(held);
    size_t next = 0;
    for (int w = low; w < high; next += count[w++])
    {
      at[w] = next;
      step[w] = 1;
    }
    order.resize(held + 1);
    for (size_t slot = 0; slot < weight.size(); ++slot)
    {
      const int w = weight[slot];
      order[at[w]] = slot;
      at[w] += step[w];
    }
    order.resize(held);
    // The links come in the order of their weights, from anywhere in the cloud: the rows and
    // the sets that a link a few places ahead reads are asked of memory before it is joined.
    constexpr size_t Ahead = 16;
    for (size_t i = 0; i < order.size(); ++i)
    {
      if (i + 2 * Ahead < order.size())
      {
        Prefetch(target.data() + order[i + 2 * Ahead]);
        Prefetch(rows.data() + order[i + 2 * Ahead] / kn);
      }
      if (i + Ahead < order.size())
      {
        sets.PrefetchParent(rows[order[i + Ahead] / kn]);
        sets.PrefetchParent(end(target[order[i + Ahead]]));
      }
      const uint64_t slot = order[i];
      const int32_t r = rows[slot / kn];
      const int32_t t = target[slot];
      if (sets.Join(r, end(t), t < 0) && forest)
      {
        forest->insert(forest->end(),
          { static_cast<double>(weight[slot]), static_cast<double>(key[r]),
            static_cast<double>(key[end(t)]), t < 0 ? 1.0 : 0.0 });
      }
    }
    low = high;
  }
}

void CreaseRun::OrientNormals(int kn, const double center[3], const float* normal,
  const unsigned char* type, double minAngle, std::vector<signed char>& side,
  std::vector<signed char>& own)
{
  std::vector<int32_t> frameOf;
  std::vector<HingeFrame> frames;
  this->MarkFrames(kn, type, minAngle, frameOf, frames);
  std::vector<double>().swap(this->Gain); // read last by MarkFrames()
  std::vector<long long> key(static_cast<size_t>(this->Rows));
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    key[r] = this->Key(this->Ids[r]);
  }
  // The own rows in the order of their keys, and each one's place in it (-1: halo).
  std::vector<int32_t> rows, place(static_cast<size_t>(this->Rows), -1);
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (this->IsOwn(this->Ids[r]))
    {
      rows.push_back(static_cast<int32_t>(r));
    }
  }
  std::sort(rows.begin(), rows.end(), [&](int32_t a, int32_t b) { return key[a] < key[b]; });
  for (size_t p = 0; p < rows.size(); ++p)
  {
    place[rows[p]] = static_cast<int32_t>(p);
  }
  std::vector<int32_t> target;
  std::vector<uint8_t> weight;
  std::vector<double> share;
  this->WeighLinks(kn, center, normal, frameOf, frames, place, key, target, weight, own, share);
  const size_t weighed = this->DropCycleMaxima(kn, rows, place, target, weight);
  std::vector<int32_t>().swap(place);
  std::vector<int32_t>().swap(frameOf);
  std::vector<HingeFrame>().swap(frames);
  // The sides, relative to each tree's root: set by the forest alone, up to one sign per tree.
  // The sets' elements: the rows; distributed, the keys of every piece's forest (sorted).
  SignedSets local(key.size());
  std::unique_ptr<SignedSets> cloud;
  std::vector<long long> all;
  {
    std::vector<double> forest;
    // One process: the sets are the forest's result, its links are not needed (32 bytes a point).
    this->SpanForest(
      kn, rows, target, weight, key, weighed, local, this->Distributed ? &forest : nullptr);
    std::vector<int32_t>().swap(target);
    std::vector<uint8_t>().swap(weight);
    if (this->Distributed)
    {
      // Every piece's forest: the cloud's forest spans their union (a link left out of a piece's
      // is the heaviest of a cycle there), found again by every process in the same order.
      this->GatherAll(forest);
      all = key;
      for (size_t e = 0; e + 3 < forest.size(); e += 4)
      {
        all.push_back(static_cast<long long>(forest[e + 1]));
        all.push_back(static_cast<long long>(forest[e + 2]));
      }
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      std::vector<size_t> order(forest.size() / 4);
      std::iota(order.begin(), order.end(), size_t(0));
      std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return std::make_tuple(forest[4 * a], forest[4 * a + 1], forest[4 * a + 2]) <
          std::make_tuple(forest[4 * b], forest[4 * b + 1], forest[4 * b + 2]);
      });
      cloud.reset(new SignedSets(all.size()));
      auto indexOf = [&](double k) {
        return static_cast<int32_t>(
          std::lower_bound(all.begin(), all.end(), static_cast<long long>(k)) - all.begin());
      };
      for (size_t e : order)
      {
        cloud->Join(
          indexOf(forest[4 * e + 1]), indexOf(forest[4 * e + 2]), forest[4 * e + 3] > 0.5);
      }
    }
  }
  side.assign(static_cast<size_t>(this->Rows), 1);
  std::vector<int32_t> root(static_cast<size_t>(this->Rows));
  SignedSets& sets = cloud ? *cloud : local;
  const std::vector<long long>& elements = cloud ? all : key;
  auto elementOf = [&](vtkIdType r) {
    return cloud ? static_cast<int32_t>(
                     std::lower_bound(all.begin(), all.end(), key[r]) - all.begin())
                 : static_cast<int32_t>(r);
  };
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    int turn = 0;
    root[r] = sets.Find(elementOf(r), turn);
    side[r] = static_cast<signed char>(turn ? -1 : 1);
  }
  // Each tree's side: the one that encloses a positive volume, summed over every piece.
  std::vector<double> volume(elements.size(), 0.0);
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (this->IsOwn(this->Ids[r]))
    {
      volume[root[r]] += side[r] * share[r];
    }
  }
  if (this->Distributed)
  {
    std::vector<double> pairs;
    for (size_t v = 0; v < volume.size(); ++v)
    {
      if (volume[v] != 0.0)
      {
        pairs.insert(pairs.end(), { static_cast<double>(all[v]), volume[v] });
      }
    }
    this->GatherAll(pairs);
    std::fill(volume.begin(), volume.end(), 0.0);
    for (size_t p = 0; p + 1 < pairs.size(); p += 2)
    {
      const auto at = std::lower_bound(all.begin(), all.end(), static_cast<long long>(pairs[p]));
      if (at != all.end() && *at == static_cast<long long>(pairs[p]))
      {
        volume[static_cast<size_t>(at - all.begin())] += pairs[p + 1];
      }
    }
  }
  // A tree that encloses nothing (duplicates alone, points without neighbours): the side of its
  // smallest key. Its elements are all known here (the rows; distributed, the gathered forest).
  std::vector<std::pair<long long, int>> smallest;
  for (size_t i = 0; i < elements.size(); ++i)
  {
    int turn = 0;
    const int32_t top = sets.Find(static_cast<int32_t>(i), turn);
    if (volume[top] == 0.0)
    {
      if (smallest.empty())
      {
        smallest.assign(elements.size(), { std::numeric_limits<long long>::max(), 0 });
      }
      if (elements[i] < smallest[top].first)
      {
        smallest[top] = { elements[i], turn };
      }
    }
  }
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const double v = volume[root[r]];
    if (v < 0.0 || (v == 0.0 && smallest[root[r]].second != 0))
    {
      side[r] = static_cast<signed char>(-side[r]);
    }
  }
}

void CreaseRun::GatherSheet(
  vtkIdType r, const int32_t* row, int count, const float* normal, Scratch& s) const
{
  const vtkIdType id = this->Ids[r];
  const int length = featurepoints::RowLength(row, this->KFit);
  const uint64_t* sheet = this->Sheet(r);
  double x[3], y[3];
  this->Reader.Get(id, x);
  s.P.resize(1);
  s.N.resize(1);
  s.P[0].setZero();
  s.N[0] = Eigen::Vector3d(normal[3 * id], normal[3 * id + 1], normal[3 * id + 2]);
  for (int j = 0; j < length && static_cast<int>(s.P.size()) <= count; ++j)
  {
    if (!Reached(sheet, j + 1))
    {
      continue;
    }
    this->Reader.Get(row[j], y);
    s.P.emplace_back(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
    const float* nj = normal + 3 * static_cast<vtkIdType>(row[j]);
    s.N.emplace_back(nj[0], nj[1], nj[2]);
  }
}

// Two-plane fit of the gathered points; where they form two parallel sheets (a thin wall), the
// fit is redone on the fitted point's sheet.
CreaseFit FitGathered(Scratch& s, double variance, bool cubic)
{
  CreaseFit fit = FitCrease(s.P, s.N, variance, s.Label, s.Next, cubic);
  if (fit.Sheet >= 0)
  {
    const unsigned char side = static_cast<unsigned char>(fit.Sheet);
    size_t kept = 0;
    for (size_t j = 0; j < s.P.size(); ++j)
    {
      if (j == 0 || s.Label[j] == side)
      {
        s.P[kept] = s.P[j];
        s.N[kept] = s.N[j];
        ++kept;
      }
    }
    s.P.resize(kept);
    s.N.resize(kept);
    fit = FitCrease(s.P, s.N, variance, s.Label, s.Next, cubic);
    fit.Sheet = -1;
  }
  return fit;
}

// Whether one plane explains the points of `all` (at least 8) within the noise: a residual of at
// most the bound of the quadric (so that Explains() holds); rss: the plane's residual.
bool PlaneExplains(const Moments& all, double variance, double& rss)
{
  Eigen::Vector3d c, n;
  return all.Count >= 8 && FitPlane(all, c, n, rss) && rss <= MisfitBound(all.Count - 6) * variance;
}

// Whether one plane explains the gathered points p within the noise (the bound of the quadric,
// so that Explains() holds), as on most of a part's faces; then `fit` is that plane alone: no
// line, no gain. Most points lie on faces, and the two-plane fit was most of the detector's
// time; what it finds there is a hinge fitted on the noise, whose line falls anywhere. Near a
// feature the points that one plane explains still cast votes that count: FitCreases() fits
// those whose sheet holds a point that one plane does not explain.
bool OnePlane(const std::vector<Eigen::Vector3d>& p, double variance, CreaseFit& fit)
{
  Moments all;
  for (const Eigen::Vector3d& q : p)
  {
    all.Add(q);
  }
  double rss = 0.0;
  if (!PlaneExplains(all, variance, rss))
  {
    return false;
  }
  fit = CreaseFit();
  fit.Points = all.Count;
  fit.RSS1 = fit.RSSQ = fit.Hinge.RSS2 = fit.Cross.RSS2 = rss;
  return true;
}

bool CreaseRun::OnePlaneRow(vtkIdType r, const int32_t* row, int count) const
{
  double x[3], y[3];
  this->Reader.Get(this->Ids[r], x);
  Moments all;
  all.Add(Eigen::Vector3d::Zero());
  for (int j = 0; j < count; ++j)
  {
    this->Reader.Get(row[j], y);
    all.Add(Eigen::Vector3d(y[0] - x[0], y[1] - x[1], y[2] - x[2]));
  }
  double rss = 0.0;
  return PlaneExplains(all, this->Variance, rss);
}

bool CreaseRun::LinkAcrossRows(vtkIdType id, const int32_t* row, int count, int32_t* links)
{
  const int first = std::min(count, SheetLinks);
  if (first < 2 || count <= first)
  {
    return false;
  }
  double x[3], y[3];
  this->Reader.Get(id, x);
  Eigen::Vector3d p[SheetLinks + 1];
  p[0].setZero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j = 0; j < first; ++j)
  {
    this->Reader.Get(row[j], y);
    p[j + 1] = Eigen::Vector3d(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
    mean += p[j + 1];
  }
  mean /= static_cast<double>(first + 1);
  featurepoints::OuterSum sum;
  for (int j = 0; j <= first; ++j)
  {
    sum.Add(p[j] - mean);
  }
  const Eigen::Matrix3d scatter = sum.Matrix();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  const Eigen::Vector3d spread = solver.eigenvalues(); // ascending
  if (!(spread[2] > 0.0) || spread[1] >= CollinearSpread * spread[2])
  {
    return false;
  }
  std::fill(links + SheetLinks, links + LinkSlots, -1);
  const Eigen::Vector3d u = solver.eigenvectors().col(2);
  Eigen::Vector3d side = Eigen::Vector3d::Zero();
  int added = 0;
  for (int j = first; j < count && added < LinkSlots - SheetLinks; ++j)
  {
    this->Reader.Get(row[j], y);
    const Eigen::Vector3d v(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
    const Eigen::Vector3d off = v - v.dot(u) * u;
    // Off the line: more across it than along it; the second on the other side of the first.
    if (off.squaredNorm() <= v.dot(u) * v.dot(u) || (added == 1 && off.dot(side) >= 0.0))
    {
      continue;
    }
    if (added == 0)
    {
      this->Across[id] = static_cast<float>(0.5 * off.norm());
    }
    side = off;
    links[SheetLinks + added++] = row[j];
  }
  return added < LinkSlots - SheetLinks;
}

void CreaseRun::PrepareFits(vtkPointCloudNeighborhoods* neighborhoods)
{
  this->Fits.Reset(this->Rows);
  this->Sheets.assign(static_cast<size_t>(this->Rows) * this->Words, 0);
  this->Scale.assign(static_cast<size_t>(this->Rows), this->KFit);
  this->Reach2.assign(static_cast<size_t>(this->Rows), std::numeric_limits<float>::infinity());
  this->Gain.assign(static_cast<size_t>(this->Rows), 0.0);
  this->Offset.assign(this->Thinning ? static_cast<size_t>(this->N) : 0, -1.0f);
  this->Spread.assign(this->Thinning ? static_cast<size_t>(this->N) : 0, 0.0f);
  // By point id: its SheetLinks nearest (the start of its row), -1 where none. The one-sheet
  // links read these for every neighbour of every point: a table of their own keeps them
  // together in memory instead of one cache line per row of the wide table.
  this->Links.assign(static_cast<size_t>(this->N) * LinkSlots, -1);
  this->Across.assign(static_cast<size_t>(this->N), 0.0f);
  const int width = std::min(SheetLinks, this->K);
  std::vector<unsigned char> wider(static_cast<size_t>(this->Rows), 0);
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->KNear));
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int32_t* row = this->Row(r, buffer.data(), this->KNear);
      int32_t* links = this->Links.data() + this->Ids[r] * LinkSlots;
      std::copy(row, row + width, links);
      wider[r] =
        this->LinkAcrossRows(this->Ids[r], row, featurepoints::RowLength(row, this->KNear), links);
    }
  });
  // Rows farther apart than the KNear nearest reach (6 points along them and more): the links
  // across from the AcrossRowsNeighbors nearest, searched for those points alone, a block at a
  // time.
  std::vector<vtkIdType> ids;
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (wider[r])
    {
      ids.push_back(this->Ids[r]);
    }
  }
  const int kw = std::min<vtkIdType>(AcrossRowsNeighbors, std::max<vtkIdType>(this->N - 1, 1));
  std::vector<int32_t> table;
  for (size_t start = 0; neighborhoods && kw > this->KNear && start < ids.size(); start += 65536)
  {
    const std::vector<vtkIdType> block(
      ids.begin() + start, ids.begin() + std::min(ids.size(), start + 65536));
    if (!neighborhoods->FindNearestNeighbors(kw, block, table))
    {
      break;
    }
    vtkSMPTools::For(0, static_cast<vtkIdType>(block.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType b = begin; b < end; ++b)
      {
        const int32_t* row = table.data() + b * kw;
        this->LinkAcrossRows(
          block[b], row, featurepoints::RowLength(row, kw), this->Links.data() + block[b] * LinkSlots);
      }
    });
  }
  this->Flat.assign(static_cast<size_t>(this->N), 0);
  this->Voter.assign(static_cast<size_t>(this->N), 0);
  this->NearBorder.assign(static_cast<size_t>(this->N), 0);
  if (this->Distributed)
  {
    this->DeferFits.assign(static_cast<size_t>(this->Rows), 0);
    this->DeferVotes.assign(static_cast<size_t>(this->Rows), 0);
  }
}

bool CreaseRun::Stream(vtkPointCloudNeighborhoods* neighborhoods, vtkAlgorithm* algorithm,
  double progressStart, double progressEnd,
  const std::function<void(vtkIdType, vtkIdType)> passes[3])
{
  // Slabs one mean spacing thick (at most one per row) across the longest side of the box.
  const double* bounds = neighborhoods->GetBounds();
  int axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    axis = bounds[2 * a + 1] - bounds[2 * a] > bounds[2 * axis + 1] - bounds[2 * axis] ? a : axis;
  }
  const double lo = bounds[2 * axis];
  const double length = bounds[2 * axis + 1] - lo;
  const double wanted = this->D > 0.0 ? length / this->D : 1.0;
  const vtkIdType slabs = wanted >= static_cast<double>(this->Rows)
    ? std::max(this->Rows, vtkIdType(1))
    : std::max(vtkIdType(1), static_cast<vtkIdType>(wanted));
  const double thickness = length > 0.0 ? length / slabs : 1.0;
  auto slabOf = [&](double x) {
    const double f = std::floor((x - lo) / thickness);
    return f < 0.0 ? vtkIdType(0) : (f >= slabs - 1 ? slabs - 1 : static_cast<vtkIdType>(f));
  };
  // A counting sort of the rows by slab, by row within a slab.
  std::vector<int32_t> slab(static_cast<size_t>(this->Rows));
  std::vector<vtkIdType> start(static_cast<size_t>(slabs) + 1, 0);
  double x[3];
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    this->Reader.Get(this->Ids[r], x);
    slab[r] = static_cast<int32_t>(slabOf(x[axis]));
    ++start[slab[r] + 1];
  }
  for (vtkIdType b = 0; b < slabs; ++b)
  {
    start[b + 1] += start[b];
  }
  this->Order.resize(static_cast<size_t>(this->Rows));
  this->Rank.resize(static_cast<size_t>(this->Rows));
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const vtkIdType i = start[slab[r]]++;
    this->Order[i] = static_cast<int32_t>(r);
    this->Rank[r] = static_cast<int32_t>(i);
  }
  if (this->K <= this->KNear)
  {
    // The narrow table holds every row whole.
    for (int pass = 0; pass < 3; ++pass)
    {
      passes[pass](0, this->Rows);
    }
    return true;
  }
  const vtkIdType blocks = (this->Rows + BlockRows - 1) / BlockRows;
  this->Blocks.clear();
  this->Blocks.resize(static_cast<size_t>(blocks));
  // Per block: the last slab its rows read (each row's farthest neighbour is at most its
  // distance away along the axis; one slab more for rounding).
  std::vector<vtkIdType> reach(static_cast<size_t>(blocks), 0);
  vtkIdType through[3] = { 0, 0, 0 }; // blocks through each pass
  // Whether every row that block c reads has been through `done` blocks.
  auto ready = [&](vtkIdType c, vtkIdType done) {
    return done == blocks || reach[c] < slab[this->Order[done * BlockRows]];
  };
  auto advance = [&]() {
    for (bool moved = true; moved;)
    {
      moved = false;
      for (int pass = 1; pass < 3 && !moved; ++pass)
      {
        const vtkIdType c = through[pass];
        if (c < through[pass - 1] && ready(c, through[pass - 1]))
        {
          passes[pass](c * BlockRows, std::min((c + 1) * BlockRows, this->Rows));
          ++through[pass];
          moved = true;
          if (pass == 2)
          {
            this->Blocks[c].reset();
          }
        }
      }
    }
  };
  std::vector<vtkIdType> blockIds;
  std::vector<vtkIdType> searched; // the block's rows that are searched (all but the halo's)
  std::vector<int32_t> found, spread;
  double y[3];
  for (vtkIdType c = 0; c < blocks; ++c)
  {
    const vtkIdType first = c * BlockRows;
    const vtkIdType count = std::min(BlockRows, this->Rows - first);
    // A halo row's k nearest are never read (its owner fits it): not searched, left empty.
    blockIds.clear();
    searched.clear();
    for (vtkIdType i = 0; i < count; ++i)
    {
      const vtkIdType id = this->Ids[this->Order[first + i]];
      if (this->IsOwn(id))
      {
        blockIds.push_back(id);
        searched.push_back(i);
      }
    }
    const double begin =
      progressStart + (progressEnd - progressStart) * static_cast<double>(first) / this->Rows;
    const double end = progressStart +
      (progressEnd - progressStart) * static_cast<double>(first + count) / this->Rows;
    if (!neighborhoods->FindNearestNeighbors(this->K, blockIds, found, nullptr, algorithm, begin, end))
    {
      return false;
    }
    if (static_cast<vtkIdType>(searched.size()) < count)
    {
      spread.assign(static_cast<size_t>(count) * this->K, -1);
      for (size_t i = 0; i < searched.size(); ++i)
      {
        std::copy_n(found.begin() + i * this->K, this->K, spread.begin() + searched[i] * this->K);
      }
      found.swap(spread);
    }
    this->Blocks[c].reset(new NeighborTable);
    this->Blocks[c]->Reset(count, this->K);
    this->Blocks[c]->Store(0, count, found.data());
    for (vtkIdType i = 0; i < count; ++i)
    {
      const int32_t* row = found.data() + i * this->K;
      const int length = featurepoints::RowLength(row, this->K);
      this->Reader.Get(this->Ids[this->Order[first + i]], x);
      double radius = 0.0;
      if (length > 0)
      {
        this->Reader.Get(row[length - 1], y);
        radius = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
      }
      reach[c] = std::max(reach[c], slabOf(x[axis] + radius) + 1);
    }
    passes[0](first, first + count);
    through[0] = c + 1;
    advance();
  }
  advance();
  this->Blocks.clear();
  std::vector<int32_t>().swap(this->Order);
  std::vector<int32_t>().swap(this->Rank);
  return true;
}

bool CreaseRun::LoadRows(
  vtkPointCloudNeighborhoods* neighborhoods, const std::function<bool(vtkIdType)>& wanted)
{
  if (this->K <= this->KNear)
  {
    return true; // the narrow table holds every row whole
  }
  this->SubsetSlot.assign(static_cast<size_t>(this->Rows), -1);
  std::vector<vtkIdType> rows;
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (wanted(r))
    {
      this->SubsetSlot[r] = static_cast<int32_t>(rows.size());
      rows.push_back(r);
    }
  }
  const vtkIdType count = static_cast<vtkIdType>(rows.size());
  this->Subset.Reset(count, this->K);
  std::vector<vtkIdType> blockIds;
  std::vector<int32_t> found;
  for (vtkIdType first = 0; first < count; first += BlockRows)
  {
    const vtkIdType size = std::min(BlockRows, count - first);
    blockIds.resize(static_cast<size_t>(size));
    for (vtkIdType i = 0; i < size; ++i)
    {
      blockIds[i] = this->Ids[rows[first + i]];
    }
    if (!neighborhoods->FindNearestNeighbors(this->K, blockIds, found))
    {
      return false;
    }
    this->Subset.Store(first, size, found.data());
  }
  return true;
}

void CreaseRun::MarkDeferredFits(vtkIdType begin, vtkIdType end)
{
  vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType i = first; i < last; ++i)
    {
      const vtkIdType r = this->Order[i];
      bool halo = !this->IsOwn(this->Ids[r]);
      const int32_t* row = this->Row(r, buffer.data(), ViewNeighbors);
      const int count = featurepoints::RowLength(row, std::min(ViewNeighbors, this->KFit));
      for (int j = 0; j < count && !halo; ++j)
      {
        halo = !this->IsOwn(row[j]);
      }
      this->DeferFits[r] = halo ? 1 : 0;
      this->DeferVotes[r] = this->DeferFits[r];
    }
  });
}

void CreaseRun::MarkDeferredVotes(vtkIdType begin, vtkIdType end)
{
  vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType i = first; i < last; ++i)
    {
      const vtkIdType r = this->Order[i];
      const int32_t* row = this->Row(r, buffer.data());
      const int count = featurepoints::RowLength(row, this->K);
      bool deferred = this->DeferFits[r] != 0;
      for (int j = 0; j < count && !deferred; ++j)
      {
        const vtkIdType q = this->RowOf[row[j]];
        deferred = q >= 0 && this->DeferFits[q] != 0;
      }
      this->DeferVotes[r] = deferred ? 1 : 0;
    }
  });
}

bool CreaseRun::RunDeferred(vtkPointCloudNeighborhoods* neighborhoods,
  const std::function<void(vtkIdType, vtkIdType)> passes[3])
{
  // Order: the DeferFits rows, then the other DeferVotes rows.
  this->Order.clear();
  for (int kind = 0; kind < 2; ++kind)
  {
    for (vtkIdType r = 0; r < this->Rows; ++r)
    {
      if (this->DeferVotes[r] && (this->DeferFits[r] != 0) == (kind == 0))
      {
        this->Order.push_back(static_cast<int32_t>(r));
      }
    }
  }
  vtkIdType fits = 0;
  while (fits < static_cast<vtkIdType>(this->Order.size()) && this->DeferFits[this->Order[fits]])
  {
    ++fits;
  }
  if (!this->LoadRows(neighborhoods,
        [&](vtkIdType r) { return this->DeferVotes[r] && this->IsOwn(this->Ids[r]); }))
  {
    return false;
  }
  // A block at a time, as the stream runs them: the passes' scratch (the fits of a block) stays
  // the size of a block.
  auto inBlocks = [](const std::function<void(vtkIdType, vtkIdType)>& pass, vtkIdType count) {
    for (vtkIdType first = 0; first < count; first += BlockRows)
    {
      pass(first, std::min(first + BlockRows, count));
    }
  };
  this->Deferring = true;
  inBlocks(passes[0], fits);
  this->ShareModels();
  inBlocks(passes[1], fits);
  inBlocks(passes[2], static_cast<vtkIdType>(this->Order.size()));
  this->Deferring = false;
  std::vector<int32_t>().swap(this->Order);
  std::vector<unsigned char>().swap(this->DeferFits);
  std::vector<unsigned char>().swap(this->DeferVotes);
  return true;
}

void CreaseRun::FitCreases(const float* normal, vtkIdType begin, vtkIdType end)
{
  // The rows' fits, stored after the loop in the rows' order (the one-plane rows' are dropped).
  std::vector<CreaseFit> fits(static_cast<size_t>(end - begin));
  vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
    Scratch& s = this->Scratches.Local();
    s.Row.resize(static_cast<size_t>(this->K));
    for (vtkIdType i = first; i < last; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (this->Defers(r, 0))
      {
        continue;
      }
      const int32_t* row = this->Row(r, s.Row.data());
      const int count = featurepoints::RowLength(row, this->KFit);
      uint64_t* sheet = this->Sheets.data() + r * this->Words;
      // Where one plane explains the whole neighbourhood (most of a part's faces), it is one
      // sheet and the point is flat: every neighbour, without following the links (a split
      // there would be a seam of the sampling, not two sheets).
      if (this->OnePlaneRow(r, row, count))
      {
        std::fill(sheet, sheet + this->Words, ~uint64_t(0));
        this->Flat[this->Ids[r]] = 1;
        continue;
      }
      // Every neighbour also when the sheet holds fewer than 8 points (an isolated point), so
      // that the fit has something to work on.
      if (s.Sheet.Reach(this->Ids[r], row, count, this->Links, sheet) < 8)
      {
        std::fill(sheet, sheet + this->Words, ~uint64_t(0));
      }
      this->GatherSheet(r, row, this->KFit, normal, s);
      if (OnePlane(s.P, this->Variance, fits[i - begin]))
      {
        this->Flat[this->Ids[r]] = 1;
        continue;
      }
      fits[i - begin] = FitGathered(s, this->Variance, true);
    }
  });
  for (vtkIdType i = begin; i < end; ++i)
  {
    if (!this->Flat[this->Ids[this->Order[i]]] && !this->Defers(this->Order[i], 0))
    {
      this->Fits.Add(this->Order[i], fits[i - begin]);
    }
  }
}

void CreaseRun::FitInView(const float* normal, vtkIdType begin, vtkIdType end)
{
  // The one-plane points with a point among their ViewNeighbors nearest on their sheet that one
  // plane does not explain: a feature in view, whose line their hinge finds too (left out, Model
  // II's recall at 0.5 s of noise falls from 0.945 to 0.895: the 15-degree creases lose those
  // votes). One plane explains their points: the hinge alone (FitViewHinge).
  std::vector<CreaseFit> fits(static_cast<size_t>(end - begin));
  std::vector<unsigned char> fitted(static_cast<size_t>(end - begin), 0);
  vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
    Scratch& s = this->Scratches.Local();
    s.Row.resize(static_cast<size_t>(this->K));
    for (vtkIdType i = first; i < last; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (!this->Flat[this->Ids[r]] || this->Defers(r, 1))
      {
        continue;
      }
      const int32_t* row = this->Row(r, s.Row.data());
      const int count = featurepoints::RowLength(row, this->KFit);
      const uint64_t* sheet = this->Sheet(r);
      bool inView = false;
      for (int j = 0; j < std::min(count, ViewNeighbors) && !inView; ++j)
      {
        inView = !this->Flat[row[j]] && Reached(sheet, j + 1);
      }
      if (inView)
      {
        this->GatherSheet(r, row, this->KFit, normal, s);
        fits[i - begin] = FitViewHinge(s.P, s.N);
        fitted[i - begin] = 1;
      }
    }
  });
  for (vtkIdType i = begin; i < end; ++i)
  {
    if (fitted[i - begin])
    {
      this->Fits.Add(this->Order[i], fits[i - begin]);
    }
  }
}

// Whether one smooth surface, one hinge or two crossing planes explain the points within the
// noise.
inline bool Explains(const CreaseFit& f, double variance)
{
  const double crossing = f.Crossing ? f.Cross.RSS2 : std::numeric_limits<double>::infinity();
  return std::min(std::min(f.RSSQ, f.Hinge.RSS2), crossing) <=
    MisfitBound(f.Points - 6) * variance;
}

void CreaseRun::ChooseScales(const float* normal, int smallest, double minAngle,
  unsigned char* detail, vtkIdType first, vtkIdType last)
{
  vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType end) {
    Scratch& s = this->Scratches.Local();
    // Whether the curved hinge explains the gathered points (two quadrics: 12 parameters)
    // within the noise.
    auto curvedExplains = [&](const CreaseFit& fit) {
      const double curved = FitCurvedHinge(s.P, fit.Hinge, s.Side);
      return curved >= 0.0 && curved <= MisfitBound(fit.Points - 12) * this->Variance;
    };
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (this->Defers(r, 1) || Explains(this->Fits[r], this->Variance))
      {
        continue;
      }
      // Halve the neighbourhood until its hinge explains it: features closer together than
      // the widest neighbourhood (grooves, small faces, detailed parts) each get a fit of
      // their own. Failing that at every scale, the largest scale whose curved hinge explains
      // it: a crease between curved faces (a cylinder's rim, a fillet's edge), which two planes
      // fit only within the faces' curvature, never within the noise of a clean cloud.
      CreaseFit fit, curvedFit;
      int curvedScale = 0;
      float curvedReach2 = 0.0f, lastReach2 = 0.0f;
      s.Row.resize(static_cast<size_t>(this->K));
      const int32_t* row = this->Row(r, s.Row.data());
      // Scales KFit / 2, KFit / 4, ... down to `smallest` itself.
      for (int scale = std::max(this->KFit / 2, smallest); scale >= smallest && scale < this->KFit;
           scale = scale > smallest ? std::max(scale / 2, smallest) : 0)
      {
        this->GatherSheet(r, row, scale, normal, s);
        fit = FitGathered(s, this->Variance, false);
        float reach2 = 0.0f;
        for (const Eigen::Vector3d& q : s.P)
        {
          reach2 = std::max(reach2, static_cast<float>(q.squaredNorm()));
        }
        if (Explains(fit, this->Variance))
        {
          this->Fits.Edit(r) = fit;
          this->Scale[r] = scale;
          this->Reach2[r] = reach2;
          break;
        }
        if (curvedScale == 0 && curvedExplains(fit))
        {
          curvedFit = fit;
          curvedScale = scale;
          curvedReach2 = reach2;
        }
        lastReach2 = reach2;
      }
      if (this->Scale[r] != this->KFit || fit.Points == 0)
      {
        continue;
      }
      if (curvedScale > 0)
      {
        this->Fits.Edit(r) = curvedFit;
        this->Scale[r] = curvedScale;
        this->Reach2[r] = curvedReach2;
        continue;
      }
      // Nothing explains even the smallest scale, not even the curved hinge: more than two
      // faces, a corner, or faces narrower than the smallest scale. Its fit and its vote are
      // those of the smallest scale: the widest fit straddles features that the smallest one at
      // least separates, and a vote counted over the widest neighbourhood is diluted by the
      // members that vote for the other features within it. The point is a feature point
      // (a detail) unless the crossing planes, even where they do not cross, fit it within the
      // noise: they take a third of a noise sample's residual, so that a detail is a
      // neighbourhood that no model at all explains. And only where the surface bends there
      // by minAngle or more, as a crease must to vote: the hinge's or the crossing planes'
      // angle. On a clean cloud sampled from a tessellated part, sigma sits at its floor and
      // the facets of a curved face (a few degrees each, several within the smallest scale) are
      // explained by no model, yet they are the smooth face that the vote's angle ignores.
      this->Fits.Edit(r) = fit;
      this->Scale[r] = fit.Points;
      this->Reach2[r] = lastReach2;
      if (std::min(std::min(fit.RSSQ, fit.Hinge.RSS2), fit.Cross.RSS2) >
          MisfitBound(fit.Points - 6) * this->Variance &&
        !(std::max(fit.Hinge.Angle, fit.Cross.Angle) < minAngle))
      {
        detail[this->Ids[r]] = 1;
      }
    }
  });
}

void CreaseRun::ChooseModels(float* gain, float* angle, vtkIdType begin, vtkIdType end)
{
  // Model choice: the hinge, unless it leaves more than the noise explains (surfaces
  // crossing, corners, strongly curved patches); then the crossing planes, as fitted. The chosen
  // model replaces the hinge in place: from here on Fits[r].Hinge is the fit that votes.
  for (vtkIdType i = begin; i < end; ++i)
  {
    const vtkIdType r = this->Order[i];
    if (!this->Fits.Has(r) || this->Defers(r, 1))
    {
      continue; // OnePlaneFit: explained, no gain, no line
    }
    CreaseFit& f = this->Fits.Edit(r);
    f.Explained = Explains(f, this->Variance);
    if (f.Crossing && f.Hinge.RSS2 > MisfitBound(f.Points - 6) * this->Variance &&
      f.Cross.RSS2 < f.Hinge.RSS2)
    {
      f.Hinge = f.Cross;
    }
    this->Gain[r] = std::max(f.RSSQ - f.Hinge.RSS2, 0.0) / this->Variance;
    // In float, the largest float at most: a point far from the rest (1e27 from a part a few
    // units wide) gains beyond float's range, and the array must hold a number.
    gain[this->Ids[r]] = static_cast<float>(
      std::min(this->Gain[r], static_cast<double>(std::numeric_limits<float>::max())));
    angle[this->Ids[r]] = f.Hinge.Angle;
  }
}

void CreaseRun::ShareModels()
{
  struct Model
  {
    double Gain;
    CreaseLine Hinge;
    float Reach2;
    bool Explained;
  };
  auto read = [&](vtkIdType id, unsigned char* record) {
    const vtkIdType r = this->RowOf[id];
    if (r >= 0)
    {
      const Model model{ this->Gain[r], this->Fits[r].Hinge, this->Reach2[r],
        this->Fits[r].Explained };
      std::memcpy(record, &model, sizeof(Model));
    }
  };
  auto write = [&](vtkIdType id, const unsigned char* record) {
    const vtkIdType r = this->RowOf[id];
    if (r < 0)
    {
      return;
    }
    Model model;
    std::memcpy(&model, record, sizeof(Model));
    // A halo row whose own fit was one plane (none stored) takes its owner's model all the same.
    if (!this->Fits.Has(r))
    {
      this->Fits.Add(r, OnePlaneFit);
    }
    this->Gain[r] = model.Gain;
    this->Fits.Edit(r).Hinge = model.Hinge;
    this->Fits.Edit(r).Explained = model.Explained;
    this->Reach2[r] = model.Reach2;
  };
  this->RecordsFromOwners(static_cast<int>(sizeof(Model)), read, write);
}

// The offset w = v - the line's point, and its component along the line.
double FromLine(const CreaseLine& f, const double v[3], double w[3])
{
  for (int c = 0; c < 3; ++c)
  {
    w[c] = v[c] - f.LinePoint[c];
  }
  return w[0] * f.LineDirection[0] + w[1] * f.LineDirection[1] + w[2] * f.LineDirection[2];
}

double CreaseRun::LineDistance(vtkIdType r, const double v[3]) const
{
  double w[3];
  const double along = FromLine(this->Fits[r].Hinge, v, w);
  return std::sqrt(std::max(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - along * along, 0.0));
}

double CreaseRun::HingeAcross(vtkIdType r, const double v[3]) const
{
  const CreaseLine& f = this->Fits[r].Hinge;
  double w[3];
  const double along = FromLine(f, v, w);
  for (int c = 0; c < 3; ++c)
  {
    w[c] -= along * f.LineDirection[c];
  }
  const double length2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  double best = length2, across = 0.0;
  for (int k = 0; k < 2; ++k)
  {
    const int16_t* u = f.Rays[k];
    const double on = (w[0] * u[0] + w[1] * u[1] + w[2] * u[2]) / RayUnit;
    const double off2 = on > 0.0 ? std::max(length2 - on * on, 0.0) : length2;
    if (off2 < best || (k == 0 && off2 <= best))
    {
      best = off2;
      across = std::max(on, 0.0);
    }
  }
  return across;
}

void CreaseRun::MarkVoters(double minAngle, vtkIdType begin, vtkIdType end)
{
  // One byte per point says whether its fit may vote, so that the vote reads only voters' fits.
  for (vtkIdType i = begin; i < end; ++i)
  {
    const vtkIdType r = this->Order[i];
    // A halo row's flag comes from its owner's model, once ShareModels() has brought it.
    if (this->IsOwn(this->Ids[r]) ? this->Defers(r, 1) : !this->Deferring)
    {
      continue;
    }
    const CreaseLine& f = this->Fits[r].Hinge;
    this->Voter[this->Ids[r]] =
      f.HasLine && this->Gain[r] > MinimumGain && !(f.Angle < minAngle) ? 1 : 0;
  }
}

void CreaseRun::CastVotes(double bandWidth, float* vote, vtkIdType first, vtkIdType last)
{
  // BandWidth d from the line, widened in quadrature by the noise: a point whose clean position
  // lies at the band's edge is moved across the line by the noise as well.
  const double band = std::sqrt(bandWidth * this->D * bandWidth * this->D +
    BandNoiseSigmas * BandNoiseSigmas * this->Variance);
  const unsigned char* voter = this->Voter.data();
  vtkSMPThreadLocal<std::vector<double>> scratch, looseScratch;
  vtkSMPThreadLocal<std::array<std::vector<double>, 3>> feetScratch;
  vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType end) {
    double x[3], y[3];
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    std::array<std::vector<double>, 3>& feet = feetScratch.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (this->Defers(r, 2))
      {
        continue;
      }
      const vtkIdType id = this->Ids[r];
      const int32_t* row = this->Row(r, buffer.data());
      const int count = featurepoints::RowLength(row, this->KFit);
      // The members of the point's sheet within its scale vote; the fraction is of them.
      const uint64_t* sheet = this->Sheet(r);
      // No voter among them (most points of a part's faces): no vote, and nothing to measure.
      bool anyVoter = false;
      for (int j = -1, members = 0; j < count && members <= this->Scale[r] && !anyVoter; ++j)
      {
        if (Reached(sheet, j + 1))
        {
          ++members;
          anyVoter = voter[j < 0 ? id : static_cast<vtkIdType>(row[j])] != 0;
        }
      }
      if (!anyVoter)
      {
        vote[id] = 0.0f;
        continue;
      }
      this->Reader.Get(id, x);
      std::vector<double>& distances = scratch.Local();
      std::vector<double>& loose = looseScratch.Local();
      distances.clear();
      loose.clear();
      for (auto& f : feet)
      {
        f.clear();
      }
      int members = 0, in = 0, blind = 0;
      for (int j = -1; j < count && members <= this->Scale[r]; ++j)
      {
        if (!Reached(sheet, j + 1))
        {
          continue;
        }
        ++members;
        const vtkIdType other = j < 0 ? id : static_cast<vtkIdType>(row[j]);
        this->Reader.Get(other, y);
        const double v[3] = { x[0] - y[0], x[1] - y[1], x[2] - y[2] };
        // A member whose fit (of a smaller scale) does not reach the point has no say on it.
        if (j >= 0 && v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > this->Reach2[this->RowOf[other]])
        {
          ++blind;
          continue;
        }
        if (!voter[other])
        {
          continue;
        }
        const double distance = this->LineDistance(this->RowOf[other], v);
        if (distance <= std::max(band, bandWidth * this->Across[id]))
        {
          ++in;
          if (this->Thinning)
          {
            // Lines whose fit explains its points place the crease; a fit that straddles two
            // features (explained at no scale) puts its line between them.
            const vtkIdType fitted = this->RowOf[other];
            (this->Fits[fitted].Explained ? distances : loose)
              .push_back(this->HingeAcross(fitted, v));
          }
          if (this->Foot)
          {
            // The foot on the line, from the point: the line's point and the step along it, less
            // the point (all from the member).
            const CreaseLine& f = this->Fits[this->RowOf[other]].Hinge;
            double w[3];
            const double along = FromLine(f, v, w);
            for (int c = 0; c < 3; ++c)
            {
              feet[c].push_back(f.LinePoint[c] + along * f.LineDirection[c] - v[c]);
            }
          }
        }
      }
      if (this->Foot && !feet[0].empty())
      {
        for (int c = 0; c < 3; ++c)
        {
          this->Foot[3 * id + c] = static_cast<float>(featurepoints::UpperMedian(feet[c]));
        }
      }
      vote[id] = static_cast<float>(in) / static_cast<float>(members - blind);
      if (distances.empty())
      {
        distances.swap(loose); // no explained line: all of them
      }
      if (!distances.empty())
      {
        const auto middle = distances.begin() + distances.size() / 2;
        std::nth_element(distances.begin(), middle, distances.end());
        const double median = *middle;
        this->Offset[id] = static_cast<float>(median);
        for (double& d : distances)
        {
          d = std::abs(d - median);
        }
        std::nth_element(distances.begin(), middle, distances.end());
        this->Spread[id] = static_cast<float>(
          1.2533 * 1.4826 * *middle / std::sqrt(static_cast<double>(distances.size())));
      }
    }
  });
}

vtkIdType CreaseRun::Grow(const float* vote, double growAt, unsigned char* m) const
{
  // The result is a set of connected components, so it does not depend on the visiting order.
  vtkIdType added = 0;
  std::vector<vtkIdType> stack;
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    if (m[this->Ids[r]] && this->IsOwn(this->Ids[r]))
    {
      stack.push_back(r);
    }
  }
  const int kc = std::min(ConnectionNeighbors, this->K);
  std::vector<int32_t> buffer(static_cast<size_t>(this->K));
  while (!stack.empty())
  {
    const vtkIdType r = stack.back();
    stack.pop_back();
    const int32_t* row = this->Row(r, buffer.data(), kc);
    for (int j = 0; j < kc && row[j] >= 0; ++j)
    {
      const vtkIdType other = row[j];
      if (!m[other] && vote[other] > growAt)
      {
        m[other] = 1;
        ++added;
        if (this->IsOwn(other))
        {
          stack.push_back(this->RowOf[other]);
        }
      }
    }
  }
  return added;
}

// Whether the directions of the points q (relative to the point) in the plane (e1, e2) may leave
// an empty sector wider than BorderGap: false when each run of empty sectors among twelve of 30
// degrees is at most one long. A gap above 120 degrees holds three whole sectors; one of its
// two end points may fall into the sector next to its own when it lies on a sector's edge
// (rounding), which leaves two. Most points are not near a border: this spares them the angles.
bool MaybeWideGap(const double* q, int count, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2)
{
  const double tan30 = std::tan(Pi / 6.0), tan60 = std::tan(Pi / 3.0);
  unsigned int occupied = 0; // one bit per sector
  for (int j = 0; j < count; ++j)
  {
    const Eigen::Vector3d v(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
    const double a = v.dot(e1), b = v.dot(e2);
    if (a == 0.0 && b == 0.0)
    {
      continue;
    }
    // Quadrant, then the angle within it, from atan(y / x) with x, y >= 0.
    const int quadrant = b >= 0.0 ? (a >= 0.0 ? 0 : 1) : (a < 0.0 ? 2 : 3);
    const double x = quadrant % 2 == 0 ? std::abs(a) : std::abs(b);
    const double y = quadrant % 2 == 0 ? std::abs(b) : std::abs(a);
    const int sector = 3 * quadrant + (y < x * tan30 ? 0 : y < x * tan60 ? 1 : 2);
    occupied |= 1u << sector;
  }
  // Two empty sectors in a row, the twelfth followed by the first.
  const unsigned int empty = ~occupied & 0xfffu;
  const unsigned int next = ((empty >> 1) | (empty << 11)) & 0xfffu;
  return (empty & next) != 0;
}

void CreaseRun::GatherSheetNearest(
  vtkIdType r, int kb, int32_t* buffer, std::vector<double>& q) const
{
  const int32_t* row = this->Row(r, buffer);
  const int length = featurepoints::RowLength(row, this->KFit);
  const uint64_t* sheet = this->Sheet(r);
  double x[3], y[3];
  q.resize(3 * static_cast<size_t>(std::max(kb, 0)));
  this->Reader.Get(this->Ids[r], x);
  size_t n = 0;
  for (int j = 0; j < length && n < q.size(); ++j)
  {
    if (Reached(sheet, j + 1))
    {
      this->Reader.Get(row[j], y);
      q[n] = y[0] - x[0];
      q[n + 1] = y[1] - x[1];
      q[n + 2] = y[2] - x[2];
      n += 3;
    }
  }
  q.resize(n);
}

void CreaseRun::FindBorders(
  int kb, unsigned char* border, float* outward, vtkIdType first, vtkIdType last) const
{
  struct BorderScratch
  {
    std::vector<double> Q, Angles;
  };
  vtkSMPThreadLocal<BorderScratch> scratch;
  vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double>& q = scratch.Local().Q;
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    double x[3], y[3], lambda[3], nrm[3];
    const double none[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (this->Defers(r, 0))
      {
        continue;
      }
      const vtkIdType id = this->Ids[r];
      // The point's kb nearest on its own sheet: on a thin wall (both sides one sheet) they
      // fold back on each other at the rim, which then shows as a border too.
      this->GatherSheetNearest(r, kb, buffer.data(), q);
      const int count = static_cast<int>(q.size() / 3);
      if (count < kb || !featurepoints::LocalPCA(q.data(), count, true, none, lambda, nrm))
      {
        continue;
      }
      // Angles of the neighbours in the tangent plane, and the widest empty sector.
      const Eigen::Vector3d n(nrm[0], nrm[1], nrm[2]);
      const Eigen::Vector3d e1 = n.unitOrthogonal();
      const Eigen::Vector3d e2 = n.cross(e1);
      if (!MaybeWideGap(q.data(), count, e1, e2))
      {
        continue;
      }
      std::vector<double>& angles = scratch.Local().Angles;
      angles.clear();
      for (int j = 0; j < count; ++j)
      {
        const Eigen::Vector3d v(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
        const double a = v.dot(e1), b = v.dot(e2);
        if (a != 0.0 || b != 0.0)
        {
          angles.push_back(std::atan2(b, a));
        }
      }
      if (angles.size() < 3)
      {
        continue;
      }
      std::sort(angles.begin(), angles.end());
      double widest = angles.front() + 2.0 * Pi - angles.back();
      double middle = angles.back() + 0.5 * widest;
      for (size_t j = 1; j < angles.size(); ++j)
      {
        const double gap = angles[j] - angles[j - 1];
        if (gap > widest)
        {
          widest = gap;
          middle = angles[j - 1] + 0.5 * gap;
        }
      }
      if (widest > BorderGap)
      {
        border[id] = 1;
        const Eigen::Vector3d u = std::cos(middle) * e1 + std::sin(middle) * e2;
        for (int c = 0; c < 3; ++c)
        {
          outward[3 * id + c] = static_cast<float>(u[c]);
        }
      }
    }
  });
}

void CreaseRun::DropShortBorders(int shortest, unsigned char* border) const
{
  // Connected components of the border points, each point linked to the border points among its
  // `shortest` nearest, either way round: a component is a set, whatever the visiting order and
  // the split into pieces. A union-find over the links of the own points' rows (a halo point's
  // row may miss points); each component's label, the smallest global id among its points,
  // agrees across the pieces after the exchanges, and its size is counted over all processes.
  if (this->FromOwners)
  {
    this->FromOwners(border, 1);
  }
  std::vector<int32_t> parent(static_cast<size_t>(this->N));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int32_t i) {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  const int kc = std::min(shortest, this->K);
  std::vector<int32_t> buffer(static_cast<size_t>(this->K));
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const vtkIdType id = this->Ids[r];
    if (!border[id] || !this->IsOwn(id))
    {
      continue;
    }
    const int32_t* row = this->Row(r, buffer.data(), kc);
    for (int j = 0; j < kc && row[j] >= 0; ++j)
    {
      if (border[row[j]])
      {
        const int32_t a = find(static_cast<int32_t>(id)), b = find(row[j]);
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  constexpr long long None = std::numeric_limits<long long>::max();
  std::vector<long long> label(static_cast<size_t>(this->N), None), least;
  for (vtkIdType id : this->Ids)
  {
    label[id] = border[id] ? this->GlobalId(id) : None;
  }
  do
  {
    least.assign(static_cast<size_t>(this->N), None);
    for (vtkIdType id : this->Ids)
    {
      long long& root = least[find(static_cast<int32_t>(id))];
      root = std::min(root, label[id]);
    }
    for (vtkIdType id : this->Ids)
    {
      if (border[id])
      {
        label[id] = least[find(static_cast<int32_t>(id))];
      }
    }
  } while (this->ShareMinimum && this->ShareMinimum(label.data()));
  std::vector<vtkIdType> members;
  std::vector<long long> labels, counts;
  for (vtkIdType id : this->Ids)
  {
    if (border[id] && this->IsOwn(id))
    {
      members.push_back(id);
      labels.push_back(label[id]);
    }
  }
  this->CountLabels(labels, counts);
  for (size_t j = 0; j < members.size(); ++j)
  {
    if (counts[j] < shortest)
    {
      border[members[j]] = 0;
    }
  }
}

bool CreaseRun::BorderWithin(vtkIdType r, int kb, double band2, const unsigned char* border,
  int32_t* buffer) const
{
  const int32_t* row = this->Row(r, buffer, kb);
  const int length = featurepoints::RowLength(row, std::min(kb, this->K));
  const uint64_t* sheet = this->Sheet(r);
  double x[3], y[3];
  this->Reader.Get(this->Ids[r], x);
  for (int j = 0; j < length; ++j)
  {
    if (!border[row[j]] || !Reached(sheet, j + 1))
    {
      continue;
    }
    this->Reader.Get(row[j], y);
    if (vtkMath::Distance2BetweenPoints(x, y) <= band2)
    {
      return true;
    }
  }
  return false;
}

void CreaseRun::MarkNearBorders(
  int kb, double bandWidth, const unsigned char* border, vtkIdType first, vtkIdType last)
{
  const double band2 = bandWidth * this->D * bandWidth * this->D;
  vtkSMPTools::For(first, last, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vtkIdType r = this->Order[i];
      if (!this->Defers(r, 2) && this->BorderWithin(r, kb, band2, border, buffer.data()))
      {
        this->NearBorder[this->Ids[r]] = 1;
      }
    }
  });
}

void CreaseRun::WidenBorders(int kb, double bandWidth, unsigned char* border) const
{
  const double band2 = bandWidth * this->D * bandWidth * this->D;
  std::vector<unsigned char> near(static_cast<size_t>(this->N), 0);
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      if (border[id] || !this->NearBorder[id])
      {
        continue;
      }
      near[id] = this->BorderWithin(r, kb, band2, border, buffer.data()) ? 1 : 0;
    }
  });
  for (vtkIdType id : this->Ids)
  {
    border[id] = border[id] || near[id];
  }
}

bool CreaseRun::Direction(vtkIdType r, const unsigned char* type, const float* outward,
  double minAngle, int kb, std::vector<double>& q, double t[3]) const
{
  const vtkIdType id = this->Ids[r];
  if (type[id] == vtkCreaseVotingFeatures::BORDER)
  {
    // Along the border: the normal of the tangent plane in which FindBorders() saw the empty
    // sector, crossed with the outward direction. Not the point's own normal: on the rim of a
    // thin wall the NormalNeighbors nearest hold the rim face, whose normal is the outward
    // direction itself. Points that joined the border band (WidenBorders()) have no outward
    // direction, and give none.
    const Eigen::Vector3d u(outward[3 * id], outward[3 * id + 1], outward[3 * id + 2]);
    if (u.squaredNorm() < 0.5)
    {
      return false;
    }
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    double lambda[3], nrm[3];
    const double none[3] = { 0.0, 0.0, 0.0 };
    this->GatherSheetNearest(r, kb, buffer.data(), q);
    if (!featurepoints::LocalPCA(q.data(), static_cast<int>(q.size() / 3), true, none, lambda, nrm))
    {
      return false;
    }
    const Eigen::Vector3d along = Eigen::Vector3d(nrm[0], nrm[1], nrm[2]).cross(u);
    const double norm = along.norm();
    if (!(norm > 0.5))
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      t[c] = along[c] / norm;
    }
    return true;
  }
  // Only a crease line that explains its neighbourhood and votes gives a direction: the crossing
  // planes of a corner run anywhere, and the hinge of a smooth patch is no crease.
  const CreaseFit& fit = this->Fits[r];
  for (int c = 0; c < 3; ++c)
  {
    t[c] = fit.Hinge.LineDirection[c];
  }
  return fit.Hinge.HasLine && fit.Explained && this->Gain[r] > MinimumGain &&
    !(fit.Hinge.Angle < minAngle);
}

double CreaseRun::CornerReach(vtkIdType r) const
{
  std::vector<int32_t> buffer(static_cast<size_t>(this->K));
  const int32_t* row = this->Row(r, buffer.data());
  const int length = featurepoints::RowLength(row, this->KFit);
  const uint64_t* sheet = this->Sheet(r);
  int members = 0;
  int last = -1;
  for (int j = 0; j < length && members < SmallestScale; ++j)
  {
    if (Reached(sheet, j + 1))
    {
      ++members;
      last = j;
    }
  }
  if (last < 0)
  {
    return 0.0;
  }
  double x[3], y[3];
  this->Reader.Get(this->Ids[r], x);
  this->Reader.Get(row[last], y);
  return CornerReachScales * std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
}

void CreaseRun::ClassifyFeatures(const unsigned char* mask, const unsigned char* border,
  const float* outward, double minAngle, int kb, unsigned char* type) const
{
  // Creases and borders first: a border point is a border; a crease point is typed by its fit.
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const vtkIdType id = this->Ids[r];
    if (mask[id])
    {
      type[id] = border[id]        ? vtkCreaseVotingFeatures::BORDER
        : this->Fits[r].Hinge.Convex ? vtkCreaseVotingFeatures::CONVEX
                                     : vtkCreaseVotingFeatures::CONCAVE;
    }
  }
  // The unit direction of every feature point that has one, once, and a point of its line
  // relative to it (the crease line's; the border point itself).
  std::vector<float> direction(3 * static_cast<size_t>(this->N), 0.0f);
  std::vector<float> anchor(3 * static_cast<size_t>(this->N), 0.0f);
  std::vector<unsigned char> directed(static_cast<size_t>(this->N), 0);
  vtkSMPThreadLocal<std::vector<double>> scratch;
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double>& q = scratch.Local();
    double t[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      // A halo point's direction, and whether it is a corner, are its owner's (below; its row
      // may not be loaded).
      if (mask[id] && this->IsOwn(id) && this->Direction(r, type, outward, minAngle, kb, q, t))
      {
        directed[id] = 1;
        for (int c = 0; c < 3; ++c)
        {
          direction[3 * id + c] = static_cast<float>(t[c]);
          anchor[3 * id + c] =
            type[id] == vtkCreaseVotingFeatures::BORDER ? 0.0f : this->Fits[r].Hinge.LinePoint[c];
        }
      }
    }
  });
  if (this->FromOwners)
  {
    this->FromOwners(directed.data(), 1);
    this->FromOwners(direction.data(), 3 * sizeof(float));
    this->FromOwners(anchor.data(), 3 * sizeof(float));
  }
  // Corners: the directions of the feature points on the sheet within CornerReach() spread in
  // more than one direction (see CornerSpread).
  std::vector<unsigned char> corner(static_cast<size_t>(this->N), 0);
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      if (!mask[id] || !this->IsOwn(id))
      {
        continue;
      }
      const int32_t* row = this->Row(r, buffer.data());
      const int length = featurepoints::RowLength(row, this->KFit);
      const uint64_t* sheet = this->Sheet(r);
      const double reach = this->CornerReach(r);
      const double reach2 = reach * reach;
      this->Reader.Get(id, x);
      Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
      // The point nearest all the lines (least squares, relative to the point): where the
      // curves meet. sum (I - t t^T) c = sum (I - t t^T) a, a on each line.
      Eigen::Vector3d meet = Eigen::Vector3d::Zero();
      int directions = 0;
      for (int j = -1; j < length; ++j)
      {
        const vtkIdType other = j < 0 ? id : static_cast<vtkIdType>(row[j]);
        if (!Reached(sheet, j + 1) || !directed[other])
        {
          continue;
        }
        this->Reader.Get(other, y);
        if (vtkMath::Distance2BetweenPoints(x, y) > reach2)
        {
          break; // the row is sorted by distance
        }
        const Eigen::Vector3d v(
          direction[3 * other], direction[3 * other + 1], direction[3 * other + 2]);
        const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - v * v.transpose();
        const Eigen::Vector3d a(y[0] - x[0] + anchor[3 * other],
          y[1] - x[1] + anchor[3 * other + 1], y[2] - x[2] + anchor[3 * other + 2]);
        spread += v * v.transpose();
        meet += across * a;
        ++directions;
      }
      if (directions < MinimumCornerDirections)
      {
        continue;
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect(spread / directions);
      if (!(1.0 - solver.eigenvalues()[2] > CornerSpread))
      {
        continue;
      }
      // A corner point's smallest-scale neighbourhood holds the meeting point. The directions
      // spread all along the curves as far as the reach from the corner; a point further out
      // than the smallest scale's radius is on one of the curves, typed by its fit.
      const Eigen::Matrix3d normalMatrix = directions * Eigen::Matrix3d::Identity() - spread;
      const Eigen::Vector3d c = normalMatrix.ldlt().solve(meet);
      const double smallest = reach / CornerReachScales;
      corner[id] = c.squaredNorm() <= smallest * smallest ? 1 : 0;
    }
  });
  for (vtkIdType id : this->Ids)
  {
    if (corner[id])
    {
      type[id] = vtkCreaseVotingFeatures::CORNER;
    }
  }
}

vtkIdType CreaseRun::Thin(const unsigned char* type, const float* outward, const float* vote,
  double trusted, int kt, int ks, unsigned char* mask) const
{
  std::vector<unsigned char> keep(static_cast<size_t>(this->N), 0);
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    double x[3], y[3];
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      if (!mask[id])
      {
        continue;
      }
      const int32_t* row = this->Row(r, buffer.data(), kt);
      this->Reader.Get(id, x);
      if (type[id] != vtkCreaseVotingFeatures::BORDER)
      {
        // Creases and corners: enough voters for a consensus line, and within half the local
        // spacing of it across the face (noise along the face's normal does not move a point
        // across it), widened by the noise (a point at the crease pushed into the solid lies on
        // a face, as far from the line as the noise moved it).
        const double half = 0.5 * this->LocalSpacing(r, ks);
        keep[id] = this->Offset[id] >= 0.0f && !(vote[id] < trusted) &&
            this->Offset[id] <= std::sqrt(half * half + this->Variance)
          ? 1
          : 0;
        continue;
      }
      // Borders: the outermost, no border neighbour further out (more across than along).
      const int count = featurepoints::RowLength(row, std::min(kt, this->K));
      const float* u = outward + 3 * id;
      bool kept = true;
      for (int j = 0; j < count && kept; ++j)
      {
        const vtkIdType other = row[j];
        if (!mask[other] || type[other] != vtkCreaseVotingFeatures::BORDER)
        {
          continue;
        }
        this->Reader.Get(other, y);
        const double v[3] = { y[0] - x[0], y[1] - x[1], y[2] - x[2] };
        const double out = v[0] * u[0] + v[1] * u[1] + v[2] * u[2];
        const double length2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        kept = !(out > 0.0 && out * out >= 0.5 * length2);
      }
      keep[id] = kept ? 1 : 0;
    }
  });
  vtkIdType count = 0;
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const vtkIdType id = this->Ids[r];
    mask[id] = keep[id];
    count += keep[id];
  }
  return count;
}

vtkIdType CreaseRun::FillThinGaps(const unsigned char* type, const float* vote, double trusted,
  int kt, const unsigned char* band, unsigned char* mask) const
{
  std::vector<unsigned char> fill(static_cast<size_t>(this->N), 0);
  auto candidate = [&](vtkIdType id) {
    return band[id] && type[id] != vtkCreaseVotingFeatures::BORDER && this->Offset[id] >= 0.0f &&
      !(vote[id] < trusted);
  };
  vtkSMPTools::For(0, this->Rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(this->K));
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      if (mask[id] || !candidate(id))
      {
        continue;
      }
      const int32_t* row = this->Row(r, buffer.data(), kt);
      const int count = featurepoints::RowLength(row, std::min(kt, this->K));
      bool gap = true;
      double least = this->Offset[id];
      for (int j = 0; j < count && gap; ++j)
      {
        const vtkIdType other = row[j];
        gap = !mask[other];
        if (candidate(other))
        {
          least = std::min<double>(least, this->Offset[other]);
        }
      }
      fill[id] = gap && this->Offset[id] <= least + this->Spread[id] ? 1 : 0;
    }
  });
  vtkIdType added = 0;
  for (vtkIdType r = 0; r < this->Rows; ++r)
  {
    const vtkIdType id = this->Ids[r];
    mask[id] |= fill[id];
    added += fill[id];
  }
  return added;
}

double CreaseRun::LocalSpacing(vtkIdType r, int ks) const
{
  std::vector<int32_t> buffer(static_cast<size_t>(this->K));
  const int32_t* row = this->Row(r, buffer.data(), ks);
  const int count = featurepoints::RowLength(row, std::min(ks, this->K));
  if (count == 0)
  {
    return this->D;
  }
  double x[3], y[3];
  this->Reader.Get(this->Ids[r], x);
  this->Reader.Get(row[count - 1], y);
  return std::sqrt(vtkMath::Pi() * vtkMath::Distance2BetweenPoints(x, y) / count);
}
} // namespace

vtkCreaseVotingFeatures::vtkCreaseVotingFeatures()
{
  this->ThresholdMode = ABSOLUTE;
  this->Threshold = 0.5;
}

vtkCreaseVotingFeatures::~vtkCreaseVotingFeatures() = default;

int vtkCreaseVotingFeatures::Run(vtkPointSet* input, vtkPolyData* output)
{
  this->OnSites = false;
  this->OutlierRuns = 0;
  this->NumberOfOutliers = 0;
  return this->Detect(input, output);
}

int vtkCreaseVotingFeatures::GetLengthPower(const char* name) const
{
  return std::strcmp(name, "CreaseOffset") == 0 ? 1 : 0;
}

void vtkCreaseVotingFeatures::ScaleFiguresBack(int exponent)
{
  this->NoiseSigma = std::ldexp(this->NoiseSigma, exponent);
}

int vtkCreaseVotingFeatures::Detect(vtkPointSet* input, vtkPolyData* output)
{
  this->NoiseSigma = 0.0;
  this->GrowThresholdUsed = this->GrowThreshold;
  this->Scored.clear();
  const vtkIdType n = input->GetNumberOfPoints();
  vtkPoints* points = input->GetPoints();
  auto normals = featurepoints::NewZeroArray<vtkFloatArray>("Normals", 3, n);
  auto votes = featurepoints::NewZeroArray<vtkFloatArray>("CreaseVotes", 1, n);
  auto gains = featurepoints::NewZeroArray<vtkFloatArray>("CreaseGain", 1, n);
  auto angles = featurepoints::NewZeroArray<vtkFloatArray>("CreaseAngle", 1, n);
  auto types = featurepoints::NewZeroArray<vtkUnsignedCharArray>("FeatureType", 1, n);
  auto mask = featurepoints::NewZeroArray<vtkUnsignedCharArray>("FeatureMask", 1, n);
  auto offsets =
    featurepoints::NewZeroArray<vtkFloatArray>("CreaseOffset", 3, this->CreaseOffsets ? n : 0);
  auto finish = [&]() {
    return this->AssembleOutput(input, output,
      { normals.GetPointer(), votes.GetPointer(), gains.GetPointer(), angles.GetPointer(),
        types.GetPointer(), this->CreaseOffsets ? offsets.GetPointer() : nullptr },
      mask);
  };

  const int k = std::max(this->NumberOfNeighbors, this->NormalNeighbors);
  // The stages that read every point's nearest but not its k nearest (normals, links, growth,
  // thinning) read them from a narrow table kept whole.
  const int kNear =
    std::min(k, std::max({ this->NormalNeighbors, ConnectionNeighbors, SheetLinks }));
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  std::vector<vtkIdType> ids;
  NeighborTable table;
  auto store = [&](vtkIdType first, vtkIdType count, const int32_t* block) {
    if (first == 0)
    {
      table.Reset(static_cast<vtkIdType>(ids.size()), kNear);
    }
    table.Store(first, count, block);
  };
  // The warnings about the cloud wait for the choice between the cloud and its distinct positions
  // or its points without the outliers: the run that scores them warns.
  const bool mayMerge = this->MergeCopies && !this->OnSites && !this->IsDistributed();
  const bool mayScreen =
    this->RemoveOutliers && this->OutlierRuns < MaxOutlierRuns - 1 && !this->IsDistributed();
  this->DeferCloudWarnings = mayMerge || mayScreen;
  const bool searched = this->SearchAllPoints(points, n, kNear, neighborhoods, ids, store, 0.1);
  this->DeferCloudWarnings = false;
  if (!searched)
  {
    return finish();
  }
  if (mayMerge)
  {
    std::vector<vtkIdType> site;
    double tolerance = 0.0;
    const vtkIdType sites = this->FindSites(neighborhoods, ids, kNear,
      [&table](vtkIdType r, int32_t* buffer, int w) { return table.Row(r, buffer, w); }, site,
      tolerance);
    if (sites > 0)
    {
      // The cloud's table is not read again: freed for the positions' run.
      table = NeighborTable();
      std::vector<vtkIdType>().swap(ids);
      return this->DetectOnSites(input, output, site, sites, tolerance);
    }
  }
  if (mayScreen)
  {
    this->BeginStage("outliers");
    std::vector<vtkIdType> site;
    std::vector<unsigned char> state;
    const vtkIdType kept = this->FindOutliers(neighborhoods, ids, kNear,
      [&table](vtkIdType r, int32_t* buffer, int w) { return table.Row(r, buffer, w); }, site,
      state);
    if (kept > 0)
    {
      table = NeighborTable();
      std::vector<vtkIdType>().swap(ids);
      ++this->OutlierRuns;
      const int ok = this->DetectOnSubset(input, output, site, kept, &state);
      --this->OutlierRuns;
      return ok;
    }
  }
  if (mayMerge || mayScreen)
  {
    this->WarnAboutCloud(neighborhoods);
  }
  const featurepoints::PointReader reader(neighborhoods->GetPoints()); // renumbered
  CreaseRun run(reader, ids, table, k, kNear, this->NumberOfNeighbors, this->MeanSpacing, n);
  run.Thinning = this->ThinFeatures;
  run.Foot = this->CreaseOffsets ? offsets->GetPointer(0) : nullptr;
  const bool renumbered = static_cast<vtkIdType>(this->OriginalIds.size()) == n;
  run.Key = [&](vtkIdType id) {
    return this->IsDistributed() && !this->Owned.empty()
      ? this->GlobalId(id)
      : static_cast<long long>(renumbered ? this->OriginalIds[id] : id);
  };
  const bool distributed = this->IsDistributed() && !this->Owned.empty();
  if (distributed)
  {
    // Every cloud-wide figure over the own points of all processes; the stages that spread
    // across the cloud (hysteresis growth, border components) exchange the halo's values.
    run.Own = this->Owned.data();
    run.RowQuantile = [&](std::vector<double>& values, double share) {
      std::vector<double> own;
      for (size_t r = 0; r < values.size(); ++r)
      {
        if (this->IsOwned(ids[r]) && values[r] >= 0.0)
        {
          own.push_back(values[r]);
        }
      }
      return this->GlobalValueOfShare(own, share);
    };
    run.CountRows = [&](const std::vector<double>& values) {
      long long own = 0;
      for (size_t r = 0; r < values.size(); ++r)
      {
        own += this->IsOwned(ids[r]) && values[r] >= 0.0;
      }
      return static_cast<long long>(this->GlobalSum(static_cast<vtkIdType>(own)));
    };
    run.ShareMinimum = [&](long long* labels) {
      return this->ShareHaloValues(labels, 1, HALO_MINIMUM);
    };
    run.CountLabels = [&](const std::vector<long long>& labels, std::vector<long long>& counts) {
      this->GlobalLabelCounts(labels, counts);
    };
    run.GlobalId = [&](vtkIdType id) { return this->GlobalId(id); };
    run.GatherAll = [&](std::vector<double>& values) { this->GatherAll(values); };
    run.RecordsFromOwners = [&](int bytes,
                              const std::function<void(vtkIdType, unsigned char*)>& read,
                              const std::function<void(vtkIdType, const unsigned char*)>& write) {
      this->ShareHaloRecords(bytes, read, write);
    };
    run.FromOwners = [&](void* values, int bytes) {
      this->ShareHaloValues(static_cast<unsigned char*>(values), bytes, HALO_FROM_OWNER);
    };
    // The rows that read the halo's values wait for the owners' (RunDeferred()).
    run.Distributed = true;
  }
  float* normal = normals->GetPointer(0);
  float* vote = votes->GetPointer(0);
  unsigned char* m = mask->GetPointer(0);

  this->BeginStage("normals");
  run.ComputeNormals(this->NormalNeighbors, this->CloudCenter(neighborhoods), normal);
  run.MeasureNoiseAcross(neighborhoods, this->NormalNeighbors);
  this->NoiseSigma = std::sqrt(run.Variance);
  this->UpdateProgress(0.2);

  // Steps 0-4 and the borders' empty sectors, row by row as the k nearest are found.
  this->BeginStage("crease fits");
  run.PrepareFits(neighborhoods);
  std::vector<unsigned char> detail(static_cast<size_t>(n), 0);
  std::vector<unsigned char> border(static_cast<size_t>(n), 0);
  std::vector<float> outward(3 * static_cast<size_t>(n), 0.0f);
  const bool widen = this->Borders && !this->ThinFeatures;
  auto chooseModels = [&](vtkIdType begin, vtkIdType end) {
    run.FitInView(normal, begin, end);
    if (this->MultiScale)
    {
      run.ChooseScales(normal, std::min(SmallestScale, this->NumberOfNeighbors),
        this->MinimumAngle, detail.data(), begin, end);
    }
    run.ChooseModels(gains->GetPointer(0), angles->GetPointer(0), begin, end);
  };
  auto castVotes = [&](vtkIdType begin, vtkIdType end) {
    run.CastVotes(this->BandWidth, vote, begin, end);
    if (widen)
    {
      run.MarkNearBorders(BorderNeighbors, this->BandWidth, border.data(), begin, end);
    }
  };
  const std::function<void(vtkIdType, vtkIdType)> passes[3] = {
    [&](vtkIdType begin, vtkIdType end) {
      run.FitCreases(normal, begin, end);
      if (this->Borders)
      {
        run.FindBorders(BorderNeighbors, border.data(), outward.data(), begin, end);
      }
      if (distributed)
      {
        run.MarkDeferredFits(begin, end);
      }
    },
    [&](vtkIdType begin, vtkIdType end) {
      chooseModels(begin, end);
      run.MarkVoters(this->MinimumAngle, begin, end);
    },
    [&](vtkIdType begin, vtkIdType end) {
      if (distributed)
      {
        run.MarkDeferredVotes(begin, end);
      }
      castVotes(begin, end);
    },
  };
  if (!run.Stream(neighborhoods, this, 0.2, 0.8, passes))
  {
    return finish();
  }
  if (distributed)
  {
    // The halo's one-plane flags (which FitInView reads), border flags (which the border band's
    // preselection reads) and models (which the votes read) from their owners, then the rows
    // that read them.
    run.FromOwners(run.Flat.data(), 1);
    if (this->Borders)
    {
      run.FromOwners(border.data(), 1);
    }
    const std::function<void(vtkIdType, vtkIdType)> deferred[3] = {
      chooseModels,
      [&](vtkIdType begin, vtkIdType end) { run.MarkVoters(this->MinimumAngle, begin, end); },
      castVotes,
    };
    if (!run.RunDeferred(neighborhoods, deferred))
    {
      return finish();
    }
  }
  std::vector<int32_t>().swap(run.Links);
  std::vector<unsigned char>().swap(run.Flat);
  std::vector<unsigned char>().swap(run.Voter);

  this->BeginStage("vote");
  // A halo point's vote counts fits beyond the piece: its owner's (exact) replaces it.
  this->ShareHaloValues(vote, 1, HALO_FROM_OWNER);
  if (run.Foot)
  {
    this->ShareHaloValues(run.Foot, 3, HALO_FROM_OWNER);
  }
  this->ApplyThreshold(vote, ids, nullptr, nullptr, m);
  // Hysteresis above the cloud's background: the median vote (most points are not on a crease;
  // on a strongly curved smooth shape every point collects some votes).
  std::vector<double> values;
  values.reserve(ids.size());
  for (vtkIdType id : ids)
  {
    if (this->IsOwned(id))
    {
      values.push_back(vote[id]);
    }
  }
  this->GrowThresholdUsed = this->GrowThreshold + this->GlobalUpperMedian(values);
  std::vector<double>().swap(values);
  if (this->GrowThresholdUsed < this->ThresholdUsed)
  {
    // Distributed: each process grows from its own points, then the pieces exchange the halo's
    // mask (a point marked by any process is marked), until no process marks another point.
    do
    {
      this->NumberOfFeaturePoints += run.Grow(vote, this->GrowThresholdUsed, m);
    } while (this->ShareHaloValues(m, 1, HALO_MAXIMUM));
  }

  // Details finer than the smallest scale and corners, which no fit explains.
  for (vtkIdType id : ids)
  {
    if (detail[id] && !m[id])
    {
      m[id] = 1;
      ++this->NumberOfFeaturePoints;
    }
  }
  this->ShareHaloValues(m, 1, HALO_FROM_OWNER);

  this->BeginStage("borders");
  // The k nearest of the points the last stages read them for: the feature points, the border
  // points (the short borders read their BorderNeighbors / 2 nearest) and those near them.
  if (!run.LoadRows(neighborhoods, [&](vtkIdType r) {
        const vtkIdType id = ids[r];
        return m[id] || border[id] || run.NearBorder[id];
      }))
  {
    return finish();
  }
  if (this->Borders)
  {
    run.DropShortBorders(BorderNeighbors / 2, border.data());
    this->ShareHaloValues(border.data(), 1, HALO_FROM_OWNER);
    this->ShareHaloValues(outward.data(), 3, HALO_FROM_OWNER);
    if (!this->ThinFeatures)
    {
      run.WidenBorders(BorderNeighbors, this->BandWidth, border.data());
      this->ShareHaloValues(border.data(), 1, HALO_FROM_OWNER);
    }
    for (vtkIdType id : ids)
    {
      if (border[id] && !m[id])
      {
        m[id] = 1;
        ++this->NumberOfFeaturePoints;
      }
    }
  }
  this->ShareHaloValues(m, 1, HALO_FROM_OWNER);
  unsigned char* type = types->GetPointer(0);
  run.ClassifyFeatures(m, border.data(), outward.data(), this->MinimumAngle, BorderNeighbors, type);
  this->ShareHaloValues(type, 1, HALO_FROM_OWNER);
  // What neither the orientation nor the thinning reads (the sheets' bits, the fits' scales and
  // reaches, the rows' gaps and the flags near borders; the borders' directions unless
  // thinning): 37-49 bytes a point less under the orientation's links, at the end of the
  // detector.
  std::vector<uint64_t>().swap(run.Sheets);
  std::vector<int32_t>().swap(run.Scale);
  std::vector<float>().swap(run.Reach2);
  std::vector<float>().swap(run.Across);
  std::vector<unsigned char>().swap(run.NearBorder);
  if (!this->ThinFeatures)
  {
    std::vector<float>().swap(outward);
  }
  // The consistent orientation: the normals turned to it, and convex and concave with them.
  this->BeginStage("orientation");
  {
    std::vector<signed char> side, own;
    run.OrientNormals(this->NormalNeighbors, this->CloudCenter(neighborhoods), normal, type,
      this->MinimumAngle, side, own);
    // A crease point that stands for its hinge: convex where the hinge keeps its side, its normal
    // turned by its side in the hinge. Any other point: its normal turned where its side is,
    // and convex and concave with it.
    for (vtkIdType r = 0; r < static_cast<vtkIdType>(ids.size()); ++r)
    {
      const vtkIdType id = ids[r];
      if (own[r] != 0)
      {
        type[id] = side[r] < 0 ? CONCAVE : CONVEX;
      }
      else if (side[r] < 0 && (type[id] == CONVEX || type[id] == CONCAVE))
      {
        type[id] = type[id] == CONVEX ? CONCAVE : CONVEX;
      }
      if ((own[r] < 0) != (side[r] < 0))
      {
        std::transform(normal + 3 * id, normal + 3 * id + 3, normal + 3 * id, std::negate<float>());
      }
    }
  }
  this->ShareHaloValues(type, 1, HALO_FROM_OWNER);
  if (this->ThinFeatures)
  {
    this->BeginStage("thin");
    // The votes the hysteresis trusts (or the threshold, where that is lower): a point with fewer
    // (one the detail rule marked) has too few voting lines for their median to locate the crease.
    const double trusted = std::min(this->GrowThresholdUsed, this->ThresholdUsed);
    const std::vector<unsigned char> band(m, m + n);
    this->NumberOfFeaturePoints = run.Thin(type, outward.data(), vote, trusted,
      ConnectionNeighbors, this->NormalNeighbors, m);
    // The gaps read their neighbours' kept flags and consensus distances: the owners'.
    this->ShareHaloValues(m, 1, HALO_FROM_OWNER);
    this->ShareHaloValues(run.Offset.data(), 1, HALO_FROM_OWNER);
    this->ShareHaloValues(run.Spread.data(), 1, HALO_FROM_OWNER);
    this->NumberOfFeaturePoints +=
      run.FillThinGaps(type, vote, trusted, ConnectionNeighbors, band.data(), m);
    this->ShareHaloValues(m, 1, HALO_FROM_OWNER);
    for (vtkIdType id : ids)
    {
      type[id] = m[id] ? type[id] : 0;
    }
  }
  if (distributed)
  {
    // The counts above include halo points: the own feature points of all processes.
    vtkIdType own = 0;
    for (vtkIdType id : ids)
    {
      own += this->IsOwned(id) ? m[id] : 0;
    }
    this->NumberOfFeaturePoints = this->GlobalSum(own);
  }
  this->UpdateProgress(1.0);
  return finish();
}

int vtkCreaseVotingFeatures::DetectOnSites(vtkPointSet* input, vtkPolyData* output,
  const std::vector<vtkIdType>& site, vtkIdType sites, double tolerance)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkIdType valid = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    valid += site[i] >= 0;
  }
  vtkWarningMacro(<< valid - sites << " of " << valid << " points lie within " << tolerance
                  << " (1 % of the median distance to a point's 8th nearest) of another point: "
                     "the detector scores the "
                  << sites << " distinct positions, and each point takes its position's results.");
  return this->DetectOnSubset(input, output, site, sites);
}

int vtkCreaseVotingFeatures::DetectOnSubset(vtkPointSet* input, vtkPolyData* output,
  const std::vector<vtkIdType>& site, vtkIdType sites, const std::vector<unsigned char>* state)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkPoints* points = input->GetPoints();
  // Each site at its first point's coordinates.
  vtkNew<vtkPoints> positions;
  positions->SetDataType(points->GetDataType());
  positions->SetNumberOfPoints(sites);
  vtkIdType placed = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (site[i] >= 0)
    {
      if (site[i] == placed)
      {
        positions->SetPoint(placed++, points->GetPoint(i));
      }
    }
  }
  vtkNew<vtkPolyData> distinct;
  distinct->SetPoints(positions);
  vtkNew<vtkPolyData> scored;
  const bool featuresOnly = this->OutputFeaturesOnly;
  this->OutputFeaturesOnly = false;
  const bool onSites = this->OnSites;
  this->OnSites = true;
  const int ok = this->Detect(distinct, scored);
  this->OnSites = onSites;
  this->OutputFeaturesOnly = featuresOnly;
  if (!ok)
  {
    return 0;
  }
  // The positions' arrays, one tuple per input point (zero for an invalid point).
  vtkPointData* from = scored->GetPointData();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  vtkSmartPointer<vtkUnsignedCharArray> mask;
  for (const char* name : { "Normals", "CreaseVotes", "CreaseGain", "CreaseAngle", "FeatureType",
         "CreaseOffset", "FeatureMask" })
  {
    vtkDataArray* source = from->GetArray(name);
    if (!source)
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> a = vtk::TakeSmartPointer(source->NewInstance());
    a->SetName(name);
    a->SetNumberOfComponents(source->GetNumberOfComponents());
    a->SetNumberOfTuples(n);
    a->Fill(0.0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (site[i] >= 0)
      {
        a->SetTuple(i, site[i], source);
      }
    }
    if (std::strcmp(name, "FeatureMask") == 0)
    {
      mask = vtkUnsignedCharArray::SafeDownCast(a);
    }
    else
    {
      arrays.push_back(a);
    }
  }
  if (!mask)
  {
    return 0;
  }
  // Which input points were scored: a site's state (the inner run's, or scored where it kept
  // every site), outliers and invalid points as the caller says.
  std::vector<unsigned char> inner;
  inner.swap(this->Scored);
  this->Scored.assign(static_cast<size_t>(n), UNSCORED);
  vtkIdType counts[3] = { 0, 0, 0 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->Scored[i] = site[i] >= 0 ? (inner.empty() ? SCORED : inner[site[i]])
                                   : (state ? (*state)[i] : UNSCORED);
    ++counts[this->Scored[i]];
  }
  this->NumberOfCandidates = counts[SCORED];
  this->NumberOfOutliers = counts[OUTLIER];
  this->NumberOfFeaturePoints = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->NumberOfFeaturePoints += mask->GetValue(i) != 0;
  }
  std::vector<vtkDataArray*> raw;
  for (const auto& a : arrays)
  {
    raw.push_back(a);
  }
  this->OriginalIds.clear(); // the arrays are in the input's order
  const int assembled = this->AssembleOutput(input, output, raw, mask);
  this->MergeRepeatedStages();
  return assembled;
}

vtkIdType vtkCreaseVotingFeatures::FindOutliers(vtkPointCloudNeighborhoods* neighborhoods,
  const std::vector<vtkIdType>& ids, int width,
  const std::function<const int32_t*(vtkIdType, int32_t*, int)>& row,
  std::vector<vtkIdType>& site, std::vector<unsigned char>& state)
{
  site.clear();
  state.clear();
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  const int kn = std::min(width, this->NormalNeighbors);
  if (this->IsDistributed() || kn < OutlierNeighbors || !(this->MeanSpacing > 0.0))
  {
    return 0;
  }
  const featurepoints::PointReader reader(neighborhoods->GetPoints());
  const double noiseFloor = NoiseFloor * this->MeanSpacing;
  const double acrossFloor = OutlierFloor * this->MeanSpacing;
  // Isolated points: the logarithm of the distance to the nearest other position beyond Tukey's
  // far fence of the cloud's (the third quartile plus 3 interquartile ranges, the range at
  // least a random sampling's: 14 times the mean spacing on a random sampling, and as much
  // wider as the cloud's density varies).
  std::vector<float> gap(static_cast<size_t>(rows), -1.0f);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(width));
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int32_t* neighbors = row(r, buffer.data(), kn);
      reader.Get(ids[r], x);
      for (int j = 0; j < kn && neighbors[j] >= 0; ++j)
      {
        reader.Get(neighbors[j], y);
        const double d2 = vtkMath::Distance2BetweenPoints(x, y);
        if (d2 > 0.0)
        {
          gap[r] = static_cast<float>(0.5 * std::log(d2));
          break;
        }
      }
    }
  });
  const double fence = IsolationFence(gap);
  std::vector<unsigned char> outlier(static_cast<size_t>(rows), 0);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(width)), around(static_cast<size_t>(width));
    std::vector<double> q(3 * (static_cast<size_t>(width) + 1));
    // How many standard errors point `id` lies off the plane of the points `others` (without
    // `id` itself); -1 where they give no plane.
    auto offPlane = [&](vtkIdType id, const int32_t* others, int width2, double floor,
                      bool* flat = nullptr) {
      int count = 0;
      double x[3], y[3];
      reader.Get(id, x);
      // Each position once (copies kept would weigh the plane as many points), the point's own
      // left out.
      for (int j = 0; j < width2 && others[j] >= 0; ++j)
      {
        if (others[j] == id)
        {
          continue;
        }
        reader.Get(others[j], y);
        const double v[3] = { y[0] - x[0], y[1] - x[1], y[2] - x[2] };
        bool seen = v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
        for (int i = 0; i < count && !seen; ++i)
        {
          seen = q[3 * i] == v[0] && q[3 * i + 1] == v[1] && q[3 * i + 2] == v[2];
        }
        if (!seen)
        {
          std::copy(v, v + 3, &q[3 * count]);
          ++count;
        }
      }
      if (count < OutlierNeighbors)
      {
        return -1.0;
      }
      // The plane through the others' mean, by its eigenvectors (ascending).
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int j = 0; j < count; ++j)
      {
        mean += Eigen::Vector3d(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
      }
      mean /= count;
      featurepoints::OuterSum sum;
      for (int j = 0; j < count; ++j)
      {
        sum.Add(Eigen::Vector3d(q[3 * j], q[3 * j + 1], q[3 * j + 2]) - mean);
      }
      const Eigen::Matrix3d scatter = sum.Matrix();
      if (!scatter.allFinite())
      {
        return -1.0;
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect(scatter / count);
      const Eigen::Vector3d lambda = solver.eigenvalues().cwiseMax(0.0);
      if (!(lambda[1] > 0.0))
      {
        return -1.0; // the others on a line or at one position: no plane
      }
      if (flat)
      {
        *flat = lambda[0] < SurfaceThickness * SurfaceThickness * lambda[1];
      }
      // The point (the origin) from the others' mean, in the plane's frame.
      const Eigen::Vector3d u = solver.eigenvectors().transpose() * (-mean);
      // Their RMS distance from the plane, its 3 parameters taken from the degrees of freedom;
      // the height's standard error adds the plane's own (a regression's prediction interval):
      // its offset and its tilts, the farther the point lies along each direction in it.
      const double rms = std::max(std::sqrt(lambda[0] * count / (count - 3)), floor);
      const double spread = 1.0 + 1.0 / count + u[1] * u[1] / (count * lambda[1]) +
        u[2] * u[2] / (count * lambda[2]);
      return std::abs(u[0]) / (rms * std::sqrt(spread));
    };
    for (vtkIdType r = begin; r < end; ++r)
    {
      // The plane of the point's nearest.
      const vtkIdType id = ids[r];
      const int32_t* neighbors = row(r, buffer.data(), kn);
      bool flat = false;
      const double own = offPlane(id, neighbors, kn, noiseFloor, &flat);
      if (own > OutlierDistance)
      {
        outlier[r] = 1;
        continue;
      }
      const bool isolated = gap[r] != -1.0f && gap[r] > fence;
      // Failing that (they may straddle a crease: a stray point above a face near an edge has
      // the edge's points among its nearest, whose plane is no face's), the plane of its
      // nearest point's nearest, one more of them to make up for the point among them.
      const auto nearest = neighbors[0] >= 0
        ? std::lower_bound(ids.begin(), ids.end(), static_cast<vtkIdType>(neighbors[0]))
        : ids.end();
      if (nearest == ids.end() || *nearest != neighbors[0])
      {
        continue;
      }
      const int wide = std::min(kn + 1, width);
      const int32_t* theirs = row(nearest - ids.begin(), around.data(), wide);
      if (isolated)
      {
        // An isolated point that no surface holds: its nearest are no surface (a scatter of
        // stray points), or it lies beyond the reach of its nearest point's nearest (no plane's
        // extrapolation says anything that far out: a stray point far from a sheet).
        double x[3], y[3], z[3];
        reader.Get(id, x);
        reader.Get(neighbors[0], y);
        const int last = featurepoints::RowLength(theirs, wide) - 1;
        bool beyond = false;
        if (last >= 1)
        {
          reader.Get(theirs[last] == id ? theirs[last - 1] : theirs[last], z);
          beyond = vtkMath::Distance2BetweenPoints(x, y) > vtkMath::Distance2BetweenPoints(y, z);
        }
        if (own < 0.0 || !flat || beyond)
        {
          outlier[r] = 1;
          continue;
        }
      }
      const double floor = own >= 0.0 && own <= OnPlane ? acrossFloor : noiseFloor;
      outlier[r] = offPlane(id, theirs, wide, floor) > OutlierDistance;
    }
  });
  const vtkIdType found = std::count(outlier.begin(), outlier.end(), 1);
  if (found == 0)
  {
    return 0;
  }
  // Input ids: the method's numbering is the renumbered cloud's (OriginalIds) when renumbered.
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  const bool renumbered = static_cast<vtkIdType>(this->OriginalIds.size()) == n;
  std::vector<unsigned char> kept(static_cast<size_t>(n), 0);
  for (vtkIdType r = 0; r < rows; ++r)
  {
    if (!outlier[r])
    {
      kept[renumbered ? this->OriginalIds[ids[r]] : ids[r]] = 1;
    }
  }
  site.assign(static_cast<size_t>(n), -1);
  state.assign(static_cast<size_t>(n), UNSCORED);
  for (vtkIdType r = 0; r < rows; ++r)
  {
    if (outlier[r])
    {
      state[renumbered ? this->OriginalIds[ids[r]] : ids[r]] = OUTLIER;
    }
  }
  vtkIdType sites = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (kept[i])
    {
      site[i] = sites++;
    }
  }
  return sites;
}

void vtkCreaseVotingFeatures::ListParameters(std::vector<std::pair<const char*, double>>& parameters) const
{
  this->Superclass::ListParameters(parameters);
  parameters.emplace_back("BandWidth", this->BandWidth);
  parameters.emplace_back("MinimumAngle", this->MinimumAngle);
  parameters.emplace_back("GrowThreshold", this->GrowThreshold);
}

void vtkCreaseVotingFeatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "NormalNeighbors: " << this->NormalNeighbors << "\n";
  os << indent << "GrowThreshold: " << this->GrowThreshold << "\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "BandWidth: " << this->BandWidth << "\n";
  os << indent << "MultiScale: " << this->MultiScale << "\n";
  os << indent << "Borders: " << this->Borders << "\n";
  os << indent << "ThinFeatures: " << this->ThinFeatures << "\n";
  os << indent << "MergeCopies: " << this->MergeCopies << "\n";
  os << indent << "NoiseSigma: " << this->NoiseSigma << "\n";
  os << indent << "GrowThresholdUsed: " << this->GrowThresholdUsed << "\n";
}
