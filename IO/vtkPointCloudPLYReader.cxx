// STUB, to be replaced.
#include "vtkPointCloudPLYReader.h"
#include "vtkObjectFactory.h"
vtkStandardNewMacro(vtkPointCloudPLYReader);
vtkPointCloudPLYReader::vtkPointCloudPLYReader() { this->SetNumberOfInputPorts(0); }
vtkPointCloudPLYReader::~vtkPointCloudPLYReader() { this->SetFileName(nullptr); }
int vtkPointCloudPLYReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) { return 0; }
void vtkPointCloudPLYReader::PrintSelf(ostream& os, vtkIndent indent) { this->Superclass::PrintSelf(os, indent); }
