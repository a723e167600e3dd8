#include "vtkFeaturePointDetector.h"
#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointCloudGridLocator.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkDataSetAttributes.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>
#include <vector>

vtkCxxSetObjectMacro(vtkFeaturePointDetector, Locator, vtkAbstractPointLocator);
vtkCxxSetObjectMacro(vtkFeaturePointDetector, Controller, vtkMultiProcessController);

vtkFeaturePointDetector::vtkFeaturePointDetector()
{
  this->Locator = vtkPointCloudGridLocator::New();
}

vtkFeaturePointDetector::~vtkFeaturePointDetector()
{
  this->SetLocator(nullptr);
  this->SetController(nullptr);
}

bool vtkFeaturePointDetector::IsDistributed() const
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

double vtkFeaturePointDetector::GlobalSum(double value) const
{
  if (!this->IsDistributed())
  {
    return value;
  }
  double total = 0.0;
  this->Controller->AllReduce(&value, &total, 1, vtkCommunicator::SUM_OP);
  return total;
}

vtkIdType vtkFeaturePointDetector::GlobalSum(vtkIdType value) const
{
  if (!this->IsDistributed())
  {
    return value;
  }
  long long local = value, total = 0;
  this->Controller->AllReduce(&local, &total, 1, vtkCommunicator::SUM_OP);
  return static_cast<vtkIdType>(total);
}

double vtkFeaturePointDetector::GlobalUpperMedian(std::vector<double>& values) const
{
  return this->GlobalValueOfShare(values, 0.5);
}

double vtkFeaturePointDetector::GlobalValueOfShare(std::vector<double>& values, double share) const
{
  if (!this->IsDistributed())
  {
    return featurepoints::ValueOfShare(values, share);
  }
  // The value of rank floor(share n) of the union (a function of the values only, not of their
  // order), selected a byte at a time: each value has a 64-bit key in the values' order, and
  // each round counts the values whose key starts with the bytes chosen so far by their next
  // byte, the counts summed over the processes. Exact, in 8 rounds, and no process holds more
  // than its own values.
  long long local = static_cast<long long>(values.size()), total = 0;
  this->Controller->AllReduce(&local, &total, 1, vtkCommunicator::SUM_OP);
  if (total == 0)
  {
    return 0.0;
  }
  constexpr uint64_t Sign = uint64_t(1) << 63;
  auto keyOf = [](double v) {
    v = v == 0.0 ? 0.0 : v; // -0 as +0: equal values, one key
    uint64_t u = 0;
    std::memcpy(&u, &v, sizeof(u));
    return (u & Sign) ? ~u : (u | Sign);
  };
  uint64_t prefix = 0;
  long long rank = std::min(total - 1,
    static_cast<long long>(std::max(0.0, share) * static_cast<double>(total)));
  for (int shift = 56; shift >= 0; shift -= 8)
  {
    const uint64_t chosen = shift == 56 ? 0 : ~uint64_t(0) << (shift + 8);
    long long counts[256] = {}, sums[256] = {};
    for (double v : values)
    {
      const uint64_t key = keyOf(v);
      if ((key & chosen) == prefix)
      {
        ++counts[(key >> shift) & 0xff];
      }
    }
    this->Controller->AllReduce(counts, sums, 256, vtkCommunicator::SUM_OP);
    int byte = 0;
    while (byte < 255 && rank >= sums[byte])
    {
      rank -= sums[byte++];
    }
    prefix |= static_cast<uint64_t>(byte) << shift;
  }
  const uint64_t u = (prefix & Sign) ? (prefix & ~Sign) : ~prefix;
  double median = 0.0;
  std::memcpy(&median, &u, sizeof(median));
  return median;
}

const double* vtkFeaturePointDetector::CloudBounds(vtkPointCloudNeighborhoods* neighborhoods) const
{
  return this->IsDistributed() ? this->GlobalBounds : neighborhoods->GetBounds();
}

const double* vtkFeaturePointDetector::CloudCenter(vtkPointCloudNeighborhoods* neighborhoods) const
{
  return this->IsDistributed() ? this->GlobalCenter : neighborhoods->GetCenter();
}

vtkIdType vtkFeaturePointDetector::CountOwned(const std::vector<vtkIdType>& ids) const
{
  if (this->Owned.empty())
  {
    return static_cast<vtkIdType>(ids.size());
  }
  vtkIdType count = 0;
  for (vtkIdType id : ids)
  {
    count += this->Owned[id];
  }
  return count;
}

double vtkFeaturePointDetector::GlobalMeanSpacing(
  vtkPointCloudNeighborhoods* neighborhoods, double local) const
{
  if (!this->IsDistributed())
  {
    return local;
  }
  // vtkPointCloudNeighborhoods::FinishMeanSpacing over the own points of every process: the
  // nearest distinct distances below 10 times their upper median, a position's copies once (the
  // copies of a position are all one process's own points: the pieces are boxes), summed
  // exactly (so in any order and split).
  const std::vector<double>& nearest = neighborhoods->GetNearestDistances();
  const unsigned char* valid = neighborhoods->GetValidMask();
  const std::vector<vtkIdType>& copies = neighborhoods->GetExtraCopies();
  std::vector<double> positive;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(nearest.size()); ++i)
  {
    if (valid[i] && this->IsOwned(i) && nearest[i] > 0.0 &&
      !std::binary_search(copies.begin(), copies.end(), i))
    {
      positive.push_back(nearest[i]);
    }
  }
  return this->GlobalMeanWithoutOutliers(positive, 10.0);
}

double vtkFeaturePointDetector::GlobalMeanWithoutOutliers(
  const std::vector<double>& values, double factor) const
{
  if (!this->IsDistributed())
  {
    return featurepoints::MeanWithoutOutliers(values, factor);
  }
  std::vector<double> copy(values);
  const double limit = factor * this->GlobalUpperMedian(copy);
  featurepoints::ExactSum sum;
  long long count[1] = { 0 };
  for (double v : values)
  {
    if (v <= limit)
    {
      sum.Add(v);
      ++count[0];
    }
  }
  sum.Normalize();
  long long limbs[featurepoints::ExactSum::NumberOfLimbs];
  long long totalLimbs[featurepoints::ExactSum::NumberOfLimbs];
  std::copy_n(sum.GetLimbs(), featurepoints::ExactSum::NumberOfLimbs, limbs);
  this->Controller->AllReduce(
    limbs, totalLimbs, featurepoints::ExactSum::NumberOfLimbs, vtkCommunicator::SUM_OP);
  long long totalCount = 0;
  this->Controller->AllReduce(count, &totalCount, 1, vtkCommunicator::SUM_OP);
  featurepoints::ExactSum total;
  std::copy_n(totalLimbs, featurepoints::ExactSum::NumberOfLimbs, total.GetLimbs());
  return totalCount > 0 ? total.Value() / static_cast<double>(totalCount) : 0.0;
}

double vtkFeaturePointDetector::AutomaticThreshold(
  const std::vector<double>& scores, const std::vector<int>& weights, double sigmas)
{
  const size_t n = std::min(scores.size(), weights.size());
  std::vector<std::pair<double, int64_t>> sorted;
  sorted.reserve(n);
  for (size_t i = 0; i < n; ++i)
  {
    if (weights[i] > 0)
    {
      sorted.emplace_back(scores[i], weights[i]);
    }
  }
  if (sorted.empty())
  {
    return 0.0;
  }
  vtkSMPTools::Sort(sorted.begin(), sorted.end());
  std::vector<double> value(sorted.size());
  std::vector<int64_t> cumulative(sorted.size() + 1, 0); // weight of the first i entries
  for (size_t i = 0; i < sorted.size(); ++i)
  {
    value[i] = sorted[i].first;
    cumulative[i + 1] = cumulative[i] + sorted[i].second;
  }
  // The value of rank r (0-based) among the first `kept` entries, repeated by their weights.
  auto atRank = [&](int64_t r) {
    const size_t i = std::upper_bound(cumulative.begin() + 1, cumulative.end(), r) -
      (cumulative.begin() + 1);
    return value[i];
  };
  size_t kept = value.size();
  double threshold = VTK_DOUBLE_MAX;
  for (int round = 0; round < 50; ++round)
  {
    // The median as featurepoints::Median() takes it: the middle value, or the mean of the two middle values.
    const int64_t total = cumulative[kept];
    const int64_t mid = total / 2;
    double mu = atRank(mid);
    if (total % 2 == 0)
    {
      mu = 0.5 * (mu + atRank(mid - 1));
    }
    // Median of |value - mu|: walk outwards from mu, the smaller deviation first, until the
    // weights passed reach the middle rank(s).
    size_t right = std::lower_bound(value.begin(), value.begin() + kept, mu) - value.begin();
    size_t left = right; // entries [0, left) lie below mu, [right, kept) at or above it
    int64_t passed = 0;
    double below = 0.0, at = 0.0; // deviations of ranks mid - 1 and mid
    bool haveBelow = total % 2 != 0 || mid == 0;
    for (;;)
    {
      double deviation;
      int64_t weight;
      if (left > 0 && (right >= kept || mu - value[left - 1] <= value[right] - mu))
      {
        --left;
        deviation = std::abs(value[left] - mu);
        weight = cumulative[left + 1] - cumulative[left];
      }
      else
      {
        deviation = std::abs(value[right] - mu);
        weight = cumulative[right + 1] - cumulative[right];
        ++right;
      }
      if (!haveBelow && passed + weight > mid - 1)
      {
        below = deviation;
        haveBelow = true;
      }
      passed += weight;
      if (passed > mid)
      {
        at = deviation;
        break;
      }
    }
    const double mad = total % 2 == 0 ? 0.5 * (at + below) : at;
    const double s = std::max(featurepoints::MADToSigma * mad, 0.01 * std::abs(mu));
    const double next = mu + sigmas * s;
    if (next == threshold)
    {
      break;
    }
    threshold = next;
    kept = std::upper_bound(value.begin(), value.end(), threshold) - value.begin();
    if (kept == 0)
    {
      break;
    }
  }
  return threshold;
}

int vtkFeaturePointDetector::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkFeaturePointDetector::ResetFigures()
{
  this->StageNames.clear();
  this->StageTimes.clear();
  this->StageRunning = false;
  this->MeanSpacing = 0.0;
  this->ThresholdUsed = 0.0;
  this->NumberOfCandidates = 0;
  this->NumberOfFeaturePoints = 0;
  this->RequiredHaloWidth = 0.0;
  this->OriginalIds.clear();
  this->PieceGlobalIds = nullptr;
}

double vtkFeaturePointDetector::AutomaticThreshold(std::vector<double>& scores, double sigmas)
{
  if (scores.empty())
  {
    return 0.0;
  }
  std::vector<double> kept(scores);
  std::vector<double> deviation;
  double threshold = VTK_DOUBLE_MAX;
  for (int round = 0; round < 50; ++round)
  {
    const double mu = featurepoints::Median(kept);
    deviation.resize(kept.size());
    for (size_t i = 0; i < kept.size(); ++i)
    {
      deviation[i] = std::abs(kept[i] - mu);
    }
    const double mad = featurepoints::Median(deviation);
    const double s = std::max(featurepoints::MADToSigma * mad, 0.01 * std::abs(mu));
    const double next = mu + sigmas * s;
    if (next == threshold)
    {
      break;
    }
    threshold = next;
    size_t m = 0;
    for (double value : scores)
    {
      if (value <= threshold)
      {
        kept[m++] = value;
      }
    }
    kept.resize(m);
    if (m == 0)
    {
      break;
    }
  }
  return threshold;
}

void vtkFeaturePointDetector::ListParameters(
  std::vector<std::pair<const char*, double>>& parameters) const
{
  parameters.emplace_back("Threshold", this->Threshold);
  parameters.emplace_back("ThresholdSigmas", this->ThresholdSigmas);
  parameters.emplace_back("HaloWidth", this->HaloWidth);
}

bool vtkFeaturePointDetector::PrepareNeighborhoods(
  vtkPoints* points, vtkIdType n, int k, vtkPointCloudNeighborhoods* neighborhoods)
{
  std::vector<std::pair<const char*, double>> parameters;
  this->ListParameters(parameters);
  if (const char* nan = featurepoints::FirstNaN(parameters.begin(), parameters.end()))
  {
    vtkErrorMacro(<< nan << " is NaN: give it a number. All scores are 0 and no point is a "
                            "feature point.");
    return false;
  }
  if (n == 0 || !points)
  {
    vtkWarningMacro("The input has no points: the output is empty.");
    return false;
  }
  this->BeginStage("locator");
  neighborhoods->SetLocator(this->Locator);
  if (!neighborhoods->Build(points))
  {
    vtkErrorMacro(<< "Cannot process the input: " << neighborhoods->GetErrorText()
                  << ". All scores are 0 and no point is a feature point.");
    return false;
  }
  const vtkIdType nValid = neighborhoods->GetNumberOfValidPoints();
  if (neighborhoods->GetFirstInvalidPoint() >= 0)
  {
    vtkWarningMacro(<< n - nValid << " of " << n
                    << " points have NaN or infinite coordinates (the first is point "
                    << neighborhoods->GetFirstInvalidPoint()
                    << "); they are skipped: scores 0, never feature points.");
  }
  if (nValid < k + 1)
  {
    vtkWarningMacro(<< "The input has " << nValid << " valid point(s), fewer than the " << k + 1
                    << " needed for neighbourhoods of " << k
                    << " points: all scores are 0 and no point is a feature point.");
    return false;
  }
  if (!neighborhoods->ReorderSpatially(this->OriginalIds))
  {
    this->OriginalIds.clear();
  }
  this->PrepareOwnership(neighborhoods);
  return true;
}

void vtkFeaturePointDetector::PrepareOwnership(vtkPointCloudNeighborhoods* neighborhoods)
{
  this->Owned.clear();
  this->PieceGlobalIds = nullptr;
  this->HaloLayoutReady = false;
  this->HaloEntries = 0;
  this->HaloRequests.clear();
  this->HaloAnswers.clear();
  if (!this->IsDistributed())
  {
    return;
  }
  // The halo's points carry vtkGhostType DUPLICATEPOINT: the piece's own points are the others.
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  vtkPointSet* input = vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
  vtkUnsignedCharArray* ghosts = input ? vtkUnsignedCharArray::SafeDownCast(
    input->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName())) : nullptr;
  this->Owned.assign(n, 1);
  if (ghosts && ghosts->GetNumberOfTuples() == n)
  {
    const bool renumbered = static_cast<vtkIdType>(this->OriginalIds.size()) == n;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType original = renumbered ? this->OriginalIds[i] : i;
      this->Owned[i] =
        (ghosts->GetValue(original) & vtkDataSetAttributes::DUPLICATEPOINT) ? 0 : 1;
    }
  }
  vtkIdTypeArray* gids = input ? vtkIdTypeArray::SafeDownCast(
    input->GetPointData()->GetArray(GetPieceGlobalIdsArrayName())) : nullptr;
  if (gids && gids->GetNumberOfTuples() == n && gids->GetNumberOfComponents() == 1 &&
    (this->OriginalIds.empty() || static_cast<vtkIdType>(this->OriginalIds.size()) == n))
  {
    this->PieceGlobalIds = gids->GetPointer(0); // read through OriginalIds (the input holds it)
  }
  // The bounds of the whole cloud: those of every process's own valid points.
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  const unsigned char* valid = neighborhoods->GetValidMask();
  vtkPoints* points = neighborhoods->GetPoints();
  double x[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (valid[i] && this->Owned[i])
    {
      points->GetPoint(i, x);
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], x[c]);
        hi[c] = std::max(hi[c], x[c]);
      }
    }
  }
  double globalLo[3], globalHi[3];
  this->Controller->AllReduce(lo, globalLo, 3, vtkCommunicator::MIN_OP);
  this->Controller->AllReduce(hi, globalHi, 3, vtkCommunicator::MAX_OP);
  for (int c = 0; c < 3; ++c)
  {
    this->GlobalBounds[2 * c] = globalLo[c];
    this->GlobalBounds[2 * c + 1] = globalHi[c];
    this->GlobalCenter[c] = 0.5 * (globalLo[c] + globalHi[c]);
  }
}

bool vtkFeaturePointDetector::BuildHaloLayout()
{
  if (this->HaloLayoutReady)
  {
    return true;
  }
  const vtkIdType n = static_cast<vtkIdType>(this->Owned.size());
  int ok = this->PieceGlobalIds ? 1 : 0;
  int allOk = 0;
  this->Controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
  if (!allOk)
  {
    vtkErrorMacro(<< "A piece has no global ids (point array " << GetPieceGlobalIdsArrayName()
                  << "): its halo cannot be matched with the other processes' points.");
    return false;
  }
  // This process's halo points, by global id: its entries in the gathered list.
  std::vector<std::pair<long long, vtkIdType>> halo;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!this->Owned[i])
    {
      halo.emplace_back(this->GlobalId(i), i);
    }
  }
  std::sort(halo.begin(), halo.end());
  const int nProcs = this->Controller->GetNumberOfProcesses();
  const int rank = this->Controller->GetLocalProcessId();
  long long mine = static_cast<long long>(halo.size());
  std::vector<long long> counts(nProcs, 0);
  this->Controller->AllGather(&mine, counts.data(), 1);
  std::vector<vtkIdType> lengths, offsets;
  this->HaloEntries = GatherLayout(counts, lengths, offsets);
  std::vector<vtkIdType> send(halo.size()), entries(static_cast<size_t>(this->HaloEntries));
  for (size_t j = 0; j < halo.size(); ++j)
  {
    send[j] = static_cast<vtkIdType>(halo[j].first);
    this->HaloRequests.emplace_back(offsets[rank] + static_cast<vtkIdType>(j), halo[j].second);
  }
  this->Controller->AllGatherV(send.data(), entries.data(),
    static_cast<vtkIdType>(send.size()), lengths.data(), offsets.data());
  // The entries of the other processes that name this process's own points: the entries (a
  // halo's worth) sorted by global id, each own point looked up among them (not the own points
  // sorted: 16 bytes a point).
  std::vector<std::pair<long long, vtkIdType>> wanted; // (global id, entry)
  for (int q = 0; q < nProcs; ++q)
  {
    for (vtkIdType e = offsets[q]; q != rank && e < offsets[q] + lengths[q]; ++e)
    {
      wanted.emplace_back(static_cast<long long>(entries[e]), e);
    }
  }
  std::sort(wanted.begin(), wanted.end());
  for (vtkIdType i = 0; i < n && !wanted.empty(); ++i)
  {
    if (!this->Owned[i])
    {
      continue;
    }
    const long long id = this->GlobalId(i);
    for (auto at = std::lower_bound(wanted.begin(), wanted.end(), std::make_pair(id, vtkIdType(-1)));
         at != wanted.end() && at->first == id; ++at)
    {
      this->HaloAnswers.emplace_back(at->second, i);
    }
  }
  this->HaloLayoutReady = true;
  return true;
}

template <typename T>
bool vtkFeaturePointDetector::ShareHalo(T* values, int components, int rule)
{
  if (!this->IsDistributed() || this->Owned.empty())
  {
    return false;
  }
  if (!this->BuildHaloLayout())
  {
    return false;
  }
  const size_t width = static_cast<size_t>(components);
  const size_t entries = static_cast<size_t>(this->HaloEntries) * width;
  bool changed = false;
  if (rule == HALO_FROM_OWNER)
  {
    // The owners' bytes, the other processes' zeros: a bitwise or gives the owner's value bit for
    // bit, whatever it is.
    const size_t bytes = sizeof(T) * width;
    std::vector<unsigned char> local(entries * sizeof(T), 0), shared(entries * sizeof(T), 0);
    for (const auto& answer : this->HaloAnswers)
    {
      std::memcpy(local.data() + answer.first * bytes, values + answer.second * width, bytes);
    }
    this->Controller->AllReduce(local.data(), shared.data(),
      static_cast<vtkIdType>(local.size()), vtkCommunicator::BITWISE_OR_OP);
    for (const auto& request : this->HaloRequests)
    {
      T* value = values + request.second * width;
      const unsigned char* owner = shared.data() + request.first * bytes;
      if (std::memcmp(value, owner, bytes) != 0)
      {
        std::memcpy(value, owner, bytes);
        changed = true;
      }
    }
  }
  else
  {
    const bool maximum = rule == HALO_MAXIMUM;
    const T identity = maximum ? std::numeric_limits<T>::lowest() : std::numeric_limits<T>::max();
    auto pick = [maximum](T a, T b) { return maximum ? std::max(a, b) : std::min(a, b); };
    std::vector<T> local(entries, identity), shared(entries, identity);
    for (const auto& request : this->HaloRequests)
    {
      std::copy_n(values + request.second * width, width, local.data() + request.first * width);
    }
    for (const auto& answer : this->HaloAnswers)
    {
      std::copy_n(values + answer.second * width, width, local.data() + answer.first * width);
    }
    this->Controller->AllReduce(local.data(), shared.data(), static_cast<vtkIdType>(entries),
      maximum ? vtkCommunicator::MAX_OP : vtkCommunicator::MIN_OP);
    auto merge = [&](const std::pair<vtkIdType, vtkIdType>& link) {
      for (size_t c = 0; c < width; ++c)
      {
        T& value = values[link.second * width + c];
        const T merged = pick(value, shared[link.first * width + c]);
        if (merged != value)
        {
          value = merged;
          changed = true;
        }
      }
    };
    std::for_each(this->HaloRequests.begin(), this->HaloRequests.end(), merge);
    std::for_each(this->HaloAnswers.begin(), this->HaloAnswers.end(), merge);
  }
  int mine = changed ? 1 : 0, any = 0;
  this->Controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  return any != 0;
}

bool vtkFeaturePointDetector::ShareHaloRecords(int bytes,
  const std::function<void(vtkIdType, unsigned char*)>& read,
  const std::function<void(vtkIdType, const unsigned char*)>& write)
{
  if (!this->IsDistributed() || this->Owned.empty() || !this->BuildHaloLayout())
  {
    return false;
  }
  // As HALO_FROM_OWNER: the owners' records, zeros elsewhere, merged by a bitwise or.
  const size_t size = static_cast<size_t>(bytes);
  const size_t entries = static_cast<size_t>(this->HaloEntries) * size;
  std::vector<unsigned char> local(entries, 0), shared(entries, 0);
  for (const auto& answer : this->HaloAnswers)
  {
    read(answer.second, local.data() + answer.first * size);
  }
  this->Controller->AllReduce(local.data(), shared.data(), static_cast<vtkIdType>(entries),
    vtkCommunicator::BITWISE_OR_OP);
  for (const auto& request : this->HaloRequests)
  {
    write(request.second, shared.data() + request.first * size);
  }
  return true;
}

bool vtkFeaturePointDetector::ShareHaloValues(unsigned char* values, int components, int rule)
{
  return this->ShareHalo(values, components, rule);
}

bool vtkFeaturePointDetector::ShareHaloValues(float* values, int components, int rule)
{
  return this->ShareHalo(values, components, rule);
}

bool vtkFeaturePointDetector::ShareHaloValues(long long* values, int components, int rule)
{
  return this->ShareHalo(values, components, rule);
}

void vtkFeaturePointDetector::GlobalLabelCounts(
  const std::vector<long long>& labels, std::vector<long long>& counts) const
{
  std::vector<long long> all(labels);
  this->GatherAll(all);
  std::sort(all.begin(), all.end());
  counts.resize(labels.size());
  for (size_t j = 0; j < labels.size(); ++j)
  {
    const auto range = std::equal_range(all.begin(), all.end(), labels[j]);
    counts[j] = static_cast<long long>(range.second - range.first);
  }
}

template <typename T>
void vtkFeaturePointDetector::GatherValues(std::vector<T>& values) const
{
  if (!this->IsDistributed())
  {
    return;
  }
  const int nProcs = this->Controller->GetNumberOfProcesses();
  long long mine = static_cast<long long>(values.size());
  std::vector<long long> sizes(nProcs, 0);
  this->Controller->AllGather(&mine, sizes.data(), 1);
  std::vector<vtkIdType> lengths, offsets;
  const vtkIdType total = GatherLayout(sizes, lengths, offsets);
  // At least one element each way: an empty vector's data() may be null.
  std::vector<T> all(static_cast<size_t>(std::max<vtkIdType>(total, 1)));
  std::vector<T> send(values);
  send.resize(std::max<size_t>(send.size(), 1));
  this->Controller->AllGatherV(send.data(), all.data(), static_cast<vtkIdType>(values.size()),
    lengths.data(), offsets.data());
  all.resize(static_cast<size_t>(total));
  values.swap(all);
}

void vtkFeaturePointDetector::GatherAll(std::vector<double>& values) const
{
  this->GatherValues(values);
}

void vtkFeaturePointDetector::GatherAll(std::vector<long long>& values) const
{
  this->GatherValues(values);
}

int vtkFeaturePointDetector::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  this->ResetFigures();
  // A cloud far larger or smaller than 2^32 units: squared lengths kept in float overflow or
  // lose their precision there (the default detector's fits: a box scaled by 2^63 lost 7 of its
  // 1,764 feature points, by 10^40 all but 9), and the methods' float scores beyond 2^+-140 (NaN
  // in SSI, PDI, Density). Distributed runs keep their pieces' frame (the scale would have to be
  // the whole cloud's).
  const int exponent = this->IsDistributed() || !input->GetPoints() ||
      input->GetNumberOfPoints() == 0
    ? 0
    : ScaledFrameExponent(input, 32);
  if (exponent == 0)
  {
    return this->Run(input, output);
  }
  vtkSmartPointer<vtkPointSet> scaled = vtkSmartPointer<vtkPointSet>::Take(input->NewInstance());
  scaled->ShallowCopy(input);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    for (double& c : x)
    {
      c = std::ldexp(c, exponent);
    }
    points->SetPoint(i, x);
  }
  scaled->SetPoints(points);
  const int result = this->Run(scaled, output);
  this->ScaleBack(input, points, exponent, output);
  return result;
}

void vtkFeaturePointDetector::ScaleBack(
  vtkPointSet* input, vtkPoints* scaled, int exponent, vtkPolyData* output)
{
  // The points: the input's own where the output holds them all.
  if (output->GetPoints() == scaled)
  {
    output->SetPoints(input->GetPoints());
  }
  else if (vtkPoints* out = output->GetPoints())
  {
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double x[3];
      out->GetPoint(i, x);
      for (double& c : x)
      {
        c = std::ldexp(c, -exponent);
      }
      out->SetPoint(i, x);
    }
  }
  this->ScaleLengthArrays(output->GetPointData(), -exponent, input->GetPointData());
  if (vtkDataArray* spacing = output->GetFieldData()->GetArray("MeanSpacing"))
  {
    spacing->SetTuple1(0, std::ldexp(spacing->GetTuple1(0), -exponent));
  }
  this->MeanSpacing = std::ldexp(this->MeanSpacing, -exponent);
  this->ScaleFiguresBack(-exponent);
}

void vtkFeaturePointDetector::ScaleLengthArrays(
  vtkPointData* arrays, int lengthExponent, vtkPointData* passedThrough) const
{
  for (int a = 0; a < arrays->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = arrays->GetArray(a);
    const int power = array && array->GetName() ? this->GetLengthPower(array->GetName()) : 0;
    if (power == 0 || (passedThrough && passedThrough->GetArray(array->GetName()) == array))
    {
      continue; // no unit, or the input's own array passed through
    }
    // In double: lengths of a cloud this large or small may lie beyond float's range.
    vtkNew<vtkDoubleArray> scaled;
    scaled->SetName(array->GetName());
    scaled->SetNumberOfComponents(array->GetNumberOfComponents());
    scaled->SetNumberOfTuples(array->GetNumberOfTuples());
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        scaled->SetComponent(i, c, std::ldexp(array->GetComponent(i, c), power * lengthExponent));
      }
    }
    const bool active = arrays->GetScalars() == array;
    arrays->AddArray(scaled); // replaces the array of that name, in its place
    if (active)
    {
      arrays->SetActiveScalars(scaled->GetName());
    }
  }
}

int vtkFeaturePointDetector::ScaledFrameExponent(vtkPointSet* cloud, int limit)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  double bounds[6];
  cloud->GetPoints()->GetBounds(bounds);
  const double extent =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  if (!(extent > 0.0) || (extent >= std::ldexp(1.0, -limit) && extent <= std::ldexp(1.0, limit)))
  {
    return 0;
  }
  const vtkIdType stride = std::max<vtkIdType>(1, n / 100000);
  double robust = 0.0;
  std::vector<double> sample;
  for (int a = 0; a < 3; ++a)
  {
    sample.clear();
    for (vtkIdType i = 0; i < n; i += stride)
    {
      sample.push_back(cloud->GetPoint(i)[a]);
    }
    const size_t lo = sample.size() / 4, hi = sample.size() - 1 - sample.size() / 4;
    std::nth_element(sample.begin(), sample.begin() + lo, sample.end());
    const double qlo = sample[lo];
    std::nth_element(sample.begin(), sample.begin() + hi, sample.end());
    robust = std::max(robust, sample[hi] - qlo);
  }
  // An overflowing span (coordinates near +-1.8e308) counts as the largest double.
  const double span = robust > 0.0 ? std::min(robust, VTK_DOUBLE_MAX) : std::min(extent, VTK_DOUBLE_MAX);
  const int power = std::ilogb(span);
  return power >= -limit && power <= limit ? 0 : -power; // a few far outliers alone: left as they are
}

bool vtkFeaturePointDetector::CheckSpacing(double d, vtkPointCloudNeighborhoods* neighborhoods)
{
  if (!(d > 0.0))
  {
    // Distinct points whose spacing squares to 0 or overflows look coincident: say why.
    const std::string why = neighborhoods ? neighborhoods->DescribeZeroSpacing(d)
                                          : std::string("All points coincide: the point spacing is 0");
    vtkWarningMacro(<< why << ". All scores are 0 and no point is a feature point.");
    return false;
  }
  this->MeanSpacing = d;
  if (!this->DeferCloudWarnings)
  {
    this->WarnAboutCloud(neighborhoods);
  }
  return true;
}

void vtkFeaturePointDetector::WarnAboutCloud(vtkPointCloudNeighborhoods* neighborhoods)
{
  if (this->IsDistributed())
  {
    // A piece's count includes its halo's points: process 0 says only whether any coincide.
    const vtkIdType pieces =
      this->GlobalSum(static_cast<vtkIdType>(neighborhoods->GetNumberOfDuplicatePoints() > 0));
    if (pieces > 0 && this->Controller->GetLocalProcessId() == 0)
    {
      vtkWarningMacro("Points coincide with other points; their neighbourhoods hold their "
                      "copies, which raises their density.");
    }
  }
  else if (neighborhoods->GetNumberOfDuplicatePoints() > 0)
  {
    vtkWarningMacro(<< neighborhoods->GetNumberOfDuplicatePoints()
                    << " point(s) coincide with another point; their neighbourhoods hold their "
                       "copies, which raises their density.");
  }
  if (!this->IsDistributed()) // a piece's shape is not the cloud's
  {
    this->WarnIfDegenerate(
      neighborhoods->GetPoints(), neighborhoods->GetValidMask(), neighborhoods->GetInputDataType());
  }
}

vtkIdType vtkFeaturePointDetector::FindSites(vtkPointCloudNeighborhoods* neighborhoods,
  const std::vector<vtkIdType>& ids, int width,
  const std::function<const int32_t*(vtkIdType, int32_t*, int)>& row, std::vector<vtkIdType>& site,
  double& tolerance) const
{
  site.clear();
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  if (this->IsDistributed() || rows < 2 || width < 1)
  {
    return 0;
  }
  vtkPoints* points = neighborhoods->GetPoints();
  const std::vector<vtkIdType>& copies = neighborhoods->GetExtraCopies();
  // The scale: the median distance to the 8th nearest, over one row per position (a stack of
  // copies is one row, however many copies it holds).
  const int eighth = std::min(width, 8) - 1;
  std::vector<double> reach(static_cast<size_t>(rows), -1.0);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    std::vector<int32_t> buffer(static_cast<size_t>(width));
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int32_t* neighbors = row(r, buffer.data(), width);
      if (neighbors[eighth] >= 0 && !std::binary_search(copies.begin(), copies.end(), ids[r]))
      {
        points->GetPoint(ids[r], x);
        points->GetPoint(neighbors[eighth], y);
        reach[r] = std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
      }
    }
  });
  reach.erase(std::remove(reach.begin(), reach.end(), -1.0), reach.end());
  if (reach.empty())
  {
    return 0;
  }
  tolerance = 0.01 * featurepoints::UpperMedian(reach);
  std::vector<double>().swap(reach);
  // The rows whose nearest lies within the tolerance (few, but for copies).
  const double tolerance2 = tolerance * tolerance;
  std::vector<unsigned char> close(static_cast<size_t>(rows), 0);
  vtkSMPTools::For(0, rows, [&](vtkIdType begin, vtkIdType end) {
    int32_t nearest[1];
    double x[3], y[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int32_t* neighbors = row(r, nearest, 1);
      if (neighbors[0] >= 0)
      {
        points->GetPoint(ids[r], x);
        points->GetPoint(neighbors[0], y);
        close[r] = vtkMath::Distance2BetweenPoints(x, y) <= tolerance2;
      }
    }
  });
  // Groups: union-find over the pairs of a row closer than the tolerance (or coincident), each
  // group's root its smallest point id, so that the groups do not depend on the order of the
  // pairs.
  const vtkIdType n = neighborhoods->GetNumberOfPoints();
  std::vector<vtkIdType> parent(static_cast<size_t>(n));
  std::iota(parent.begin(), parent.end(), vtkIdType(0));
  auto root = [&parent](vtkIdType i) {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  vtkIdType merged = 0;
  std::vector<int32_t> buffer(static_cast<size_t>(width));
  double x[3], y[3];
  for (vtkIdType r = 0; r < rows; ++r)
  {
    if (!close[r])
    {
      continue;
    }
    const int32_t* neighbors = row(r, buffer.data(), width);
    points->GetPoint(ids[r], x);
    for (int j = 0; j < width && neighbors[j] >= 0; ++j)
    {
      points->GetPoint(neighbors[j], y);
      if (!(vtkMath::Distance2BetweenPoints(x, y) <= tolerance2))
      {
        break; // nearest first
      }
      const vtkIdType a = root(ids[r]), b = root(neighbors[j]);
      if (a != b)
      {
        parent[std::max(a, b)] = std::min(a, b);
        ++merged;
      }
    }
  }
  if (merged == 0 || 100 * merged < rows)
  {
    return 0;
  }
  // Input ids: the method's numbering is the renumbered cloud's (OriginalIds) when renumbered.
  const bool renumbered = static_cast<vtkIdType>(this->OriginalIds.size()) == n;
  std::vector<vtkIdType> first(static_cast<size_t>(n), -1); // by root: the group's first input id
  for (vtkIdType id : ids)
  {
    const vtkIdType input = renumbered ? this->OriginalIds[id] : id;
    vtkIdType& f = first[root(id)];
    f = f < 0 ? input : std::min(f, input);
  }
  // Groups numbered in the order of their first input points.
  std::vector<vtkIdType> groupOf(static_cast<size_t>(n), -1); // by input id of a group's first
  for (vtkIdType id : ids)
  {
    if (root(id) == id)
    {
      groupOf[first[id]] = 0;
    }
  }
  vtkIdType groups = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (groupOf[i] == 0)
    {
      groupOf[i] = ++groups; // 1-based while marking
    }
  }
  site.assign(static_cast<size_t>(n), -1);
  for (vtkIdType id : ids)
  {
    const vtkIdType input = renumbered ? this->OriginalIds[id] : id;
    site[input] = groupOf[first[root(id)]] - 1;
  }
  return groups;
}

bool vtkFeaturePointDetector::SearchAllPoints(vtkPoints* points, vtkIdType n, int k,
  vtkPointCloudNeighborhoods* neighborhoods, std::vector<vtkIdType>& ids,
  std::vector<int32_t>& table, double progressEnd)
{
  if (!this->PrepareNeighborhoods(points, n, k, neighborhoods))
  {
    return false;
  }
  this->BeginStage("neighbours");
  ids = neighborhoods->GetValidIds();
  if (!neighborhoods->FindNearestNeighbors(k, ids, table, nullptr, this, 0.0, progressEnd))
  {
    return false;
  }
  const double d =
    this->GlobalMeanSpacing(neighborhoods, neighborhoods->ComputeMeanSpacing(ids, table, k));
  if (!this->CheckSpacing(d, neighborhoods))
  {
    return false;
  }
  this->NumberOfCandidates = this->GlobalSum(this->CountOwned(ids));
  this->BeginStage("scores");
  return !this->GetAbortExecute();
}

bool vtkFeaturePointDetector::SearchAllPoints(vtkPoints* points, vtkIdType n, int k,
  vtkPointCloudNeighborhoods* neighborhoods, std::vector<vtkIdType>& ids,
  const std::function<void(vtkIdType, vtkIdType, const int32_t*)>& consume, double progressEnd)
{
  if (!this->PrepareNeighborhoods(points, n, k, neighborhoods))
  {
    return false;
  }
  this->BeginStage("neighbours");
  ids = neighborhoods->GetValidIds();
  // Blocks of consecutive rows: ids are in the grid's cell order, so that each block is a
  // compact region and its batched query as fast as the whole table's. The nearest neighbour of
  // each row is kept for the mean spacing, which reads only that.
  constexpr vtkIdType Block = 16384;
  const vtkIdType rows = static_cast<vtkIdType>(ids.size());
  std::vector<int32_t> nearest(static_cast<size_t>(rows), -1), block;
  std::vector<vtkIdType> blockIds;
  for (vtkIdType first = 0; first < rows; first += Block)
  {
    const vtkIdType count = std::min(Block, rows - first);
    blockIds.assign(ids.begin() + first, ids.begin() + first + count);
    const double start = progressEnd * static_cast<double>(first) / static_cast<double>(rows);
    const double end = progressEnd * static_cast<double>(first + count) / static_cast<double>(rows);
    if (!neighborhoods->FindNearestNeighbors(k, blockIds, block, nullptr, this, start, end))
    {
      return false;
    }
    for (vtkIdType r = 0; r < count && k > 0; ++r)
    {
      nearest[first + r] = block[r * k];
    }
    consume(first, count, block.data());
  }
  const double d =
    this->GlobalMeanSpacing(neighborhoods, neighborhoods->ComputeMeanSpacing(ids, nearest, 1));
  if (!this->CheckSpacing(d, neighborhoods))
  {
    return false;
  }
  this->NumberOfCandidates = this->GlobalSum(this->CountOwned(ids));
  this->BeginStage("scores");
  return !this->GetAbortExecute();
}

void vtkFeaturePointDetector::ApplyThreshold(const float* score,
  const std::vector<vtkIdType>& ids, const std::vector<int>* weights,
  const unsigned char* eligible, unsigned char* mask)
{
  this->BeginStage("threshold");
  if (this->ThresholdMode == AUTOMATIC)
  {
    // The rule sees the own points' scores of every process: gathered on the first process (the
    // rule's medians depend on the values only, not on their order).
    std::vector<double> scores;
    std::vector<int> kept;
    scores.reserve(ids.size());
    for (size_t r = 0; r < ids.size(); ++r)
    {
      if (this->IsOwned(ids[r]))
      {
        scores.push_back(score[ids[r]]);
        if (weights)
        {
          kept.push_back((*weights)[r]);
        }
      }
    }
    if (this->IsDistributed())
    {
      this->GatherScores(scores, weights ? &kept : nullptr);
    }
    double threshold = 0.0;
    if (!this->IsDistributed() || this->Controller->GetLocalProcessId() == 0)
    {
      threshold = weights ? AutomaticThreshold(scores, kept, this->ThresholdSigmas)
                          : AutomaticThreshold(scores, this->ThresholdSigmas);
    }
    if (this->IsDistributed())
    {
      this->Controller->Broadcast(&threshold, 1, 0);
    }
    this->ThresholdUsed = threshold;
  }
  else
  {
    this->ThresholdUsed = this->Threshold;
  }
  vtkIdType features = 0;
  for (vtkIdType id : ids)
  {
    mask[id] = (!eligible || eligible[id]) && score[id] > this->ThresholdUsed ? 1 : 0;
    features += this->IsOwned(id) ? mask[id] : 0;
  }
  this->NumberOfFeaturePoints = this->GlobalSum(features);
}

vtkIdType vtkFeaturePointDetector::GatherLayout(const std::vector<long long>& counts,
  std::vector<vtkIdType>& lengths, std::vector<vtkIdType>& offsets)
{
  lengths.assign(counts.size(), 0);
  offsets.assign(counts.size(), 0);
  vtkIdType total = 0;
  for (size_t p = 0; p < counts.size(); ++p)
  {
    lengths[p] = static_cast<vtkIdType>(counts[p]);
    offsets[p] = total;
    total += lengths[p];
  }
  return total;
}

void vtkFeaturePointDetector::GatherScores(
  std::vector<double>& scores, std::vector<int>* weights) const
{
  const int nProcs = this->Controller->GetNumberOfProcesses();
  const int rank = this->Controller->GetLocalProcessId();
  long long count = static_cast<long long>(scores.size());
  std::vector<long long> counts(nProcs, 0);
  this->Controller->Gather(&count, counts.data(), 1, 0);
  std::vector<vtkIdType> lengths, offsets;
  const vtkIdType total = GatherLayout(counts, lengths, offsets);
  std::vector<double> all(rank == 0 ? std::max<vtkIdType>(total, 1) : 1);
  this->Controller->GatherV(scores.data(), all.data(), static_cast<vtkIdType>(scores.size()),
    lengths.data(), offsets.data(), 0);
  std::vector<int> allWeights(weights && rank == 0 ? std::max<vtkIdType>(total, 1) : 1);
  if (weights)
  {
    this->Controller->GatherV(weights->data(), allWeights.data(),
      static_cast<vtkIdType>(weights->size()), lengths.data(), offsets.data(), 0);
  }
  if (rank == 0)
  {
    all.resize(total);
    scores.swap(all);
    if (weights)
    {
      allWeights.resize(total);
      weights->swap(allWeights);
    }
  }
}

namespace
{
// The point arrays of `data` that hold one tuple per point (n), shallow copies, with the
// attributes' flags: an array of another length (a malformed input) is left out with a warning
// (from `reporter` when given), since copying it, or picking the feature points' tuples from it,
// would read past its end.
vtkSmartPointer<vtkPointData> PointArraysOfLength(
  vtkPointData* data, vtkIdType n, vtkObject* reporter = nullptr)
{
  auto kept = vtkSmartPointer<vtkPointData>::New();
  if (!data)
  {
    return kept;
  }
  kept->ShallowCopy(data);
  for (int a = kept->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = kept->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() != n)
    {
      std::ostringstream text;
      text << "The point array '" << (array->GetName() ? array->GetName() : "(no name)")
           << "' has " << array->GetNumberOfTuples() << " tuples for " << n
           << " points: left out of the output.";
      if (reporter)
      {
        vtkWarningWithObjectMacro(reporter, << text.str());
      }
      else
      {
        vtkGenericWarningMacro(<< text.str());
      }
      kept->RemoveArray(a);
    }
  }
  return kept;
}
} // namespace

int vtkFeaturePointDetector::AssembleOutput(vtkPointSet* input, vtkPolyData* output,
  const std::vector<vtkDataArray*>& arrays, vtkUnsignedCharArray* mask)
{
  this->BeginStage("output");
  const vtkIdType n = input->GetNumberOfPoints();
  if (static_cast<vtkIdType>(this->OriginalIds.size()) == n)
  {
    // Back to the input's order: tuple i of the renumbered cloud goes to OriginalIds[i].
    std::vector<vtkDataArray*> all(arrays);
    all.push_back(mask);
    std::vector<unsigned char> buffer;
    for (vtkDataArray* a : all)
    {
      if (!a || a->GetNumberOfTuples() != n)
      {
        continue;
      }
      const size_t bytes = static_cast<size_t>(a->GetDataTypeSize()) * a->GetNumberOfComponents();
      unsigned char* data = static_cast<unsigned char*>(a->GetVoidPointer(0));
      buffer.resize(bytes * static_cast<size_t>(n));
      const int32_t* original = this->OriginalIds.data();
      vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          std::memcpy(buffer.data() + bytes * original[i], data + bytes * i, bytes);
        }
      });
      std::memcpy(data, buffer.data(), buffer.size());
      a->Modified();
    }
  }
  this->OriginalIds.clear();
  this->PieceGlobalIds = nullptr; // read through OriginalIds
  vtkPoints* points = input->GetPoints();
  vtkNew<vtkPolyData> full;
  if (points)
  {
    full->SetPoints(points);
  }
  else
  {
    full->SetPoints(vtkNew<vtkPoints>());
  }
  full->GetPointData()->PassData(PointArraysOfLength(input->GetPointData(), n, this));
  for (vtkDataArray* a : arrays)
  {
    if (a)
    {
      full->GetPointData()->AddArray(a);
    }
  }
  full->GetPointData()->AddArray(mask);
  full->GetPointData()->SetActiveScalars(this->GetScoreArrayName());

  vtkNew<vtkDoubleArray> spacing;
  spacing->SetName("MeanSpacing");
  spacing->InsertNextValue(this->MeanSpacing);
  vtkNew<vtkDoubleArray> threshold;
  threshold->SetName("FeatureThreshold");
  threshold->InsertNextValue(this->ThresholdUsed);

  if (!this->OutputFeaturesOnly)
  {
    output->ShallowCopy(full);
    output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  }
  else
  {
    SelectFeaturePoints(full, mask, output);
  }
  output->GetFieldData()->AddArray(spacing);
  output->GetFieldData()->AddArray(threshold);
  this->BeginStage(nullptr);
  return 1;
}

void vtkFeaturePointDetector::SelectFeaturePoints(
  vtkPolyData* full, vtkUnsignedCharArray* mask, vtkPolyData* output)
{
  if (!full || !output)
  {
    vtkGenericWarningMacro("SelectFeaturePoints needs a cloud and an output: nothing selected.");
    return;
  }
  const vtkIdType n = full->GetNumberOfPoints();
  vtkPoints* points = full->GetPoints();
  if (mask && (mask->GetNumberOfTuples() != n || mask->GetNumberOfComponents() != 1))
  {
    vtkGenericWarningMacro(<< "SelectFeaturePoints: the mask has " << mask->GetNumberOfTuples()
                           << " tuples of " << mask->GetNumberOfComponents() << " values for "
                           << n << " points, not one value per point: nothing selected.");
    mask = nullptr;
  }
  const vtkSmartPointer<vtkPointData> data = PointArraysOfLength(full->GetPointData(), n);
  vtkIdType nf = 0;
  for (vtkIdType i = 0; mask && i < n; ++i)
  {
    nf += mask->GetValue(i) ? 1 : 0;
  }
  vtkNew<vtkPoints> kept;
  kept->SetDataType(points ? points->GetDataType() : VTK_FLOAT);
  kept->SetNumberOfPoints(nf);
  vtkNew<vtkIdTypeArray> original;
  original->SetName("vtkOriginalPointIds");
  original->SetNumberOfValues(nf);
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(data, nf);
  vtkIdType j = 0;
  for (vtkIdType i = 0; mask && i < n; ++i)
  {
    if (mask->GetValue(i))
    {
      kept->SetPoint(j, points->GetPoint(i));
      outPD->CopyData(data, i, j);
      original->SetValue(j, i);
      ++j;
    }
  }
  outPD->SetNumberOfTuples(nf);
  outPD->AddArray(original);
  if (vtkDataArray* scalars = data->GetScalars())
  {
    outPD->SetActiveScalars(scalars->GetName());
  }
  output->SetPoints(kept);
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(nf));
  output->GetFieldData()->ShallowCopy(full->GetFieldData());
}

void vtkFeaturePointDetector::BeginStage(const char* name)
{
  const auto now = std::chrono::steady_clock::now();
  if (this->StageRunning)
  {
    this->StageTimes.back() = std::chrono::duration<double>(now - this->StageStart).count();
  }
  this->StageRunning = name != nullptr;
  if (name)
  {
    this->StageNames.emplace_back(name);
    this->StageTimes.push_back(0.0);
    this->StageStart = now;
  }
}

void vtkFeaturePointDetector::MergeRepeatedStages()
{
  std::vector<std::string> names;
  std::vector<double> times;
  for (size_t i = 0; i < this->StageNames.size(); ++i)
  {
    const auto at = std::find(names.begin(), names.end(), this->StageNames[i]);
    if (at == names.end())
    {
      names.push_back(this->StageNames[i]);
      times.push_back(this->StageTimes[i]);
    }
    else
    {
      times[at - names.begin()] += this->StageTimes[i];
    }
  }
  this->StageNames.swap(names);
  this->StageTimes.swap(times);
}

void vtkFeaturePointDetector::WarnIfDegenerate(
  vtkPoints* points, const unsigned char* valid, int dataType)
{
  // Covariance of the whole cloud about its mean. The sums run in parallel over fixed blocks of
  // points and are combined in block order, so they do not depend on the thread count.
  const vtkIdType n = points->GetNumberOfPoints();
  constexpr vtkIdType Block = 65536;
  const vtkIdType nBlocks = (n + Block - 1) / Block;
  const featurepoints::PointReader reader(points);
  // A few far outliers (one point at 1e30 among 100,000) would make the covariance theirs: only
  // the points in the robust box count, the central 99 % of the points on each axis widened by
  // half its size, as in vtkPointCloudNeighborhoods' grid.
  double lo[3], hi[3];
  double magnitude = 0.0; // the largest coordinate of the central points, in absolute value
  {
    const vtkIdType stride = std::max<vtkIdType>(1, n / 100000);
    std::vector<double> sample;
    double x[3];
    for (int a = 0; a < 3; ++a)
    {
      sample.clear();
      for (vtkIdType i = 0; i < n; i += stride)
      {
        if (valid[i])
        {
          reader.Get(i, x);
          sample.push_back(x[a]);
        }
      }
      lo[a] = -VTK_DOUBLE_MAX;
      hi[a] = VTK_DOUBLE_MAX;
      if (sample.empty())
      {
        continue;
      }
      double rlo, rhi;
      featurepoints::CentralRange(sample, rlo, rhi);
      magnitude = std::max({ magnitude, std::abs(rlo), std::abs(rhi) });
      lo[a] = rlo - 0.5 * (rhi - rlo);
      hi[a] = rhi + 0.5 * (rhi - rlo);
    }
  }
  auto inBox = [&lo, &hi](const double x[3]) {
    return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] &&
      x[2] <= hi[2];
  };
  auto sumOverValid = [&](auto zero, auto term) {
    std::vector<decltype(zero)> sums(nBlocks, zero);
    vtkSMPTools::For(0, nBlocks, [&](vtkIdType first, vtkIdType last) {
      double x[3];
      for (vtkIdType blk = first; blk < last; ++blk)
      {
        for (vtkIdType i = blk * Block; i < std::min(n, (blk + 1) * Block); ++i)
        {
          if (valid[i])
          {
            reader.Get(i, x);
            if (inBox(x))
            {
              sums[blk] += term(Eigen::Vector3d(x[0], x[1], x[2]));
            }
          }
        }
      }
    });
    decltype(zero) total = zero;
    for (const auto& sum : sums)
    {
      total += sum;
    }
    return total;
  };
  // (x, y, z, 1): the coordinates' sum and the count.
  const Eigen::Vector4d sum = sumOverValid(Eigen::Vector4d(Eigen::Vector4d::Zero()),
    [](const Eigen::Vector3d& p) { return Eigen::Vector4d(p[0], p[1], p[2], 1.0); });
  const Eigen::Vector3d mean = sum.head<3>() / std::max(sum[3], 1.0);
  const Eigen::Matrix3d cov = sumOverValid(Eigen::Matrix3d(Eigen::Matrix3d::Zero()),
    [&mean](const Eigen::Vector3d& p) -> Eigen::Matrix3d {
      const Eigen::Vector3d v = p - mean;
      return v * v.transpose();
    });
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  const Eigen::Matrix3d axes = solver.eigenvectors(); // columns by ascending eigenvalue
  // The RMS distances from the principal line and from the principal plane, summed point by
  // point: a small eigenvalue of the covariance is lost in the rounding of a large one (two
  // surfaces 1e12 apart), a distance is not.
  // The spread across the principal line, as the covariance of the two coordinates across it
  // (its small eigenvalues come out right there, apart from the line's large one): its trace is
  // the squared distance from the line, its smallest eigenvalue the squared distance from the
  // principal plane.
  const Eigen::Vector3d across[2] = { axes.col(0), axes.col(1) };
  const Eigen::Matrix2d spread = sumOverValid(Eigen::Matrix2d(Eigen::Matrix2d::Zero()),
    [&mean, &across](const Eigen::Vector3d& p) -> Eigen::Matrix2d {
      const Eigen::Vector3d v = p - mean;
      const Eigen::Vector2d a(v.dot(across[0]), v.dot(across[1]));
      return a * a.transpose();
    });
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> flat(spread, Eigen::EigenvaluesOnly);
  const double count = std::max(sum[3], 1.0);
  const double fromLine = std::sqrt(std::max(spread.trace(), 0.0) / count);
  const double fromPlane = std::sqrt(std::max(flat.eigenvalues()[0], 0.0) / count);
  // Degenerate where those distances are below what the coordinates resolve (a few units in
  // their last place at the cloud's largest coordinate), not merely small beside the extent.
  const double unit = dataType == VTK_FLOAT ? std::numeric_limits<float>::epsilon()
                                            : std::numeric_limits<double>::epsilon();
  // And below the mean spacing: a cloud that the coordinates resolve no better than a few
  // units in their last place (a unit cube stored as float32 at 1e6, where the unit is 1/16;
  // outliers at FLT_MAX, which set the magnitude) is still a surface where its points spread
  // further across the line or the plane than from one point to the next; rounded points on a
  // line or a plane lie within half a unit of it, and a unit apart at least.
  const double resolved = std::min(16.0 * unit * magnitude, this->MeanSpacing);
  if (fromLine <= resolved)
  {
    vtkWarningMacro("All points lie on a straight line: surface normals are undefined there, so "
                    "the normals and scores are arbitrary and no feature point is meaningful.");
  }
  else if (fromPlane <= resolved)
  {
    vtkWarningMacro("All points lie on one plane: such a cloud has no crease, so any feature point "
                    "found is a boundary or sampling effect.");
  }
}

void vtkFeaturePointDetector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ThresholdMode: " << this->ThresholdMode << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "ThresholdSigmas: " << this->ThresholdSigmas << "\n";
  os << indent << "OutputFeaturesOnly: " << this->OutputFeaturesOnly << "\n";
  os << indent << "Locator: " << (this->Locator ? this->Locator->GetClassName() : "(none)") << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "HaloWidth: " << this->HaloWidth << "\n";
}
