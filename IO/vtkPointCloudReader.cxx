#include "vtkPointCloudReader.h"

#include "vtkCallbackCommand.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudIO.h"
#include "vtkPolyData.h"

#include <sys/stat.h>

vtkStandardNewMacro(vtkPointCloudReader);

namespace
{
// The inner reader's ProgressEvent, passed on as this reader's progress.
void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<vtkPointCloudReader*>(clientData)->UpdateProgress(*static_cast<double*>(callData));
}
} // namespace

vtkPointCloudReader::vtkPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudReader::~vtkPointCloudReader()
{
  this->SetFileName(nullptr);
}

int vtkPointCloudReader::CanReadFile(const char* fileName)
{
  return fileName && vtkPointCloudIO::CanRead(vtkPointCloudIO::GetExtension(fileName)) ? 1 : 0;
}

std::string vtkPointCloudReader::GetReadableExtensions()
{
  return vtkPointCloudIO::GetReadableExtensions();
}

int vtkPointCloudReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->ErrorMessage.clear();
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    this->ErrorMessage = "vtkPointCloudReader: no file name given";
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
  }
  else
  {
    vtkNew<vtkCallbackCommand> progress;
    progress->SetCallback(ForwardProgress);
    progress->SetClientData(this);
    if (vtkPointCloudIO::ReadPolyData(this->FileName, output, this->ErrorMessage, progress))
    {
      return 1;
    }
    struct stat info;
    this->SetErrorCode(::stat(this->FileName, &info) != 0 ? vtkErrorCode::FileNotFoundError
        : !this->CanReadFile(this->FileName)             ? vtkErrorCode::UnrecognizedFileTypeError
                                                         : vtkErrorCode::FileFormatError);
  }
  // Once, as one line: the request succeeds, so that the executive adds no report of its own.
  vtkErrorMacro(<< this->ErrorMessage);
  output->Initialize();
  return 1;
}

void vtkPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
