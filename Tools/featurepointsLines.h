// featurepoints --lines: the feature curves written as .vtp, .vtk (polylines with their arrays),
// .csv (one line per vertex: x, y, z, CurveId, Tangent) or .obj (`v` vertices, one `l` per curve).
// Like the cloud's output, the file is written to a temporary file beside the target and renamed
// only once complete: a failure leaves no file behind.
#ifndef featurepointsLines_h
#define featurepointsLines_h

#include <string>

class vtkPolyData;

namespace featurepoints
{
/** Whether --lines can write files of this extension (lower case, without the dot). */
bool CanWriteLines(const std::string& extension);

/** The extensions --lines writes, for messages: ".vtp, .vtk, .csv, .obj". */
std::string GetLinesExtensions();

/**
 * Writes `curves` (vtkFeatureCurveExtraction's second output) to `fileName`, in the format of
 * `format` (an extension; the file name's own when empty). Returns false with a one-line `error`
 * naming the file on failure.
 */
bool WriteLines(vtkPolyData* curves, const std::string& fileName, std::string& error,
  const std::string& format = "");
}

#endif
