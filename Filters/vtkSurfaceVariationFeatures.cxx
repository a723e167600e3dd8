#include "vtkSurfaceVariationFeatures.h"

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

#include <vector>

vtkStandardNewMacro(vtkSurfaceVariationFeatures);

namespace
{
struct SurfaceVariationWorker
{
  vtkPoints* Points;
  const std::vector<vtkIdType>& Ids;
  const int32_t* Table;
  int K;
  const double* Center;
  float* Normals;
  float* Variation;
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
      const int n = featurepoints::RowLength(row, this->K);
      featurepoints::GatherRelative(this->Points, id, row, n, q.data(), x);
      const double outward[3] = { x[0] - this->Center[0], x[1] - this->Center[1],
        x[2] - this->Center[2] };
      featurepoints::LocalPCA(q.data(), n, true, outward, lambda, normal);
      const double sum = lambda[0] + lambda[1] + lambda[2];
      this->Variation[id] = sum > 0.0 ? static_cast<float>(lambda[0] / sum) : 0.0f;
      for (int c = 0; c < 3; ++c)
      {
        this->Normals[3 * id + c] = static_cast<float>(normal[c]);
      }
    }
  }

  void Reduce() {}
};
} // namespace

vtkSurfaceVariationFeatures::vtkSurfaceVariationFeatures()
{
  this->Threshold = 0.05;
}

vtkSurfaceVariationFeatures::~vtkSurfaceVariationFeatures() = default;

int vtkSurfaceVariationFeatures::RequestData(
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
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  normals->Fill(0.0);
  vtkNew<vtkFloatArray> variation;
  variation->SetName("SurfaceVariation");
  variation->SetNumberOfValues(n);
  variation->Fill(0.0);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("FeatureMask");
  mask->SetNumberOfValues(n);
  mask->Fill(0);

  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  std::vector<vtkIdType> ids;
  std::vector<int32_t> table;
  if (this->SearchAllPoints(
        input->GetPoints(), n, this->NumberOfNeighbors, neighborhoods, ids, table, 0.7))
  {
    SurfaceVariationWorker worker{ input->GetPoints(), ids, table.data(), this->NumberOfNeighbors,
      neighborhoods->GetCenter(), normals->GetPointer(0), variation->GetPointer(0), {} };
    vtkSMPTools::For(0, static_cast<vtkIdType>(ids.size()), worker);
    this->ApplyThreshold(variation->GetPointer(0), ids, nullptr, nullptr, mask->GetPointer(0));
    this->UpdateProgress(1.0);
  }
  return this->AssembleOutput(input, output, { normals, variation }, mask);
}

void vtkSurfaceVariationFeatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
}
