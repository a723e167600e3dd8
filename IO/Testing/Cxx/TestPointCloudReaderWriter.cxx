// vtkPointCloudReader and vtkPointCloudWriter: the pipeline algorithms over vtkPointCloudIO.
// A cloud written by the writer in every writable format reads back through the reader with its
// points and arrays, and passes through a downstream filter-like consumer; the reader's and the
// writer's failures are one error event each, the message starting with the file name, the
// matching error code, an empty output (reader) and no file left (writer); progress reaches the
// algorithm's own ProgressEvent.
#include "FeaturePointsTestFiles.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointCloudReader.h"
#include "vtkPointCloudWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using namespace fptest;

// Counts the events of one kind and keeps the last message.
class EventCounter : public vtkCommand
{
public:
  static EventCounter* New() { return new EventCounter; }
  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    ++this->Count;
    if (event == vtkCommand::ErrorEvent && callData)
    {
      this->Message = static_cast<const char*>(callData);
    }
    if (event == vtkCommand::ProgressEvent && callData)
    {
      this->Last = *static_cast<double*>(callData);
    }
  }
  int Count = 0;
  double Last = -1.0;
  std::string Message;
};

// A 40 x 25 grid on a paraboloid with a float score and a uint8 mask.
vtkNew<vtkPolyData> MakeCloud()
{
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> score;
  score->SetName("Score");
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("FeatureMask");
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 25; ++j)
    {
      const double x = 0.1 * i, y = 0.2 * j;
      points->InsertNextPoint(x, y, 0.5 * x * x - 0.25 * y * y);
      score->InsertNextValue(static_cast<float>(std::sin(x) * std::cos(y)));
      mask->InsertNextValue((i + j) % 7 == 0 ? 1 : 0);
    }
  }
  cloud->SetPoints(points);
  cloud->GetPointData()->AddArray(score);
  cloud->GetPointData()->AddArray(mask);
  return cloud;
}
} // namespace

// Two arrays named `names` (values i and 2 i) added to `cloud`, written to `file` and read back:
// found there as `expected`, the values intact, the caller's arrays keeping their names.
void NamesRoundTrip(vtkPolyData* cloud, const std::string& file,
  const std::array<std::string, 2>& names, const std::array<std::string, 2>& expected,
  const std::string& what)
{
  const vtkIdType n = cloud->GetNumberOfPoints();
  vtkNew<vtkPolyData> named;
  named->ShallowCopy(cloud);
  vtkNew<vtkFloatArray> arrays[2];
  for (int k = 0; k < 2; ++k)
  {
    arrays[k]->SetName(names[k].c_str());
    for (vtkIdType i = 0; i < n; ++i)
    {
      arrays[k]->InsertNextValue(static_cast<float>((k + 1) * i));
    }
    named->GetPointData()->AddArray(arrays[k]);
  }
  vtkNew<vtkPointCloudWriter> writer;
  writer->SetInputData(named);
  writer->SetFileName(file.c_str());
  vtkNew<vtkPointCloudReader> reader;
  reader->SetFileName(file.c_str());
  const bool written = writer->Write() == 1;
  reader->Update();
  bool same = written && reader->GetErrorMessage().empty();
  for (int k = 0; k < 2 && same; ++k)
  {
    vtkDataArray* back = reader->GetOutput()->GetPointData()->GetArray(expected[k].c_str());
    same = back && back->GetTuple1(n - 1) == (k + 1) * (n - 1) && arrays[k]->GetName() == names[k];
  }
  Check(same, what + ": '" + reader->GetErrorMessage() + "'");
  std::remove(file.c_str());
}

int TestPointCloudReaderWriter(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  vtkNew<vtkPolyData> cloud = MakeCloud();
  const vtkIdType n = cloud->GetNumberOfPoints();

  // Every writable format, written by the writer and read back by the reader.
  for (const std::string extension : { "vtp", "vtk", "ply", "csv" })
  {
    const std::string file = folder + "/cloud." + extension;
    std::remove(file.c_str());
    vtkNew<vtkPointCloudWriter> writer;
    writer->SetInputData(cloud);
    writer->SetFileName(file.c_str());
    Check(writer->Write() == 1 && writer->GetErrorMessage().empty(),
      extension + ": write failed: " + writer->GetErrorMessage());
    vtkNew<vtkPointCloudReader> reader;
    reader->SetFileName(file.c_str());
    Check(reader->CanReadFile(file.c_str()) == 1, extension + ": CanReadFile is 0");
    vtkNew<EventCounter> progress;
    reader->AddObserver(vtkCommand::ProgressEvent, progress);
    reader->Update();
    vtkPolyData* back = reader->GetOutput();
    Check(reader->GetErrorCode() == vtkErrorCode::NoError && reader->GetErrorMessage().empty(),
      extension + ": read failed: " + reader->GetErrorMessage());
    Check(progress->Count > 0 && progress->Last == 1.0,
      extension + ": no progress reaching 1 from the reader");
    Check(back->GetNumberOfPoints() == n && back->GetNumberOfVerts() == n,
      extension + ": " + std::to_string(back->GetNumberOfPoints()) + " points, " +
        std::to_string(back->GetNumberOfVerts()) + " vertices, not " + std::to_string(n));
    vtkDataArray* score = back->GetPointData()->GetArray("Score");
    vtkDataArray* mask = back->GetPointData()->GetArray("FeatureMask");
    Check(score && mask, extension + ": Score or FeatureMask missing");
    if (score && mask && back->GetNumberOfPoints() == n)
    {
      int wrong = 0;
      for (vtkIdType i = 0; i < n; ++i)
      {
        double p[3], q[3];
        cloud->GetPoint(i, p);
        back->GetPoint(i, q);
        // Scores are float: every format gives back the same float (as a double in CSV).
        wrong += p[0] != q[0] || p[1] != q[1] || p[2] != q[2] ||
            static_cast<float>(score->GetTuple1(i)) !=
              cloud->GetPointData()->GetArray("Score")->GetTuple1(i) ||
            mask->GetTuple1(i) != cloud->GetPointData()->GetArray("FeatureMask")->GetTuple1(i)
          ? 1
          : 0;
      }
      Check(wrong == 0, extension + ": " + std::to_string(wrong) + " points differ after the round trip");
    }
    // The reader re-reads when the file name changes, not otherwise.
    const vtkMTimeType before = back->GetMTime();
    reader->Update();
    Check(reader->GetOutput()->GetMTime() == before, extension + ": read again without a change");
  }

  // Array names that XML does not take as they are: written escaped, read back as they were (an
  // empty one as "unnamed"); the caller's arrays keep their names.
  NamesRoundTrip(cloud, folder + "/names.vtp", { "a\"b<c>&'d", "" }, { "a\"b<c>&'d", "unnamed" },
    "vtp: array names with XML's special characters");
  // Names VTK's readers cannot take back as they are: a Windows-1252 byte (not UTF-8: the XML
  // did not parse) and 300 bytes (past the readers' 256-byte buffers). Written as UTF-8 (the
  // byte as Latin-1) and cut to 240 bytes, in .vtp and .vtk: both read back.
  for (const std::string extension : { "vtp", "vtk" })
  {
    NamesRoundTrip(cloud, folder + "/encoded." + extension,
      { "Temp\xE9rature", std::string(300, 'w') }, { "Temp\xC3\xA9rature", std::string(240, 'w') },
      extension + ": a Latin-1 name and a 300-byte name");
  }

  // Format overrides the extension.
  {
    const std::string file = folder + "/cloud.data";
    vtkNew<vtkPointCloudWriter> writer;
    writer->SetInputData(cloud);
    writer->SetFileName(file.c_str());
    writer->SetFormat("ply");
    Check(writer->Write() == 1, "Format ply: " + writer->GetErrorMessage());
    std::ifstream in(file, std::ios::binary);
    std::string magic(3, '\0');
    in.read(&magic[0], 3);
    Check(magic == "ply", "Format ply: the file starts with '" + magic + "'");
  }

  // Reader failures: one error event, the message, the code, an empty output.
  const std::string bad = folder + "/bad.xyz";
  {
    std::ofstream out(bad);
    out << "0 0 0\n1 1 1\n2 two 2\n";
  }
  const std::string unknown = folder + "/cloud.unknown";
  {
    std::ofstream out(unknown);
    out << "0 0 0\n";
  }
  struct ReadCase
  {
    std::string File;
    unsigned long Code;
    std::string Expected;
  };
  const std::vector<ReadCase> readCases = {
    { folder + "/missing.xyz", vtkErrorCode::FileNotFoundError, "No such file or directory" },
    { bad, vtkErrorCode::FileFormatError, "bad.xyz:3: " },
    { unknown, vtkErrorCode::UnrecognizedFileTypeError, "cannot tell the format" },
    { "", vtkErrorCode::NoFileNameError, "no file name" },
  };
  vtkNew<vtkPointCloudReader> reader;
  vtkNew<EventCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  for (const ReadCase& c : readCases)
  {
    const int count = errors->Count;
    reader->SetFileName(c.File.empty() ? nullptr : c.File.c_str());
    reader->Update();
    const std::string message = reader->GetErrorMessage();
    const std::string what = "reading '" + c.File + "'";
    Check(reader->GetErrorCode() == c.Code,
      what + ": error code " + std::to_string(reader->GetErrorCode()));
    Check(message.find(c.Expected) != std::string::npos && message.find('\n') == std::string::npos &&
        (c.File.empty() || message.compare(0, c.File.size(), c.File) == 0),
      what + ": message '" + message + "'");
    Check(errors->Count == count + 1 && errors->Message.find(message) != std::string::npos,
      what + ": " + std::to_string(errors->Count - count) + " error events");
    Check(reader->GetOutput()->GetNumberOfPoints() == 0, what + ": the output is not empty");
  }
  // After a failure, a good file reads again.
  reader->SetFileName((folder + "/cloud.ply").c_str());
  reader->Update();
  Check(reader->GetErrorCode() == vtkErrorCode::NoError && reader->GetOutput()->GetNumberOfPoints() == n,
    "a good file after a failure: " + reader->GetErrorMessage());

  // Writer failures: Write() 0, one error event, the code, no file.
  struct WriteCase
  {
    std::string File;
    unsigned long Code;
  };
  const std::vector<WriteCase> writeCases = {
    { folder + "/no/such/folder/cloud.vtp", vtkErrorCode::CannotOpenFileError },
    { folder + "/cloud.xyz", vtkErrorCode::UnrecognizedFileTypeError },
    { "", vtkErrorCode::NoFileNameError },
  };
  vtkNew<vtkPointCloudWriter> writer;
  writer->SetInputData(cloud);
  vtkNew<EventCounter> writeErrors;
  writer->AddObserver(vtkCommand::ErrorEvent, writeErrors);
  for (const WriteCase& c : writeCases)
  {
    const int count = writeErrors->Count;
    writer->SetFileName(c.File.empty() ? nullptr : c.File.c_str());
    const std::string what = "writing '" + c.File + "'";
    Check(writer->Write() == 0, what + ": Write() succeeded");
    Check(writer->GetErrorCode() == c.Code,
      what + ": error code " + std::to_string(writer->GetErrorCode()));
    Check(writeErrors->Count == count + 1, what + ": " + std::to_string(writeErrors->Count - count) +
        " error events");
    Check(c.File.empty() || (writer->GetErrorMessage().compare(0, c.File.size(), c.File) == 0 &&
                              !Exists(c.File)),
      what + ": message '" + writer->GetErrorMessage() + "' or a file left");
  }

  // A pipe as the output is refused and left a pipe (the temporary file renamed over it would
  // replace it); a file replaced keeps its permissions.
  {
    const std::string pipe = folder + "/pipe.vtp";
    std::remove(pipe.c_str());
    struct stat info;
    if (::mkfifo(pipe.c_str(), 0644) == 0)
    {
      writer->SetFileName(pipe.c_str());
      Check(writer->Write() == 0 && writer->GetErrorCode() == vtkErrorCode::CannotOpenFileError &&
          writer->GetErrorMessage().find("not a regular file") != std::string::npos,
        "writing a pipe: '" + writer->GetErrorMessage() + "'");
      Check(::stat(pipe.c_str(), &info) == 0 && S_ISFIFO(info.st_mode), "the pipe was replaced");
      std::remove(pipe.c_str());
    }
    const std::string own = folder + "/private.vtp";
    std::ofstream(own) << "x";
    ::chmod(own.c_str(), 0600);
    writer->SetFileName(own.c_str());
    Check(writer->Write() == 1 && ::stat(own.c_str(), &info) == 0 &&
        (info.st_mode & 07777) == 0600 && info.st_size > 1,
      "a file replaced keeps its permissions (0600)");
    std::remove(own.c_str());
  }

  std::printf("%s\n", Failures ? "vtkPointCloudReader/Writer: FAILED" : "vtkPointCloudReader/Writer: ok");
  return Failures ? 1 : 0;
}
