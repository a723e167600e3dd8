/**
 * @class   vtkPointCloudWriter
 * @brief   Writes a point set to any file vtkPointCloudIO can write, choosing the format by the
 *          file's extension (or by Format), never leaving a partial file behind.
 *
 * The formats are vtkPointCloudIO's (GetWritableExtensions(): `.vtp` binary compressed XML,
 * `.vtk` binary legacy, `.ply` with every numeric point array as a vertex property, `.csv`); a
 * point set that is not polydata is written as polydata with one vertex cell per point where
 * the format has cells. The file is written to a temporary file in the target's folder and
 * renamed over the target only when the whole write succeeded (vtkPointCloudIO::Write()): an
 * error, a full disk or an interrupted program leaves the target as it was.
 *
 * Errors: one line that starts with the file name (vtkErrorMacro, also GetErrorMessage()), the
 * error code set (NoFileNameError, UnrecognizedFileTypeError for a format that cannot be written,
 * CannotOpenFileError for any other failure) and Write() returning 0.
 *
 * Python:
 * @code{.py}
 * from featurepoints import vtkPointCloudWriter
 * writer = vtkPointCloudWriter()
 * writer.SetFileName("features.ply")
 * writer.SetInputConnection(features.GetOutputPort())
 * if not writer.Write():
 *     raise RuntimeError(writer.GetErrorMessage())
 * @endcode
 *
 * @sa vtkPointCloudIO vtkPointCloudReader vtkPointCloudPLYWriter vtkPointCloudTextWriter
 */
#ifndef vtkPointCloudWriter_h
#define vtkPointCloudWriter_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For ErrorMessage

class vtkPointSet;

class FEATUREPOINTSIO_EXPORT vtkPointCloudWriter : public vtkWriter
{
public:
  static vtkPointCloudWriter* New();
  vtkTypeMacro(vtkPointCloudWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * The format as an extension without the dot ("vtp", "vtk", "ply", "csv"), whatever the file
   * name's extension. Default: none, the format of the file name's extension.
   */
  vtkSetStringMacro(Format);
  vtkGetStringMacro(Format);
  ///@}

  /** The writable extensions, as a list for messages (".vtp, .vtk, ..."). */
  static std::string GetWritableExtensions();

  /** The one-line message of the last error ("" after a successful write). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  /** The input, as a point set. */
  vtkPointSet* GetInput();

protected:
  vtkPointCloudWriter();
  ~vtkPointCloudWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char* Format = nullptr;
  std::string ErrorMessage;

private:
  vtkPointCloudWriter(const vtkPointCloudWriter&) = delete;
  void operator=(const vtkPointCloudWriter&) = delete;
};

#endif
