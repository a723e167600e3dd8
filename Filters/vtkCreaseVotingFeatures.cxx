#include "vtkCreaseVotingFeatures.h"

#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkCreaseVotingFeatures);

namespace
{
// sigma is never taken below this fraction of the mean spacing (noise-free clouds).
constexpr double NoiseFloor = 0.05;
// Rounds of the two-plane assignment.
constexpr int MaximumRounds = 8;
// Rounds of the refit by side of the crease line.
constexpr int SideRounds = 3;
// A hinge whose residual exceeds this many times the noise variance per degree of freedom does
// not describe the neighbourhood.
constexpr double HingeMisfit = 2.0;
// Two planes of the nearest-plane fit within 10 degrees of parallel and more than 4 times their
// residual's RMS apart at the fitted point are two sheets (a thin wall), not a crease: a split of
// pure Gaussian noise puts its planes 2.7 RMS apart.
const double SheetCosine = std::cos(10.0 * 3.14159265358979323846 / 180.0);
constexpr double SheetSeparation = 4.0;
// Links of the one-sheet neighbourhoods: each point to its 5 nearest. On a randomly sampled
// surface these reach about 2.5 mean spacings: walls thicker than about 5 spacings keep their
// sides apart (4 links split noisy single sheets; 6 join the walls of PCEDNet's abc/7010).
constexpr int SheetLinks = 5;
// A fit votes only where its hinge explains more than this many noise variances beyond one plane.
// The gate used to be the cloud's median gain, taken as what a fit gains by chance; with 150
// neighbours (the default) the angle and the line decide: gates of 1, 4, 10 and 25 give the same
// F1 within 0.003 on every part and smooth shape of the quality probes. The median
// failed where most points lie within a neighbourhood of a crease (features sampled denser, small
// clouds): it was then a crease's gain, and the shallow creases fell below it.
constexpr double MinimumGain = 1.0;
// Neighbours through which the hysteresis step connects points.
constexpr int ConnectionNeighbors = 8;

// Moments of a set of points: count, sum, sum of outer products (upper triangle). The points are
// relative to the fitted point, a few spacings long, so the one-pass covariance loses nothing.
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

// One two-plane model of a neighbourhood: its residual and the line where its planes meet.
struct CreaseLine
{
  double RSS2 = 0.0;  // residual of the two planes
  float Angle = 0.0f; // degrees
  bool HasLine = false;
  float LinePoint[3] = { 0.0f, 0.0f, 0.0f }; // relative to the point
  float LineDirection[3] = { 0.0f, 0.0f, 0.0f };
};

struct CreaseFit
{
  double RSS1 = 0.0; // residual of one plane
  CreaseLine Hinge;  // two half-planes, points split by the side of the line they lie on
  CreaseLine Cross;  // two whole planes, points split by the nearer plane
  int Points = 0;    // points fitted
  int Sheet = -1;    // two parallel sheets (a thin wall): the fitted point's sheet (0, 1)
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
  const Eigen::Vector3d& t)
{
  line.RSS2 = rss2;
  line.Angle = static_cast<float>(std::asin(std::min(sine, 1.0)) * 180.0 / 3.14159265358979323846);
  line.HasLine = hasLine;
  for (int c = 0; c < 3; ++c)
  {
    line.LinePoint[c] = hasLine ? static_cast<float>(x[c]) : 0.0f;
    line.LineDirection[c] = hasLine ? static_cast<float>(t[c]) : 0.0f;
  }
}

// Two-plane fit of one neighbourhood: p[0] is the point (the origin), nr the normals.
CreaseFit FitCrease(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& nr,
  std::vector<unsigned char>& label, std::vector<unsigned char>& next)
{
  CreaseFit fit;
  fit.Points = static_cast<int>(p.size());
  const size_t m = p.size();
  label.assign(m, 0);
  Eigen::Vector3d c1, n1;
  double rss1 = 0.0;
  Moments all;
  for (size_t j = 0; j < m; ++j)
  {
    all.Add(p[j]);
  }
  if (m < 8 || !FitPlane(all, c1, n1, rss1))
  {
    return fit;
  }
  // Split by the direction in which the (consistently oriented) normals vary most.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < m; ++j)
  {
    mean += nr[j].dot(n1) < 0.0 ? -nr[j] : nr[j];
  }
  mean /= static_cast<double>(m);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (size_t j = 0; j < m; ++j)
  {
    const Eigen::Vector3d v = (nr[j].dot(n1) < 0.0 ? -nr[j] : nr[j]) - mean;
    spread += v * v.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(spread);
  const Eigen::Vector3d e = solver.eigenvectors().col(2);
  Moments side[2];
  for (size_t j = 0; j < m; ++j)
  {
    const Eigen::Vector3d v = (nr[j].dot(n1) < 0.0 ? -nr[j] : nr[j]) - mean;
    label[j] = v.dot(e) >= 0.0 ? 0 : 1;
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
  if (!fitted)
  {
    fit.Hinge.RSS2 = fit.Cross.RSS2 = rss1;
    return fit;
  }
  // Two parallel sheets a few noise widths apart, the fitted point on one of them: both sides
  // of a thin wall are in the neighbourhood. The caller fits the point's sheet alone.
  if (std::abs(na.dot(nb)) > SheetCosine)
  {
    const double rms = std::sqrt(rss2 / static_cast<double>(m));
    // Signed offsets of the fitted point (the origin) from the planes, both normals one way.
    const double sa = -ca.dot(na), sb = -cb.dot(na.dot(nb) < 0.0 ? -nb : nb);
    if (std::abs(sa - sb) > SheetSeparation * rms)
    {
      fit.Sheet = std::abs(sa) <= std::abs(sb) ? 0 : 1;
    }
  }
  Eigen::Vector3d t, x;
  double sine = 0.0;
  bool hasLine = MeetingLine(ca, na, cb, nb, x, t, sine);
  StoreLine(fit.Cross, rss2, sine, hasLine, x, t);
  // The nearest-plane assignment fits noise too: each point picks the plane nearer to it, so on a
  // flat noisy patch two planes "gain" a large share of the residual, and a shallow crease hides
  // in that. The hinge model is fitted on a partition by position instead: each point goes to the
  // side of the crease line it lies on, each side gets its plane, and the line is refitted from
  // these planes, a few rounds. On pure noise it gains what a hinge gains by chance (a few
  // sigma^2); on a crease of any angle it keeps the whole bend. Where surfaces cross (four
  // half-planes at the line) it cannot fit, and the caller falls back to the crossing planes.
  for (int round = 0; hasLine && round < SideRounds; ++round)
  {
    // Normal of the plane through the line that separates the two sides' centroids.
    Eigen::Vector3d across = ca - cb;
    across -= across.dot(t) * t;
    if (!(across.squaredNorm() > 0.0))
    {
      break;
    }
    Moments half[2];
    for (size_t j = 0; j < m; ++j)
    {
      half[(p[j] - x).dot(across) >= 0.0 ? 0 : 1].Add(p[j]);
    }
    double qa = 0.0, qb = 0.0;
    if (!FitPlane(half[0], ca, na, qa) || !FitPlane(half[1], cb, nb, qb))
    {
      break;
    }
    rss2 = qa + qb;
    hasLine = MeetingLine(ca, na, cb, nb, x, t, sine);
  }
  StoreLine(fit.Hinge, rss2, sine, hasLine, x, t);
  return fit;
}

// The neighbours of a point on its own sheet: the neighbourhood's points joined to it through
// links, a link joining each point to its SheetLinks nearest (either way round). A wall thinner
// than the neighbourhood but thicker than the links then keeps its two sides apart.
struct SheetReach
{
  std::vector<int16_t> LocalOf; // by point id: its local index in the current neighbourhood, or -1
  std::vector<int32_t> Parent, Size;

  // Marks the reached neighbours in the bit mask `reached` (local indices); returns their count.
  int Reach(vtkIdType id, const int32_t* row, int count, const int32_t* table, int k,
    const std::vector<vtkIdType>& rowOf, uint64_t* reached)
  {
    if (this->LocalOf.size() != rowOf.size())
    {
      this->LocalOf.assign(rowOf.size(), -1);
    }
    auto idOf = [&](int j) { return j == 0 ? id : static_cast<vtkIdType>(row[j - 1]); };
    this->Parent.resize(static_cast<size_t>(count) + 1);
    this->Size.assign(static_cast<size_t>(count) + 1, 1);
    for (int j = 0; j <= count; ++j)
    {
      this->LocalOf[idOf(j)] = static_cast<int16_t>(j);
      this->Parent[j] = j;
    }
    auto find = [&](int j) {
      while (this->Parent[j] != j)
      {
        this->Parent[j] = this->Parent[this->Parent[j]];
        j = this->Parent[j];
      }
      return j;
    };
    for (int j = 0; j <= count; ++j)
    {
      // A neighbour's nearest come first in its own row of the table.
      const int32_t* linked = table + rowOf[idOf(j)] * k;
      for (int e = 0; e < SheetLinks && linked[e] >= 0; ++e)
      {
        const int other = this->LocalOf[linked[e]];
        if (other >= 0)
        {
          int a = find(j), b = find(other);
          if (a != b) // union by size: the trees stay shallow
          {
            if (this->Size[a] > this->Size[b])
            {
              std::swap(a, b);
            }
            this->Parent[a] = b;
            this->Size[b] += this->Size[a];
          }
        }
      }
    }
    const int root = find(0);
    int members = 0;
    for (int j = 0; j <= count; ++j)
    {
      this->LocalOf[idOf(j)] = -1;
      if (find(j) == root)
      {
        reached[j / 64] |= uint64_t(1) << (j % 64);
        ++members;
      }
    }
    return members;
  }
};

inline bool Reached(const uint64_t* reached, int j)
{
  return (reached[j / 64] >> (j % 64)) & 1u;
}

struct Scratch
{
  std::vector<double> Q;
  std::vector<Eigen::Vector3d> P, N;
  std::vector<unsigned char> Label, Next;
  SheetReach Sheet;
};
} // namespace

vtkCreaseVotingFeatures::vtkCreaseVotingFeatures()
{
  this->ThresholdMode = ABSOLUTE;
  this->Threshold = 0.5;
}

vtkCreaseVotingFeatures::~vtkCreaseVotingFeatures() = default;

int vtkCreaseVotingFeatures::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  this->ResetFigures();
  this->NoiseSigma = 0.0;
  this->GrowThresholdUsed = this->GrowThreshold;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkPoints* points = input->GetPoints();
  auto normals = featurepoints::NewZeroArray<vtkFloatArray>("Normals", 3, n);
  auto votes = featurepoints::NewZeroArray<vtkFloatArray>("CreaseVotes", 1, n);
  auto gains = featurepoints::NewZeroArray<vtkFloatArray>("CreaseGain", 1, n);
  auto angles = featurepoints::NewZeroArray<vtkFloatArray>("CreaseAngle", 1, n);
  auto mask = featurepoints::NewZeroArray<vtkUnsignedCharArray>("FeatureMask", 1, n);
  auto finish = [&]() {
    return this->AssembleOutput(input, output,
      { normals.GetPointer(), votes.GetPointer(), gains.GetPointer(), angles.GetPointer() }, mask);
  };

  const int k = std::max(this->NumberOfNeighbors, this->NormalNeighbors);
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  std::vector<vtkIdType> ids;
  std::vector<int32_t> table;
  if (!this->SearchAllPoints(points, n, k, neighborhoods, ids, table, 0.4))
  {
    return finish();
  }
  const featurepoints::PointReader reader(neighborhoods->GetPoints()); // renumbered
  const double d = this->MeanSpacing;
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  std::vector<vtkIdType> rowOf(n, -1);
  for (vtkIdType r = 0; r < rows; ++r)
  {
    rowOf[ids[r]] = r;
  }

  // Step 1a: PCA normals.
  this->BeginStage("normals");
  const double* center = neighborhoods->GetCenter();
  float* normal = normals->GetPointer(0);
  const int kn = this->NormalNeighbors;
  vtkSMPThreadLocal<std::vector<double>> normalScratch;
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<double>& q = normalScratch.Local();
    q.resize(3 * static_cast<size_t>(kn));
    double x[3], lambda[3], nrm[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = ids[r];
      const int32_t* row = table.data() + r * k;
      const int count = featurepoints::RowLength(row, kn);
      featurepoints::GatherRelative(reader, id, row, count, q.data(), x);
      const double outward[3] = { x[0] - center[0], x[1] - center[1], x[2] - center[2] };
      featurepoints::LocalPCA(q.data(), count, true, outward, lambda, nrm);
      for (int c = 0; c < 3; ++c)
      {
        normal[3 * id + c] = static_cast<float>(nrm[c]);
      }
    }
  });
  this->UpdateProgress(0.5);

  // Steps 1b-3: two-plane fits.
  this->BeginStage("crease fits");
  const int kf = this->NumberOfNeighbors;
  std::vector<CreaseFit> fits(static_cast<size_t>(rows));
  vtkSMPThreadLocal<Scratch> scratch;
  // One bit per neighbour (and the point): on the point's sheet. Every neighbour when the sheet
  // holds fewer than 8 points (an isolated point), so that the fit has something to work on.
  const size_t words = (static_cast<size_t>(kf) + 1 + 63) / 64;
  std::vector<uint64_t> sheets(static_cast<size_t>(rows) * words, 0);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    Scratch& s = scratch.Local();
    s.Q.resize(3 * static_cast<size_t>(kf));
    double x[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = ids[r];
      const int32_t* row = table.data() + r * k;
      const int count = featurepoints::RowLength(row, kf);
      featurepoints::GatherRelative(reader, id, row, count, s.Q.data(), x);
      uint64_t* sheet = sheets.data() + r * words;
      if (s.Sheet.Reach(id, row, count, table.data(), k, rowOf, sheet) < 8)
      {
        std::fill(sheet, sheet + words, ~uint64_t(0));
      }
      s.P.resize(1);
      s.N.resize(1);
      s.P[0].setZero();
      s.N[0] = Eigen::Vector3d(normal[3 * id], normal[3 * id + 1], normal[3 * id + 2]);
      for (int j = 0; j < count; ++j)
      {
        if (!Reached(sheet, j + 1))
        {
          continue;
        }
        s.P.emplace_back(s.Q[3 * j], s.Q[3 * j + 1], s.Q[3 * j + 2]);
        const float* nj = normal + 3 * static_cast<vtkIdType>(row[j]);
        s.N.emplace_back(nj[0], nj[1], nj[2]);
      }
      fits[r] = FitCrease(s.P, s.N, s.Label, s.Next);
      if (fits[r].Sheet >= 0)
      {
        // Two parallel sheets (a thin wall): fit the fitted point's sheet alone.
        const unsigned char side = static_cast<unsigned char>(fits[r].Sheet);
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
        fits[r] = FitCrease(s.P, s.N, s.Label, s.Next);
        fits[r].Sheet = -1;
      }
    }
  });
  this->UpdateProgress(0.8);

  // sigma^2, from the whole cloud.
  this->BeginStage("vote");
  std::vector<double> values(static_cast<size_t>(rows));
  auto dof = [&](vtkIdType r) { return std::max(fits[r].Points - 6, 0); };
  for (vtkIdType r = 0; r < rows; ++r)
  {
    values[r] = dof(r) > 0 ? fits[r].Hinge.RSS2 / dof(r) : 0.0;
  }
  auto median = [](std::vector<double>& v) {
    if (v.empty())
    {
      return 0.0;
    }
    auto middle = v.begin() + v.size() / 2;
    std::nth_element(v.begin(), middle, v.end());
    return *middle;
  };
  const double variance = std::max(median(values), NoiseFloor * NoiseFloor * d * d);
  this->NoiseSigma = std::sqrt(variance);
  // Model choice: the hinge, unless it leaves more than HingeMisfit times the noise (surfaces
  // crossing, corners, strongly curved patches); then the crossing planes, as fitted. The chosen
  // model replaces the hinge in place: from here on fits[r].Hinge is the fit that votes.
  float* gain = gains->GetPointer(0);
  float* angle = angles->GetPointer(0);
  for (vtkIdType r = 0; r < rows; ++r)
  {
    CreaseFit& f = fits[r];
    if (f.Hinge.RSS2 > HingeMisfit * dof(r) * variance)
    {
      f.Hinge = f.Cross;
    }
    values[r] = std::max(f.RSS1 - f.Hinge.RSS2, 0.0) / variance;
    gain[ids[r]] = static_cast<float>(values[r]);
    angle[ids[r]] = f.Hinge.Angle;
  }

  // Step 4: votes.
  const double minAngle = this->MinimumAngle;
  const double band2 = this->BandWidth * d * this->BandWidth * d;
  float* vote = votes->GetPointer(0);
  // One byte per point says whether its fit may vote, so that the vote reads only voters' fits.
  std::vector<unsigned char> voter(n, 0);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const CreaseLine& f = fits[r].Hinge;
      voter[ids[r]] = f.HasLine && values[r] > MinimumGain && !(f.Angle < minAngle) ? 1 : 0;
    }
  });
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = ids[r];
      const int32_t* row = table.data() + r * k;
      const int count = featurepoints::RowLength(row, kf);
      reader.Get(id, x);
      int in = 0;
      // The point's sheet votes, and the fraction is of its members.
      const uint64_t* sheet = sheets.data() + r * words;
      int members = 0;
      for (int j = 0; j <= count; ++j)
      {
        members += Reached(sheet, j);
      }
      for (int j = -1; j < count; ++j)
      {
        const vtkIdType other = j < 0 ? id : static_cast<vtkIdType>(row[j]);
        if (!voter[other] || !Reached(sheet, j + 1))
        {
          continue;
        }
        const CreaseLine& f = fits[rowOf[other]].Hinge;
        reader.Get(other, y);
        double v[3];
        for (int c = 0; c < 3; ++c)
        {
          v[c] = x[c] - y[c] - f.LinePoint[c];
        }
        const double along =
          v[0] * f.LineDirection[0] + v[1] * f.LineDirection[1] + v[2] * f.LineDirection[2];
        if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - along * along <= band2)
        {
          ++in;
        }
      }
      vote[id] = static_cast<float>(in) / static_cast<float>(members);
    }
  });
  this->ApplyThreshold(vote, ids, nullptr, nullptr, mask->GetPointer(0));

  // Step 6: hysteresis. Points whose votes exceed GrowThreshold join the feature points they are
  // connected to through such points (each point linked to its ConnectionNeighbors nearest).
  // The result is a set of connected components, so it does not depend on the visiting order.
  // The growth threshold is counted above the cloud's background: the median vote (most points
  // are not on a crease; on a strongly curved smooth shape every point collects some votes).
  for (vtkIdType r = 0; r < rows; ++r)
  {
    values[r] = vote[ids[r]];
  }
  const double growAt = this->GrowThreshold + median(values);
  this->GrowThresholdUsed = growAt;
  if (growAt < this->ThresholdUsed)
  {
    unsigned char* m = mask->GetPointer(0);
    std::vector<vtkIdType> stack;
    for (vtkIdType r = 0; r < rows; ++r)
    {
      if (m[ids[r]])
      {
        stack.push_back(r);
      }
    }
    const int kc = std::min(ConnectionNeighbors, k);
    while (!stack.empty())
    {
      const vtkIdType r = stack.back();
      stack.pop_back();
      const int32_t* row = table.data() + r * k;
      for (int j = 0; j < kc && row[j] >= 0; ++j)
      {
        const vtkIdType other = row[j];
        if (!m[other] && vote[other] > growAt)
        {
          m[other] = 1;
          ++this->NumberOfFeaturePoints;
          stack.push_back(rowOf[other]);
        }
      }
    }
  }
  this->UpdateProgress(1.0);
  return finish();
}

void vtkCreaseVotingFeatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "NormalNeighbors: " << this->NormalNeighbors << "\n";
  os << indent << "GrowThreshold: " << this->GrowThreshold << "\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "BandWidth: " << this->BandWidth << "\n";
  os << indent << "NoiseSigma: " << this->NoiseSigma << "\n";
  os << indent << "GrowThresholdUsed: " << this->GrowThresholdUsed << "\n";
}
