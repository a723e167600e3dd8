/**
 * @class   vtkPointCloudIO
 * @brief   Reads and writes point clouds, choosing the reader or writer by the file's extension;
 *          every failure comes back as one line that names the file and the problem.
 *
 * Reading (the extension, any case):
 * - `.ply`: vtkPointCloudPLYReader (ASCII or binary, every vertex property kept, faces skipped).
 * - `.vtp`, `.vtu`: vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader.
 * - `.vtk`: vtkDataSetReader (legacy VTK); the file must hold a point set.
 * - `.pts`, `.xyz`, `.txt`, `.csv`: vtkPointCloudTextReader.
 * - `.pcd`: vtkPointCloudPCDReader (ascii, binary, binary_compressed; every field kept).
 * - `.las`: vtkPointCloudLASReader (LAS 1.0-1.4, point formats 0-10, double coordinates).
 * - `.laz` is recognized (CanRead() is true, so that a program passes it on) but not listed as
 *   readable: Read() fails with one line saying that this build has no LASzip.
 *
 * Writing: `.vtp` (vtkXMLPolyDataWriter, binary, compressed), `.vtk` (vtkPolyDataWriter, binary),
 * `.ply` (vtkPointCloudPLYWriter, binary, every numeric point array as a vertex property), `.csv`
 * (vtkPointCloudTextWriter), `.pcd` (vtkPointCloudPCDWriter, binary, every numeric point array as
 * a field). Write() never leaves a partial file: it writes to a temporary file
 * in the target's folder and renames it over the target only when the writer succeeded.
 *
 * In a pipeline, and from Python, vtkPointCloudReader and vtkPointCloudWriter do the same as
 * algorithms. Read() and MakeVertexCells() return smart pointers, which VTK's wrappers cannot
 * pass: they are C++ only, and ReadPolyData() and MakeVertexCells(n, cells) are their wrapped
 * counterparts. Methods with a `std::string& error` take a `vtkmodules.vtkCommonCore.reference`
 * from Python.
 *
 * @sa vtkPointCloudReader vtkPointCloudWriter vtkPointCloudPLYReader vtkPointCloudPLYWriter
 * vtkPointCloudTextReader vtkPointCloudTextWriter vtkPointCloudPCDReader vtkPointCloudPCDWriter
 * vtkPointCloudLASReader
 */
#ifndef vtkPointCloudIO_h
#define vtkPointCloudIO_h

#include "FeaturePointsIOModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For Read

#include <string> // For file names and messages
#include <utility> // For ReadWithReader
#include <vector>  // For ReadWithReader

class vtkAlgorithm;
class vtkCellArray;
class vtkCommand;
class vtkPointSet;
class vtkPolyData;

class FEATUREPOINTSIO_EXPORT vtkPointCloudIO : public vtkObject
{
public:
  static vtkPointCloudIO* New();
  vtkTypeMacro(vtkPointCloudIO, vtkObject);

  /** The extension of a file name, lower case and without the dot ("" if there is none). */
  static std::string GetExtension(const std::string& fileName);

  ///@{
  /**
   * Whether an extension (as GetExtension returns it) can be read or written. CanRead() is also
   * true for `laz`, which Read() refuses with a message that says why.
   */
  static bool CanRead(const std::string& extension);
  static bool CanWrite(const std::string& extension);
  ///@}

  ///@{
  /** The extensions that can be read or written, as a list for messages ("ply, vtp, ..."). */
  static std::string GetReadableExtensions();
  static std::string GetWritableExtensions();
  ///@}

  /**
   * Reads a point cloud. Returns nullptr and sets `error` (one line, starting with the file name)
   * when the file is missing, unreadable, of an unknown extension, malformed or not a point set.
   * `observer`, if given, is added to the reader for its ProgressEvent.
   * C++ only (a smart pointer): ReadPolyData() is the wrapped counterpart.
   */
  VTK_WRAPEXCLUDE static vtkSmartPointer<vtkPointSet> Read(
    const std::string& fileName, std::string& error, vtkCommand* observer = nullptr);

  /**
   * Read() into `output`: the cloud's points and point data, its cells when it is polydata with
   * cells, one vertex cell per point otherwise (points alone, a .vtu or .vtk unstructured grid). Returns false, with
   * `output` emptied and `error` set as by Read(), on any failure.
   */
  static bool ReadPolyData(const std::string& fileName, vtkPolyData* output, std::string& error,
    vtkCommand* observer = nullptr);

  ///@{
  /**
   * VTK's own readers (.vtp, .vtu, .vtk) run in a child process, so that a malformed file that
   * makes them crash or loop ends in a message rather than in a crash or a hang: the child has this
   * many seconds (0, the default: 60 s plus 1 s per 4 MB of file) and no more address space than
   * the machine has memory.
   */
  static void SetReaderTimeLimit(double seconds);
  static double GetReaderTimeLimit();
  ///@}

  /**
   * Writes `data` in the format of `extension` (the file name's own when empty) to a temporary
   * file beside `fileName`, then renames it to `fileName`. Returns false and sets `error` (one
   * line, starting with the file name) on any failure, leaving no file behind. Several threads
   * may write at once, each its own data set (VTK's writers touch the information of their
   * input's arrays, so one data set is not written by two threads at once).
   */
  static bool Write(vtkPointSet* data, const std::string& fileName, std::string& error,
    const std::string& extension = "", vtkCommand* observer = nullptr);

  /**
   * Whether a file can be created at `fileName` (its folder exists and is writable): checked by
   * creating and removing a temporary file there. Sets `error` when not.
   */
  static bool CanCreate(const std::string& fileName, std::string& error);

  /**
   * A temporary file name beside `fileName`, created empty with the permissions a new file would
   * get; "" (and `error` set) when none can be created. With `removeOnSignal`, the name is known
   * to RemoveTemporaryFileInProgress() from before the file exists until ReleaseTemporaryFile(),
   * so that a signal leaves no such file whichever thread it reaches (up to 16 such files at
   * once; beyond that a file is created without it).
   */
  static std::string CreateTemporaryFile(
    const std::string& fileName, std::string& error, bool removeOnSignal = false);

  /**
   * The file that writing `fileName` replaces: the target of a symbolic link (written through,
   * the link kept, as a shell's redirection does), else `fileName` itself (a link whose target
   * cannot be resolved is replaced).
   */
  static std::string WriteTarget(const std::string& fileName);

  /**
   * Forgets a temporary file of CreateTemporaryFile(..., true) once it is renamed or removed.
   */
  static void ReleaseTemporaryFile(const std::string& temporary);

  /**
   * Removes the temporary files of the Write() calls in progress (any number of them, from any
   * threads) and those of CreateTemporaryFile(..., true) not yet released. Async-signal-safe: a
   * program's SIGINT/SIGTERM handler calls it so that an interrupted run leaves no file behind.
   */
  static void RemoveTemporaryFileInProgress();

  /**
   * `poly` with its arrays' names made fit for VTK's XML writers (VTK 9.1 writes names as they
   * are): quotes, '<', '>', '&' and apostrophes as XML entities (the XML readers give the names
   * back as they were), an empty name as "unnamed" (then "unnamed_2", ... where taken), control
   * characters as '_', bytes that are not UTF-8 as Latin-1 characters (XML must be UTF-8), and
   * names cut to 240 bytes (VTK's readers keep at most 255; .vtk outputs are cut alike). `poly` itself when every name already is; else a shallow copy whose
   * renamed arrays share the originals' values (the caller's arrays keep their names). String
   * arrays with a value that holds a NUL byte are left out, with a warning that names them (and
   * `fileName`, the output, when given): VTK's XML reader crashes on them. Write() applies it to
   * .vtp outputs; C++ only.
   */
  VTK_WRAPEXCLUDE static vtkSmartPointer<vtkPolyData> WithXMLNames(
    vtkPolyData* poly, const std::string& fileName = std::string());

  ///@{
  /**
   * One vertex cell per point, 0 to n-1, with 32-bit storage when n allows: a new cell array
   * (nullptr when the memory cannot be had; C++ only), or into `cells` (false, `cells` left empty,
   * when the memory cannot be had). The same cells as vtkPointCloudNeighborhoods::MakeVertexCells().
   */
  VTK_WRAPEXCLUDE static vtkSmartPointer<vtkCellArray> MakeVertexCells(vtkIdType n);
  static bool MakeVertexCells(vtkIdType n, vtkCellArray* cells);
  ///@}

  /** The message of a VTK error or warning event, without its "ERROR: In file, line" preamble. */
  static std::string MessageText(const char* vtkMessage);

  /**
   * A message as one readable line: control characters (a NUL or a newline inside a file's token
   * or name) escaped as \xHH, and any word longer than 1,024 bytes (a 150,000-digit field, never
   * a file's path) cut to its first 64 bytes and its length.
   */
  static std::string OneLine(const std::string& message);

protected:
  vtkPointCloudIO() = default;

  // Read() once the file is known to exist: with the reader of the extension, in this process.
  // `leaveOut`: arrays a VTK XML reader does not read, each a name and whether it is cell data.
  static vtkSmartPointer<vtkPointSet> ReadWithReader(const std::string& fileName,
    const std::string& extension, std::string& error, vtkCommand* observer,
    const std::vector<std::pair<std::string, bool>>& leaveOut = {});
  // ReadWithReader() in a child process, under the limits of SetReaderTimeLimit().
  static vtkSmartPointer<vtkPointSet> ReadIsolated(const std::string& fileName,
    const std::string& extension, double fileSize, std::string& error, vtkCommand* observer);
  ~vtkPointCloudIO() override = default;

private:
  vtkPointCloudIO(const vtkPointCloudIO&) = delete;
  void operator=(const vtkPointCloudIO&) = delete;
};

#endif
