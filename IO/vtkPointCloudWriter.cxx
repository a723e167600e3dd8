#include "vtkPointCloudWriter.h"

#include "vtkCallbackCommand.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudIO.h"
#include "vtkPointSet.h"

vtkStandardNewMacro(vtkPointCloudWriter);

namespace
{
// The inner writer's ProgressEvent, passed on as this writer's progress.
void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<vtkPointCloudWriter*>(clientData)->UpdateProgress(*static_cast<double*>(callData));
}
} // namespace

vtkPointCloudWriter::vtkPointCloudWriter() = default;

vtkPointCloudWriter::~vtkPointCloudWriter()
{
  this->SetFileName(nullptr);
  this->SetFormat(nullptr);
}

std::string vtkPointCloudWriter::GetWritableExtensions()
{
  return vtkPointCloudIO::GetWritableExtensions();
}

vtkPointSet* vtkPointCloudWriter::GetInput()
{
  return vtkPointSet::SafeDownCast(this->Superclass::GetInput());
}

int vtkPointCloudWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkPointCloudWriter::WriteData()
{
  this->ErrorMessage.clear();
  this->SetErrorCode(vtkErrorCode::NoError);
  const std::string format = this->Format ? this->Format : "";
  if (!this->FileName || !*this->FileName)
  {
    this->ErrorMessage = "vtkPointCloudWriter: no file name given";
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
  }
  else
  {
    vtkNew<vtkCallbackCommand> progress;
    progress->SetCallback(ForwardProgress);
    progress->SetClientData(this);
    if (vtkPointCloudIO::Write(this->GetInput(), this->FileName, this->ErrorMessage, format, progress))
    {
      return;
    }
    const std::string extension =
      format.empty() ? vtkPointCloudIO::GetExtension(this->FileName) : format;
    this->SetErrorCode(vtkPointCloudIO::CanWrite(extension) ? vtkErrorCode::CannotOpenFileError
                                                            : vtkErrorCode::UnrecognizedFileTypeError);
  }
  vtkErrorMacro(<< this->ErrorMessage);
}

void vtkPointCloudWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Format: " << (this->Format ? this->Format : "(from the file name)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
