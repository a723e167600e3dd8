/**
 * @class   vtkPointCloudReader
 * @brief   Reads a point cloud from any file vtkPointCloudIO can read, choosing the format by the
 *          file's extension: one reader for a pipeline, for Python and for ParaView.
 *
 * The output is polydata: the file's points and every point array it holds (scores, normals,
 * colours, labels), its cells when the file holds polydata with cells, one vertex cell per point
 * otherwise.
 * The formats are vtkPointCloudIO's (GetReadableExtensions(); `.ply`, `.vtp`, `.vtu`, `.vtk`,
 * `.pts`, `.xyz`, `.txt`, `.csv` and whatever is added there), read with the same readers and
 * the same guards: VTK's own readers run in a child process under a time and memory limit
 * (vtkPointCloudIO::SetReaderTimeLimit()).
 *
 * Errors: a missing, unreadable, empty or malformed file, an unknown extension. The reader
 * reports one line that starts with the file name (vtkErrorMacro, also GetErrorMessage()), sets
 * its error code (FileNotFoundError, UnrecognizedFileTypeError, NoFileNameError or
 * FileFormatError) and leaves the output empty, never a partial cloud; the request itself still
 * succeeds, so that this line is the only message (no pipeline dump after it). The inner
 * reader's progress is this reader's ProgressEvent.
 *
 * Python:
 * @code{.py}
 * from featurepoints import vtkPointCloudReader
 * reader = vtkPointCloudReader()
 * reader.SetFileName("cloud.xyz")
 * reader.Update()
 * if reader.GetErrorCode():
 *     raise RuntimeError(reader.GetErrorMessage())
 * @endcode
 *
 * @sa vtkPointCloudIO vtkPointCloudWriter vtkPointCloudPLYReader vtkPointCloudTextReader
 */
#ifndef vtkPointCloudReader_h
#define vtkPointCloudReader_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For ErrorMessage

class FEATUREPOINTSIO_EXPORT vtkPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudReader* New();
  vtkTypeMacro(vtkPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read; its extension (any case) picks the format. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /**
   * 1 when the file's extension is one this reader reads (the file itself is not opened), else 0:
   * what ParaView's reader factory asks.
   */
  virtual int CanReadFile(VTK_FILEPATH const char* fileName);

  /** The readable extensions, as a list for messages (".ply, .vtp, ..."). */
  static std::string GetReadableExtensions();

  /** The one-line message of the last error ("" after a successful read). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

protected:
  vtkPointCloudReader();
  ~vtkPointCloudReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  std::string ErrorMessage;

private:
  vtkPointCloudReader(const vtkPointCloudReader&) = delete;
  void operator=(const vtkPointCloudReader&) = delete;
};

#endif
