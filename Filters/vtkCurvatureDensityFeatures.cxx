#include "vtkCurvatureDensityFeatures.h"

#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFeaturePointsStatistics.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkCurvatureDensityFeatures);

namespace
{
} // namespace

double vtkCurvatureDensityFeatures::MedianOf(const float* values, const std::vector<vtkIdType>& ids)
{
  // Over the own points of every process in a distributed run (the float values, widened to
  // double, keep their order and so their upper median).
  std::vector<double> v;
  v.reserve(ids.size());
  for (vtkIdType id : ids)
  {
    if (this->IsOwned(id))
    {
      v.push_back(values[id]);
    }
  }
  return this->GlobalUpperMedian(v);
}

vtkCurvatureDensityFeatures::vtkCurvatureDensityFeatures()
{
  this->Threshold = 2.0;
}

vtkCurvatureDensityFeatures::~vtkCurvatureDensityFeatures() = default;

int vtkCurvatureDensityFeatures::GetLengthPower(const char* name) const
{
  return std::strcmp(name, "Density") == 0 ? -1 : 0;
}

int vtkCurvatureDensityFeatures::Run(vtkPointSet* input, vtkPolyData* output)
{
  const vtkIdType n = input->GetNumberOfPoints();
  using featurepoints::NewZeroArray;
  auto normals = NewZeroArray<vtkFloatArray>("Normals", 3, n);
  auto curvature = NewZeroArray<vtkFloatArray>("Curvature", 1, n);
  auto angle = NewZeroArray<vtkFloatArray>("NormalAngle", 1, n);
  auto density = NewZeroArray<vtkFloatArray>("Density", 1, n);
  auto score = NewZeroArray<vtkFloatArray>("CurvatureDensity", 1, n);
  auto mask = NewZeroArray<vtkUnsignedCharArray>("FeatureMask", 1, n);
  auto finish = [&]() {
    return this->AssembleOutput(
      input, output, { normals, curvature, angle, density, score }, mask);
  };

  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  std::vector<vtkIdType> ids;
  std::vector<int32_t> table;
  const int k = this->NumberOfNeighbors;
  if (!this->SearchAllPoints(input->GetPoints(), n, k, neighborhoods, ids, table, 0.6))
  {
    return finish();
  }
  // Pass 1: normal, curvature and density of each point.
  featurepoints::LocalShapeWorker worker{ neighborhoods->GetPoints(), ids, table.data(), k,
    this->CloudCenter(neighborhoods), normals->GetPointer(0), curvature->GetPointer(0),
    density->GetPointer(0), {} };
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), worker);
  this->UpdateProgress(0.8);

  // Pass 2: the mean angle between the point's normal and its neighbours' normals.
  const float* nrm = normals->GetPointer(0);
  float* theta = angle->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType r = begin; r < end; ++r)
    {
      const vtkIdType id = ids[r];
      const int32_t* row = table.data() + r * k;
      const int count = featurepoints::RowLength(row, k);
      double sum = 0.0;
      for (int j = 0; j < count; ++j)
      {
        const float* a = nrm + 3 * id;
        const float* b = nrm + 3 * static_cast<vtkIdType>(row[j]);
        const double c = std::abs(double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2]);
        sum += std::acos(std::min(1.0, c));
      }
      theta[id] = count > 0 ? static_cast<float>(sum / count) : 0.0f;
    }
  });

  // The score: each indicator over its median (a zero median leaves its term out).
  const double medC = this->MedianOf(curvature->GetPointer(0), ids);
  const double medT = this->MedianOf(theta, ids);
  const double medD = this->MedianOf(density->GetPointer(0), ids);
  const double wc = medC > 0.0 ? this->CurvatureWeight / medC : 0.0;
  const double wt = medT > 0.0 ? this->NormalAngleWeight / medT : 0.0;
  const double wd = medD > 0.0 ? this->DensityWeight / medD : 0.0;
  const double total = this->CurvatureWeight + this->NormalAngleWeight + this->DensityWeight;
  const double norm = total > 0.0 ? 1.0 / total : 0.0;
  const float* c = curvature->GetPointer(0);
  const float* d = density->GetPointer(0);
  float* s = score->GetPointer(0);
  for (vtkIdType id : ids)
  {
    s[id] = static_cast<float>(norm * (wc * c[id] + wt * theta[id] + wd * d[id]));
  }
  this->ApplyThreshold(s, ids, nullptr, nullptr, mask->GetPointer(0));
  this->UpdateProgress(1.0);
  return finish();
}

void vtkCurvatureDensityFeatures::ListParameters(std::vector<std::pair<const char*, double>>& parameters) const
{
  this->Superclass::ListParameters(parameters);
  parameters.emplace_back("CurvatureWeight", this->CurvatureWeight);
  parameters.emplace_back("NormalAngleWeight", this->NormalAngleWeight);
  parameters.emplace_back("DensityWeight", this->DensityWeight);
}

void vtkCurvatureDensityFeatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "CurvatureWeight: " << this->CurvatureWeight << "\n";
  os << indent << "NormalAngleWeight: " << this->NormalAngleWeight << "\n";
  os << indent << "DensityWeight: " << this->DensityWeight << "\n";
}
