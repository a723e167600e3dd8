#include "vtkFeaturePointExtraction.h"

#include "vtkCellArray.h"
#include "vtkFeaturePointsDensityContrast.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
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

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkFeaturePointExtraction);

namespace
{
// m(i) never goes below this fraction of the mean spacing (stacks of coincident points).
constexpr double MinimumMeanDistance = 1e-3;

// The AUTOMATIC threshold must see the cloud's background, not only the candidates' feature-rich
// population: a sample of the non-candidates is scored too. The sample is made of whole blocks of
// side BackgroundBlockFactor * d, one in BackgroundBlockModulus (at least) chosen by a hash of the
// block's grid coordinates, so that it depends on where the points are, not on their order, and
// the neighbourhoods of a sampled block's points overlap: the m(j) a block needs come from about
// twice its own points, where scattered samples would need the m(j) of nearly every point.
constexpr double BackgroundBlockFactor = 16.0;
constexpr uint64_t BackgroundBlockModulus = 8;
// Enough background for the threshold's median and MAD; larger clouds sample fewer blocks.
constexpr vtkIdType BackgroundTarget = 65536;
// Below this many sampled points, every non-candidate is scored (small clouds: cheap anyway).
constexpr vtkIdType BackgroundMinimum = 512;

// Eq. 7: mean distance from point `id` to the first k entries of its row.
inline double MeanDistance(
  const featurepoints::PointReader& points, vtkIdType id, const int32_t* row, int k, double floor)
{
  double x[3], y[3];
  points.Get(id, x);
  double sum = 0.0;
  int n = 0;
  for (; n < k && row[n] >= 0; ++n)
  {
    points.Get(row[n], y);
    sum += std::sqrt((y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
      (y[2] - x[2]) * (y[2] - x[2]));
  }
  return n > 0 ? std::max(sum / n, floor) : floor;
}

struct ScoreParameters
{
  int K;
  int NormalNeighbors;
  int SSINeighbors;
  int DensityNeighbors;
  int CenterNeighbors;
  bool DensityWeightedCenter;
  double Alpha;
  double Spacing;
  double Radius;
  double Center[3];
};

// Normal, SSI, PDI and F of each candidate, from its neighbour row and the m(j) of its neighbours.
struct ScoreWorker
{
  featurepoints::PointReader Points;
  const std::vector<vtkIdType>& Ids;
  const int32_t* Table;
  const double* MeanDistances; // m(j) for every point that some candidate uses
  const ScoreParameters& P;
  float* Normals;
  float* SSI;
  float* PDI;
  float* F;
  vtkSMPThreadLocal<std::vector<double>> Scratch; // relative coordinates of the neighbours

  void Initialize() { this->Scratch.Local().resize(3 * static_cast<size_t>(this->P.K)); }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    std::vector<double>& q = this->Scratch.Local();
    double x[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      const int32_t* row = this->Table + r * this->P.K;
      const int n = featurepoints::RowLength(row, this->P.K);
      featurepoints::GatherRelative(this->Points, id, row, n, q.data(), x);
      auto dist2 = [&q](int j) {
        return q[3 * j] * q[3 * j] + q[3 * j + 1] * q[3 * j + 1] + q[3 * j + 2] * q[3 * j + 2];
      };

      // Eq. 3: PCA normal of the NormalNeighbors nearest points.
      const int kn = std::min(n, this->P.NormalNeighbors);
      const double outward[3] = { x[0] - this->P.Center[0], x[1] - this->P.Center[1],
        x[2] - this->P.Center[2] };
      double lambda[3], nrm[3];
      featurepoints::LocalPCA(q.data(), kn, false, outward, lambda, nrm);
      const Eigen::Vector3d normal(nrm[0], nrm[1], nrm[2]);

      // Eqs. 7, 9: m(i) and D(i).
      const double mi = this->MeanDistances[id];
      const double density = 1.0 / mi;

      // Eqs. 4-5: weighted centroid, weights g_j m(j), shifted by the nearest distance (see header).
      const int ks = std::min(n, this->P.SSINeighbors);
      const double inv_r2 = 1.0 / (this->P.Radius * this->P.Radius);
      const double d0 = n > 0 ? dist2(0) : 0.0;
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
      double weightSum = 0.0;
      for (int j = 0; j < ks; ++j)
      {
        const double w = std::exp(-(dist2(j) - d0) * inv_r2) * this->MeanDistances[row[j]];
        weighted += w * Eigen::Vector3d(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
        weightSum += w;
      }
      if (weightSum > 0.0)
      {
        weighted /= weightSum;
      }

      // Eq. 6 (or Eq. 2): the centre the SSI measures from, relative to P_i.
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      if (this->P.DensityWeightedCenter)
      {
        const int kc = std::min(n, this->P.CenterNeighbors);
        double sum = mi; // the point itself, at relative position 0
        for (int j = 0; j < kc; ++j)
        {
          const double w = this->MeanDistances[row[j]];
          centre += w * Eigen::Vector3d(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
          sum += w;
        }
        centre /= sum;
      }

      // Eq. 8 and Eq. 1 on dimensionless terms.
      double ssi = std::abs((centre - weighted).dot(normal));
      if (!std::isfinite(ssi))
      {
        ssi = 0.0;
      }
      const double f = this->P.Alpha * ssi / this->P.Spacing +
        (1.0 - this->P.Alpha) * this->P.Spacing * density;

      for (int c = 0; c < 3; ++c)
      {
        this->Normals[3 * id + c] = static_cast<float>(normal[c]);
      }
      this->SSI[id] = static_cast<float>(ssi);
      this->PDI[id] = static_cast<float>(density);
      this->F[id] = static_cast<float>(f);
    }
  }

  void Reduce() {}
};

} // namespace

// The points a run scores and their neighbourhoods: the voxel pre-filter's candidates (or every
// valid point) and, for the AUTOMATIC threshold, the background sample among them.
struct vtkFeaturePointExtraction::ScoredPoints
{
  std::vector<vtkIdType> Ids;        // in point order
  std::vector<int32_t> Table;        // their k nearest, row r for Ids[r]
  std::vector<vtkIdType> Background; // the sampled non-candidates (scored, never marked)
  int BackgroundWeight = 1;          // how many non-candidates each of them stands for
  double Spacing = 0.0;              // the mean spacing d
  bool Screen = false;               // the voxel pre-filter runs (its sample showed contrast)
  bool ScoreAll = true;              // every valid point is a candidate
  // Distributed runs: the own points and the reductions the voxel pre-filter takes.
  featurepoints::DensityContrastProcesses Processes;
  bool Distributed = false;
};

namespace
{
// The voxel density-contrast test with the filter's parameters (and a distributed run's processes).
featurepoints::DensityContrast MakeVoxelTest(
  vtkFeaturePointExtraction* self, const featurepoints::DensityContrastProcesses* processes)
{
  featurepoints::DensityContrast voxels;
  voxels.VoxelSizeFactor = self->GetVoxelSizeFactor();
  voxels.DensityContrast = self->GetDensityContrast();
  voxels.ContrastRule = self->GetVoxelContrastRule();
  voxels.Reporter = self;
  voxels.Processes = processes;
  return voxels;
}
} // namespace

double vtkFeaturePointExtraction::GetHaloWidthFor(double spacing) const
{
  return this->UseVoxelFilter
    ? featurepoints::DensityContrast::HaloWidthFor(this->VoxelSizeFactor * spacing)
    : 0.0;
}

bool vtkFeaturePointExtraction::HaloSuffices(double required)
{
  this->RequiredHaloWidth = std::max(this->RequiredHaloWidth, required);
  return !this->IsDistributed() || required <= this->HaloWidth;
}

void vtkFeaturePointExtraction::PrepareProcesses(ScoredPoints& scored)
{
  scored.Distributed = this->IsDistributed();
  if (!scored.Distributed)
  {
    return;
  }
  featurepoints::DensityContrastProcesses& p = scored.Processes;
  p.Owned = this->Owned.data();
  p.InputOrder = this->OriginalIds.empty() ? nullptr : this->OriginalIds.data();
  p.Bounds = this->GlobalBounds;
  p.HaloWidth = this->HaloWidth;
  p.Sum = [this](vtkIdType value) { return this->GlobalSum(value); };
  p.UpperMedian = [this](std::vector<double>& values) { return this->GlobalUpperMedian(values); };
  p.MinMax = [this](double lo[3], double hi[3]) {
    double globalLo[3], globalHi[3];
    this->Controller->AllReduce(lo, globalLo, 3, vtkCommunicator::MIN_OP);
    this->Controller->AllReduce(hi, globalHi, 3, vtkCommunicator::MAX_OP);
    std::copy_n(globalLo, 3, lo);
    std::copy_n(globalHi, 3, hi);
  };
  p.MeanWithoutOutliers = [this](std::vector<double>& values) {
    return this->GlobalMeanWithoutOutliers(values, 10.0);
  };
  p.AllGather = [this](std::vector<uint64_t>& keys) {
    std::vector<long long> all(keys.begin(), keys.end());
    this->GatherAll(all);
    keys.assign(all.begin(), all.end());
  };
}

vtkFeaturePointExtraction::vtkFeaturePointExtraction() = default;
vtkFeaturePointExtraction::~vtkFeaturePointExtraction() = default;

bool vtkFeaturePointExtraction::MeasureSpacing(
  vtkPointCloudNeighborhoods* neighborhoods, int k, ScoredPoints& scored)
{
  // A sample of the cloud that shows no density contrast: the full test would most likely find
  // none either, and its 1-nearest pass is skipped (see the header).
  this->PrepareProcesses(scored);
  const featurepoints::DensityContrastProcesses* processes =
    scored.Distributed ? &scored.Processes : nullptr;
  scored.Screen = this->UseVoxelFilter;
  if (scored.Screen)
  {
    this->BeginStage("voxel screen");
    featurepoints::DensityContrast screen = MakeVoxelTest(this, processes);
    scored.Screen = screen.SampleShowsContrast(neighborhoods);
    if (!this->HaloSuffices(screen.RequiredHaloWidth))
    {
      return false;
    }
  }
  // Without the pre-filter every point is scored: its k-nearest table also gives the spacing, so
  // each point is searched once. With it, a 1-nearest pass over all points comes first.
  if (scored.Screen)
  {
    this->BeginStage("spacing");
    scored.Spacing =
      this->GlobalMeanSpacing(neighborhoods, neighborhoods->ComputeMeanSpacing());
  }
  else
  {
    this->BeginStage("neighbours");
    scored.Ids = neighborhoods->GetValidIds();
    if (!neighborhoods->FindNearestNeighbors(k, scored.Ids, scored.Table, nullptr, this, 0.0, 0.6))
    {
      return false;
    }
    scored.Spacing = this->GlobalMeanSpacing(
      neighborhoods, neighborhoods->ComputeMeanSpacing(scored.Ids, scored.Table, k));
  }
  this->UpdateProgress(0.1);
  return !this->GetAbortExecute() && this->CheckSpacing(scored.Spacing, neighborhoods);
}

bool vtkFeaturePointExtraction::MarkCandidates(
  vtkPointCloudNeighborhoods* neighborhoods, ScoredPoints& scored, unsigned char* isCandidate)
{
  const unsigned char* valid = neighborhoods->GetValidMask();
  scored.ScoreAll = !scored.Screen;
  if (scored.Screen)
  {
    this->BeginStage("voxel filter");
    featurepoints::DensityContrast voxels =
      MakeVoxelTest(this, scored.Distributed ? &scored.Processes : nullptr);
    voxels.MarkCandidates(neighborhoods->GetPoints(), valid, scored.Spacing,
      neighborhoods->GetNearestDistances().data(), isCandidate);
    if (!this->HaloSuffices(voxels.RequiredHaloWidth))
    {
      return false;
    }
    // No density contrast anywhere: the cloud is uniformly sampled and the step would drop every
    // feature, so every point is scored instead.
    scored.ScoreAll = voxels.NumberOfContrastVoxels == 0;
  }
  if (scored.ScoreAll)
  {
    std::copy(valid, valid + neighborhoods->GetNumberOfPoints(), isCandidate);
  }
  return true;
}

bool vtkFeaturePointExtraction::FindScoredNeighbors(vtkPointCloudNeighborhoods* neighborhoods,
  int k, const unsigned char* isCandidate, ScoredPoints& scored)
{
  if (!scored.Screen)
  {
    return true; // MeasureSpacing searched every valid point already
  }
  // The candidates, and for the AUTOMATIC threshold the other points of a sample of whole blocks
  // (SampleBackground), so that the threshold sees the cloud's background rather than the
  // candidates' feature-rich population alone. The sample is scored but never marked, and its
  // scores are cleared from the output.
  vtkPoints* points = neighborhoods->GetPoints();
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  if (this->ThresholdMode == AUTOMATIC && !scored.ScoreAll)
  {
    scored.BackgroundWeight = this->SampleBackground(points, neighborhoods->GetValidMask(),
      isCandidate, scored.Spacing, this->CloudBounds(neighborhoods), scored.Background);
  }
  std::vector<unsigned char> sampled(n, 0);
  for (vtkIdType id : scored.Background)
  {
    sampled[id] = 1;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (isCandidate[i] || sampled[i])
    {
      scored.Ids.push_back(i);
    }
  }
  // One k-nearest query per scored point, for every quantity.
  this->BeginStage("neighbours");
  return neighborhoods->FindNearestNeighbors(k, scored.Ids, scored.Table, nullptr, this, 0.1, 0.7);
}

bool vtkFeaturePointExtraction::ComputeMeanDistances(vtkPointCloudNeighborhoods* neighborhoods,
  int k, const ScoredPoints& scored, std::vector<double>& meanDistance)
{
  const std::vector<vtkIdType>& ids = scored.Ids;
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  const double floor = MinimumMeanDistance * scored.Spacing;
  const featurepoints::PointReader reader(neighborhoods->GetPoints());
  meanDistance.assign(n, 0.0);
  const int kd = this->DensityNeighbors;
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      meanDistance[ids[r]] = MeanDistance(reader, ids[r], scored.Table.data() + r * k, kd, floor);
    }
  });
  // The neighbours a scored point weighs in Eqs. 4 and 6 that are not scored themselves.
  const int used = std::max(this->SSINeighbors,
    this->SSICenter == DENSITY_WEIGHTED_MEAN ? this->CenterNeighbors : 0);
  std::vector<unsigned char> needed(n, 0);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    const int32_t* row = scored.Table.data() + r * k;
    for (int j = 0; j < used && row[j] >= 0; ++j)
    {
      needed[row[j]] = meanDistance[row[j]] > 0.0 ? 0 : 1;
    }
  }
  std::vector<vtkIdType> neighbors;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (needed[i])
    {
      neighbors.push_back(i);
    }
  }
  if (neighbors.empty())
  {
    return true;
  }
  std::vector<int32_t> neighborTable;
  if (!neighborhoods->FindNearestNeighbors(kd, neighbors, neighborTable, nullptr, this, 0.7, 0.8))
  {
    return false;
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(neighbors.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      meanDistance[neighbors[r]] =
        MeanDistance(reader, neighbors[r], neighborTable.data() + r * kd, kd, floor);
    }
  });
  return true;
}

int vtkFeaturePointExtraction::GetLengthPower(const char* name) const
{
  return std::strcmp(name, "SSI") == 0 ? 1 : std::strcmp(name, "PDI") == 0 ? -1 : 0;
}

int vtkFeaturePointExtraction::Run(vtkPointSet* input, vtkPolyData* output)
{

  const vtkIdType n = input->GetNumberOfPoints();
  auto normals = featurepoints::NewZeroArray<vtkFloatArray>("Normals", 3, n);
  auto ssi = featurepoints::NewZeroArray<vtkFloatArray>("SSI", 1, n);
  auto pdi = featurepoints::NewZeroArray<vtkFloatArray>("PDI", 1, n);
  auto score = featurepoints::NewZeroArray<vtkFloatArray>("F", 1, n);
  auto candidate = featurepoints::NewZeroArray<vtkUnsignedCharArray>("Candidate", 1, n);
  auto mask = featurepoints::NewZeroArray<vtkUnsignedCharArray>("FeatureMask", 1, n);
  // Assembles the output from whatever the arrays hold when it is called.
  auto finish = [&]() {
    return this->AssembleOutput(input, output,
      { normals.GetPointer(), ssi.GetPointer(), pdi.GetPointer(), score.GetPointer(),
        candidate.GetPointer() },
      mask);
  };

  const int k = std::max(std::max(this->NormalNeighbors, this->SSINeighbors),
    std::max(this->DensityNeighbors,
      this->SSICenter == DENSITY_WEIGHTED_MEAN ? this->CenterNeighbors : 0));
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  if (!this->PrepareNeighborhoods(input->GetPoints(), n, k, neighborhoods))
  {
    return finish();
  }

  // Section 3.2: the mean spacing, the candidates of the voxel pre-filter (or every valid point)
  // and the neighbourhoods of the scored points.
  ScoredPoints scored;
  unsigned char* isCandidate = candidate->GetPointer(0);
  if (!this->MeasureSpacing(neighborhoods, k, scored))
  {
    return finish();
  }
  if (!this->MarkCandidates(neighborhoods, scored, isCandidate) ||
    !this->FindScoredNeighbors(neighborhoods, k, isCandidate, scored))
  {
    return finish();
  }
  const std::vector<vtkIdType>& ids = scored.Ids;
  this->NumberOfCandidates =
    this->GlobalSum(this->CountOwned(ids) - this->CountOwned(scored.Background));

  // m(j) for the scored points and for every point they weigh in Eqs. 4 and 6, then the scores.
  this->BeginStage("scores");
  std::vector<double> meanDistance;
  if (!this->ComputeMeanDistances(neighborhoods, k, scored, meanDistance))
  {
    return finish();
  }
  const double d = scored.Spacing;
  ScoreParameters parameters{ k, this->NormalNeighbors, this->SSINeighbors, this->DensityNeighbors,
    this->CenterNeighbors, this->SSICenter == DENSITY_WEIGHTED_MEAN, this->Alpha, d,
    this->GaussianRadiusFactor * d,
    { this->CloudCenter(neighborhoods)[0], this->CloudCenter(neighborhoods)[1],
      this->CloudCenter(neighborhoods)[2] } };
  ScoreWorker worker{ featurepoints::PointReader(neighborhoods->GetPoints()), ids,
    scored.Table.data(), meanDistance.data(), parameters, normals->GetPointer(0),
    ssi->GetPointer(0), pdi->GetPointer(0), score->GetPointer(0), {} };
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), worker);
  this->UpdateProgress(0.9);

  // Threshold and mask, decided on the stored (float) F so that the output agrees with itself.
  // For the AUTOMATIC rule each background point stands for BackgroundWeight non-candidates (the
  // non-candidates of the blocks SampleBackground did not sample).
  std::vector<int> weights(ids.size(), 1);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    weights[r] = isCandidate[ids[r]] ? 1 : scored.BackgroundWeight;
  }
  this->ApplyThreshold(score->GetPointer(0), ids, &weights, isCandidate, mask->GetPointer(0));
  for (vtkIdType id : scored.Background)
  {
    std::fill_n(normals->GetPointer(3 * id), 3, 0.0f);
    ssi->SetValue(id, 0.0f);
    pdi->SetValue(id, 0.0f);
    score->SetValue(id, 0.0f);
  }
  this->UpdateProgress(1.0);
  return finish();
}

int vtkFeaturePointExtraction::SampleBackground(vtkPoints* points, const unsigned char* valid,
  const unsigned char* isCandidate, double d, const double bounds[6],
  std::vector<vtkIdType>& background)
{
  // Distributed runs: the own points' figures over all processes, and only own points sampled
  // (the halo's scores are not the process's to give).
  background.clear();
  const vtkIdType n = points->GetNumberOfPoints();
  auto eligible = [&](vtkIdType i) { return valid[i] && !isCandidate[i] && this->IsOwned(i); };
  vtkIdType others = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    others += eligible(i) ? 1 : 0;
  }
  others = this->GlobalSum(others);
  if (others == 0)
  {
    return 1;
  }
  // One block in `modulus`: BackgroundBlockModulus, or more blocks skipped in large clouds.
  const uint64_t modulus = std::max<uint64_t>(BackgroundBlockModulus,
    static_cast<uint64_t>(others / BackgroundTarget));
  const double side = BackgroundBlockFactor * d;
  const double origin[3] = { bounds[0], bounds[2], bounds[4] };
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!eligible(i))
    {
      continue;
    }
    points->GetPoint(i, x);
    if (featurepoints::InSampledRegion(x, origin, side, modulus))
    {
      background.push_back(i);
    }
  }
  const vtkIdType sampled = this->GlobalSum(static_cast<vtkIdType>(background.size()));
  if (sampled < std::min(others, BackgroundMinimum))
  {
    // Too few blocks (a small cloud): every non-candidate stands for itself.
    background.clear();
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (eligible(i))
      {
        background.push_back(i);
      }
    }
    return 1;
  }
  // Each sampled point stands for the non-candidates of the blocks that were not sampled.
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(others) / sampled)));
}

void vtkFeaturePointExtraction::ListParameters(std::vector<std::pair<const char*, double>>& parameters) const
{
  this->Superclass::ListParameters(parameters);
  parameters.emplace_back("Alpha", this->Alpha);
  parameters.emplace_back("GaussianRadiusFactor", this->GaussianRadiusFactor);
  parameters.emplace_back("VoxelSizeFactor", this->VoxelSizeFactor);
  parameters.emplace_back("DensityContrast", this->DensityContrast);
}

void vtkFeaturePointExtraction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Alpha: " << this->Alpha << "\n";
  os << indent << "NormalNeighbors: " << this->NormalNeighbors << "\n";
  os << indent << "SSINeighbors: " << this->SSINeighbors << "\n";
  os << indent << "DensityNeighbors: " << this->DensityNeighbors << "\n";
  os << indent << "CenterNeighbors: " << this->CenterNeighbors << "\n";
  os << indent << "SSICenter: " << this->SSICenter << "\n";
  os << indent << "GaussianRadiusFactor: " << this->GaussianRadiusFactor << "\n";
  os << indent << "UseVoxelFilter: " << this->UseVoxelFilter << "\n";
  os << indent << "VoxelSizeFactor: " << this->VoxelSizeFactor << "\n";
  os << indent << "DensityContrast: " << this->DensityContrast << "\n";
  os << indent << "VoxelContrastRule: " << this->VoxelContrastRule << "\n";
}
