#include "vtkPointCloudTextReader.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudFiles.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

vtkStandardNewMacro(vtkPointCloudTextReader);

namespace
{
// Where a column's values go: a coordinate, or component `Component` of array `Array`.
struct ColumnTarget
{
  int Coordinate = -1; // 0, 1, 2 for x, y, z
  int Array = -1;
  int Component = 0;
};

struct ArraySpec
{
  std::string Name;
  int Components = 1;
  bool Colour = false; // unsigned char 0..255
  std::vector<double> Values;
};

std::string Lower(std::string_view s)
{
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string_view Trim(std::string_view s)
{
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
  {
    s.remove_prefix(1);
  }
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
  {
    s.remove_suffix(1);
  }
  return s;
}

// The whole field must be a number; a leading '+' is accepted (strtod accepts it, from_chars not).
// A number below the smallest double (1e-400) reads as a signed zero (denormals are read as
// such); one beyond the largest (1e400) is none: `outOfRange` says which failure it was.
bool ParseNumber(std::string_view field, double& value, bool* outOfRange = nullptr)
{
  if (outOfRange)
  {
    *outOfRange = false;
  }
  if (!field.empty() && field.front() == '+')
  {
    field.remove_prefix(1);
  }
  if (field.empty())
  {
    return false;
  }
  const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
  if (result.ptr != field.data() + field.size())
  {
    return false;
  }
  if (result.ec == std::errc::result_out_of_range)
  {
    // Underflow (below 1 in magnitude: "1e-400", "0.000...1") keeps its rounding, a subnormal or
    // a signed zero, as the PLY and PCD readers read it; overflow is no number. Told apart by the
    // digits and the exponent, not by strtod, which reads the current locale's decimal point.
    if (featurepoints::Underflows(field))
    {
      long double wide = 0.0L;
      const auto w = std::from_chars(field.data(), field.data() + field.size(), wide);
      value = w.ec == std::errc() ? static_cast<double>(wide) : field.front() == '-' ? -0.0 : 0.0;
      return true;
    }
    if (outOfRange)
    {
      *outOfRange = true;
    }
    return false;
  }
  return result.ec == std::errc();
}

void Split(std::string_view line, char delimiter, std::vector<std::string_view>& fields)
{
  fields.clear();
  if (delimiter == ' ')
  {
    size_t i = 0;
    while (i < line.size())
    {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
      {
        ++i;
      }
      size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])))
      {
        ++j;
      }
      if (j > i)
      {
        fields.push_back(line.substr(i, j - i));
      }
      i = j;
    }
    return;
  }
  size_t start = 0;
  while (true)
  {
    const size_t end = line.find(delimiter, start);
    fields.push_back(Trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
    if (end == std::string_view::npos)
    {
      break;
    }
    start = end + 1;
  }
  // One delimiter ending the line (spreadsheets export rows as "1,2,3,") ends the last field; it
  // opens no empty one.
  if (fields.size() > 1 && fields.back().empty() && !line.empty() && line.back() == delimiter)
  {
    fields.pop_back();
  }
}

// The field separator, from the first line that is not a comment: the format's own (blanks for
// XYZ/TXT/PTS, commas for CSV), unless the line has none of it and has another: commas (or
// semicolons) in a .xyz/.txt/.pts file, semicolons or tabs in a .csv file.
char SniffDelimiter(std::string_view line, int format)
{
  const bool comma = line.find(',') != std::string_view::npos;
  const bool semicolon = line.find(';') != std::string_view::npos;
  const bool tab = line.find('\t') != std::string_view::npos;
  const bool blank = std::any_of(line.begin(), line.end(),
    [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  if (format == vtkPointCloudTextReader::CSV)
  {
    return comma ? ',' : semicolon ? ';' : tab ? '\t' : blank ? ' ' : ',';
  }
  return comma ? ',' : semicolon ? ';' : ' ';
}

// The first column that gives component k of array a.
size_t FirstColumn(const std::vector<ColumnTarget>& targets, int a, int k)
{
  for (size_t c = 0; c < targets.size(); ++c)
  {
    if (targets[c].Array == a && targets[c].Component == k)
    {
      return c;
    }
  }
  return 0;
}

// Header names to column targets: x/y/z, nx/ny/nz as Normals, NAME:k as components of NAME.
std::vector<ColumnTarget> TargetsFromHeader(
  const std::vector<std::string>& names, std::vector<ArraySpec>& arrays, std::string& problem)
{
  const size_t n = names.size();
  std::vector<ColumnTarget> targets(n);
  int coordinateColumn[3] = { -1, -1, -1 };
  for (size_t c = 0; c < n; ++c)
  {
    std::string name = Lower(names[c]);
    while (!name.empty() && name.front() == '/') // CloudCompare writes "//X"
    {
      name.erase(0, 1);
    }
    if (name == "x" || name == "y" || name == "z")
    {
      int& column = coordinateColumn[name[0] - 'x'];
      if (column >= 0)
      {
        // Which of them holds the coordinate is anyone's guess.
        problem = "the header names the coordinate '" + name + "' more than once (columns " +
          std::to_string(column + 1) + " and " + std::to_string(c + 1) + ")";
        return {};
      }
      column = static_cast<int>(c);
      targets[c].Coordinate = name[0] - 'x';
    }
  }
  if (coordinateColumn[0] < 0 || coordinateColumn[1] < 0 || coordinateColumn[2] < 0)
  {
    problem = "the header names no x, y and z columns";
    return {};
  }
  // nx, ny, nz are the components of Normals only when all three are there: a lone "nx" is a
  // column of its own (as "Normals" it would be replaced by the filters' normals).
  int normalColumns = 0;
  for (size_t c = 0; c < n; ++c)
  {
    const std::string lower = Lower(names[c]);
    normalColumns |= lower == "nx" ? 1 : lower == "ny" ? 2 : lower == "nz" ? 4 : 0;
  }
  std::map<std::string, int> arrayIndex;
  for (size_t c = 0; c < n; ++c)
  {
    if (targets[c].Coordinate >= 0)
    {
      continue;
    }
    std::string name = names[c];
    int component = 0;
    const std::string lower = Lower(name);
    if (normalColumns == 7 && (lower == "nx" || lower == "ny" || lower == "nz"))
    {
      component = lower[1] - 'x';
      name = "Normals";
    }
    else
    {
      const size_t colon = name.rfind(':');
      int k = 0;
      if (colon != std::string::npos && colon + 1 < name.size() &&
        std::from_chars(name.data() + colon + 1, name.data() + name.size(), k).ptr ==
          name.data() + name.size() &&
        k >= 0)
      {
        component = k;
        name.erase(colon);
      }
    }
    auto found = arrayIndex.find(name);
    if (found == arrayIndex.end())
    {
      found = arrayIndex.emplace(name, static_cast<int>(arrays.size())).first;
      arrays.push_back(ArraySpec{ name, 0, false, {} });
    }
    targets[c].Array = found->second;
    targets[c].Component = component;
    arrays[found->second].Components = std::max(arrays[found->second].Components, component + 1);
  }
  if (arrays.size() > vtkPointCloudTextReader::MaximumNumberOfArrays)
  {
    problem = "the header names " + std::to_string(arrays.size()) +
      " point arrays besides x, y, z; at most " +
      std::to_string(vtkPointCloudTextReader::MaximumNumberOfArrays) +
      " are read (name the columns of one array NAME:0, NAME:1, ...)";
    return {};
  }
  // Every component of a grouped array must have its column exactly once.
  std::vector<std::vector<int>> seen(arrays.size());
  for (size_t a = 0; a < arrays.size(); ++a)
  {
    if (arrays[a].Components > static_cast<int>(n))
    {
      problem = "the header names component " + std::to_string(arrays[a].Components - 1) +
        " of '" + arrays[a].Name + "', but has only " + std::to_string(n) + " columns";
      return {};
    }
    seen[a].assign(arrays[a].Components, 0);
  }
  for (const ColumnTarget& t : targets)
  {
    if (t.Array >= 0)
    {
      ++seen[t.Array][t.Component];
    }
  }
  for (size_t a = 0; a < arrays.size(); ++a)
  {
    for (int k = 0; k < arrays[a].Components; ++k)
    {
      if (seen[a][k] == 1)
      {
        continue;
      }
      if (seen[a][k] == 0)
      {
        problem = "the header names components of '" + arrays[a].Name + "' up to " +
          std::to_string(arrays[a].Components - 1) + " but no column '" + arrays[a].Name + ":" +
          std::to_string(k) + "'";
        return {};
      }
      // The same name twice: which columns (counting from 1).
      std::string columns;
      for (size_t c = 0; c < n; ++c)
      {
        if (targets[c].Array == static_cast<int>(a) && targets[c].Component == k)
        {
          columns += (columns.empty() ? "" : " and ") + std::to_string(c + 1);
        }
      }
      const std::string& name = names[FirstColumn(targets, static_cast<int>(a), k)];
      problem = (name.empty() ? std::string("the header leaves more than one column unnamed")
                              : "the header names '" + name + "' more than once") +
        " (columns " + columns + ")";
      return {};
    }
  }
  return targets;
}

// Columns without a header: x, y, z, then `Field 3` ...; PTS's intensity and colours.
std::vector<ColumnTarget> TargetsByPosition(size_t n, bool pts, std::vector<ArraySpec>& arrays)
{
  std::vector<ColumnTarget> targets(n);
  for (int c = 0; c < 3; ++c)
  {
    targets[c].Coordinate = c;
  }
  size_t c = 3;
  if (pts && (n == 4 || n == 7))
  {
    arrays.push_back(ArraySpec{ "Intensity", 1, false, {} });
    targets[c++].Array = static_cast<int>(arrays.size() - 1);
  }
  if (pts && (n == 6 || n == 7))
  {
    arrays.push_back(ArraySpec{ "RGB", 3, true, {} });
    for (int k = 0; k < 3; ++k, ++c)
    {
      targets[c].Array = static_cast<int>(arrays.size() - 1);
      targets[c].Component = k;
    }
  }
  for (; c < n; ++c)
  {
    arrays.push_back(ArraySpec{ "Field " + std::to_string(c), 1, false, {} });
    targets[c].Array = static_cast<int>(arrays.size() - 1);
  }
  return targets;
}

// What stops a read: the error code, the line (0: the file as a whole) and what is wrong.
struct Problem
{
  unsigned long Code = vtkErrorCode::NoError;
  long Line = 0;
  std::string What;
};

// One read of a text file, line by line: each kind of line (a PTS count, the header or the first
// data line, a point) is one member function, which returns false with `Stop` set when the file
// is malformed.
struct TextParse
{
  int Format;
  char Delimiter;
  std::vector<ColumnTarget> Targets;
  std::vector<ArraySpec> Arrays;
  std::vector<double> XYZ;
  std::vector<std::string_view> Fields;
  long ReferenceLine = 0; // the header, or the first data line: it fixes the number of fields
  bool ReferenceIsHeader = false;
  long CountLine = 0;            // the first PTS count line
  long long DeclaredCount = -1;  // the points all the count lines declare
  long long ScanEnd = -1;        // the number of points at which the current PTS scan ends
  long long ScanPoints = 0;      // the points the current PTS scan's count line declares
  long ScanLine = 0;             // the current PTS scan's count line
  std::string ScanText;          // its count, as written
  int Scans = 0;
  bool First = true;
  Problem Stop;

  explicit TextParse(int format)
    : Format(format)
    , Delimiter(format == vtkPointCloudTextReader::CSV ? ',' : ' ')
  {
  }

  bool Fail(unsigned long code, long line, const std::string& what)
  {
    this->Stop = Problem{ code, line, what };
    return false;
  }

  vtkIdType NumberOfPoints() const { return static_cast<vtkIdType>(this->XYZ.size() / 3); }

  // A line that is not empty nor a comment, trimmed.
  bool Line(std::string_view trimmed, long number)
  {
    double ignored = 0.0;
    if (this->Format == vtkPointCloudTextReader::PTS &&
      (this->CountLine == 0 ||
        (this->NumberOfPoints() == this->ScanEnd &&
          (CountValue(trimmed, ignored) || AllDigits(trimmed)))))
    {
      return this->Count(trimmed, number); // the first scan's count, or the next scan's
    }
    if (this->First)
    {
      bool header = false;
      if (!this->FirstLine(trimmed, number, header))
      {
        return false;
      }
      if (header)
      {
        return true;
      }
    }
    else
    {
      Split(trimmed, this->Delimiter, this->Fields);
    }
    return this->Point(number);
  }

  // A PTS scan's count line (the file's first line, and the line before each further scan).
  bool Count(std::string_view trimmed, long number)
  {
    const std::string text = Shorten(trimmed);
    double count = 0.0;
    // A count beyond 2^62 would overflow the conversion; no file holds that many points anyway.
    const bool huge =
      AllDigits(trimmed) && !(ParseNumber(trimmed, count) && count <= 4611686018427387904.0);
    if (!huge && !CountValue(trimmed, count))
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        "a PTS file starts with its number of points; found '" + text + "'");
    }
    const long long points = huge ? -1 : static_cast<long long>(count);
    if (points < 0 || std::max(this->DeclaredCount, 0LL) > 4611686018427387904LL - points)
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        "the PTS count line says " + text + " points: more than any file holds");
    }
    this->DeclaredCount = std::max(this->DeclaredCount, 0LL) + points;
    this->ScanEnd = this->NumberOfPoints() + points;
    this->ScanPoints = points;
    this->ScanLine = number;
    this->ScanText = text;
    this->CountLine = this->CountLine == 0 ? number : this->CountLine;
    ++this->Scans;
    return true;
  }

  // A field that reads as a PTS count: a whole number of 0 or more.
  static bool CountValue(std::string_view trimmed, double& count)
  {
    return ParseNumber(trimmed, count) && count >= 0 && count == std::floor(count);
  }

  // A field of digits only (after an optional '+'): a count, however large.
  static bool AllDigits(std::string_view field)
  {
    const size_t first = !field.empty() && field[0] == '+' ? 1 : 0;
    return first < field.size() &&
      std::all_of(field.begin() + first, field.end(), [](char c) { return c >= '0' && c <= '9'; });
  }

  // At most 40 characters of a field for a message.
  static std::string Shorten(std::string_view field)
  {
    return field.size() <= 40 ? std::string(field)
                              : std::string(field.substr(0, 40)) + "... (" +
        std::to_string(field.size()) + " characters)";
  }

  // The first line after any count: the delimiter, and the columns from the header or by
  // position. A header has no finite number and some field that is no number at all
  // ("x,y,z,nan" is a header, "nan,nan,nan" data): a line with some numbers is data, with a bad
  // field.
  bool FirstLine(std::string_view trimmed, long number, bool& header)
  {
    this->Delimiter = SniffDelimiter(trimmed, this->Format);
    Split(trimmed, this->Delimiter, this->Fields);
    bool finite = false;
    double value;
    header = false;
    for (std::string_view f : this->Fields)
    {
      const bool isNumber = ParseNumber(f, value);
      header = header || !isNumber;
      finite = finite || (isNumber && std::isfinite(value));
    }
    header = header && !finite;
    this->First = false;
    this->ReferenceLine = number;
    if (header)
    {
      std::vector<std::string> names;
      for (std::string_view f : this->Fields)
      {
        if (f.size() >= 2 && (f.front() == '"' || f.front() == '\'') && f.back() == f.front())
        {
          f = f.substr(1, f.size() - 2);
        }
        names.emplace_back(f);
      }
      std::string problem;
      this->Targets = TargetsFromHeader(names, this->Arrays, problem);
      if (this->Targets.empty())
      {
        // Every field written like a number ("0x1p-1", "1,5" split wrong, "1e"): data with a
        // field the reader cannot read, not a header.
        const auto numeric = [](std::string_view f) {
          size_t i = !f.empty() && (f[0] == '+' || f[0] == '-') ? 1 : 0;
          i += i < f.size() && f[i] == '.' ? 1 : 0;
          return i < f.size() && std::isdigit(static_cast<unsigned char>(f[i])) != 0;
        };
        if (std::all_of(this->Fields.begin(), this->Fields.end(), numeric))
        {
          for (size_t c = 0; c < this->Fields.size(); ++c)
          {
            if (!ParseNumber(this->Fields[c], value))
            {
              const std::string_view f = this->Fields[c];
              const bool hex = f.find("0x") != std::string_view::npos ||
                f.find("0X") != std::string_view::npos;
              return this->Fail(vtkErrorCode::FileFormatError, number,
                "field " + std::to_string(c + 1) + " ('" + Shorten(f) + "') is not a number" +
                  (hex ? " (hexadecimal numbers are not read)" : ""));
            }
          }
        }
        return this->Fail(vtkErrorCode::FileFormatError, number, problem);
      }
      this->ReferenceIsHeader = true;
      return true;
    }
    const size_t n = this->Fields.size();
    if (n < 3)
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        "a point needs 3 coordinates; the line has " + std::to_string(n) + " field(s)");
    }
    if (n - 3 > vtkPointCloudTextReader::MaximumNumberOfArrays)
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        std::to_string(n) + " fields: at most " +
          std::to_string(vtkPointCloudTextReader::MaximumNumberOfArrays + 3) +
          " are read (x, y, z and one point array per further column)");
    }
    this->Targets = TargetsByPosition(n, this->Format == vtkPointCloudTextReader::PTS, this->Arrays);
    return true;
  }

  // The fields of a data line: the point's coordinates and its values of each array.
  bool Point(long number)
  {
    const std::vector<std::string_view>& fields = this->Fields;
    double count = 0.0;
    if (this->Format == vtkPointCloudTextReader::PTS && fields.size() == 1 &&
      CountValue(fields[0], count))
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        "'" + Shorten(fields[0]) + "' reads as a scan's count line, but the scan counted on line " +
          std::to_string(this->ScanLine) + " (" + this->ScanText + " points) has " +
          std::to_string(this->NumberOfPoints() - (this->ScanEnd - this->ScanPoints)) +
          " before it");
    }
    if (fields.size() != this->Targets.size())
    {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        std::to_string(fields.size()) + " field(s), expected " +
          std::to_string(this->Targets.size()) +
          (this->ReferenceIsHeader ? " (as in the header on line " : " (as on line ") +
          std::to_string(this->ReferenceLine) + ")");
    }
    // "field N ('TEXT') is not ...".
    auto bad = [&](size_t c, const char* what) {
      return this->Fail(vtkErrorCode::FileFormatError, number,
        "field " + std::to_string(c + 1) + " ('" + std::string(fields[c]) + "') is not " + what);
    };
    double point[3] = { 0.0, 0.0, 0.0 };
    for (size_t c = 0; c < fields.size(); ++c)
    {
      double value = 0.0;
      bool outOfRange = false;
      if (!ParseNumber(fields[c], value, &outOfRange))
      {
        return bad(c, outOfRange ? "within the range of a double (about 1.8e308)" : "a number");
      }
      if (!std::isfinite(value))
      {
        return bad(c, "a finite number");
      }
      const ColumnTarget& t = this->Targets[c];
      if (t.Coordinate >= 0)
      {
        point[t.Coordinate] = value;
        continue;
      }
      ArraySpec& a = this->Arrays[t.Array];
      if (a.Colour && (value < 0.0 || value > 255.0 || value != std::floor(value)))
      {
        return bad(c, "a colour value (an integer from 0 to 255)");
      }
      const size_t tuple = this->XYZ.size() / 3;
      if (a.Values.size() < (tuple + 1) * a.Components)
      {
        a.Values.resize((tuple + 1) * a.Components, 0.0);
      }
      a.Values[tuple * a.Components + t.Component] = value;
    }
    this->XYZ.insert(this->XYZ.end(), point, point + 3);
    return true;
  }

  // What only the whole file tells: a PTS count that does not match, no point at all.
  bool Finish()
  {
    const vtkIdType n = this->NumberOfPoints();
    if (this->Format == vtkPointCloudTextReader::PTS && this->CountLine == 0)
    {
      return this->Fail(vtkErrorCode::FileFormatError, 0, "the file is empty (no PTS count line)");
    }
    if (this->DeclaredCount >= 0 && this->DeclaredCount != n)
    {
      // Every scan but the last was checked when the next one's count line came: the last one
      // is short.
      return this->Fail(vtkErrorCode::FileFormatError, this->ScanLine,
        this->Scans > 1 ? "the count line of the last of " + std::to_string(this->Scans) +
            " scans says " + this->ScanText + " points but the scan has " +
            std::to_string(n - (this->ScanEnd - this->ScanPoints))
                        : "the count line says " + this->ScanText + " points but the file has " +
            std::to_string(n));
    }
    if (n == 0 && this->Format != vtkPointCloudTextReader::PTS)
    {
      return this->Fail(vtkErrorCode::FileFormatError, 0, "the file holds no point");
    }
    return true;
  }

  // The points and one array per ArraySpec (colours as unsigned char), the values handed over.
  void FillOutput(vtkPolyData* output)
  {
    const vtkIdType n = this->NumberOfPoints();
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(n);
    std::copy(this->XYZ.begin(), this->XYZ.end(), coordinates->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    output->SetPoints(points);
    for (ArraySpec& a : this->Arrays)
    {
      a.Values.resize(static_cast<size_t>(n) * a.Components, 0.0);
      vtkSmartPointer<vtkDataArray> array;
      if (a.Colour)
      {
        auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
        colours->SetNumberOfComponents(a.Components);
        colours->SetNumberOfTuples(n);
        std::transform(a.Values.begin(), a.Values.end(), colours->GetPointer(0),
          [](double v) { return static_cast<unsigned char>(v); });
        array = colours;
      }
      else
      {
        auto values = vtkSmartPointer<vtkDoubleArray>::New();
        values->SetNumberOfComponents(a.Components);
        values->SetNumberOfTuples(n);
        std::copy(a.Values.begin(), a.Values.end(), values->GetPointer(0));
        array = values;
      }
      array->SetName(a.Name.c_str());
      std::vector<double>().swap(a.Values);
      output->GetPointData()->AddArray(array);
      if (a.Name == "Normals" && a.Components == 3)
      {
        output->GetPointData()->SetNormals(array);
      }
      else if (a.Colour)
      {
        output->GetPointData()->SetScalars(array);
      }
    }
  }
};

// The error for a NUL byte on line `line`, at offset `byte` (counting from 0): no text holds one.
Problem BinaryData(long line, long long byte)
{
  return Problem{ vtkErrorCode::FileFormatError, line,
    "binary data (a NUL byte at byte " + std::to_string(byte) + "), not a text file" };
}

// What the file's first bytes say against reading it as text: UTF-16 (a byte order mark, or a
// NUL in every other byte of the first line: each character would read as two, the second a
// NUL), or binary data (a NUL byte anywhere in `start`, as in a LAS or PLY file given the wrong
// extension). Looked at before any line is parsed, so that binary data is named as such rather
// than as a header without x, y and z. Code NoError when the start reads as text.
Problem SniffText(std::string_view start)
{
  const char* const first = start.data();
  if (start.substr(0, 3) == "\xEF\xBB\xBF")
  {
    start.remove_prefix(3); // a UTF-8 byte order mark
  }
  const std::string_view line = start.substr(0, start.find('\n'));
  // UTF-16 without a byte order mark: NUL bytes on one side only (the high bytes of Latin text,
  // little- or big-endian), at least half of that side's bytes; binary data has NUL bytes on
  // both sides, or a few anywhere.
  size_t nul[2] = { 0, 0 };
  for (size_t i = 0; i < line.size(); ++i)
  {
    nul[i % 2] += line[i] == '\0';
  }
  const size_t sides[2] = { (line.size() + 1) / 2, line.size() / 2 };
  const bool utf16 = start.substr(0, 2) == "\xFF\xFE" || start.substr(0, 2) == "\xFE\xFF" ||
    (line.size() >= 4 &&
      ((nul[0] == 0 && nul[1] >= 2 && 2 * nul[1] >= sides[1]) ||
        (nul[1] == 0 && nul[0] >= 2 && 2 * nul[0] >= sides[0])));
  if (utf16)
  {
    return Problem{ vtkErrorCode::FileFormatError, 1,
      "the file is UTF-16 text; save it as UTF-8 or ASCII (iconv -f UTF-16 -t UTF-8)" };
  }
  const size_t at = start.find('\0');
  if (at != std::string_view::npos)
  {
    const long number = 1 + static_cast<long>(std::count(start.begin(), start.begin() + at, '\n'));
    return BinaryData(number, static_cast<long long>(at + (start.data() - first)));
  }
  return Problem{};
}

// The format of AUTOMATIC, from the file name's extension.
int FormatOfFile(const std::string& file)
{
  const size_t dot = file.rfind('.');
  const std::string extension = dot == std::string::npos ? "" : Lower(file.substr(dot + 1));
  return extension == "csv" ? vtkPointCloudTextReader::CSV
    : extension == "pts"    ? vtkPointCloudTextReader::PTS
                            : vtkPointCloudTextReader::XYZ;
}
} // namespace

vtkPointCloudTextReader::vtkPointCloudTextReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudTextReader::~vtkPointCloudTextReader()
{
  this->SetFileName(nullptr);
}

int vtkPointCloudTextReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->ErrorMessage.clear();
  this->SetErrorCode(vtkErrorCode::NoError);
  const std::string file = this->FileName ? this->FileName : "";
  // Every error: the file, the line when there is one, and what is wrong; an empty output.
  auto fail = [&](const Problem& problem) {
    std::ostringstream message;
    message << file;
    if (problem.Line > 0)
    {
      message << ":" << problem.Line;
    }
    message << ": " << problem.What;
    this->ErrorMessage = vtkPointCloudIO::OneLine(message.str());
    vtkErrorMacro(<< this->ErrorMessage);
    this->SetErrorCode(problem.Code);
    output->Initialize();
    return 1;
  };
  if (file.empty())
  {
    return fail(Problem{ vtkErrorCode::NoFileNameError, 0, "no file name given" });
  }
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    return fail(Problem{ vtkErrorCode::CannotOpenFileError, 0, "cannot open the file" });
  }
  in.seekg(0, std::ios::end);
  const double fileSize = std::max(1.0, static_cast<double>(in.tellg()));
  in.seekg(0, std::ios::beg);

  // UTF-16 and binary data are told from the first 64 KiB, before any line is parsed.
  {
    std::string start(65536, '\0');
    in.read(&start[0], static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<size_t>(in.gcount()));
    const Problem sniffed = SniffText(start);
    if (sniffed.Code != vtkErrorCode::NoError)
    {
      return fail(sniffed);
    }
    in.clear();
    in.seekg(0, std::ios::beg);
  }

  TextParse parse(this->Format == AUTOMATIC ? FormatOfFile(file) : this->Format);
  std::string text;
  long lineNumber = 0;
  long long lineStart = 0; // the byte the line starts at
  while (std::getline(in, text))
  {
    ++lineNumber;
    std::string_view line(text);
    if (lineNumber == 1 && line.substr(0, 3) == "\xEF\xBB\xBF")
    {
      line.remove_prefix(3); // a UTF-8 byte order mark
    }
    // A NUL past the start that SniffText() saw.
    const size_t nul = text.find('\0');
    if (nul != std::string::npos)
    {
      return fail(BinaryData(lineNumber, lineStart + static_cast<long long>(nul)));
    }
    lineStart += static_cast<long long>(text.size()) + 1;
    if (!line.empty() && line.back() == '\r')
    {
      line.remove_suffix(1);
    }
    const std::string_view trimmed = Trim(line);
    if (trimmed.empty() || trimmed.front() == '#')
    {
      continue;
    }
    // A carriage return with data after it (trailing ones are trimmed as whitespace).
    if (trimmed.find('\r') != std::string_view::npos)
    {
      return fail(Problem{ vtkErrorCode::FileFormatError, lineNumber,
        "a carriage return inside the line: the file's lines end in CR alone (old Mac text); "
        "convert them to LF (tr '\\r' '\\n')" });
    }
    const vtkIdType before = parse.NumberOfPoints();
    if (!parse.Line(trimmed, lineNumber))
    {
      return fail(parse.Stop);
    }
    if (parse.NumberOfPoints() != before && parse.NumberOfPoints() % 65536 == 0)
    {
      this->UpdateProgress(std::min(0.99, static_cast<double>(in.tellg()) / fileSize));
    }
  }
  if (in.bad())
  {
    return fail(Problem{ vtkErrorCode::PrematureEndOfFileError, lineNumber, "read error" });
  }
  if (!parse.Finish())
  {
    return fail(parse.Stop);
  }
  parse.FillOutput(output);
  if (this->CreateVertexCells)
  {
    output->SetVerts(vtkPointCloudIO::MakeVertexCells(parse.NumberOfPoints()));
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkPointCloudTextReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Format: " << this->Format << "\n";
  os << indent << "CreateVertexCells: " << this->CreateVertexCells << "\n";
}
