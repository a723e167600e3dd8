/**
 * @class   vtkPointCloudPLYReader
 * @brief   Reads the vertices of a PLY file (ASCII, binary little- or big-endian) as a point
 *          cloud, with every vertex property as a point-data array.
 *
 * VTK 9.1's vtkPLYReader keeps only coordinates, normals, colours and texture coordinates, so the
 * scores a tool writes as vertex properties would be lost on reading; this reader keeps them all.
 *
 * - `x`, `y`, `z` become the points: double precision if any of the three is stored as a double,
 *   float otherwise.
 * - `nx`, `ny`, `nz` become the 3-component array `Normals` (set as the active normals).
 * - `red`, `green`, `blue` (and `alpha`) of type uchar become the unsigned char array `RGB`
 *   (`RGBA`), set as the active scalars.
 * - Properties named `NAME_0`, `NAME_1`, ... `NAME_<k-1>` that follow each other with the same
 *   type become one k-component array `NAME` (vtkPointCloudPLYWriter writes multi-component
 *   arrays that way).
 * - Every other scalar property becomes a 1-component array with its name and type (char,
 *   uchar, short, ushort, int, uint, float, double and their int8 ... float64 aliases).
 * - At most MaximumNumberOfArrays arrays besides the points (each array costs time per array
 *   in VTK's point data: 100,000 properties would take minutes); more is an error.
 * - List properties of the vertex element are skipped (with a warning). Other elements (faces,
 *   edges, ...) are skipped: a mesh's vertices are read as a point cloud. Their rows are still
 *   read past, before and after the vertices: a file cut short in them, or whose rows do not
 *   hold what their list counts say, is an error (a piece other than the whole file does not
 *   reach the elements after the vertices).
 *
 * With CreateVertexCells on (default) the output has one vertex cell per point, so that it
 * renders as points.
 *
 * Pieces (the pipeline's UPDATE_PIECE_NUMBER of UPDATE_NUMBER_OF_PIECES, as in
 * `UpdatePiece(rank, ranks, 0)`): in a binary file whose vertex rows have a fixed size (no list
 * property), piece p of P holds the vertices [n p / P, n (p + 1) / P) and reads only their bytes,
 * so that each MPI process reads its own share; in other files piece 0 holds every vertex and
 * the other pieces none. The whole file's size is still checked against the header.
 *
 * Errors (vtkErrorMacro, error code set, empty output; never a partial cloud) name the file and
 * what is wrong: not a PLY file, an unknown format or property type, a malformed header line
 * (with its line number), no vertex element or no x/y/z, a binary file that ends before its last
 * vertex ("ends in vertex 1234 of 5000"), an ASCII line with too few values or a field that is
 * not a number (with its line number).
 *
 * @sa vtkPointCloudPLYWriter vtkPointCloudIO vtkPLYReader
 */
#ifndef vtkPointCloudPLYReader_h
#define vtkPointCloudPLYReader_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstddef> // For size_t
#include <string>  // For ErrorMessage

class FEATUREPOINTSIO_EXPORT vtkPointCloudPLYReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudPLYReader* New();
  vtkTypeMacro(vtkPointCloudPLYReader, vtkPolyDataAlgorithm);
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

  /** The most point arrays a file may give besides the points (more is an error). */
  static constexpr size_t MaximumNumberOfArrays = 1000;

  /** The message of the last error ("" after a successful read). */
  const std::string& GetErrorMessage() const { return this->ErrorMessage; }

protected:
  vtkPointCloudPLYReader();
  ~vtkPointCloudPLYReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  bool CreateVertexCells = true;
  std::string ErrorMessage;

private:
  vtkPointCloudPLYReader(const vtkPointCloudPLYReader&) = delete;
  void operator=(const vtkPointCloudPLYReader&) = delete;
};

#endif
