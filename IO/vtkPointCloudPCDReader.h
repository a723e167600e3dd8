/**
 * @class   vtkPointCloudPCDReader
 * @brief   Reads a PCD file (the Point Cloud Library's format, version 0.7 and older) as a point
 *          cloud: DATA ascii, binary and binary_compressed, every field as a point-data array.
 *
 * The header names the fields (FIELDS), their SIZE in bytes, their TYPE (I signed integer, U
 * unsigned integer, F floating point) and COUNT (values per point, 1 when there is no COUNT line),
 * and the number of points (POINTS, or WIDTH x HEIGHT). The body is one text line per point
 * (ascii), the points' bytes one point after the other (binary, little-endian), or the fields'
 * bytes one field after the other, compressed with LZF (binary_compressed: a 32-bit compressed
 * size, a 32-bit uncompressed size, then the LZF data).
 *
 * - The fields `x`, `y`, `z` (found by name, anywhere in the row) become the points: double
 *   precision if any of the three is an 8-byte float or a 4- or 8-byte integer, float otherwise.
 * - `normal_x`, `normal_y`, `normal_z` become the 3-component array `Normals` (set as the active
 *   normals).
 * - With DecodeColors on (default), a 4-byte `rgb` field (PCL's colour packed into the bits of a
 *   float: 0x00RRGGBB) becomes the unsigned char array `RGB`, and a 4-byte `rgba` field
 *   (0xAARRGGBB) the array `RGBA`, set as the active scalars. With DecodeColors off they are
 *   kept as written, as any other field.
 * - Every other field becomes an array of its name, type and COUNT components (I/U 1, 2, 4, 8
 *   bytes: signed char ... long long, unsigned char ... unsigned long long; F 4 or 8: float,
 *   double). Fields named `_` (PCL's padding) are skipped.
 * - An organized cloud (HEIGHT > 1) is read as plain points, row after row; its invalid points
 *   (PCL marks them with a NaN coordinate) are skipped, with a warning that gives their number
 *   (GetNumberOfSkippedPoints()). So is any point with an infinite coordinate. When points are
 *   skipped, the output's field data holds `FilePointIds` (vtkIdTypeArray, one value per output
 *   point: its index in the file, from 0) and, for DATA ascii, `FileLines` (its line, from 1),
 *   so that a message about an output point can name it as the file numbers it.
 * - In ASCII data, a value of an F 4 field named `rgb` or `rgba` written as an integer (as PCL
 *   writes it) is the packed colour's bits, not a number to convert.
 *
 * With CreateVertexCells on (default) the output has one vertex cell per point.
 *
 * Errors (vtkErrorMacro, error code set, empty output; never a partial cloud) are one line that
 * names the file and what is wrong: not a PCD file, a malformed or contradicting header line
 * (with its line number: SIZE, TYPE or COUNT of another length than FIELDS, an unknown TYPE or
 * SIZE, POINTS other than WIDTH x HEIGHT), no x, y or z field, more points declared than the rest
 * of the file can hold (checked against the file's size before anything is allocated), a body
 * that ends before the last point, an ASCII line with too few or too many values or a value that
 * is not a number of its field's type, a compressed block whose sizes contradict the header or
 * that does not decompress.
 *
 * @sa vtkPointCloudPCDWriter vtkPointCloudIO vtkPointCloudPLYReader
 */
#ifndef vtkPointCloudPCDReader_h
#define vtkPointCloudPCDReader_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstddef> // For size_t
#include <string>  // For ErrorMessage

class FEATUREPOINTSIO_EXPORT vtkPointCloudPCDReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudPCDReader* New();
  vtkTypeMacro(vtkPointCloudPCDReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** One vertex cell per point in the output. Default on. */
  vtkSetMacro(CreateVertexCells, bool);
  vtkGetMacro(CreateVertexCells, bool);
  vtkBooleanMacro(CreateVertexCells, bool);
  ///@}

  ///@{
  /**
   * Decode the packed `rgb` / `rgba` fields to the unsigned char arrays `RGB` / `RGBA`
   * (default on); off keeps them as written.
   */
  vtkSetMacro(DecodeColors, bool);
  vtkGetMacro(DecodeColors, bool);
  vtkBooleanMacro(DecodeColors, bool);
  ///@}

  /** The points of the last read skipped for a NaN or infinite coordinate. */
  vtkGetMacro(NumberOfSkippedPoints, vtkIdType);

  ///@{
  /** WIDTH and HEIGHT of the last file read (HEIGHT > 1: an organized cloud). */
  vtkGetMacro(Width, vtkIdType);
  vtkGetMacro(Height, vtkIdType);
  ///@}

  /** The most point arrays a file may give besides the points (more is an error). */
  static constexpr size_t MaximumNumberOfArrays = 1000;

  /** The message of the last error ("" after a successful read). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

protected:
  vtkPointCloudPCDReader();
  ~vtkPointCloudPCDReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  bool CreateVertexCells = true;
  bool DecodeColors = true;
  vtkIdType NumberOfSkippedPoints = 0;
  vtkIdType Width = 0;
  vtkIdType Height = 0;
  std::string ErrorMessage;

private:
  vtkPointCloudPCDReader(const vtkPointCloudPCDReader&) = delete;
  void operator=(const vtkPointCloudPCDReader&) = delete;
};

#endif
