/**
 * @class   vtkPointCloudPLYWriter
 * @brief   Writes a point set to a PLY file: coordinates plus every point-data array as vertex
 *          properties, so that scores and masks travel with the points.
 *
 * VTK 9.1's vtkPLYWriter writes coordinates, normals, colours and texture coordinates only; this
 * writer writes every numeric point-data array, and vtkPointCloudPLYReader reads them back:
 *
 * - Points: `x`, `y`, `z` as float if the points are float, double otherwise.
 * - A 3-component array set as (or named) `Normals`: `nx`, `ny`, `nz`.
 * - An unsigned char array named `RGB` or `RGBA` (3 or 4 components): `red`, `green`, `blue`
 *   (`alpha`) as uchar.
 * - Any other 1-component array: one property named after the array (characters other than
 *   letters, digits, '_', '-' and '.' replaced by '_'), in the array's type: char, uchar, short,
 *   ushort, int, uint, float, double. 64-bit integer arrays (vtkIdTypeArray such as
 *   `vtkOriginalPointIds`) are written as int when every value fits, as double otherwise.
 * - A k-component array (k > 1): k properties `NAME_0` ... `NAME_<k-1>`.
 * - String and other non-numeric arrays are skipped with a warning.
 *
 * FileType VTK_BINARY (default) writes binary_little_endian; VTK_ASCII writes text with enough
 * digits that every value reads back exactly. No faces are written.
 *
 * On an I/O failure (cannot open, disk full) the writer reports an error naming the file and
 * sets its error code; it does not remove the partial file (vtkPointCloudIO writes to a
 * temporary file and renames it).
 *
 * @sa vtkPointCloudPLYReader vtkPointCloudIO vtkPLYWriter
 */
#ifndef vtkPointCloudPLYWriter_h
#define vtkPointCloudPLYWriter_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For ErrorMessage

class vtkPointSet;

class FEATUREPOINTSIO_EXPORT vtkPointCloudPLYWriter : public vtkWriter
{
public:
  static vtkPointCloudPLYWriter* New();
  vtkTypeMacro(vtkPointCloudPLYWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** VTK_BINARY (default, binary_little_endian) or VTK_ASCII. */
  vtkSetClampMacro(FileType, int, VTK_ASCII, VTK_BINARY);
  vtkGetMacro(FileType, int);
  void SetFileTypeToASCII() { this->SetFileType(VTK_ASCII); }
  void SetFileTypeToBinary() { this->SetFileType(VTK_BINARY); }
  ///@}

  /** The message of the last error ("" after a successful write). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  vtkPointSet* GetInput();

protected:
  vtkPointCloudPLYWriter();
  ~vtkPointCloudPLYWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  int FileType = VTK_BINARY;
  std::string ErrorMessage;

private:
  vtkPointCloudPLYWriter(const vtkPointCloudPLYWriter&) = delete;
  void operator=(const vtkPointCloudPLYWriter&) = delete;
};

#endif
