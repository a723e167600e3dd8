// vtkPointCloudTextReader on hand-written files: headers, delimiters, PTS columns, comments and
// CRLF line ends; and every malformed file it must reject with the file, line and problem.
#include "FeaturePointsTestFiles.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointCloudTextReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
using namespace fptest;

// Keeps the reader's error off the console (the test checks the message itself).
class Silence : public vtkCommand
{
public:
  static Silence* New() { return new Silence; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};

std::string Write(const std::string& folder, const std::string& name, const std::string& text)
{
  const std::string path = folder + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

struct Read
{
  vtkNew<vtkPointCloudTextReader> Reader;
  vtkPolyData* Output = nullptr;
  std::string Error;
  explicit Read(const std::string& path)
  {
    vtkNew<Silence> silence;
    this->Reader->AddObserver(vtkCommand::ErrorEvent, silence);
    this->Reader->SetFileName(path.c_str());
    this->Reader->Update();
    this->Output = this->Reader->GetOutput();
    this->Error = this->Reader->GetErrorMessage();
  }
  double Value(const char* array, vtkIdType i, int c = 0)
  {
    vtkDataArray* a = this->Output->GetPointData()->GetArray(array);
    return a ? a->GetComponent(i, c) : std::nan("");
  }
};

// The reader must fail with a message that holds the file name and `expected`.
void ExpectError(const std::string& folder, const std::string& name, const std::string& text,
  const std::string& expected)
{
  const std::string path = Write(folder, name, text);
  Read r(path);
  Check(!r.Error.empty() && r.Reader->GetErrorCode() != 0, name + ": no error reported");
  Check(r.Output->GetNumberOfPoints() == 0, name + ": points in the output of a failed read");
  Check(r.Error.find(path) != std::string::npos, name + ": message lacks the file: " + r.Error);
  Check(r.Error.find(expected) != std::string::npos,
    name + ": message '" + r.Error + "' lacks '" + expected + "'");
}
} // namespace

int TestPointCloudText(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";

  // XYZ without header: comments, blank lines, tabs, CRLF, a leading '+', extra columns.
  {
    Read r(Write(folder, "plain.xyz",
      "# a comment\r\n1 2 3 0.5\r\n\r\n  4\t5 6 +7e-1\r\n-1.5 0 1e3 9\r\n"));
    Check(r.Error.empty(), "plain.xyz: " + r.Error);
    Check(r.Output->GetNumberOfPoints() == 3, "plain.xyz: 3 points");
    double p[3];
    r.Output->GetPoint(2, p);
    Check(p[0] == -1.5 && p[1] == 0.0 && p[2] == 1000.0, "plain.xyz: third point");
    Check(r.Value("Field 3", 1) == 0.7, "plain.xyz: 'Field 3' of the second point");
    Check(r.Output->GetNumberOfVerts() == 3, "plain.xyz: one vertex per point");
  }
  // CSV with a header in any column order, normals and a grouped 2-component array.
  {
    Read r(Write(folder, "header.csv",
      "id, Z ,y,x,nx,ny,nz,Pair:1,Pair:0\n7,3,2,1,0,0,1,20,10\n8,6,5,4,1,0,0,21,11\n"));
    Check(r.Error.empty(), "header.csv: " + r.Error);
    Check(r.Output->GetNumberOfPoints() == 2, "header.csv: 2 points");
    double p[3];
    r.Output->GetPoint(1, p);
    Check(p[0] == 4 && p[1] == 5 && p[2] == 6, "header.csv: coordinates from the named columns");
    Check(r.Value("id", 1) == 8, "header.csv: id column");
    Check(r.Output->GetPointData()->GetNormals() &&
        r.Output->GetPointData()->GetNormals()->GetComponent(1, 0) == 1,
      "header.csv: nx ny nz as the active normals");
    Check(r.Value("Pair", 0, 0) == 10 && r.Value("Pair", 0, 1) == 20,
      "header.csv: Pair:0 and Pair:1 grouped in component order");
  }
  // Semicolons, and CloudCompare's "//X" header.
  {
    Read r(Write(folder, "semicolon.csv", "//X;Y;Z;Intensity\n1;2;3;4\n"));
    Check(r.Error.empty() && r.Output->GetNumberOfPoints() == 1 && r.Value("Intensity", 0) == 4,
      "semicolon.csv: " + r.Error);
  }
  // PTS: count line, intensity and colours.
  {
    Read r(Write(folder, "scan.pts", "2\n0 0 0 -120 10 20 30\n1 1 1 5 255 0 7\n"));
    Check(r.Error.empty() && r.Output->GetNumberOfPoints() == 2, "scan.pts: " + r.Error);
    Check(r.Value("Intensity", 0) == -120, "scan.pts: intensity");
    auto* rgb = vtkUnsignedCharArray::SafeDownCast(r.Output->GetPointData()->GetScalars());
    Check(rgb && rgb->GetNumberOfComponents() == 3 && rgb->GetValue(3) == 255 &&
        rgb->GetValue(5) == 7,
      "scan.pts: RGB as unsigned char active scalars");
  }
  {
    // Several scans, each after its own count line (an empty scan too).
    Read r(Write(folder, "scans.pts",
      "2\n0 0 0 -120 10 20 30\n1 1 1 5 255 0 7\n0\n1\n2 2 2 7 1 2 3\n"));
    Check(r.Error.empty() && r.Output->GetNumberOfPoints() == 3, "scans.pts: " + r.Error);
    Check(r.Output && r.Output->GetNumberOfPoints() == 3 && r.Output->GetPoint(2)[0] == 2 &&
        r.Value("Intensity", 2) == 7,
      "scans.pts: the third point");
  }
  {
    // Commas between the fields, as some exporters write PTS.
    Read r(Write(folder, "commas.pts", "2\n0,0,0,-120,10,20,30\n1,1,1,5,255,0,7\n"));
    Check(r.Error.empty() && r.Output && r.Output->GetNumberOfPoints() == 2 &&
        r.Value("Intensity", 1) == 5,
      "commas.pts: " + r.Error);
  }

  // Malformed files: the line and the problem in the message, and no points.
  ExpectError(folder, "word.xyz", "1 2 3\n4 five 6\n", ":2: field 2 ('five') is not a number");
  ExpectError(folder, "short.xyz", "1 2 3\n4 5 6\n7 8\n", ":3: 2 field(s), expected 3 (as on line 1)");
  ExpectError(folder, "long.csv", "x,y,z\n1,2,3\n1,2,3,4\n",
    ":3: 4 field(s), expected 3 (as in the header on line 1)");
  ExpectError(folder, "nan.xyz", "1 2 3\nnan 2 3\n", ":2: field 1 ('nan') is not a finite number");
  ExpectError(folder, "inf.csv", "1,2,inf\n", ":1: field 3 ('inf') is not a finite number");
  ExpectError(folder, "suffix.xyz", "1 2 3.5abc\n", "('3.5abc') is not a number");
  ExpectError(folder, "overflow.xyz", "1 2 3\n1 2 1e400\n",
    ":2: field 3 ('1e400') is not within the range of a double");
  ExpectError(folder, "cr.csv", "x,y,z\r1,2,3\r4,5,6\r",
    ":1: a carriage return inside the line: the file's lines end in CR alone");
  {
    // Below the smallest double: read as strtod reads it (0, of its sign), not refused, whatever
    // the exponent or the digits ("0.000...1" with 400 zeros was refused as beyond a double),
    // as the PLY and PCD readers read it.
    Spit(folder + "/underflow.xyz",
      "1 2 3\n1e-400 -1e-5000 0." + std::string(400, '0') + "1\n");
    Read r(folder + "/underflow.xyz");
    double x[3] = { 1, 1, 1 };
    if (r.Error.empty() && r.Output->GetNumberOfPoints() == 2)
    {
      r.Output->GetPoint(1, x);
    }
    Check(r.Error.empty() && x[0] == 0.0 && x[1] == 0.0 && std::signbit(x[1]) && x[2] == 0.0,
      "underflow.xyz: 1e-400, -1e-5000 and 0.000...1 read as 0, -0 and 0: " + r.Error);
  }
  ExpectError(folder, "twocolumns.xyz", "1 2\n", "a point needs 3 coordinates");
  ExpectError(folder, "noxyz.csv", "a,b,c\n1,2,3\n", "names no x, y and z");
  ExpectError(folder, "utf16.csv", std::string("\xFF\xFEx\0,\0y\0,\0z\0\n\0", 14),
    ":1: the file is UTF-16 text");
  // Without a byte order mark: a NUL in every other byte, little- or big-endian.
  ExpectError(folder, "utf16le.csv", std::string("x\0,\0y\0,\0z\0\r\0\n\0001\0", 16),
    ":1: the file is UTF-16 text");
  ExpectError(folder, "utf16be.csv", std::string("\0x\0,\0y\0,\0z\0\r\0\n\0001", 16),
    ":1: the file is UTF-16 text");
  // Binary data with a text extension: named as such, not as UTF-16, CR line ends or a header.
  {
    std::string bytes(256, '\0');
    for (int b = 0; b < 256; ++b)
    {
      bytes[b] = static_cast<char>(b);
    }
    ExpectError(
      folder, "bytes.xyz", bytes, ":1: binary data (a NUL byte at byte 0), not a text file");
  }
  ExpectError(folder, "las.xyz", std::string("LASF\0\0\x01\0\r\x02\0\0", 12),
    ":1: binary data (a NUL byte at byte 4), not a text file");
  ExpectError(folder, "random.xyz", std::string("\x81\x92 x\xff\n\x01\0\x02", 9),
    ":2: binary data (a NUL byte at byte 7), not a text file");
  {
    // A NUL past the start the reader looks at first: found on its line.
    std::string text;
    while (text.size() < 70000)
    {
      text += "1 2 3\n";
    }
    const std::string at = std::to_string(text.size() + 3);
    ExpectError(folder, "late-nul.xyz", text + std::string("4 5\0 6\n", 8),
      ":11668: binary data (a NUL byte at byte " + at + "), not a text file");
  }
  ExpectError(folder, "twox.csv", "x,y,z,X\n1,2,3,4\n",
    ":1: the header names the coordinate 'x' more than once (columns 1 and 4)");
  // A first line written like numbers is data with a bad field, not a header without x, y, z.
  ExpectError(folder, "hex.xyz", "0x1p-1 0x1p-2 0x1p-3\n1 2 3\n",
    ":1: field 1 ('0x1p-1') is not a number (hexadecimal numbers are not read)");
  ExpectError(folder, "exponent.csv", "1e,2,3\n1,2,3\n", ":1: field 1 ('1e') is not a number");
  ExpectError(folder, "twice.csv", "x,y,z,a,b,a\n1,2,3,4,5,6\n",
    "the header names 'a' more than once (columns 4 and 6)");
  ExpectError(folder, "unnamed.csv", "x,y,z,,,w\n1,2,3,4,5,6\n",
    "the header leaves more than one column unnamed (columns 4 and 5)");
  {
    // A delimiter ending every line (a spreadsheet's export) opens no empty column.
    Read r(Write(folder, "trailing.csv", "x,y,z,\n1,2,3,\n4,5,6,\n"));
    Check(r.Error.empty() && r.Output->GetNumberOfPoints() == 2 &&
        r.Output->GetPointData()->GetNumberOfArrays() == 0 && r.Output->GetPoint(1)[2] == 6,
      "trailing.csv: " + r.Error);
  }
  ExpectError(folder, "gap.csv", "x,y,z,c:0,c:2\n1,2,3,4,5\n",
    "the header names components of 'c' up to 2 but no column 'c:1'");
  ExpectError(folder, "comments.txt", "# nothing\n\n", "holds no point");
  ExpectError(folder, "count.pts", "3\n0 0 0\n1 1 1\n", ":1: the count line says 3 points but the file has 2");
  ExpectError(folder, "scans.pts", "1\n0 0 0\n2\n1 1 1\n",
    ":3: the count line of the last of 2 scans says 2 points but the scan has 1");
  ExpectError(folder, "scan-count.pts", "2\n0 0 0\n1 1 1\n2 2 2\n1\n3 3 3\n",
    ":5: '1' reads as a scan's count line, but the scan counted on line 1 (2 points) has 3 before");
  ExpectError(folder, "nocount.pts", "0 0 0\n", "starts with its number of points");
  ExpectError(folder, "colour.pts", "1\n0 0 0 1 300 0 0\n", "not a colour value");
  {
    Read r(folder + "/missing.xyz");
    Check(r.Error.find("cannot open") != std::string::npos, "missing file: " + r.Error);
  }

  // A cloud large enough to cross the reader's progress steps, read exactly.
  {
    std::string text;
    for (int i = 0; i < 200000; ++i)
    {
      text += std::to_string(i) + " " + std::to_string(i % 7) + " 0.25\n";
    }
    Read r(Write(folder, "large.xyz", text));
    double p[3];
    r.Output->GetPoint(199999, p);
    Check(r.Error.empty() && r.Output->GetNumberOfPoints() == 200000 && p[0] == 199999 &&
        p[1] == 199999 % 7 && p[2] == 0.25,
      "large.xyz: 200000 points read back exactly");
  }

  std::printf("%d failure(s)\n", Failures);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
