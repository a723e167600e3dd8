/**
 * @class   vtkPointCloudLASReader
 * @brief   Reads an uncompressed LAS file (ASPRS lidar format 1.0 to 1.4, point data record
 *          formats 0 to 10) as a point cloud, coordinates in double precision.
 *
 * The points are the records' integer X, Y, Z times the header's scale factors plus its
 * offsets, computed in double precision and stored as double: lidar coordinates are often
 * 10^5 to 10^6 (UTM metres) with millimetre steps, which float (24-bit mantissa) cannot hold.
 *
 * Point-data arrays, where the record format has the attribute:
 * - `Intensity` (unsigned short), every format;
 * - `ReturnNumber`, `NumberOfReturns` (unsigned char): 3 bits each in formats 0-5, 4 bits in
 *   6-10;
 * - `Classification` (unsigned char): the 5-bit class of formats 0-5 (its synthetic, key-point
 *   and withheld flags dropped), the whole byte in formats 6-10;
 * - `GpsTime` (double): formats 1, 3, 4, 5, 6-10;
 * - `RGB` (unsigned short, 3 components, as stored: usually 0-65535): formats 2, 3, 5, 7, 8, 10;
 * - `NIR` (unsigned short): formats 8 and 10.
 * Other attributes (scan angle, user data, point source ID, flags, wave packets) and extra bytes
 * at the end of longer records are skipped. Variable-length records (the coordinate system among
 * them) are not read.
 *
 * The number of points is the header's 64-bit count in LAS 1.4 (the legacy 32-bit count when the
 * 64-bit one is 0), the 32-bit count before.
 *
 * Compressed files (LAZ: a `.laz` name or the compression bit of the point format set) are not
 * read: this build has no LASzip (Debian 12 does not package it); the error says so.
 *
 * With CreateVertexCells on (default) the output has one vertex cell per point.
 *
 * Errors (vtkErrorMacro, error code set, empty output; never a partial cloud) are one line that
 * names the file and what is wrong: not a LAS file (no LASF signature), an unsupported version or
 * point format, a header size, point offset or record length that contradicts the format, a scale
 * factor of 0 or a scale and offset that overflow, more points declared than the file holds
 * (checked against the file's size before anything is allocated).
 *
 * @sa vtkPointCloudIO vtkPointCloudPLYReader vtkPointCloudPCDReader
 */
#ifndef vtkPointCloudLASReader_h
#define vtkPointCloudLASReader_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For ErrorMessage

class FEATUREPOINTSIO_EXPORT vtkPointCloudLASReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudLASReader* New();
  vtkTypeMacro(vtkPointCloudLASReader, vtkPolyDataAlgorithm);
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
  /** The version (major.minor, 1.0 to 1.4) and point data record format of the last file read. */
  vtkGetMacro(VersionMajor, int);
  vtkGetMacro(VersionMinor, int);
  vtkGetMacro(PointDataFormat, int);
  ///@}

  /** The message of the last error ("" after a successful read). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

protected:
  vtkPointCloudLASReader();
  ~vtkPointCloudLASReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  bool CreateVertexCells = true;
  int VersionMajor = 0;
  int VersionMinor = 0;
  int PointDataFormat = -1;
  std::string ErrorMessage;

private:
  vtkPointCloudLASReader(const vtkPointCloudLASReader&) = delete;
  void operator=(const vtkPointCloudLASReader&) = delete;
};

#endif
