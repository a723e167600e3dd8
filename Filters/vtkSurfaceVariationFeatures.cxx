#include "vtkSurfaceVariationFeatures.h"

#include "vtkFeaturePointsLocalPCA.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

vtkStandardNewMacro(vtkSurfaceVariationFeatures);


vtkSurfaceVariationFeatures::vtkSurfaceVariationFeatures()
{
  this->Threshold = 0.05;
}

vtkSurfaceVariationFeatures::~vtkSurfaceVariationFeatures() = default;

int vtkSurfaceVariationFeatures::Run(vtkPointSet* input, vtkPolyData* output)
{
  const vtkIdType n = input->GetNumberOfPoints();
  auto normals = featurepoints::NewZeroArray<vtkFloatArray>("Normals", 3, n);
  auto variation = featurepoints::NewZeroArray<vtkFloatArray>("SurfaceVariation", 1, n);
  auto mask = featurepoints::NewZeroArray<vtkUnsignedCharArray>("FeatureMask", 1, n);

  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  std::vector<vtkIdType> ids;
  std::vector<int32_t> table;
  if (this->SearchAllPoints(
        input->GetPoints(), n, this->NumberOfNeighbors, neighborhoods, ids, table, 0.7))
  {
    featurepoints::LocalShapeWorker worker{ neighborhoods->GetPoints(), ids, table.data(),
      this->NumberOfNeighbors, this->CloudCenter(neighborhoods), normals->GetPointer(0),
      variation->GetPointer(0), nullptr, {} };
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
