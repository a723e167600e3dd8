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

vtkFeaturePointExtraction::vtkFeaturePointExtraction() = default;
vtkFeaturePointExtraction::~vtkFeaturePointExtraction() = default;

int vtkFeaturePointExtraction::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  this->ResetFigures();

  const vtkIdType n = input->GetNumberOfPoints();
  vtkPoints* points = input->GetPoints();
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
  if (!this->PrepareNeighborhoods(points, n, k, neighborhoods))
  {
    return finish();
  }
  points = neighborhoods->GetPoints(); // renumbered (see PrepareNeighborhoods)

  // Without the pre-filter every point is scored: its k-nearest table also gives the spacing, so
  // each point is searched once. With it, a 1-nearest pass over all points comes first.
  std::vector<vtkIdType> ids;
  std::vector<int32_t> table;
  double d = 0.0;
  // A sample of the cloud that shows no density contrast: the full test would most likely find
  // none either, and its 1-nearest pass is skipped (see the header).
  featurepoints::DensityContrast voxels;
  voxels.VoxelSizeFactor = this->VoxelSizeFactor;
  voxels.DensityContrast = this->DensityContrast;
  voxels.ContrastRule = this->VoxelContrastRule;
  voxels.Reporter = this;
  bool screen = this->UseVoxelFilter;
  if (screen)
  {
    this->BeginStage("voxel screen");
    screen = voxels.SampleShowsContrast(neighborhoods);
  }
  if (screen)
  {
    this->BeginStage("spacing");
    d = neighborhoods->ComputeMeanSpacing();
  }
  else
  {
    this->BeginStage("neighbours");
    ids = neighborhoods->GetValidIds();
    if (!neighborhoods->FindNearestNeighbors(k, ids, table, nullptr, this, 0.0, 0.6))
    {
      return finish();
    }
    d = neighborhoods->ComputeMeanSpacing(ids, table, k);
  }
  this->UpdateProgress(0.1);
  if (this->GetAbortExecute())
  {
    return finish();
  }
  if (!this->CheckSpacing(d, neighborhoods))
  {
    return finish();
  }

  // Section 3.2: candidates of the voxel pre-filter, or every valid point.
  unsigned char* isCandidate = candidate->GetPointer(0);
  const unsigned char* valid = neighborhoods->GetValidMask();
  bool scoreAll = !screen;
  if (screen)
  {
    this->BeginStage("voxel filter");
    voxels.MarkCandidates(
      points, valid, d, neighborhoods->GetNearestDistances().data(), isCandidate);
    // No density contrast anywhere: the cloud is uniformly sampled and the step would drop every
    // feature, so every point is scored instead.
    scoreAll = voxels.NumberOfContrastVoxels == 0;
  }
  if (scoreAll)
  {
    std::copy(valid, valid + n, isCandidate);
  }
  // The scored points: the candidates, and for the AUTOMATIC threshold the other points of a
  // sample of whole blocks (SampleBackground), so that the threshold sees the cloud's background
  // rather than the candidates' feature-rich population alone. The sample is scored but never
  // marked, and its scores are cleared from the output.
  std::vector<vtkIdType> background;
  int backgroundWeight = 1;
  if (screen)
  {
    if (this->ThresholdMode == AUTOMATIC && !scoreAll)
    {
      backgroundWeight = this->SampleBackground(points, valid, isCandidate, d,
        neighborhoods->GetBounds(), background);
    }
    std::vector<unsigned char> sampled(n, 0);
    for (vtkIdType id : background)
    {
      sampled[id] = 1;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (isCandidate[i] || sampled[i])
      {
        ids.push_back(i);
      }
    }
    // One k-nearest query per scored point, for every quantity.
    this->BeginStage("neighbours");
    if (!neighborhoods->FindNearestNeighbors(k, ids, table, nullptr, this, 0.1, 0.7))
    {
      return finish();
    }
  }
  this->NumberOfCandidates = static_cast<vtkIdType>(ids.size() - background.size());

  // m(j) for the candidates and for every point a candidate weighs in Eqs. 4 and 6.
  this->BeginStage("scores");
  const double floor = MinimumMeanDistance * d;
  const featurepoints::PointReader reader(points);
  std::vector<double> meanDistance(n, 0.0);
  const int kd = this->DensityNeighbors;
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      meanDistance[ids[r]] = MeanDistance(reader, ids[r], table.data() + r * k, kd, floor);
    }
  });
  const int used = std::max(this->SSINeighbors,
    this->SSICenter == DENSITY_WEIGHTED_MEAN ? this->CenterNeighbors : 0);
  std::vector<unsigned char> needed(n, 0);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    const int32_t* row = table.data() + r * k;
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
  if (!neighbors.empty())
  {
    std::vector<int32_t> neighborTable;
    if (!neighborhoods->FindNearestNeighbors(kd, neighbors, neighborTable, nullptr, this, 0.7, 0.8))
    {
      return finish();
    }
    vtkSMPTools::For(0, static_cast<vtkIdType>(neighbors.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType r = begin; r < end; ++r)
      {
        meanDistance[neighbors[r]] =
          MeanDistance(reader, neighbors[r], neighborTable.data() + r * kd, kd, floor);
      }
    });
  }

  ScoreParameters parameters{ k, this->NormalNeighbors, this->SSINeighbors, this->DensityNeighbors,
    this->CenterNeighbors, this->SSICenter == DENSITY_WEIGHTED_MEAN, this->Alpha, d,
    this->GaussianRadiusFactor * d,
    { neighborhoods->GetCenter()[0], neighborhoods->GetCenter()[1],
      neighborhoods->GetCenter()[2] } };
  ScoreWorker worker{ reader, ids, table.data(), meanDistance.data(), parameters,
    normals->GetPointer(0), ssi->GetPointer(0), pdi->GetPointer(0), score->GetPointer(0), {} };
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), worker);
  this->UpdateProgress(0.9);

  // Threshold and mask, decided on the stored (float) F so that the output agrees with itself.
  // For the AUTOMATIC rule each background point stands for backgroundWeight non-candidates (the
  // non-candidates of the blocks SampleBackground did not sample).
  std::vector<int> weights(ids.size(), 1);
  for (size_t r = 0; r < ids.size(); ++r)
  {
    weights[r] = isCandidate[ids[r]] ? 1 : backgroundWeight;
  }
  this->ApplyThreshold(score->GetPointer(0), ids, &weights, isCandidate, mask->GetPointer(0));
  for (vtkIdType id : background)
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
  background.clear();
  const vtkIdType n = points->GetNumberOfPoints();
  vtkIdType others = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    others += valid[i] && !isCandidate[i] ? 1 : 0;
  }
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
    if (!valid[i] || isCandidate[i])
    {
      continue;
    }
    points->GetPoint(i, x);
    if (featurepoints::InSampledRegion(x, origin, side, modulus))
    {
      background.push_back(i);
    }
  }
  const vtkIdType sampled = static_cast<vtkIdType>(background.size());
  if (sampled < std::min(others, BackgroundMinimum))
  {
    // Too few blocks (a small cloud): every non-candidate stands for itself.
    background.clear();
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (valid[i] && !isCandidate[i])
      {
        background.push_back(i);
      }
    }
    return 1;
  }
  // Each sampled point stands for the non-candidates of the blocks that were not sampled.
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(others) / sampled)));
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
