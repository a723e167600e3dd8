#include "vtkVoxelDensityContrastFilter.h"
#include "vtkFeaturePointsStatistics.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeaturePointsDensityContrast.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkVoxelDensityContrastFilter);

namespace
{
// The test with this filter's parameters; its warnings are the filter's.
featurepoints::DensityContrast MakeTest(vtkVoxelDensityContrastFilter* self)
{
  featurepoints::DensityContrast test;
  test.VoxelSizeFactor = self->GetVoxelSizeFactor();
  test.DensityContrast = self->GetDensityContrast();
  test.ContrastSigmas = self->GetContrastSigmas();
  test.MinimumContrastFraction = self->GetMinimumContrastFraction();
  test.ContrastRule = self->GetContrastRule();
  test.Reporter = self;
  return test;
}
} // namespace

vtkVoxelDensityContrastFilter::vtkVoxelDensityContrastFilter() = default;
vtkVoxelDensityContrastFilter::~vtkVoxelDensityContrastFilter() = default;

void vtkVoxelDensityContrastFilter::KeepFigures(const featurepoints::DensityContrast& test)
{
  this->VoxelSize = test.VoxelSize;
  this->NumberOfOccupiedVoxels = test.NumberOfOccupiedVoxels;
  this->NumberOfContrastVoxels = test.NumberOfContrastVoxels;
  this->NumberOfCandidates = test.NumberOfCandidates;
  this->NumberOfClampedPoints = test.NumberOfClampedPoints;
  this->ReferenceLevel = test.ReferenceLevel;
}

vtkIdType vtkVoxelDensityContrastFilter::MarkCandidates(vtkPoints* points,
  const unsigned char* valid, double spacing, const double* nearest, unsigned char* candidate,
  int32_t* voxelCount)
{
  featurepoints::DensityContrast test = MakeTest(this);
  test.MarkCandidates(points, valid, spacing, nearest, candidate, voxelCount);
  this->KeepFigures(test);
  return this->NumberOfCandidates;
}

bool vtkVoxelDensityContrastFilter::SampleShowsContrast(vtkPointCloudNeighborhoods* neighborhoods)
{
  featurepoints::DensityContrast test = MakeTest(this);
  const bool contrast = test.SampleShowsContrast(neighborhoods);
  this->KeepFigures(test);
  return contrast;
}

int vtkVoxelDensityContrastFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkVoxelDensityContrastFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  if (const char* nan = featurepoints::FirstNaN({ { "VoxelSizeFactor", this->VoxelSizeFactor },
        { "Spacing", this->Spacing }, { "DensityContrast", this->DensityContrast },
        { "ContrastSigmas", this->ContrastSigmas },
        { "MinimumContrastFraction", this->MinimumContrastFraction } }))
  {
    vtkErrorMacro(<< nan << " is NaN: give it a number. The output is empty.");
    output->Initialize();
    return 1;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkUnsignedCharArray> candidate;
  candidate->SetName("Candidate");
  candidate->SetNumberOfValues(n);
  vtkNew<vtkIntArray> counts;
  counts->SetName("VoxelPointCount");
  counts->SetNumberOfValues(n);
  std::fill_n(candidate->GetPointer(0), n, 0);
  std::fill_n(counts->GetPointer(0), n, 0);

  if (n > 0)
  {
    vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
    if (!neighborhoods->Build(input->GetPoints()))
    {
      vtkErrorMacro(<< "Cannot voxelize the input: " << neighborhoods->GetErrorText() << ".");
    }
    else
    {
      if (neighborhoods->GetFirstInvalidPoint() >= 0)
      {
        vtkWarningMacro(<< n - neighborhoods->GetNumberOfValidPoints()
                        << " point(s) have NaN or infinite coordinates (the first is point "
                        << neighborhoods->GetFirstInvalidPoint() << "); they are never candidates.");
      }
      const double mean = neighborhoods->ComputeMeanSpacing();
      const double d = this->Spacing > 0.0 ? this->Spacing : mean;
      if (d > 0.0 && std::isfinite(d))
      {
        this->MarkCandidates(input->GetPoints(), neighborhoods->GetValidMask(), d,
          neighborhoods->GetNearestDistances().data(), candidate->GetPointer(0),
          counts->GetPointer(0));
      }
      else
      {
        vtkWarningMacro(<< neighborhoods->DescribeZeroSpacing(d)
                        << ". No voxel grid can be built and no point is a candidate.");
      }
    }
  }

  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  output->GetPointData()->AddArray(candidate);
  output->GetPointData()->AddArray(counts);
  return 1;
}

void vtkVoxelDensityContrastFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VoxelSizeFactor: " << this->VoxelSizeFactor << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "DensityContrast: " << this->DensityContrast << "\n";
  os << indent << "ContrastSigmas: " << this->ContrastSigmas << "\n";
  os << indent << "ContrastRule: " << this->ContrastRule << "\n";
  os << indent << "MinimumContrastFraction: " << this->MinimumContrastFraction << "\n";
}

vtkIdType vtkVoxelDensityContrastFilter::MarkCandidates(vtkPoints* points,
  vtkUnsignedCharArray* valid, double spacing, vtkDoubleArray* nearest,
  vtkUnsignedCharArray* candidate, vtkIntArray* voxelCount)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (!candidate || (valid && valid->GetNumberOfValues() != n) ||
    (nearest && nearest->GetNumberOfValues() != n))
  {
    vtkErrorMacro(<< "MarkCandidates: valid and nearest need one value per point (" << n
                  << "), and candidate an array to fill");
    return -1;
  }
  candidate->SetNumberOfComponents(1);
  candidate->SetNumberOfValues(n);
  if (voxelCount)
  {
    voxelCount->SetNumberOfComponents(1);
    voxelCount->SetNumberOfValues(n);
  }
  return this->MarkCandidates(points, valid ? valid->GetPointer(0) : nullptr, spacing,
    nearest ? nearest->GetPointer(0) : nullptr, candidate->GetPointer(0),
    voxelCount ? voxelCount->GetPointer(0) : nullptr);
}
