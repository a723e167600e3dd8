/**
 * @class   vtkPointCloudTextWriter
 * @brief   Writes a point set as CSV: one line per point, x, y, z, then every numeric point-data
 *          array, under a header line.
 *
 * The header names the columns `x,y,z`, then each 1-component array by its name and each
 * k-component array as `NAME:0` ... `NAME:<k-1>` (vtkDelimitedTextWriter's convention), which
 * vtkPointCloudTextReader groups back into one array. Characters of a name that would break the
 * line (the delimiter, quotes, line breaks) are replaced by '_'.
 *
 * Values are written in the shortest form that reads back to the same float or double
 * (std::to_chars), integers as integers. String and other non-numeric arrays are skipped with a
 * warning.
 *
 * On an I/O failure (cannot open, disk full) the writer reports an error naming the file and sets
 * its error code; it does not remove the partial file (vtkPointCloudIO writes to a temporary
 * file and renames it).
 *
 * vtkDelimitedTextWriter writes a vtkTable, not the points; going through vtkTable would copy
 * the cloud and its arrays once more.
 *
 * @sa vtkPointCloudTextReader vtkPointCloudIO vtkDelimitedTextWriter
 */
#ifndef vtkPointCloudTextWriter_h
#define vtkPointCloudTextWriter_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For ErrorMessage

class vtkPointSet;

class FEATUREPOINTSIO_EXPORT vtkPointCloudTextWriter : public vtkWriter
{
public:
  static vtkPointCloudTextWriter* New();
  vtkTypeMacro(vtkPointCloudTextWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** The field delimiter. Default ','. */
  vtkSetMacro(Delimiter, char);
  vtkGetMacro(Delimiter, char);
  ///@}

  /** The message of the last error ("" after a successful write). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  vtkPointSet* GetInput();

protected:
  vtkPointCloudTextWriter();
  ~vtkPointCloudTextWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char Delimiter = ',';
  std::string ErrorMessage;

private:
  vtkPointCloudTextWriter(const vtkPointCloudTextWriter&) = delete;
  void operator=(const vtkPointCloudTextWriter&) = delete;
};

#endif
