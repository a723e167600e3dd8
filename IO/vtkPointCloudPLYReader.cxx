#include "vtkPointCloudPLYReader.h"
#include "vtkPointCloudPLYTypes.h"
#include "vtkPointCloudFiles.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkPointCloudPLYReader);

using namespace featurepoints::ply;
using featurepoints::Printable;
using featurepoints::Quote;

namespace
{

using featurepoints::HostIsBigEndian;
using featurepoints::Load;

// One property of a packed row (file byte order) to one component of an output array.
template <typename S, typename D, bool Swap>
void DecodeColumn(const char* src, size_t rowSize, vtkIdType rows, D* dst, int stride)
{
  for (vtkIdType r = 0; r < rows; ++r, src += rowSize, dst += stride)
  {
    *dst = static_cast<D>(Load<S, Swap>(src));
  }
}

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits a line at whitespace; the views point into the line.
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

enum class Parse
{
  Ok,
  NotANumber,
  NotAnInteger,
  OutOfRange
};

// The whole token must be the number: "1.5abc" and "" are not numbers.
template <typename T>
Parse ParseNumber(std::string_view token, T& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  // std::from_chars does not accept a leading '+'.
  if (last - first > 1 && *first == '+' && first[1] != '-')
  {
    ++first;
  }
  if constexpr (std::is_floating_point<T>::value)
  {
    auto r = std::from_chars(first, last, value);
    if (r.ec == std::errc::result_out_of_range && r.ptr == last)
    {
      // Underflow is a value too close to 0 for T: keep its rounding (a signed zero beyond long
      // double's range too); overflow is an error.
      if (!featurepoints::Underflows(std::string_view(first, static_cast<size_t>(last - first))))
      {
        return Parse::OutOfRange;
      }
      long double wide;
      auto w = std::from_chars(first, last, wide);
      value = w.ec == std::errc() && w.ptr == last ? static_cast<T>(wide)
        : *first == '-'                            ? -T(0)
                                                   : T(0);
      return Parse::Ok;
    }
    return (r.ec == std::errc() && r.ptr == last) ? Parse::Ok : Parse::NotANumber;
  }
  else
  {
    // Every PLY integer type fits in int64_t, so one parse covers signed and unsigned types.
    int64_t wide;
    auto r = std::from_chars(first, last, wide);
    if (r.ec == std::errc::result_out_of_range && r.ptr == last)
    {
      return Parse::OutOfRange;
    }
    if (r.ec != std::errc() || r.ptr != last)
    {
      double d;
      auto f = std::from_chars(first, last, d);
      return (f.ec == std::errc() && f.ptr == last) ? Parse::NotAnInteger : Parse::NotANumber;
    }
    if (wide < static_cast<int64_t>(std::numeric_limits<T>::lowest()) ||
      wide > static_cast<int64_t>(std::numeric_limits<T>::max()))
    {
      return Parse::OutOfRange;
    }
    value = static_cast<T>(wide);
    return Parse::Ok;
  }
}

struct Property
{
  std::string Name;
  PlyType Type = PlyType::Float32; // the item type of a list
  bool IsList = false;
  PlyType CountType = PlyType::UInt8;
};

struct Element
{
  std::string Name;
  uint64_t Count = 0;
  int Line = 0; // of its element line in the header
  std::vector<Property> Properties;
  std::set<std::string> PropertyNames; // to find a repeated name without a quadratic search
};

enum class Format
{
  None,
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

// Buffered reading of the file: lines for the header and ASCII data, bytes for binary data.
class Input
{
public:
  Input(std::istream& stream, uint64_t size)
    : Stream(stream)
    , Size(size)
    , Buffer(1 << 20)
  {
  }

  uint64_t FileSize() const { return this->Size; }
  // File offset of the next unread byte.
  uint64_t Position() const { return this->Offset + this->Begin; }
  bool TooLong() const { return this->LineTooLong; }
  // False when the last line read ended with the file rather than with "\n".
  bool LineEnded() const { return this->LastLineEnded; }
  bool IOError() const { return this->Stream.bad(); }

  // The next line without its "\n" or "\r\n"; false at the end of the file, or when the line
  // is longer than maxLength (TooLong() then says so).
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
        const size_t stop = static_cast<const char*>(nl) - base;
        line = std::string_view(base + this->Begin, stop - this->Begin);
        this->Begin = stop + 1;
        this->LastLineEnded = true;
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
        this->LastLineEnded = false;
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
    if (n >= this->Buffer.size() / 2)
    {
      // A big block goes straight to its destination.
      this->Offset += this->End;
      this->Begin = this->End = 0;
      this->Stream.read(dst, static_cast<std::streamsize>(n));
      const auto got = static_cast<size_t>(this->Stream.gcount());
      this->Offset += got;
      return got == n;
    }
    while (n > 0)
    {
      if (!this->Fill())
      {
        return false;
      }
      const size_t more = std::min(n, this->End - this->Begin);
      std::memcpy(dst, this->Buffer.data() + this->Begin, more);
      this->Begin += more;
      dst += more;
      n -= more;
    }
    return true;
  }

  // False when the file ends first.
  bool Skip(uint64_t n)
  {
    if (n <= this->End - this->Begin)
    {
      this->Begin += static_cast<size_t>(n);
      return true;
    }
    n -= this->End - this->Begin;
    this->Offset += this->End;
    this->Begin = this->End = 0;
    if (n > this->Size - std::min(this->Offset, this->Size))
    {
      this->Offset = this->Size;
      return false;
    }
    this->Offset += n;
    this->Stream.clear();
    this->Stream.seekg(static_cast<std::streamoff>(this->Offset));
    return !this->Stream.fail();
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
  bool LastLineEnded = true;
};

constexpr size_t MaxHeaderLine = size_t(1) << 20;
constexpr size_t MaxDataLine = size_t(64) << 20;
constexpr size_t ChunkBytes = size_t(4) << 20;

// Where the values of one scalar vertex property go.
struct Target
{
  PlyType Source = PlyType::Float32; // type in the file
  PlyType Type = PlyType::Float32;   // type of the output array
  void* Base = nullptr;              // first value of the output array
  int Stride = 1;                    // components of the output array
  int Component = 0;                 // component this property fills
  size_t Offset = 0;                 // offset of the property in a packed row
};

// Parses a value of a PLY type into its native bytes at dst.
Parse ParseInto(PlyType type, std::string_view token, char* dst)
{
  Parse result = Parse::NotANumber;
  WithType(type, [&](auto v) {
    using T = decltype(v);
    T value;
    result = ParseNumber(token, value);
    if (result == Parse::Ok)
    {
      std::memcpy(dst, &value, sizeof(T));
    }
  });
  return result;
}

// A list count (integer types only) stored at p.
int64_t LoadCount(PlyType type, const char* p, bool swap)
{
  int64_t count = 0;
  WithType(type, [&](auto v) {
    using T = decltype(v);
    count = static_cast<int64_t>(swap ? Load<T, true>(p) : Load<T, false>(p));
  });
  return count;
}

std::string ParseMessage(Parse result, std::string_view token, PlyType type)
{
  const std::string quoted = Quote(token);
  switch (result)
  {
    case Parse::NotAnInteger:
      return quoted + " is not an integer (type " + TypeName(type) + ")";
    case Parse::OutOfRange:
      return quoted + " is out of range for type " + TypeName(type);
    default:
      return quoted + " is not a number";
  }
}

// a + b, saturated at 2^64 - 1 (a sum of counts from a header is only compared with sizes).
uint64_t SaturatedSum(uint64_t a, uint64_t b)
{
  return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max()
                                                       : a + b;
}

// The fewest bytes a row of element e can take: in binary its scalars and each list's count (the
// lists empty), in ASCII a value and a separator per property.
uint64_t LeastRowBytes(const Element& e, bool ascii)
{
  uint64_t row = 0;
  for (const Property& p : e.Properties)
  {
    row += ascii ? 2 : TypeSize(p.IsList ? p.CountType : p.Type);
  }
  return row;
}

// The fewest bytes all the rows of element e can take, saturated at 2^64 - 1.
uint64_t LeastBytes(const Element& e, bool ascii)
{
  const uint64_t row = LeastRowBytes(e, ascii);
  return row > 0 && e.Count > std::numeric_limits<uint64_t>::max() / row
    ? std::numeric_limits<uint64_t>::max()
    : e.Count * row;
}

// The file, parsed in one pass. Every method returns false after setting Error.
class PLYParser
{
public:
  PLYParser(const std::string& fileName, std::istream& stream, uint64_t size)
    : FileName(fileName)
    , In(stream, size)
  {
  }

  // Reads the vertices into `output`: points, point data and, if asked, vertex cells. Piece
  // `piece` of `pieces`: the vertices [n piece / pieces, n (piece + 1) / pieces) of a binary file
  // whose vertex rows have a fixed size (their byte range alone is read); otherwise piece 0 gets
  // every vertex and the other pieces none.
  bool Read(vtkPolyData* output, bool createVertexCells, int piece = 0, int pieces = 1);

  std::string Error;
  std::vector<std::string> Warnings;

private:
  bool Fail(const std::string& what, int line = 0)
  {
    this->Error =
      this->FileName + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what;
    return false;
  }
  // The file ended (or a read failed) in row `row` (0-based) of element e.
  bool FailEnd(const Element& e, uint64_t row, const std::string& detail)
  {
    return this->Fail(std::string(this->In.IOError() ? "read error in " : "the file ends in ") +
      Printable(e.Name) + " " + std::to_string(row + 1) + " of " + std::to_string(e.Count) + " (" +
      detail +
      ")");
  }
  bool FailLongLine() { return this->Fail("line longer than 64 MiB", this->Line + 1); }

  bool ReadHeader();
  bool CheckElementBytes(const Element& vertex);
  bool SkipElement(const Element& e, uint64_t reserve, const std::string& after);
  bool SkipElementsAfter(const Element& vertex);
  bool CheckAfterLastElement(const Element& last);
  bool ParseAsciiRow(const Element& e, uint64_t r, char* row);
  bool Prepare(const Element& vertex, vtkPolyData* output);
  bool CheckVertexBytes(const Element& vertex);
  bool ReadBinaryVertices(const Element& vertex);
  bool ReadAsciiVertices(const Element& vertex);
  void Decode(const char* rows, vtkIdType count, vtkIdType first, bool swap);
  bool NextDataLine(std::string_view& line);
  bool SwapBytes() const
  {
    return (this->FileFormat == Format::BinaryBigEndian) != HostIsBigEndian();
  }
  std::string BinaryDetail(uint64_t start, uint64_t rows, uint64_t rowSize) const
  {
    return "binary data: " + std::to_string(rows) + " rows of " + std::to_string(rowSize) +
      " bytes from byte " + std::to_string(start) + ", the file has " +
      std::to_string(this->In.FileSize()) + " bytes";
  }

  std::string FileName;
  Input In;
  int Line = 0; // number of the last line read
  Format FileFormat = Format::None;
  std::vector<Element> Elements;
  std::vector<std::string_view> Tokens;

  // The vertex element's scalar properties, in file order, and where each goes.
  std::vector<Target> Targets;
  std::vector<int> TargetOfProperty; // -1 for a list property
  size_t PackedRowSize = 0;          // bytes of the scalar properties of one vertex
  vtkIdType Allocated = 0;           // tuples of the output arrays
  uint64_t FirstRow = 0;             // the piece's first vertex
  uint64_t NumberOfRows = 0;         // the piece's vertices
};

bool PLYParser::ReadHeader()
{
  if (this->In.FileSize() == 0)
  {
    return this->Fail("not a PLY file (the file is empty)");
  }
  std::string_view line;
  const bool gotFirst = this->In.NextLine(line, MaxHeaderLine);
  this->Line = 1;
  Split(gotFirst ? line : std::string_view(), this->Tokens);
  if (this->Tokens.size() != 1 || this->Tokens[0] != "ply")
  {
    return this->Fail("not a PLY file (the first line is not \"ply\")");
  }
  auto bad = [this](const std::string& what) { return this->Fail(what, this->Line); };
  auto quote = [](std::string_view s) { return Quote(s); };
  Element* current = nullptr;
  for (;;)
  {
    if (!this->In.NextLine(line, MaxHeaderLine))
    {
      if (this->In.TooLong())
      {
        return this->Fail("header line longer than 1 MiB", this->Line + 1);
      }
      return this->Fail("the file ends in the header (no end_header line after line " +
        std::to_string(this->Line) + ")");
    }
    ++this->Line;
    Split(line, this->Tokens);
    if (!this->In.LineEnded() && !(this->Tokens.size() == 1 && this->Tokens[0] == "end_header"))
    {
      return this->Fail("the file ends in the header (line " + std::to_string(this->Line) +
        " is cut short, no end_header line)");
    }
    if (this->Tokens.empty())
    {
      continue;
    }
    const std::vector<std::string_view>& w = this->Tokens;
    const std::string_view keyword = w[0];
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    if (keyword == "end_header")
    {
      if (w.size() != 1)
      {
        return bad("words after end_header");
      }
      break;
    }
    if (keyword == "format")
    {
      if (w.size() != 3)
      {
        return bad("malformed format line (expected \"format TYPE 1.0\")");
      }
      if (this->FileFormat != Format::None)
      {
        return bad("second format line");
      }
      if (w[1] == "ascii")
      {
        this->FileFormat = Format::Ascii;
      }
      else if (w[1] == "binary_little_endian")
      {
        this->FileFormat = Format::BinaryLittleEndian;
      }
      else if (w[1] == "binary_big_endian")
      {
        this->FileFormat = Format::BinaryBigEndian;
      }
      else
      {
        return bad("unknown format " + quote(w[1]));
      }
      if (w[2] != "1.0" && w[2] != "1")
      {
        return bad("unsupported format version " + quote(w[2]) + " (1.0 expected)");
      }
    }
    else if (keyword == "element")
    {
      uint64_t count = 0;
      const char* end = w.size() == 3 ? w[2].data() + w[2].size() : nullptr;
      const auto parsed = end ? std::from_chars(w[2].data(), end, count) : std::from_chars_result{};
      if (!end || parsed.ptr != end)
      {
        return bad("malformed element line (expected \"element NAME COUNT\", COUNT a "
                   "non-negative integer)");
      }
      if (parsed.ec == std::errc::result_out_of_range)
      {
        return bad("element " + quote(w[1]) + ": count " + quote(w[2]) +
          " is beyond any file (at most 2^64 - 1)");
      }
      // Elements other than the vertices are only skipped, whatever their names.
      if (w[1] == "vertex" &&
        std::any_of(this->Elements.begin(), this->Elements.end(),
          [](const Element& e) { return e.Name == "vertex"; }))
      {
        return bad("second vertex element");
      }
      this->Elements.emplace_back();
      current = &this->Elements.back();
      current->Name = std::string(w[1]);
      current->Count = count;
      current->Line = this->Line;
    }
    else if (keyword == "property")
    {
      if (!current)
      {
        return bad("property line before any element line");
      }
      Property p;
      if (w.size() >= 2 && w[1] == "list")
      {
        if (w.size() != 5)
        {
          return bad("malformed property line (expected \"property list COUNTTYPE ITEMTYPE "
                     "NAME\")");
        }
        if (!TypeFromName(w[2], p.CountType) || !TypeFromName(w[3], p.Type))
        {
          return bad(
            "unknown property type " + quote(TypeFromName(w[2], p.CountType) ? w[3] : w[2]));
        }
        if (!IsInteger(p.CountType))
        {
          return bad("the count type of a list must be an integer type, not " + quote(w[2]));
        }
        p.IsList = true;
        p.Name = std::string(w[4]);
      }
      else
      {
        if (w.size() != 3)
        {
          return bad("malformed property line (expected \"property TYPE NAME\")");
        }
        if (!TypeFromName(w[1], p.Type))
        {
          return bad("unknown property type " + quote(w[1]));
        }
        p.Name = std::string(w[2]);
      }
      if (!current->PropertyNames.insert(p.Name).second)
      {
        return bad(
          "second property named " + quote(p.Name) + " in element " + quote(current->Name));
      }
      current->Properties.push_back(p);
    }
    else
    {
      return bad("unknown header keyword " + quote(keyword));
    }
  }
  if (this->FileFormat == Format::None)
  {
    return this->Fail("no format line in the header");
  }
  return true;
}

// The next line with a value on it.
bool PLYParser::NextDataLine(std::string_view& line)
{
  while (this->In.NextLine(line, MaxDataLine))
  {
    ++this->Line;
    if (std::any_of(line.begin(), line.end(), [](char c) { return !IsSpace(c); }))
    {
      return true;
    }
  }
  return false;
}

// Reads past the rows of element e, an element other than the vertices. ASCII: each row must hold
// the values its properties and list counts say (ParseAsciiRow). Binary: when the file holds e's
// rows at their least and the `reserve` bytes that the elements after e take at least (`after`
// names them), a list count that runs into those bytes is e's error, not theirs (they would
// otherwise be read from e's data and blamed). For the last element (`after` empty) a list that
// runs past the file is where the file ends.
bool PLYParser::SkipElement(const Element& e, uint64_t reserve, const std::string& after)
{
  if (e.Properties.empty())
  {
    return true; // its rows hold nothing
  }
  if (this->FileFormat == Format::Ascii)
  {
    std::string_view line;
    for (uint64_t r = 0; r < e.Count; ++r)
    {
      if (!this->NextDataLine(line))
      {
        return this->In.TooLong()
          ? this->FailLongLine()
          : this->FailEnd(e, r, "ASCII data, after line " + std::to_string(this->Line));
      }
      Split(line, this->Tokens);
      if (!this->ParseAsciiRow(e, r, nullptr))
      {
        return false;
      }
    }
    return true;
  }
  const bool hasList = std::any_of(
    e.Properties.begin(), e.Properties.end(), [](const Property& p) { return p.IsList; });
  const uint64_t start = this->In.Position();
  if (!hasList)
  {
    uint64_t rowSize = 0;
    for (const Property& p : e.Properties)
    {
      rowSize += TypeSize(p.Type);
    }
    const uint64_t remaining = this->In.FileSize() - std::min(start, this->In.FileSize());
    if (e.Count > remaining / rowSize)
    {
      return this->FailEnd(e, remaining / rowSize, this->BinaryDetail(start, e.Count, rowSize));
    }
    return this->In.Skip(e.Count * rowSize) ||
      this->FailEnd(e, 0, this->BinaryDetail(start, e.Count, rowSize));
  }
  const uint64_t size = this->In.FileSize();
  const uint64_t room = size - std::min(start, size);
  const uint64_t least = LeastBytes(e, false);
  const bool blame = !after.empty() && least <= room && reserve <= room - least;
  // The least bytes of the properties after each one in a row.
  std::vector<uint64_t> rest(e.Properties.size() + 1, 0);
  for (size_t i = e.Properties.size(); i-- > 0;)
  {
    const Property& p = e.Properties[i];
    rest[i] = rest[i + 1] + TypeSize(p.IsList ? p.CountType : p.Type);
  }
  const bool swap = this->SwapBytes();
  char count[8];
  for (uint64_t r = 0; r < e.Count; ++r)
  {
    for (size_t i = 0; i < e.Properties.size(); ++i)
    {
      const Property& p = e.Properties[i];
      if (!p.IsList)
      {
        if (!this->In.Skip(TypeSize(p.Type)))
        {
          return this->FailEnd(e, r, "binary data from byte " + std::to_string(start));
        }
        continue;
      }
      if (!this->In.Read(count, TypeSize(p.CountType)))
      {
        return this->FailEnd(e, r, "binary data from byte " + std::to_string(start));
      }
      const int64_t n = LoadCount(p.CountType, count, swap);
      if (n < 0)
      {
        return this->Fail("negative count " + std::to_string(n) + " of list " + Quote(p.Name) +
          " in " + Printable(e.Name) + " " + std::to_string(r + 1));
      }
      // Where the items must end: before the rest of e's rows at their least, and the reserve.
      const uint64_t at = this->In.Position();
      const uint64_t item = TypeSize(p.Type);
      const uint64_t limit =
        blame ? size - reserve - (e.Count - r - 1) * rest[0] - rest[i + 1] : size;
      if (static_cast<uint64_t>(n) > (limit - std::min(at, limit)) / item)
      {
        if (!blame)
        {
          return this->FailEnd(e, r, "binary data from byte " + std::to_string(start));
        }
        return this->Fail("list " + Quote(p.Name) + " of " + Printable(e.Name) + " " +
          std::to_string(r + 1) + " of " + std::to_string(e.Count) + " counts " +
          std::to_string(n) + " items of " + std::to_string(item) + " bytes from byte " +
          std::to_string(at) + ": they run into the data of " + after +
          ", at least " + std::to_string(reserve) + " of the file's " + std::to_string(size) +
          " bytes (a wrong list count)");
      }
      if (!this->In.Skip(static_cast<uint64_t>(n) * item))
      {
        return this->FailEnd(e, r, "binary data from byte " + std::to_string(start));
      }
    }
  }
  return true;
}

// The elements after the vertices are never read, but their rows must fit in the file at their
// least (LeastBytes): a count beyond the file is as much an error there as in the vertex element.
// Elements up to the vertices that do not fit are found where they are read.
bool PLYParser::CheckElementBytes(const Element& vertex)
{
  const bool ascii = this->FileFormat == Format::Ascii;
  const uint64_t start = this->In.Position();
  const uint64_t room = this->In.FileSize() - std::min(start, this->In.FileSize());
  uint64_t need = 0;
  bool afterVertex = false;
  for (const Element& e : this->Elements)
  {
    need = SaturatedSum(need, LeastBytes(e, ascii));
    // ASCII: the file's last value needs no separator after it.
    if (afterVertex && need - (ascii && need > 0 ? 1 : 0) > room)
    {
      const std::string least = need == std::numeric_limits<uint64_t>::max()
        ? "more than 2^64 - 2"
        : "at least " + std::to_string(need);
      return this->Fail("element " + Quote(e.Name) + " after the vertices declares " +
          std::to_string(e.Count) + " rows of at least " + std::to_string(LeastRowBytes(e, ascii)) +
          " bytes" + (ascii ? " (a value and a separator per property)" : "") +
          ": the elements up to it take " + least + " bytes, but " + std::to_string(room) +
          " bytes follow end_header",
        e.Line);
    }
    afterVertex = afterVertex || &e == &vertex;
  }
  return true;
}

// Reads past the elements after the vertices, as past those before them (SkipElement): a file
// cut short in them (a mesh's faces), or whose rows do not hold what their list counts say, is an
// error, as it is before the vertices; their values are not kept. Called once every vertex is
// read (a piece of the vertices alone does not reach them).
bool PLYParser::SkipElementsAfter(const Element& vertex)
{
  const size_t first = static_cast<size_t>(&vertex - this->Elements.data()) + 1;
  std::vector<uint64_t> reserve(this->Elements.size() + 1, 0); // [i]: elements after i, at least
  for (size_t i = this->Elements.size(); i-- > first;)
  {
    reserve[i] = SaturatedSum(reserve[i + 1], LeastBytes(this->Elements[i], false));
  }
  for (size_t i = first; i < this->Elements.size(); ++i)
  {
    const std::string after = i + 1 < this->Elements.size()
      ? "the " + Printable(this->Elements[i + 1].Name) + " element" +
        (i + 2 < this->Elements.size() ? " and those after it" : "")
      : std::string();
    if (!this->SkipElement(this->Elements[i], reserve[i + 1], after))
    {
      return false;
    }
  }
  return first == this->Elements.size() || this->CheckAfterLastElement(this->Elements.back());
}

// After the rows of the last element (not the vertices: see CheckVertexBytes and Read), data
// that would make at least one more row is refused as it is after vertices that come last: a
// count smaller than the rows stored would drop them unsaid (a byte or two after binary data, as
// some writers leave, are no row).
bool PLYParser::CheckAfterLastElement(const Element& last)
{
  const std::string rows = std::to_string(last.Count) + " " + Printable(last.Name) + " rows";
  if (this->FileFormat == Format::Ascii)
  {
    std::string_view line;
    return !this->NextDataLine(line) ||
      this->Fail("data after the " + rows + " that the header declares (the " +
          Printable(last.Name) + " element is the last)",
        this->Line);
  }
  const uint64_t end = this->In.Position();
  const uint64_t remaining = this->In.FileSize() - std::min(end, this->In.FileSize());
  if (remaining < std::max<uint64_t>(3, LeastRowBytes(last, false)))
  {
    return true;
  }
  return this->Fail("the header declares " + rows + ", but " + std::to_string(remaining) +
    " bytes follow the last of them (from byte " + std::to_string(end) + " of " +
    std::to_string(this->In.FileSize()) + ", the " + Printable(last.Name) +
    " element the last): a wrong count, or data the header does not declare");
}

// Creates the output points and arrays of the vertex element and says where each property goes.
bool PLYParser::Prepare(const Element& vertex, vtkPolyData* output)
{
  const std::vector<Property>& props = vertex.Properties;
  const int np = static_cast<int>(props.size());
  auto find = [&props, np](const char* name, bool ucharOnly) -> int {
    for (int i = 0; i < np; ++i)
    {
      if (!props[i].IsList && props[i].Name == name &&
        (!ucharOnly || props[i].Type == PlyType::UInt8))
      {
        return i;
      }
    }
    return -1;
  };
  const int xyz[3] = { find("x", false), find("y", false), find("z", false) };
  const int normal[3] = { find("nx", false), find("ny", false), find("nz", false) };
  const int colour[4] = { find("red", true), find("green", true), find("blue", true),
    find("alpha", true) };

  // An output array and the properties that fill its components.
  struct Output
  {
    std::string Name;
    PlyType Type;
    std::vector<int> Properties;
    enum
    {
      Plain,
      Points,
      Normals,
      Colours
    } Role;
  };
  std::vector<Output> outputs;
  std::vector<bool> used(np, false);
  auto add = [&outputs, &used](Output o) {
    for (int i : o.Properties)
    {
      used[i] = true;
    }
    outputs.push_back(std::move(o));
  };
  auto commonType = [&props](const int* ids) {
    const PlyType t0 = props[ids[0]].Type;
    bool same = true, anyDouble = false;
    for (int c = 0; c < 3; ++c)
    {
      same = same && props[ids[c]].Type == t0;
      anyDouble = anyDouble || props[ids[c]].Type == PlyType::Float64;
    }
    return same ? t0 : (anyDouble ? PlyType::Float64 : PlyType::Float32);
  };
  const bool doublePoints = props[xyz[0]].Type == PlyType::Float64 ||
    props[xyz[1]].Type == PlyType::Float64 || props[xyz[2]].Type == PlyType::Float64;
  add({ "", doublePoints ? PlyType::Float64 : PlyType::Float32, { xyz[0], xyz[1], xyz[2] },
    Output::Points });
  if (normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0)
  {
    add({ "Normals", commonType(normal), { normal[0], normal[1], normal[2] }, Output::Normals });
  }
  if (colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0)
  {
    Output rgb{ "RGB", PlyType::UInt8, { colour[0], colour[1], colour[2] }, Output::Colours };
    if (colour[3] >= 0)
    {
      rgb.Name = "RGBA";
      rgb.Properties.push_back(colour[3]);
    }
    add(rgb);
  }
  for (int i = 0; i < np; ++i)
  {
    if (used[i])
    {
      continue;
    }
    if (props[i].IsList)
    {
      this->Warnings.push_back(
        this->FileName + ": list property " + Quote(props[i].Name) +
        " of the vertex element skipped");
      continue;
    }
    // NAME_0, NAME_1, ... of one type, one after the other: the components of array NAME.
    const std::string& name = props[i].Name;
    if (name.size() > 2 && name.compare(name.size() - 2, 2, "_0") == 0)
    {
      const std::string base = name.substr(0, name.size() - 2);
      int j = i + 1;
      while (j < np && !used[j] && !props[j].IsList && props[j].Type == props[i].Type &&
        props[j].Name == base + "_" + std::to_string(j - i))
      {
        ++j;
      }
      if (j - i >= 2)
      {
        Output group{ base, props[i].Type, {}, Output::Plain };
        for (int k = i; k < j; ++k)
        {
          group.Properties.push_back(k);
        }
        add(group);
        continue;
      }
    }
    add({ name, props[i].Type, { i }, Output::Plain });
  }

  if (outputs.size() - 1 > vtkPointCloudPLYReader::MaximumNumberOfArrays)
  {
    return this->Fail("the vertex element has " + std::to_string(outputs.size() - 1) +
      " properties besides x, y, z (as point arrays); at most " +
      std::to_string(vtkPointCloudPLYReader::MaximumNumberOfArrays) +
      " are read (name the properties of one array NAME_0, NAME_1, ...)");
  }

  // vtkPointData keeps one array per name: a clash (a scalar "Normals" beside nx, ny, nz) gets a
  // suffix rather than replacing an array.
  std::set<std::string> names;
  for (Output& o : outputs)
  {
    if (o.Role == Output::Points)
    {
      continue;
    }
    const std::string base = o.Name;
    for (int s = 2; names.count(o.Name); ++s)
    {
      o.Name = base + "_" + std::to_string(s);
    }
    names.insert(o.Name);
  }

  // The arrays hold every vertex, or as many as the rest of the file could hold when the header
  // declares more: the read then fails where the file ends, without a huge allocation first.
  const uint64_t remaining =
    this->In.FileSize() - std::min(this->In.Position(), this->In.FileSize());
  uint64_t minRowSize = 0;
  for (const Property& p : props)
  {
    const bool ascii = this->FileFormat == Format::Ascii;
    minRowSize += ascii ? 2 : TypeSize(p.IsList ? p.CountType : p.Type); // value and separator
  }
  this->Allocated =
    static_cast<vtkIdType>(std::min(this->NumberOfRows, remaining / minRowSize + 1));

  this->Targets.clear();
  this->TargetOfProperty.assign(np, -1);
  this->PackedRowSize = 0;
  for (int i = 0; i < np; ++i)
  {
    if (!props[i].IsList)
    {
      this->TargetOfProperty[i] = static_cast<int>(this->Targets.size());
      Target t;
      t.Source = props[i].Type;
      t.Offset = this->PackedRowSize;
      this->PackedRowSize += TypeSize(props[i].Type);
      this->Targets.push_back(t);
    }
  }

  vtkNew<vtkPoints> points;
  vtkPointData* pd = output->GetPointData();
  for (const Output& o : outputs)
  {
    vtkSmartPointer<vtkDataArray> array;
    if (o.Role == Output::Points)
    {
      points->SetDataType(VTKType(o.Type));
      array = points->GetData();
    }
    else
    {
      array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(VTKType(o.Type)));
      array->SetName(o.Name.c_str());
    }
    const int k = static_cast<int>(o.Properties.size());
    array->SetNumberOfComponents(k);
    array->SetNumberOfTuples(this->Allocated);
    if (array->GetNumberOfTuples() != this->Allocated ||
      (this->Allocated > 0 && !array->GetVoidPointer(0)))
    {
      return this->Fail(
        "cannot allocate memory for " + std::to_string(this->Allocated) + " vertices");
    }
    for (int c = 0; c < k; ++c)
    {
      Target& t = this->Targets[this->TargetOfProperty[o.Properties[c]]];
      t.Base = this->Allocated > 0 ? array->GetVoidPointer(0) : nullptr;
      t.Type = o.Type;
      t.Stride = k;
      t.Component = c;
    }
    switch (o.Role)
    {
      case Output::Points:
        output->SetPoints(points);
        break;
      case Output::Normals:
        pd->SetNormals(array);
        break;
      case Output::Colours:
        pd->SetScalars(array);
        break;
      default:
        pd->AddArray(array);
    }
  }
  return true;
}

// Decodes `count` packed rows into the output arrays, from vertex `first` on.
void PLYParser::Decode(const char* rows, vtkIdType count, vtkIdType first, bool swap)
{
  for (const Target& t : this->Targets)
  {
    WithType(t.Source, [&](auto s) {
      using S = decltype(s);
      WithType(t.Type, [&](auto d) {
        using D = decltype(d);
        D* dst = static_cast<D*>(t.Base) + first * t.Stride + t.Component;
        const char* src = rows + t.Offset;
        if (swap)
        {
          DecodeColumn<S, D, true>(src, this->PackedRowSize, count, dst, t.Stride);
        }
        else
        {
          DecodeColumn<S, D, false>(src, this->PackedRowSize, count, dst, t.Stride);
        }
      });
    });
  }
}

// Rows of fixed size: the file's size says at once, before any allocation, whether every
// vertex is there.
bool PLYParser::CheckVertexBytes(const Element& vertex)
{
  uint64_t rowSize = 0;
  for (const Property& p : vertex.Properties)
  {
    if (p.IsList)
    {
      return true; // rows of varying size: the read finds where the file ends
    }
    rowSize += TypeSize(p.Type);
  }
  const uint64_t start = this->In.Position();
  const uint64_t remaining = this->In.FileSize() - std::min(start, this->In.FileSize());
  if (vertex.Count > remaining / rowSize)
  {
    return this->FailEnd(
      vertex, remaining / rowSize, this->BinaryDetail(start, vertex.Count, rowSize));
  }
  // The last element, followed by whole rows more: a count smaller than the rows stored would
  // drop them unsaid (a byte or a few after the data, as some writers leave, are no row).
  if (&vertex == &this->Elements.back() && remaining / rowSize > vertex.Count)
  {
    return this->Fail("the header declares " + std::to_string(vertex.Count) + " " + vertex.Name +
      " rows of " + std::to_string(rowSize) + " bytes, but " + std::to_string(remaining) +
      " bytes follow end_header (" + std::to_string(remaining / rowSize) +
      " rows): a wrong count, or data the header does not declare");
  }
  return true;
}

bool PLYParser::ReadBinaryVertices(const Element& vertex)
{
  const bool swap = this->SwapBytes();
  const bool hasList = std::any_of(
    vertex.Properties.begin(), vertex.Properties.end(), [](const Property& p) { return p.IsList; });
  const size_t rowSize = this->PackedRowSize;
  const vtkIdType n = static_cast<vtkIdType>(this->NumberOfRows);
  const vtkIdType rowsPerChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
  std::vector<char> chunk(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
  const uint64_t start = this->In.Position();

  if (!hasList)
  {
    // CheckVertexBytes has made sure the file holds every row; a piece starts at its own.
    if (this->FirstRow > 0 && !this->In.Skip(this->FirstRow * rowSize))
    {
      return this->FailEnd(vertex, 0, this->BinaryDetail(start, vertex.Count, rowSize));
    }
    for (vtkIdType first = 0; first < n; first += rowsPerChunk)
    {
      const vtkIdType rows = std::min(rowsPerChunk, n - first);
      if (!this->In.Read(chunk.data(), static_cast<size_t>(rows) * rowSize))
      {
        return this->FailEnd(vertex, (this->In.Position() - start) / rowSize,
          this->BinaryDetail(start, vertex.Count, rowSize));
      }
      this->Decode(chunk.data(), rows, first, swap);
    }
    return true;
  }

  // List properties make rows of varying size: the scalars of each row are gathered into a
  // packed row, the lists skipped.
  char count[8];
  auto failEnd = [&](vtkIdType v) {
    return this->FailEnd(vertex, static_cast<uint64_t>(v),
      "binary data from byte " + std::to_string(start) + ", the file has " +
        std::to_string(this->In.FileSize()) + " bytes");
  };
  for (vtkIdType first = 0; first < n; first += rowsPerChunk)
  {
    const vtkIdType rows = std::min(rowsPerChunk, n - first);
    for (vtkIdType r = 0; r < rows; ++r)
    {
      const vtkIdType v = first + r;
      if (v >= this->Allocated)
      {
        return failEnd(v);
      }
      char* row = chunk.data() + static_cast<size_t>(r) * rowSize;
      for (size_t i = 0; i < vertex.Properties.size(); ++i)
      {
        const Property& p = vertex.Properties[i];
        bool ok;
        if (!p.IsList)
        {
          ok =
            this->In.Read(row + this->Targets[this->TargetOfProperty[i]].Offset, TypeSize(p.Type));
        }
        else
        {
          ok = this->In.Read(count, TypeSize(p.CountType));
          const int64_t items = ok ? LoadCount(p.CountType, count, swap) : 0;
          if (items < 0)
          {
            return this->Fail("negative count " + std::to_string(items) + " of list " +
              Quote(p.Name) + " in vertex " + std::to_string(v + 1));
          }
          ok = ok && this->In.Skip(static_cast<uint64_t>(items) * TypeSize(p.Type));
        }
        if (!ok)
        {
          return failEnd(v);
        }
      }
    }
    this->Decode(chunk.data(), rows, first, swap);
  }
  return true;
}

// The values of row r of element e on an ASCII line (this->Tokens, line this->Line), as its
// properties declare them: each scalar, each list's count and that many items, nothing more.
// The vertex element's scalars go to `row` at their targets' offsets; a row of another element
// (row nullptr) is only checked.
bool PLYParser::ParseAsciiRow(const Element& e, uint64_t r, char* row)
{
  auto which = [&e, r]() {
    return Printable(e.Name) + " " + std::to_string(r + 1) + " of " + std::to_string(e.Count);
  };
  char scratch[8];
  size_t next = 0; // token
  for (size_t i = 0; i < e.Properties.size(); ++i)
  {
    const Property& p = e.Properties[i];
    auto missing = [&]() {
      return this->Fail("too few values for " + which() + ": no value for property " +
          Quote(p.Name) + " (the line has " + std::to_string(this->Tokens.size()) + ")",
        this->Line);
    };
    auto invalid = [&](Parse result, std::string_view token, PlyType type) {
      return this->Fail(
        ParseMessage(result, token, type) + " in property " + Quote(p.Name) + " of " + which(),
        this->Line);
    };
    if (next >= this->Tokens.size())
    {
      return missing();
    }
    const std::string_view token = this->Tokens[next++];
    if (!p.IsList)
    {
      char* dst = row ? row + this->Targets[this->TargetOfProperty[i]].Offset : scratch;
      const Parse result = ParseInto(p.Type, token, dst);
      if (result != Parse::Ok)
      {
        return invalid(result, token, p.Type);
      }
      continue;
    }
    const Parse result = ParseInto(p.CountType, token, scratch);
    if (result != Parse::Ok)
    {
      return invalid(result, token, p.CountType);
    }
    const int64_t items = LoadCount(p.CountType, scratch, false);
    if (items < 0)
    {
      return this->Fail("negative list count " + std::to_string(items) + " in property " +
          Quote(p.Name) + " of " + which(),
        this->Line);
    }
    if (static_cast<uint64_t>(items) > this->Tokens.size() - next)
    {
      return this->Fail("list count " + std::to_string(items) + " in property " + Quote(p.Name) +
          " of " + which() + ", but the line has " + std::to_string(this->Tokens.size() - next) +
          " values after it",
        this->Line);
    }
    for (int64_t k = 0; k < items; ++k)
    {
      const std::string_view item = this->Tokens[next++];
      const Parse itemResult = ParseInto(p.Type, item, scratch);
      if (itemResult != Parse::Ok)
      {
        return invalid(itemResult, item, p.Type);
      }
    }
  }
  if (next != this->Tokens.size())
  {
    return this->Fail("too many values for " + which() + " (" +
        std::to_string(this->Tokens.size()) + ", " + std::to_string(next) + " expected)",
      this->Line);
  }
  return true;
}

bool PLYParser::ReadAsciiVertices(const Element& vertex)
{
  const size_t rowSize = this->PackedRowSize;
  const vtkIdType n = static_cast<vtkIdType>(this->NumberOfRows);
  const vtkIdType rowsPerChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
  std::vector<char> chunk(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
  std::string_view line;
  for (vtkIdType first = 0; first < n; first += rowsPerChunk)
  {
    const vtkIdType rows = std::min(rowsPerChunk, n - first);
    for (vtkIdType r = 0; r < rows; ++r)
    {
      const vtkIdType v = first + r;
      if (v >= this->Allocated || !this->NextDataLine(line))
      {
        return this->In.TooLong()
          ? this->FailLongLine()
          : this->FailEnd(vertex, v, "ASCII data, after line " + std::to_string(this->Line));
      }
      Split(line, this->Tokens);
      if (!this->ParseAsciiRow(
            vertex, static_cast<uint64_t>(v), chunk.data() + static_cast<size_t>(r) * rowSize))
      {
        return false;
      }
    }
    this->Decode(chunk.data(), rows, first, false);
  }
  return true;
}

bool PLYParser::Read(vtkPolyData* output, bool createVertexCells, int piece, int pieces)
{
  if (!this->ReadHeader())
  {
    return false;
  }
  auto vertex = std::find_if(this->Elements.begin(), this->Elements.end(),
    [](const Element& e) { return e.Name == "vertex"; });
  if (vertex == this->Elements.end())
  {
    return this->Fail("no vertex element in the header");
  }
  for (const char* axis : { "x", "y", "z" })
  {
    if (std::none_of(vertex->Properties.begin(), vertex->Properties.end(),
          [axis](const Property& p) { return !p.IsList && p.Name == axis; }))
    {
      return this->Fail(std::string("the vertex element has no ") + axis + " property");
    }
  }
  if (vertex->Count > static_cast<uint64_t>(std::numeric_limits<vtkIdType>::max()))
  {
    return this->Fail("too many vertices (" + std::to_string(vertex->Count) + ")");
  }
  if (!this->CheckElementBytes(*vertex))
  {
    return false;
  }
  // The elements before the vertices, each skipped knowing the least bytes of those after it
  // (a list count that runs into them is the skipped element's). Elements after the vertex
  // element are never read (CheckElementBytes: their rows fit in the file at their least).
  const size_t before = static_cast<size_t>(vertex - this->Elements.begin());
  std::vector<uint64_t> reserve(before + 1, 0); // [i]: the least bytes of elements i, i + 1, ...
  for (auto e = this->Elements.begin() + before; e != this->Elements.end(); ++e)
  {
    reserve[before] = SaturatedSum(reserve[before], LeastBytes(*e, false));
  }
  for (size_t i = before; i-- > 0;)
  {
    reserve[i] = SaturatedSum(reserve[i + 1], LeastBytes(this->Elements[i], false));
  }
  for (size_t i = 0; i < before; ++i)
  {
    const Element& next = this->Elements[i + 1];
    const std::string after = "the " + Printable(next.Name) + " element" +
      (i + 2 < this->Elements.size() ? " and those after it" : "");
    if (!this->SkipElement(this->Elements[i], reserve[i + 1], after))
    {
      return false;
    }
  }
  if (this->FileFormat != Format::Ascii && !this->CheckVertexBytes(*vertex))
  {
    return false;
  }
  this->FirstRow = 0;
  this->NumberOfRows = vertex->Count;
  const bool fixedRows = this->FileFormat != Format::Ascii &&
    std::none_of(vertex->Properties.begin(), vertex->Properties.end(),
      [](const Property& p) { return p.IsList; });
  if (pieces > 1 && fixedRows)
  {
    const uint64_t n = vertex->Count, p = static_cast<uint64_t>(piece);
    const uint64_t q = static_cast<uint64_t>(pieces);
    this->FirstRow = n / q * p + n % q * p / q;
    this->NumberOfRows = n / q * (p + 1) + n % q * (p + 1) / q - this->FirstRow;
  }
  else if (piece > 0)
  {
    this->NumberOfRows = 0; // piece 0 reads the whole file
  }
  if (!this->Prepare(*vertex, output))
  {
    return false;
  }
  const bool ok = this->FileFormat == Format::Ascii ? this->ReadAsciiVertices(*vertex)
                                                    : this->ReadBinaryVertices(*vertex);
  if (!ok || (this->NumberOfRows == vertex->Count && !this->SkipElementsAfter(*vertex)))
  {
    return false;
  }
  // ASCII data after the vertices when they are the last element: the header counts fewer
  // vertices than the file holds.
  if (this->FileFormat == Format::Ascii && this->NumberOfRows == vertex->Count &&
    std::next(vertex) == this->Elements.end())
  {
    std::string_view line;
    if (this->NextDataLine(line))
    {
      return this->Fail("data after the " + std::to_string(vertex->Count) +
          " vertices that the header declares (the vertex element is the last)",
        this->Line);
    }
  }
  if (createVertexCells)
  {
    const vtkIdType n = static_cast<vtkIdType>(this->NumberOfRows);
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

vtkPointCloudPLYReader::vtkPointCloudPLYReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudPLYReader::~vtkPointCloudPLYReader()
{
  this->SetFileName(nullptr);
}

int vtkPointCloudPLYReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkPointCloudPLYReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  this->SetErrorCode(vtkErrorCode::NoError);

  // Errors are reported here and the request still succeeds with an empty output: a failed
  // request would add the executive's own, less telling, error.
  auto fail = [this](unsigned long code, const std::string& message) {
    this->ErrorMessage = vtkPointCloudIO::OneLine(message);
    this->SetErrorCode(code);
    vtkErrorMacro(<< this->ErrorMessage);
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

  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int piece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  PLYParser parser(name, stream, size);
  vtkNew<vtkPolyData> cloud;
  const bool ok = parser.Read(
    cloud, this->CreateVertexCells, std::max(piece, 0), std::max(pieces, 1));
  for (const std::string& warning : parser.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!ok)
  {
    return fail(vtkErrorCode::FileFormatError, parser.Error);
  }
  output->ShallowCopy(cloud);
  return 1;
}

void vtkPointCloudPLYReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CreateVertexCells: " << (this->CreateVertexCells ? "On" : "Off") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
