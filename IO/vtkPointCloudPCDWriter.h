/**
 * @class   vtkPointCloudPCDWriter
 * @brief   Writes a point set to a PCD file (the Point Cloud Library's format, version 0.7):
 *          coordinates plus every numeric point-data array as fields.
 *
 * - Points: fields `x`, `y`, `z` of type F 4 if the points are float, F 8 otherwise.
 * - A 3-component array set as (or named) `Normals`: `normal_x`, `normal_y`, `normal_z`.
 * - An unsigned char array named `RGB` (3 components): PCL's `rgb` field, the colour packed into
 *   the bits of an F 4 value as 0x00RRGGBB; `RGBA` (4 components): `rgba`, U 4, 0xAARRGGBB.
 * - Any other array: one field named after the array (characters other than letters, digits,
 *   '_', '-' and '.' replaced by '_'), with COUNT its number of components, of the array's type:
 *   I 1/2/4/8 (signed char, char, short, int, long long, vtkIdType), U 1/2/4/8 (unsigned types),
 *   F 4/8 (float, double). A name taken by another field gets a suffix `_2`, `_3`, ...
 * - String and other non-numeric arrays are skipped with a warning.
 *
 * The cloud is written unorganized (WIDTH the number of points, HEIGHT 1). DataFormat BINARY
 * (default) writes `DATA binary` (little-endian), ASCII `DATA ascii` with enough digits that
 * every value reads back exactly (the packed colours as the integers of their bits, as PCL writes
 * them), BINARY_COMPRESSED `DATA binary_compressed` (LZF, at most 4 GiB uncompressed).
 *
 * On an I/O failure (cannot open, disk full) the writer reports an error naming the file and
 * sets its error code; it does not remove the partial file (vtkPointCloudIO writes to a
 * temporary file and renames it).
 *
 * @sa vtkPointCloudPCDReader vtkPointCloudIO vtkPointCloudPLYWriter
 */
#ifndef vtkPointCloudPCDWriter_h
#define vtkPointCloudPCDWriter_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkWriter.h"

#include <string> // For ErrorMessage

class vtkPointSet;

class FEATUREPOINTSIO_EXPORT vtkPointCloudPCDWriter : public vtkWriter
{
public:
  static vtkPointCloudPCDWriter* New();
  vtkTypeMacro(vtkPointCloudPCDWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DataFormats
  {
    ASCII = 0,
    BINARY = 1,
    BINARY_COMPRESSED = 2
  };

  ///@{
  /** The file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** How the points are stored: ASCII, BINARY (default) or BINARY_COMPRESSED. */
  vtkSetClampMacro(DataFormat, int, ASCII, BINARY_COMPRESSED);
  vtkGetMacro(DataFormat, int);
  void SetDataFormatToASCII() { this->SetDataFormat(ASCII); }
  void SetDataFormatToBinary() { this->SetDataFormat(BINARY); }
  void SetDataFormatToBinaryCompressed() { this->SetDataFormat(BINARY_COMPRESSED); }
  ///@}

  /** The message of the last error ("" after a successful write). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

  vtkPointSet* GetInput();

protected:
  vtkPointCloudPCDWriter();
  ~vtkPointCloudPCDWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  int DataFormat = BINARY;
  std::string ErrorMessage;

private:
  vtkPointCloudPCDWriter(const vtkPointCloudPCDWriter&) = delete;
  void operator=(const vtkPointCloudPCDWriter&) = delete;
};

#endif
