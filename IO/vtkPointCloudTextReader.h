/**
 * @class   vtkPointCloudTextReader
 * @brief   Reads a point cloud from a text file: XYZ/TXT (whitespace separated), CSV (with or
 *          without a header) or PTS (Leica: a point count, then x y z [intensity] [r g b]; a file of
 *          several scans has a count line before each).
 *
 * One point per line; the first three columns are x, y, z unless a header names them. Every
 * other column becomes a point-data array, so nothing in the file is lost:
 *
 * - Header: the first non-comment line is a header when none of its fields is a finite number
 *   and some field is no number at all (a UTF-8 byte order mark before it is skipped). A
 *   header's `x`, `y`, `z` columns (any case, CloudCompare's `//X` too) are the coordinates;
 *   `nx`, `ny`, `nz`, when all three are there, become `Normals` (active normals; one or two of
 *   them stay columns of their own); columns `NAME:0` ... `NAME:<k-1>`
 *   (as vtkPointCloudTextWriter and vtkDelimitedTextWriter write them) become one k-component
 *   array `NAME`; any other column a double array with the header's name.
 * - Without a header, the extra columns are named `Field 3`, `Field 4`, ... (0-based, as
 *   vtkDelimitedTextReader names them); a PTS file's 4th column is `Intensity` and its last
 *   three `RGB` (unsigned char, active scalars) when there are 6 or 7 columns.
 * - Empty lines and lines starting with `#` are skipped. CSV fields are separated by commas
 *   (or by semicolons, tabs or blanks when the first line has no comma), with optional blanks
 *   around them; XYZ/TXT fields by blanks, or by commas (semicolons) when the first line has any.
 * - At most MaximumNumberOfArrays point arrays besides the coordinates (each array costs time
 *   per array in VTK's point data: a file of 100,000 columns would take minutes).
 *
 * Points are double precision. With CreateVertexCells on (default) the output has one vertex
 * cell per point.
 *
 * Errors (vtkErrorMacro, error code set, empty output, never a partial cloud) give the file, the
 * line and what is wrong: a field that is not a number, a line with a different number of fields
 * than the first data line, a non-finite coordinate, a PTS count that does not match the lines,
 * a file without any point.
 *
 * VTK's vtkDelimitedTextReader and vtkPTSReader read these files too, but report neither the
 * line of a malformed field nor a short line (a non-numeric field turns the whole column into
 * strings), which a command-line tool must tell its user.
 *
 * @sa vtkPointCloudTextWriter vtkPointCloudIO vtkDelimitedTextReader vtkPTSReader
 */
#ifndef vtkPointCloudTextReader_h
#define vtkPointCloudTextReader_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstddef> // For size_t
#include <string>  // For ErrorMessage

class FEATUREPOINTSIO_EXPORT vtkPointCloudTextReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudTextReader* New();
  vtkTypeMacro(vtkPointCloudTextReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Formats
  {
    AUTOMATIC = 0, ///< from the extension: .csv CSV, .pts PTS, anything else XYZ
    XYZ = 1,       ///< whitespace-separated columns
    CSV = 2,       ///< comma- (or semicolon-) separated columns
    PTS = 3,       ///< Leica PTS: a count line, then whitespace-separated columns
  };

  ///@{
  /** The file to read. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /** The file's layout. Default AUTOMATIC (from the file name's extension). */
  vtkSetClampMacro(Format, int, AUTOMATIC, PTS);
  vtkGetMacro(Format, int);
  ///@}

  ///@{
  /** One vertex cell per point in the output. Default on. */
  vtkSetMacro(CreateVertexCells, bool);
  vtkGetMacro(CreateVertexCells, bool);
  vtkBooleanMacro(CreateVertexCells, bool);
  ///@}

  /** The most point arrays a file may give besides the coordinates (more is an error). */
  static constexpr size_t MaximumNumberOfArrays = 1000;

  /** The message of the last error ("" after a successful read). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

protected:
  vtkPointCloudTextReader();
  ~vtkPointCloudTextReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int Format = AUTOMATIC;
  bool CreateVertexCells = true;
  std::string ErrorMessage;

private:
  vtkPointCloudTextReader(const vtkPointCloudTextReader&) = delete;
  void operator=(const vtkPointCloudTextReader&) = delete;
};

#endif
