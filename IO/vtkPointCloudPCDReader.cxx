#include "vtkPointCloudPCDReader.h"
#include "vtkPointCloudPCDTypes.h"
#include "vtkPointCloudFiles.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <lzf.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkPointCloudPCDReader);

using featurepoints::HostIsBigEndian;
using featurepoints::Load;

using namespace featurepoints::pcd;

namespace
{
constexpr size_t MaxHeaderLine = size_t(1) << 20;
constexpr size_t MaxDataLine = size_t(64) << 20;
constexpr size_t ChunkBytes = size_t(4) << 20;
// A point of more values than this is not a point cloud (PCL's largest descriptors have a few
// hundred).
constexpr uint64_t MaxValuesPerPoint = uint64_t(1) << 20;
// LZF's longest back reference (3 bytes) stands for 264 bytes: no LZF block decompresses to more
// than 88 times its size.
constexpr uint64_t MaxLZFExpansion = 88;

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

void Split(std::string_view line, std::vector<std::string_view>& tokens)
{
  tokens.clear();
  size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && IsSpace(line[i]))
    {
      ++i;
    }
    const size_t begin = i;
    while (i < line.size() && !IsSpace(line[i]))
    {
      ++i;
    }
    if (i > begin)
    {
      tokens.push_back(line.substr(begin, i - begin));
    }
  }
}

using featurepoints::Quote;

bool ParseCount(std::string_view token, uint64_t& value)
{
  const char* end = token.data() + token.size();
  auto r = std::from_chars(token.data(), end, value);
  return r.ec == std::errc() && r.ptr == end;
}

// Parses a value of type T; the whole token must be the number. An empty string: the value is
// fine; otherwise what is wrong with the token.
template <typename T>
std::string ParseValue(std::string_view token, T& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  if (last - first > 1 && *first == '+' && first[1] != '-')
  {
    ++first; // std::from_chars does not accept a leading '+'
  }
  const std::string quoted = Quote(token);
  if constexpr (std::is_floating_point<T>::value)
  {
    auto r = std::from_chars(first, last, value);
    if (r.ec == std::errc::result_out_of_range && r.ptr == last)
    {
      // Underflow is a value too close to 0 for T: keep its rounding (a signed zero beyond long
      // double's range too); overflow is an error.
      if (!featurepoints::Underflows(std::string_view(first, static_cast<size_t>(last - first))))
      {
        return quoted + " is out of range for F " + std::to_string(sizeof(T));
      }
      long double wide;
      auto w = std::from_chars(first, last, wide);
      value = w.ec == std::errc() && w.ptr == last ? static_cast<T>(wide)
        : *first == '-'                            ? -T(0)
                                                   : T(0);
      return "";
    }
    return (r.ec == std::errc() && r.ptr == last) ? "" : quoted + " is not a number";
  }
  else
  {
    auto r = std::from_chars(first, last, value);
    if (r.ec == std::errc() && r.ptr == last)
    {
      return "";
    }
    const char letter = std::is_signed<T>::value ? 'I' : 'U';
    const std::string type = std::string(1, letter) + " " + std::to_string(sizeof(T));
    if (r.ec == std::errc::result_out_of_range && r.ptr == last)
    {
      return quoted + " is out of range for " + type;
    }
    double d;
    auto f = std::from_chars(first, last, d);
    if (f.ec == std::errc() && f.ptr == last)
    {
      return quoted + " is not " +
        (std::is_signed<T>::value || d >= 0 ? "an integer" : "unsigned") + " (type " + type + ")";
    }
    return quoted + " is not a number";
  }
}

// Buffered reading of the file: lines for the header and ASCII data, bytes for binary data.
class Input
{
public:
  Input(std::istream& stream, uint64_t size)
    : Stream(stream)
    , Size(size)
    , Buffer(size_t(1) << 16)
  {
  }

  uint64_t FileSize() const { return this->Size; }
  uint64_t Position() const { return this->Offset + this->Begin; }
  uint64_t Remaining() const { return this->Size - std::min(this->Position(), this->Size); }
  bool TooLong() const { return this->LineTooLong; }
  bool IOError() const { return this->Stream.bad(); }

  // The next line without its "\n" or "\r\n"; false at the end of the file, or when the line is
  // longer than maxLength (TooLong() then says so).
  bool NextLine(std::string_view& line, size_t maxLength)
  {
    size_t scanned = 0;
    for (;;)
    {
      const char* base = this->Buffer.data();
      const void* nl =
        std::memchr(base + this->Begin + scanned, '\n', this->End - this->Begin - scanned);
      if (nl)
      {
        const size_t stop = static_cast<size_t>(static_cast<const char*>(nl) - base);
        line = std::string_view(base + this->Begin, stop - this->Begin);
        this->Begin = stop + 1;
        break;
      }
      scanned = this->End - this->Begin;
      if (scanned > maxLength)
      {
        this->LineTooLong = true;
        return false;
      }
      if (!this->Fill())
      {
        if (this->Begin == this->End)
        {
          return false;
        }
        line = std::string_view(this->Buffer.data() + this->Begin, this->End - this->Begin);
        this->Begin = this->End;
        break;
      }
    }
    if (!line.empty() && line.back() == '\r')
    {
      line.remove_suffix(1);
    }
    return true;
  }

  // False when the file ends first.
  bool Read(char* dst, size_t n)
  {
    const size_t take = std::min(n, this->End - this->Begin);
    std::memcpy(dst, this->Buffer.data() + this->Begin, take);
    this->Begin += take;
    dst += take;
    n -= take;
    if (n == 0)
    {
      return true;
    }
    // The rest goes straight to its destination.
    this->Offset += this->End;
    this->Begin = this->End = 0;
    this->Stream.read(dst, static_cast<std::streamsize>(n));
    const auto got = static_cast<size_t>(this->Stream.gcount());
    this->Offset += got;
    return got == n;
  }

private:
  // Keeps the unread bytes and appends more; false when nothing more could be read.
  bool Fill()
  {
    if (this->Begin > 0)
    {
      std::memmove(this->Buffer.data(), this->Buffer.data() + this->Begin, this->End - this->Begin);
      this->Offset += this->Begin;
      this->End -= this->Begin;
      this->Begin = 0;
    }
    if (this->End == this->Buffer.size())
    {
      this->Buffer.resize(2 * this->Buffer.size());
    }
    if (!this->Stream.good())
    {
      return false;
    }
    this->Stream.read(this->Buffer.data() + this->End,
      static_cast<std::streamsize>(this->Buffer.size() - this->End));
    const auto got = static_cast<size_t>(this->Stream.gcount());
    this->End += got;
    return got > 0;
  }

  std::istream& Stream;
  uint64_t Size;
  std::vector<char> Buffer;
  size_t Begin = 0;    // next unread byte of Buffer
  size_t End = 0;      // end of the valid bytes of Buffer
  uint64_t Offset = 0; // file offset of Buffer[0]
  bool LineTooLong = false;
};

struct Field
{
  std::string Name;
  PcdType Type = PcdType::Float32;
  uint64_t Count = 1;
  size_t Offset = 0; // in a packed (binary) row
};

enum class Encoding
{
  None,
  Ascii,
  Binary,
  Compressed
};

// Where the values of one field go.
struct Target
{
  enum
  {
    Skip,    // padding
    Copy,    // Count values to components [Component, Component + Count) of the array
    Colour3, // packed 0x00RRGGBB to 3 unsigned chars
    Colour4  // packed 0xAARRGGBB to 4 unsigned chars (r, g, b, a)
  } Kind = Skip;
  vtkDataArray* Array = nullptr;
  int Component = 0;
};

// The file, parsed in one pass. Every method returns false after setting Error.
class PCDParser
{
public:
  PCDParser(const std::string& fileName, std::istream& stream, uint64_t size)
    : FileName(fileName)
    , In(stream, size)
  {
  }

  bool Read(vtkPolyData* output, bool decodeColors, bool createVertexCells);

  std::string Error;
  uint64_t Width = 0, Height = 1, Points = 0;
  vtkIdType Skipped = 0;

private:
  bool Fail(const std::string& what, int line = 0)
  {
    this->Error =
      this->FileName + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what;
    return false;
  }
  bool FailEnd(uint64_t point, const std::string& detail)
  {
    return this->Fail(std::string(this->In.IOError() ? "read error in " : "the file ends in ") +
      "point " + std::to_string(point + 1) + " of " + std::to_string(this->Points) + " (" + detail +
      ")");
  }
  bool ReadHeader();
  bool CheckHeader();
  bool Prepare(vtkPolyData* output, bool decodeColors);
  void Decode(const char* base, size_t stride, size_t fieldStep, vtkIdType first, vtkIdType count,
    size_t field);
  bool ReadAscii();
  bool ReadBinary();
  bool ReadCompressedSizes();
  bool ReadCompressed();
  bool RemoveInvalidPoints(vtkPolyData* output);
  bool RecordFilePoints(vtkPolyData* output, const std::vector<unsigned char>& keep);

  std::string FileName;
  Input In;
  int Line = 0;
  Encoding Data = Encoding::None;
  std::vector<Field> Fields;
  std::vector<Target> Targets; // one per field
  size_t RowSize = 0;          // bytes of a packed point
  uint64_t ValuesPerPoint = 0; // values of an ASCII line
  bool Swap = HostIsBigEndian();
  std::vector<std::string_view> Tokens;
  // The lines of the header keywords, for messages.
  std::map<std::string, int> KeywordLine;
  std::vector<std::string> Sizes, Types, Counts;
  bool HasWidth = false, HasHeight = false, HasPoints = false;
  uint32_t CompressedBytes = 0;
  // ASCII data: the points whose line is not the one after the previous point's (blank lines
  // before them), with that line; every other point's line follows from the last such point.
  std::vector<std::pair<vtkIdType, int>> LineRuns;
};

bool PCDParser::ReadHeader()
{
  std::string_view line;
  std::vector<std::string_view>& w = this->Tokens;
  bool first = true;
  for (;;)
  {
    if (!this->In.NextLine(line, MaxHeaderLine))
    {
      if (this->In.TooLong())
      {
        return this->Fail(
          "header line longer than " + std::to_string(MaxHeaderLine) + " bytes", this->Line + 1);
      }
      return this->Fail(
        first ? std::string("empty file, not a PCD file") : "the header ends without a DATA line");
    }
    ++this->Line;
    Split(line, w);
    if (w.empty() || w[0][0] == '#')
    {
      continue;
    }
    const std::string keyword(w[0]);
    const auto quote = Quote;
    static const std::set<std::string> known = { "VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE",
      "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA" };
    if (!known.count(keyword))
    {
      return this->Fail(first
          ? "not a PCD file (its first line is not a PCD header line such as VERSION or FIELDS)"
          : "unknown header keyword " + quote(w[0]),
        this->Line);
    }
    first = false;
    if (!this->KeywordLine.emplace(keyword, this->Line).second)
    {
      return this->Fail("second " + keyword + " line", this->Line);
    }
    auto bad = [this](const std::string& what) { return this->Fail(what, this->Line); };
    if (keyword == "FIELDS" || keyword == "COLUMNS")
    {
      if (this->KeywordLine.count("FIELDS") && this->KeywordLine.count("COLUMNS"))
      {
        return bad("both FIELDS and COLUMNS lines");
      }
      if (w.size() < 2)
      {
        return bad(keyword + " line without field names");
      }
      std::set<std::string> names;
      for (size_t i = 1; i < w.size(); ++i)
      {
        Field f;
        f.Name = std::string(w[i]);
        if (f.Name != "_" && !names.insert(f.Name).second)
        {
          return bad("second field named " + quote(w[i]));
        }
        this->Fields.push_back(f);
      }
    }
    else if (keyword == "SIZE" || keyword == "TYPE" || keyword == "COUNT")
    {
      std::vector<std::string>& values = keyword == "SIZE" ? this->Sizes
        : keyword == "TYPE"                                ? this->Types
                                                           : this->Counts;
      for (size_t i = 1; i < w.size(); ++i)
      {
        values.emplace_back(w[i]);
      }
    }
    else if (keyword == "WIDTH" || keyword == "HEIGHT" || keyword == "POINTS")
    {
      uint64_t value = 0;
      if (w.size() != 2 || !ParseCount(w[1], value))
      {
        return bad("malformed " + keyword + " line (expected \"" + keyword +
          " N\", N a non-negative integer)");
      }
      (keyword == "WIDTH"       ? this->Width
          : keyword == "HEIGHT" ? this->Height
                                : this->Points) = value;
      (keyword == "WIDTH"       ? this->HasWidth
          : keyword == "HEIGHT" ? this->HasHeight
                                : this->HasPoints) = true;
    }
    else if (keyword == "DATA")
    {
      if (w.size() != 2)
      {
        return bad("malformed DATA line (expected \"DATA ascii\", \"DATA binary\" or \"DATA "
                   "binary_compressed\")");
      }
      if (w[1] == "ascii")
      {
        this->Data = Encoding::Ascii;
      }
      else if (w[1] == "binary")
      {
        this->Data = Encoding::Binary;
      }
      else if (w[1] == "binary_compressed")
      {
        this->Data = Encoding::Compressed;
      }
      else
      {
        return bad(
          "unknown DATA encoding " + quote(w[1]) + " (ascii, binary or binary_compressed)");
      }
      return true;
    }
    // VERSION and VIEWPOINT say nothing the points need.
  }
}

bool PCDParser::CheckHeader()
{
  auto lineOf = [this](const char* keyword) {
    auto it = this->KeywordLine.find(keyword);
    return it == this->KeywordLine.end() ? 0 : it->second;
  };
  if (this->Fields.empty())
  {
    return this->Fail("the header has no FIELDS line");
  }
  const size_t nf = this->Fields.size();
  for (const char* keyword : { "SIZE", "TYPE" })
  {
    if (!lineOf(keyword))
    {
      return this->Fail(std::string("the header has no ") + keyword + " line");
    }
  }
  const std::pair<const char*, std::vector<std::string>*> lists[] = { { "SIZE", &this->Sizes },
    { "TYPE", &this->Types }, { "COUNT", &this->Counts } };
  for (const auto& list : lists)
  {
    if (lineOf(list.first) && list.second->size() != nf)
    {
      return this->Fail(std::string(list.first) + " has " + std::to_string(list.second->size()) +
          " values for " + std::to_string(nf) + " fields",
        lineOf(list.first));
    }
  }
  uint64_t values = 0;
  for (size_t i = 0; i < nf; ++i)
  {
    Field& f = this->Fields[i];
    uint64_t size = 0;
    if (!ParseCount(this->Sizes[i], size) || size > 8)
    {
      return this->Fail(
        "field " + Quote(f.Name) + ": SIZE " + Quote(this->Sizes[i]) + " is not 1, 2, 4 or 8",
        lineOf("SIZE"));
    }
    const std::string& letter = this->Types[i];
    if (letter.size() != 1 || !TypeFromLetter(letter[0], static_cast<int>(size), f.Type))
    {
      return this->Fail("field " + Quote(f.Name) + ": unknown type " + Quote(letter) + " of size " +
          std::to_string(size) + " (I and U of 1, 2, 4, 8 bytes, F of 4, 8)",
        lineOf("TYPE"));
    }
    if (!this->Counts.empty() &&
      (!ParseCount(this->Counts[i], f.Count) || f.Count == 0 || f.Count > MaxValuesPerPoint))
    {
      return this->Fail("field " + Quote(f.Name) + ": COUNT " + Quote(this->Counts[i]) +
          " is not an integer from 1 to " + std::to_string(MaxValuesPerPoint),
        lineOf("COUNT"));
    }
    values += f.Count;
    if (values > MaxValuesPerPoint)
    {
      return this->Fail("more than " + std::to_string(MaxValuesPerPoint) + " values per point");
    }
    f.Offset = this->RowSize;
    this->RowSize += static_cast<size_t>(f.Count * TypeSize(f.Type));
  }
  this->ValuesPerPoint = values;
  for (const char* axis : { "x", "y", "z" })
  {
    auto f = std::find_if(this->Fields.begin(), this->Fields.end(),
      [axis](const Field& field) { return field.Name == axis; });
    if (f == this->Fields.end())
    {
      return this->Fail(std::string("no ") + axis + " field", lineOf("FIELDS") + lineOf("COLUMNS"));
    }
    if (f->Count != 1)
    {
      return this->Fail(
        std::string("field ") + axis + " has COUNT " + std::to_string(f->Count) + ", 1 expected",
        lineOf("COUNT"));
    }
  }
  // POINTS is WIDTH x HEIGHT; either says the number of points when the other is missing.
  if (this->HasWidth && this->Height > 0 &&
    this->Width > std::numeric_limits<uint64_t>::max() / this->Height)
  {
    return this->Fail("WIDTH " + std::to_string(this->Width) + " x HEIGHT " +
        std::to_string(this->Height) + " overflows",
      lineOf("HEIGHT"));
  }
  if (this->HasPoints && this->HasWidth && this->Points != this->Width * this->Height)
  {
    return this->Fail("POINTS " + std::to_string(this->Points) + " is not WIDTH x HEIGHT (" +
        std::to_string(this->Width) + " x " + std::to_string(this->Height) + ")",
      lineOf("POINTS"));
  }
  if (!this->HasPoints && !this->HasWidth)
  {
    return this->Fail("the header has neither POINTS nor WIDTH: the number of points is unknown");
  }
  if (!this->HasPoints)
  {
    this->Points = this->Width * this->Height;
  }
  if (!this->HasWidth)
  {
    this->Width = this->Points;
    this->Height = 1;
  }
  if (this->Points > static_cast<uint64_t>(std::numeric_limits<vtkIdType>::max()))
  {
    return this->Fail("too many points (" + std::to_string(this->Points) + ")");
  }
  return true;
}

// Creates the output points and arrays and says where each field goes.
bool PCDParser::Prepare(vtkPolyData* output, bool decodeColors)
{
  const size_t nf = this->Fields.size();
  auto find = [this](const char* name) -> int {
    for (size_t i = 0; i < this->Fields.size(); ++i)
    {
      if (this->Fields[i].Name == name)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  };
  const vtkIdType n = static_cast<vtkIdType>(this->Points);
  this->Targets.assign(nf, Target());
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  auto allocate = [&](int vtkType, int components, const std::string& name) -> vtkDataArray* {
    auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(vtkType));
    array->SetName(name.empty() ? nullptr : name.c_str());
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(n);
    if (array->GetNumberOfTuples() != n || (n > 0 && !array->GetVoidPointer(0)))
    {
      return nullptr;
    }
    arrays.push_back(array);
    return array;
  };
  auto noMemory = [this, n]() {
    return this->Fail("cannot allocate memory for " + std::to_string(n) + " points");
  };

  // Points: double when float cannot hold every value of a coordinate field.
  const int xyz[3] = { find("x"), find("y"), find("z") };
  bool wide = false;
  for (int i : xyz)
  {
    const PcdType t = this->Fields[i].Type;
    wide = wide || t == PcdType::Float64 || (!IsFloatingPoint(t) && TypeSize(t) >= 4);
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(wide ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  vtkDataArray* coordinates = points->GetData();
  if (coordinates->GetNumberOfTuples() != n || (n > 0 && !coordinates->GetVoidPointer(0)))
  {
    return noMemory();
  }
  for (int c = 0; c < 3; ++c)
  {
    this->Targets[xyz[c]] = { Target::Copy, coordinates, c };
  }
  output->SetPoints(points);

  vtkPointData* pd = output->GetPointData();
  const int normal[3] = { find("normal_x"), find("normal_y"), find("normal_z") };
  if (normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0 && this->Fields[normal[0]].Count == 1 &&
    this->Fields[normal[1]].Count == 1 && this->Fields[normal[2]].Count == 1)
  {
    bool anyDouble = false;
    for (int i : normal)
    {
      anyDouble = anyDouble || this->Fields[i].Type == PcdType::Float64;
    }
    vtkDataArray* normals = allocate(anyDouble ? VTK_DOUBLE : VTK_FLOAT, 3, "Normals");
    if (!normals)
    {
      return noMemory();
    }
    for (int c = 0; c < 3; ++c)
    {
      this->Targets[normal[c]] = { Target::Copy, normals, c };
    }
    pd->SetNormals(normals);
  }
  if (decodeColors)
  {
    for (const char* name : { "rgb", "rgba" })
    {
      const int i = find(name);
      if (i < 0 || this->Fields[i].Count != 1 || TypeSize(this->Fields[i].Type) != 4)
      {
        continue;
      }
      const bool alpha = name[3] == 'a';
      vtkDataArray* colours = allocate(VTK_UNSIGNED_CHAR, alpha ? 4 : 3, alpha ? "RGBA" : "RGB");
      if (!colours)
      {
        return noMemory();
      }
      this->Targets[i] = { alpha ? Target::Colour4 : Target::Colour3, colours, 0 };
      if (!pd->GetScalars())
      {
        pd->SetScalars(colours);
      }
      else
      {
        pd->AddArray(colours);
      }
    }
  }
  // vtkPointData keeps one array per name: a field named like an array made above gets a suffix.
  std::set<std::string> names;
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    names.insert(pd->GetArrayName(a));
  }
  for (size_t i = 0; i < nf; ++i)
  {
    const Field& f = this->Fields[i];
    if (this->Targets[i].Kind != Target::Skip || f.Name == "_")
    {
      continue;
    }
    if (static_cast<size_t>(pd->GetNumberOfArrays()) >=
      vtkPointCloudPCDReader::MaximumNumberOfArrays)
    {
      return this->Fail("more than " +
        std::to_string(vtkPointCloudPCDReader::MaximumNumberOfArrays) +
        " fields besides x, y, z (as point arrays)");
    }
    std::string name = f.Name;
    for (int s = 2; names.count(name); ++s)
    {
      name = f.Name + "_" + std::to_string(s);
    }
    names.insert(name);
    vtkDataArray* array = allocate(VTKType(f.Type), static_cast<int>(f.Count), name);
    if (!array)
    {
      return noMemory();
    }
    this->Targets[i] = { Target::Copy, array, 0 };
    pd->AddArray(array);
  }
  return true;
}

// Decodes field `field` of points [first, first + count): the field's first value of point
// `first` is at base, the next point's `stride` bytes further, the next value of a point
// `fieldStep` bytes further.
void PCDParser::Decode(
  const char* base, size_t stride, size_t fieldStep, vtkIdType first, vtkIdType count, size_t field)
{
  const Field& f = this->Fields[field];
  const Target& t = this->Targets[field];
  const bool swap = this->Swap;
  if (t.Kind == Target::Skip)
  {
    return;
  }
  if (t.Kind == Target::Colour3 || t.Kind == Target::Colour4)
  {
    const int k = t.Kind == Target::Colour4 ? 4 : 3;
    unsigned char* dst = static_cast<unsigned char*>(t.Array->GetVoidPointer(0)) + first * k;
    for (vtkIdType i = 0; i < count; ++i, base += stride, dst += k)
    {
      const uint32_t packed = Load<uint32_t>(base, swap);
      dst[0] = static_cast<unsigned char>((packed >> 16) & 0xff);
      dst[1] = static_cast<unsigned char>((packed >> 8) & 0xff);
      dst[2] = static_cast<unsigned char>(packed & 0xff);
      if (k == 4)
      {
        dst[3] = static_cast<unsigned char>((packed >> 24) & 0xff);
      }
    }
    return;
  }
  const int components = t.Array->GetNumberOfComponents();
  const vtkIdType values = static_cast<vtkIdType>(f.Count);
  WithType(f.Type, [&](auto s) {
    using S = decltype(s);
    if (t.Array->GetDataType() == VTKType(f.Type))
    {
      S* dst = static_cast<S*>(t.Array->GetVoidPointer(0)) + first * components + t.Component;
      for (vtkIdType i = 0; i < count; ++i, base += stride, dst += components)
      {
        for (vtkIdType k = 0; k < values; ++k)
        {
          dst[k] = Load<S>(base + k * fieldStep, swap);
        }
      }
      return;
    }
    // Coordinates and normals: float or double.
    auto convert = [&](auto* dst) {
      using D = std::remove_pointer_t<decltype(dst)>;
      dst += first * components + t.Component;
      for (vtkIdType i = 0; i < count; ++i, base += stride, dst += components)
      {
        for (vtkIdType k = 0; k < values; ++k)
        {
          dst[k] = static_cast<D>(Load<S>(base + k * fieldStep, swap));
        }
      }
    };
    if (t.Array->GetDataType() == VTK_DOUBLE)
    {
      convert(static_cast<double*>(t.Array->GetVoidPointer(0)));
    }
    else
    {
      convert(static_cast<float*>(t.Array->GetVoidPointer(0)));
    }
  });
}

bool PCDParser::ReadBinary()
{
  const vtkIdType n = static_cast<vtkIdType>(this->Points);
  const size_t rowSize = this->RowSize;
  const uint64_t start = this->In.Position();
  const vtkIdType rowsPerChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
  std::vector<char> chunk(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
  for (vtkIdType first = 0; first < n; first += rowsPerChunk)
  {
    const vtkIdType rows = std::min(rowsPerChunk, n - first);
    if (!this->In.Read(chunk.data(), static_cast<size_t>(rows) * rowSize))
    {
      return this->FailEnd((this->In.Position() - start) / rowSize,
        "binary data of " + std::to_string(rowSize) + "-byte points from byte " +
          std::to_string(start) + ", the file has " + std::to_string(this->In.FileSize()) +
          " bytes");
    }
    for (size_t f = 0; f < this->Fields.size(); ++f)
    {
      this->Decode(chunk.data() + this->Fields[f].Offset, rowSize, TypeSize(this->Fields[f].Type),
        first, rows, f);
    }
  }
  return true;
}

// The sizes of the compressed block, checked against the header and the file before anything is
// allocated.
bool PCDParser::ReadCompressedSizes()
{
  const uint64_t start = this->In.Position();
  char sizes[8];
  if (!this->In.Read(sizes, 8))
  {
    return this->Fail("the file ends in the sizes of the compressed data (8 bytes from byte " +
      std::to_string(start) + ", the file has " + std::to_string(this->In.FileSize()) + " bytes)");
  }
  const uint32_t compressed = Load<uint32_t>(sizes, this->Swap);
  const uint32_t uncompressed = Load<uint32_t>(sizes + 4, this->Swap);
  const uint64_t expected = this->Points * this->RowSize;
  if (uncompressed != expected)
  {
    return this->Fail("the compressed data declares " + std::to_string(uncompressed) +
      " bytes, but " + std::to_string(this->Points) + " points of " +
      std::to_string(this->RowSize) + " bytes are " + std::to_string(expected));
  }
  if (compressed == 0 && uncompressed > 0)
  {
    // An empty LZF stream decompresses to nothing: the bound below allows it up to 8 bytes.
    return this->Fail("the compressed data declares 0 bytes (at byte " + std::to_string(start) +
      ") for " + std::to_string(this->Points) + " points of " + std::to_string(this->RowSize) +
      " bytes (" + std::to_string(uncompressed) + " bytes uncompressed)");
  }
  if (compressed > this->In.Remaining())
  {
    return this->Fail("the file ends in the compressed data (" + std::to_string(compressed) +
      " bytes from byte " + std::to_string(start + 8) + ", the file has " +
      std::to_string(this->In.FileSize()) + " bytes)");
  }
  if (uncompressed > MaxLZFExpansion * uint64_t(compressed) + 8)
  {
    return this->Fail("the compressed data cannot hold " + std::to_string(this->Points) +
      " points: " + std::to_string(compressed) + " LZF bytes decompress to at most " +
      std::to_string(MaxLZFExpansion * uint64_t(compressed) + 8) + ", not " +
      std::to_string(uncompressed));
  }
  // As in binary data, a point's worth of bytes or more after the block would be dropped unsaid
  // (a byte or a few after it are no point).
  const uint64_t after = this->In.Remaining() - compressed;
  if (after >= this->RowSize)
  {
    return this->Fail("the compressed data (" + std::to_string(compressed) + " bytes from byte " +
      std::to_string(start + 8) + ") ends at byte " + std::to_string(start + 8 + compressed) +
      ", but " + std::to_string(after) + " more bytes follow it (the file has " +
      std::to_string(this->In.FileSize()) +
      " bytes): a wrong compressed size, or data the header does not declare");
  }
  this->CompressedBytes = compressed;
  return true;
}

bool PCDParser::ReadCompressed()
{
  const uint64_t start = this->In.Position();
  const uint32_t compressed = this->CompressedBytes;
  const size_t uncompressed = static_cast<size_t>(this->Points * this->RowSize);
  if (uncompressed == 0)
  {
    return true;
  }
  std::vector<char> packed(compressed);
  if (!this->In.Read(packed.data(), compressed))
  {
    return this->Fail("the file ends in the compressed data (" + std::to_string(compressed) +
      " bytes from byte " + std::to_string(start) + ")");
  }
  std::vector<char> data(uncompressed);
  const unsigned int got =
    lzf_decompress(packed.data(), compressed, data.data(), static_cast<unsigned int>(uncompressed));
  if (got != uncompressed)
  {
    return this->Fail("the compressed data is corrupt (LZF decompression gave " +
      std::to_string(got) + " bytes of " + std::to_string(uncompressed) + ")");
  }
  packed = std::vector<char>();
  // The fields one after the other: all the points' values of a field, then the next field.
  const vtkIdType n = static_cast<vtkIdType>(this->Points);
  size_t block = 0;
  for (size_t f = 0; f < this->Fields.size(); ++f)
  {
    const size_t value = TypeSize(this->Fields[f].Type);
    const size_t perPoint = static_cast<size_t>(this->Fields[f].Count) * value;
    this->Decode(data.data() + block, perPoint, value, 0, n, f);
    block += perPoint * static_cast<size_t>(n);
  }
  return true;
}

bool PCDParser::ReadAscii()
{
  const vtkIdType n = static_cast<vtkIdType>(this->Points);
  const size_t rowSize = this->RowSize;
  const vtkIdType rowsPerChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
  std::vector<char> chunk(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
  std::string_view line;
  std::vector<std::string_view>& tokens = this->Tokens;
  for (vtkIdType first = 0; first < n; first += rowsPerChunk)
  {
    const vtkIdType rows = std::min(rowsPerChunk, n - first);
    for (vtkIdType r = 0; r < rows; ++r)
    {
      const vtkIdType p = first + r;
      // The next line with a value on it.
      bool found = false;
      while (this->In.NextLine(line, MaxDataLine))
      {
        ++this->Line;
        if (std::any_of(line.begin(), line.end(), [](char c) { return !IsSpace(c); }))
        {
          found = true;
          break;
        }
      }
      if (!found)
      {
        if (this->In.TooLong())
        {
          return this->Fail(
            "line longer than " + std::to_string(MaxDataLine) + " bytes", this->Line + 1);
        }
        return this->FailEnd(
          static_cast<uint64_t>(p), "ASCII data, after line " + std::to_string(this->Line));
      }
      if (this->LineRuns.empty() ||
        this->Line - this->LineRuns.back().second != p - this->LineRuns.back().first)
      {
        this->LineRuns.emplace_back(p, this->Line);
      }
      Split(line, tokens);
      const std::string which = "point " + std::to_string(p + 1) + " of " + std::to_string(n);
      if (tokens.size() != this->ValuesPerPoint)
      {
        return this->Fail(
          std::string(tokens.size() < this->ValuesPerPoint ? "too few" : "too many") +
            " values for " + which + " (" + std::to_string(tokens.size()) + ", " +
            std::to_string(this->ValuesPerPoint) + " expected)",
          this->Line);
      }
      char* row = chunk.data() + static_cast<size_t>(r) * rowSize;
      size_t next = 0;
      for (const Field& f : this->Fields)
      {
        if (f.Name == "_")
        {
          next += static_cast<size_t>(f.Count); // padding: its values are not read, as PCL does
          continue;
        }
        const size_t size = TypeSize(f.Type);
        const bool packedColour =
          f.Type == PcdType::Float32 && (f.Name == "rgb" || f.Name == "rgba");
        for (uint64_t k = 0; k < f.Count; ++k)
        {
          const std::string_view token = tokens[next++];
          char* dst = row + f.Offset + k * size;
          std::string problem;
          uint32_t bits = 0;
          if (packedColour &&
            std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
            ParseValue(token, bits).empty())
          {
            // PCL writes a packed colour as the integer of its bits.
            std::memcpy(dst, &bits, 4);
            if (this->Swap)
            {
              std::reverse(dst, dst + 4);
            }
            continue;
          }
          WithType(f.Type, [&](auto v) {
            using T = decltype(v);
            T value{};
            problem = ParseValue(token, value);
            if (problem.empty())
            {
              std::memcpy(dst, &value, sizeof(T));
              if (this->Swap)
              {
                std::reverse(dst, dst + sizeof(T));
              }
            }
          });
          if (!problem.empty())
          {
            return this->Fail(problem + " in field " + Quote(f.Name) + " of " + which, this->Line);
          }
        }
      }
    }
    for (size_t f = 0; f < this->Fields.size(); ++f)
    {
      this->Decode(chunk.data() + this->Fields[f].Offset, rowSize, TypeSize(this->Fields[f].Type),
        first, rows, f);
    }
  }
  // A line with values after the last point: POINTS counts fewer points than the file holds.
  while (this->In.NextLine(line, MaxDataLine))
  {
    ++this->Line;
    if (std::any_of(line.begin(), line.end(), [](char c) { return !IsSpace(c); }))
    {
      return this->Fail(
        "data after the " + std::to_string(n) + " points that POINTS declares", this->Line);
    }
  }
  return true;
}

// Removes the points with a NaN or infinite coordinate (PCL's invalid points) from the output.
bool PCDParser::RemoveInvalidPoints(vtkPolyData* output)
{
  vtkDataArray* coordinates = output->GetPoints()->GetData();
  const vtkIdType n = coordinates->GetNumberOfTuples();
  std::vector<unsigned char> keep(static_cast<size_t>(n), 1);
  vtkIdType kept = 0;
  auto scan = [&](const auto* x) {
    for (vtkIdType i = 0; i < n; ++i, x += 3)
    {
      keep[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
      kept += keep[i];
    }
  };
  if (coordinates->GetDataType() == VTK_DOUBLE)
  {
    scan(static_cast<const double*>(coordinates->GetVoidPointer(0)));
  }
  else
  {
    scan(static_cast<const float*>(coordinates->GetVoidPointer(0)));
  }
  this->Skipped = n - kept;
  if (kept == n)
  {
    return true;
  }
  std::vector<vtkDataArray*> arrays = { coordinates };
  vtkPointData* pd = output->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    arrays.push_back(pd->GetArray(a));
  }
  for (vtkDataArray* array : arrays)
  {
    const size_t tupleBytes =
      static_cast<size_t>(array->GetNumberOfComponents()) * array->GetDataTypeSize();
    char* data = static_cast<char*>(array->GetVoidPointer(0));
    vtkIdType j = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (keep[i])
      {
        if (j != i)
        {
          std::memcpy(data + j * tupleBytes, data + i * tupleBytes, tupleBytes);
        }
        ++j;
      }
    }
    array->SetNumberOfTuples(kept);
  }
  output->GetPoints()->Modified();
  return this->RecordFilePoints(output, keep);
}

// The file's numbering of the points kept by RemoveInvalidPoints, as field data of the output:
// `FilePointIds`, each point's index in the file (from 0), and for ASCII data `FileLines`, its
// line, so that a message about an output point can name the point as the file holds it.
bool PCDParser::RecordFilePoints(vtkPolyData* output, const std::vector<unsigned char>& keep)
{
  const vtkIdType kept = output->GetNumberOfPoints();
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("FilePointIds");
  vtkNew<vtkIdTypeArray> lines;
  lines->SetName("FileLines");
  const bool ascii = this->Data == Encoding::Ascii;
  ids->SetNumberOfValues(kept);
  lines->SetNumberOfValues(ascii ? kept : 0);
  if (ids->GetNumberOfValues() != kept || lines->GetNumberOfValues() != (ascii ? kept : 0))
  {
    return this->Fail(
      "cannot allocate memory for the file's ids of " + std::to_string(kept) + " points");
  }
  size_t run = 0;
  vtkIdType j = 0;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(keep.size()); ++i)
  {
    if (!keep[i])
    {
      continue;
    }
    ids->SetValue(j, i);
    if (ascii)
    {
      while (run + 1 < this->LineRuns.size() && this->LineRuns[run + 1].first <= i)
      {
        ++run;
      }
      lines->SetValue(j, this->LineRuns[run].second + (i - this->LineRuns[run].first));
    }
    ++j;
  }
  output->GetFieldData()->AddArray(ids);
  if (ascii)
  {
    output->GetFieldData()->AddArray(lines);
  }
  return true;
}

bool PCDParser::Read(vtkPolyData* output, bool decodeColors, bool createVertexCells)
{
  if (!this->ReadHeader() || !this->CheckHeader())
  {
    return false;
  }
  // The rest of the file must be able to hold every declared point before anything is allocated.
  const uint64_t remaining = this->In.Remaining();
  const uint64_t start = this->In.Position();
  if (this->Data == Encoding::Binary && this->Points > remaining / this->RowSize)
  {
    return this->FailEnd(remaining / this->RowSize,
      "binary data of " + std::to_string(this->RowSize) + "-byte points from byte " +
        std::to_string(start) + ", the file has " + std::to_string(this->In.FileSize()) + " bytes");
  }
  if (this->Data == Encoding::Binary && remaining / this->RowSize > this->Points)
  {
    // Whole points more than declared would be dropped unsaid (a byte or a few after the data
    // are no point).
    return this->Fail("the header declares " + std::to_string(this->Points) + " points of " +
      std::to_string(this->RowSize) + " bytes, but " + std::to_string(remaining) +
      " bytes of binary data follow it (" + std::to_string(remaining / this->RowSize) +
      " points): a wrong POINTS count");
  }
  if (this->Data == Encoding::Ascii && this->Points > 0)
  {
    // A line holds each value and a separator after it (the last line may end without one).
    const uint64_t leastLine = 2 * this->ValuesPerPoint;
    const uint64_t most = (remaining + 1) / leastLine;
    if (this->Points > most)
    {
      return this->Fail("the header declares " + std::to_string(this->Points) +
        " points, but the " + std::to_string(remaining) +
        " bytes of ASCII data after it can hold " + "at most " + std::to_string(most) + " (of " +
        std::to_string(this->ValuesPerPoint) + " values each)");
    }
  }
  if (this->Data == Encoding::Compressed &&
    this->Points > std::numeric_limits<uint32_t>::max() / this->RowSize)
  {
    return this->Fail(std::to_string(this->Points) + " points of " + std::to_string(this->RowSize) +
      " bytes do not fit in binary_compressed data (at most 4 GiB uncompressed)");
  }
  if (this->Data == Encoding::Compressed && !this->ReadCompressedSizes())
  {
    return false;
  }
  if (!this->Prepare(output, decodeColors))
  {
    return false;
  }
  const bool ok = this->Data == Encoding::Ascii ? this->ReadAscii()
    : this->Data == Encoding::Binary            ? this->ReadBinary()
                                                : this->ReadCompressed();
  if (!ok || !this->RemoveInvalidPoints(output))
  {
    return false;
  }
  if (createVertexCells)
  {
    const vtkIdType n = output->GetNumberOfPoints();
    vtkSmartPointer<vtkCellArray> verts = vtkPointCloudIO::MakeVertexCells(n);
    if (!verts)
    {
      return this->Fail("cannot allocate memory for " + std::to_string(n) + " vertex cells");
    }
    output->SetVerts(verts);
  }
  return true;
}
} // namespace

vtkPointCloudPCDReader::vtkPointCloudPCDReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudPCDReader::~vtkPointCloudPCDReader()
{
  this->SetFileName(nullptr);
}

int vtkPointCloudPCDReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  this->NumberOfSkippedPoints = 0;
  this->Width = this->Height = 0;
  this->SetErrorCode(vtkErrorCode::NoError);

  // Errors are reported here and the request still succeeds with an empty output: a failed
  // request would add the executive's own, less telling, error.
  auto fail = [this](unsigned long code, const std::string& message) {
    this->ErrorMessage = message;
    this->SetErrorCode(code);
    vtkErrorMacro(<< message);
    return 1;
  };
  std::string message;
  if (const unsigned long code = featurepoints::CheckReaderFileName(this->FileName, message))
  {
    return fail(code, message);
  }
  const std::string name = this->FileName;
  vtksys::ifstream stream;
  uint64_t size = 0;
  if (const unsigned long code = featurepoints::OpenReaderFile(name, stream, size, message))
  {
    return fail(code, message);
  }

  PCDParser parser(name, stream, size);
  vtkNew<vtkPolyData> cloud;
  if (!parser.Read(cloud, this->DecodeColors, this->CreateVertexCells))
  {
    return fail(vtkErrorCode::FileFormatError, parser.Error);
  }
  this->Width = static_cast<vtkIdType>(parser.Width);
  this->Height = static_cast<vtkIdType>(parser.Height);
  this->NumberOfSkippedPoints = parser.Skipped;
  if (parser.Skipped > 0)
  {
    vtkWarningMacro(<< name << ": " << parser.Skipped << " of " << parser.Points
                    << " points skipped: a NaN or infinite coordinate"
                    << (parser.Height > 1 ? " (invalid points of an organized cloud)" : ""));
  }
  output->ShallowCopy(cloud);
  return 1;
}

void vtkPointCloudPCDReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CreateVertexCells: " << (this->CreateVertexCells ? "On" : "Off") << "\n";
  os << indent << "DecodeColors: " << (this->DecodeColors ? "On" : "Off") << "\n";
  os << indent << "NumberOfSkippedPoints: " << this->NumberOfSkippedPoints << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
