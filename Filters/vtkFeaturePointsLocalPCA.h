// Private header of FeaturePoints::Filters (not installed): the principal component analysis of
// one point's neighbourhood, shared by the proposed method (Eq. 3's normal) and the baselines
// (PCA surface variation, Wang & Yuan's curvature), so that every method sees the same normals.
#ifndef vtkFeaturePointsLocalPCA_h
#define vtkFeaturePointsLocalPCA_h

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cstdint>

namespace featurepoints
{
// Number of filled entries at the head of a neighbour row (rows are padded with -1).
inline int RowLength(const int32_t* row, int k)
{
  int n = 0;
  while (n < k && row[n] >= 0)
  {
    ++n;
  }
  return n;
}

/**
 * Whether point x falls in a sampled region: space is cut into cubes of side `side` from `origin`,
 * and one cube in `modulus` is sampled, chosen by a hash of its grid coordinates. The choice
 * depends on where the point is, not on the order of the points, and not on scale or offset when
 * origin and side follow the cloud. The voxel screen and the threshold's background sample use it.
 */
inline bool InSampledRegion(const double x[3], const double origin[3], double side, uint64_t modulus)
{
  uint64_t key = 0;
  for (int c = 0; c < 3; ++c)
  {
    // Clamped before the conversion: a far outlier stretches the box (then all points share a few
    // regions and the sample is all or nothing, which is slower, not wrong).
    const double r = std::min(std::floor((x[c] - origin[c]) / side), double((1 << 21) - 1));
    key = key * 0x100000001b3ULL + static_cast<uint64_t>(static_cast<int64_t>(r));
  }
  key ^= key >> 33;
  key *= 0xff51afd7ed558ccdULL;
  key ^= key >> 33;
  key *= 0xc4ceb9fe1a85ec53ULL;
  key ^= key >> 33;
  return key % modulus == 0;
}

/**
 * Reads point coordinates straight from the memory of float or double points (the two types
 * vtkPoints is used with), through vtkPoints::GetPoint for any other type: the per-neighbour
 * reads of the scoring loops are then not virtual calls.
 */
class PointReader
{
public:
  explicit PointReader(vtkPoints* points)
    : Points(points)
  {
    vtkDataArray* data = points ? points->GetData() : nullptr;
    if (auto* d = vtkDoubleArray::FastDownCast(data))
    {
      this->Doubles = d->GetPointer(0);
    }
    else if (auto* f = vtkFloatArray::FastDownCast(data))
    {
      this->Floats = f->GetPointer(0);
    }
  }

  void Get(vtkIdType id, double x[3]) const
  {
    if (this->Doubles)
    {
      const double* p = this->Doubles + 3 * id;
      x[0] = p[0];
      x[1] = p[1];
      x[2] = p[2];
    }
    else if (this->Floats)
    {
      const float* p = this->Floats + 3 * id;
      x[0] = p[0];
      x[1] = p[1];
      x[2] = p[2];
    }
    else
    {
      this->Points->GetPoint(id, x);
    }
  }

private:
  vtkPoints* Points;
  const double* Doubles = nullptr;
  const float* Floats = nullptr;
};

/**
 * Coordinates of the first `count` points of `row` relative to point `id` (written to `x`), into
 * `q` (x y z per point): working relative to the point costs no precision far from the origin.
 */
inline void GatherRelative(
  const PointReader& points, vtkIdType id, const int32_t* row, int count, double* q, double x[3])
{
  double y[3];
  points.Get(id, x);
  for (int j = 0; j < count; ++j)
  {
    points.Get(row[j], y);
    q[3 * j] = y[0] - x[0];
    q[3 * j + 1] = y[1] - x[1];
    q[3 * j + 2] = y[2] - x[2];
  }
}

inline void GatherRelative(
  vtkPoints* points, vtkIdType id, const int32_t* row, int count, double* q, double x[3])
{
  GatherRelative(PointReader(points), id, row, count, q, x);
}

// The sum of the outer products v v^T of the vectors added: the upper triangle summed in the
// order they come, then mirrored. v_i v_j and v_j v_i are the same product, so this is
// `m += v * v.transpose()` entry for entry, bit for bit, without the partial stores and loads
// through memory that Eigen's expression compiles to (perf put about half of the outlier
// screen's plane-fit samples on two of them; the stage ran about 10 % faster without).
struct OuterSum
{
  double C[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }; // xx xy xz yy yz zz
  void Add(double x, double y, double z)
  {
    this->C[0] += x * x;
    this->C[1] += x * y;
    this->C[2] += x * z;
    this->C[3] += y * y;
    this->C[4] += y * z;
    this->C[5] += z * z;
  }
  void Add(const Eigen::Vector3d& v) { this->Add(v[0], v[1], v[2]); }
  Eigen::Matrix3d Matrix() const
  {
    Eigen::Matrix3d m;
    m << this->C[0], this->C[1], this->C[2], this->C[1], this->C[3], this->C[4], this->C[2],
      this->C[4], this->C[5];
    return m;
  }
};

/**
 * Covariance of the first `count` points of `q` (coordinates relative to the query point, x y z
 * per point), plus the query point itself (the origin) when `withOrigin`, about their mean;
 * its eigenvalues, ascending, in `lambda` and the unit eigenvector of the smallest, turned to
 * point along `outward`, in `normal`. Returns false (normal 0, lambda 0) when fewer than 3 points
 * or a degenerate matrix leave the normal undefined.
 */
inline bool LocalPCA(const double* q, int count, bool withOrigin, const double outward[3],
  double lambda[3], double normal[3])
{
  lambda[0] = lambda[1] = lambda[2] = 0.0;
  normal[0] = normal[1] = normal[2] = 0.0;
  const int m = count + (withOrigin ? 1 : 0);
  if (m < 3)
  {
    return false;
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j = 0; j < count; ++j)
  {
    mean += Eigen::Vector3d(q[3 * j], q[3 * j + 1], q[3 * j + 2]);
  }
  mean /= m;
  OuterSum c;
  for (int j = 0; j < count; ++j)
  {
    c.Add(q[3 * j] - mean[0], q[3 * j + 1] - mean[1], q[3 * j + 2] - mean[2]);
  }
  if (withOrigin)
  {
    c.Add(mean[0], mean[1], mean[2]);
  }
  const Eigen::Matrix3d cov = c.Matrix();
  if (!cov.allFinite())
  {
    return false;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov / m);
  Eigen::Vector3d n = solver.eigenvectors().col(0);
  if (!n.allFinite() || n.squaredNorm() == 0.0)
  {
    return false;
  }
  n.normalize();
  if (n.dot(Eigen::Vector3d(outward[0], outward[1], outward[2])) < 0.0)
  {
    n = -n;
  }
  const Eigen::Vector3d ev = solver.eigenvalues();
  for (int c = 0; c < 3; ++c)
  {
    lambda[c] = std::max(ev[c], 0.0);
    normal[c] = n[c];
  }
  return true;
}
/** A named array of n tuples, filled with 0: how every detector starts its output arrays. */
template <typename ArrayT>
vtkSmartPointer<ArrayT> NewZeroArray(const char* name, int components, vtkIdType n)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n);
  a->Fill(0);
  return a;
}

/**
 * vtkSMPTools functor: for each point of `Ids` (row r of `Table`, K entries), the PCA of the point
 * and its neighbours: the normal (turned away from `Center`), the surface variation
 * lambda0 / (lambda0 + lambda1 + lambda2), and, when `Density` is set, 1 / (mean distance to the
 * neighbours). Shared by the baselines that use these quantities.
 */
struct LocalShapeWorker
{
  vtkPoints* Points;
  const std::vector<vtkIdType>& Ids;
  const int32_t* Table;
  int K;
  const double* Center;
  float* Normals;
  float* Variation;
  float* Density; // may be null
  vtkSMPThreadLocal<std::vector<double>> Scratch;

  void Initialize() { this->Scratch.Local().resize(3 * static_cast<size_t>(this->K)); }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    std::vector<double>& q = this->Scratch.Local();
    double x[3], lambda[3], normal[3];
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = this->Ids[r];
      const int32_t* row = this->Table + r * this->K;
      const int n = RowLength(row, this->K);
      GatherRelative(this->Points, id, row, n, q.data(), x);
      const double outward[3] = { x[0] - this->Center[0], x[1] - this->Center[1],
        x[2] - this->Center[2] };
      LocalPCA(q.data(), n, true, outward, lambda, normal);
      const double sum = lambda[0] + lambda[1] + lambda[2];
      this->Variation[id] = sum > 0.0 ? static_cast<float>(lambda[0] / sum) : 0.0f;
      for (int c = 0; c < 3; ++c)
      {
        this->Normals[3 * id + c] = static_cast<float>(normal[c]);
      }
      if (this->Density)
      {
        double distance = 0.0;
        for (int j = 0; j < n; ++j)
        {
          distance += std::sqrt(
            q[3 * j] * q[3 * j] + q[3 * j + 1] * q[3 * j + 1] + q[3 * j + 2] * q[3 * j + 2]);
        }
        // Coincident neighbours only: 0 rather than an infinite density.
        this->Density[id] = distance > 0.0 ? static_cast<float>(n / distance) : 0.0f;
      }
    }
  }

  void Reduce() {}
};
} // namespace featurepoints

#endif
