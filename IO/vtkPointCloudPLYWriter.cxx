// STUB, to be replaced.
#include "vtkPointCloudPLYWriter.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
vtkStandardNewMacro(vtkPointCloudPLYWriter);
vtkPointCloudPLYWriter::vtkPointCloudPLYWriter() = default;
vtkPointCloudPLYWriter::~vtkPointCloudPLYWriter() { this->SetFileName(nullptr); }
vtkPointSet* vtkPointCloudPLYWriter::GetInput() { return vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0)); }
void vtkPointCloudPLYWriter::WriteData() {}
int vtkPointCloudPLYWriter::FillInputPortInformation(int, vtkInformation* info) { info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet"); return 1; }
void vtkPointCloudPLYWriter::PrintSelf(ostream& os, vtkIndent indent) { this->Superclass::PrintSelf(os, indent); }
