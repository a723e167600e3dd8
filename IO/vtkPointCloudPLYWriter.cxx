#include "vtkPointCloudPLYWriter.h"
#include "vtkPointCloudPLYTypes.h"
#include "vtkPointCloudFiles.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPointCloudPLYWriter);

using namespace featurepoints::ply;

namespace
{

// True when every value of a (64-bit integer) array fits in a 32-bit int.
bool FitsInt32(vtkDataArray* array)
{
  if (array->GetNumberOfTuples() == 0)
  {
    return true;
  }
  for (int c = 0; c < array->GetNumberOfComponents(); ++c)
  {
    // The range is computed in double: exact for integers up to 2^53, far beyond int's range.
    double range[2];
    array->GetRange(range, c);
    if (range[0] < std::numeric_limits<int32_t>::lowest() ||
      range[1] > std::numeric_limits<int32_t>::max())
    {
      return false;
    }
  }
  return true;
}

// The PLY type an array is written in; false for types PLY cannot hold.
bool ChooseType(vtkDataArray* array, PlyType& type)
{
  const bool is32 = array->GetDataTypeSize() == 4;
  switch (array->GetDataType())
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      type = PlyType::Int8;
      return true;
    case VTK_UNSIGNED_CHAR:
    case VTK_BIT:
      type = PlyType::UInt8;
      return true;
    case VTK_SHORT:
      type = PlyType::Int16;
      return true;
    case VTK_UNSIGNED_SHORT:
      type = PlyType::UInt16;
      return true;
    case VTK_INT:
      type = PlyType::Int32;
      return true;
    case VTK_UNSIGNED_INT:
      type = PlyType::UInt32;
      return true;
    case VTK_LONG:
    case VTK_LONG_LONG:
    case VTK_ID_TYPE:
      // PLY has no 64-bit integers.
      type = (is32 || FitsInt32(array)) ? PlyType::Int32 : PlyType::Float64;
      return true;
    case VTK_UNSIGNED_LONG:
    case VTK_UNSIGNED_LONG_LONG:
      type = is32 ? PlyType::UInt32 : (FitsInt32(array) ? PlyType::Int32 : PlyType::Float64);
      return true;
    case VTK_FLOAT:
      type = PlyType::Float32;
      return true;
    case VTK_DOUBLE:
      type = PlyType::Float64;
      return true;
    default:
      return false;
  }
}

// A property name is one word of the header: anything but letters, digits, '_', '-', '.' is
// replaced.
std::string Sanitize(const char* name)
{
  std::string s = name ? name : "";
  for (char& c : s)
  {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
      c == '_' || c == '-' || c == '.';
    c = keep ? c : '_';
  }
  return s.empty() ? "unnamed" : s;
}

// One vertex property: one component of an array.
struct Column
{
  std::string Name;
  vtkDataArray* Array;
  int Component;
  PlyType Type;
  size_t Offset; // in a packed row
};

// Writes one component of tuples [begin, end) as D, every `stride` bytes.
template <typename D>
struct EncodeWorker
{
  template <typename ArrayT>
  void operator()(
    ArrayT* array, int component, vtkIdType begin, vtkIdType end, char* out, size_t stride) const
  {
    for (const auto tuple : vtk::DataArrayTupleRange(array, begin, end))
    {
      const D value = static_cast<D>(tuple[component]);
      std::memcpy(out, &value, sizeof(D));
      out += stride;
    }
  }
};

// Packs rows [begin, end) of every column, in host byte order.
void Encode(
  const std::vector<Column>& columns, vtkIdType begin, vtkIdType end, char* out, size_t rowSize)
{
  for (const Column& c : columns)
  {
    WithType(c.Type, [&](auto d) {
      EncodeWorker<decltype(d)> worker;
      char* dst = out + c.Offset;
      if (!vtkArrayDispatch::Dispatch::Execute(
            c.Array, worker, c.Component, begin, end, dst, rowSize))
      {
        worker(c.Array, c.Component, begin, end, dst, rowSize);
      }
    });
  }
}

// Appends one packed value as text: integers as integers, floating-point values with the
// shortest text that reads back to the same value.
char* FormatValue(PlyType type, const char* src, char* out, char* end)
{
  WithType(type, [&](auto v) {
    using T = decltype(v);
    T value;
    std::memcpy(&value, src, sizeof(T));
    if constexpr (sizeof(T) == 1)
    {
      out = std::to_chars(out, end, static_cast<int>(value)).ptr;
    }
    else
    {
      out = std::to_chars(out, end, value).ptr;
    }
  });
  return out;
}

constexpr size_t ChunkBytes = size_t(4) << 20;
constexpr size_t MaxValueChars = 32; // "-1.7976931348623157e+308" and a separator
} // namespace

vtkPointCloudPLYWriter::vtkPointCloudPLYWriter() = default;

vtkPointCloudPLYWriter::~vtkPointCloudPLYWriter()
{
  this->SetFileName(nullptr);
}

vtkPointSet* vtkPointCloudPLYWriter::GetInput()
{
  return vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
}

int vtkPointCloudPLYWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkPointCloudPLYWriter::WriteData()
{
  this->ErrorMessage.clear();
  auto fail = [this](unsigned long code, const std::string& message) {
    this->ErrorMessage = message;
    this->SetErrorCode(code);
    vtkErrorMacro(<< message);
  };
  vtkPointSet* input = this->GetInput();
  if (!input)
  {
    fail(vtkErrorCode::UnknownError, "no input point set");
    return;
  }
  if (!this->FileName || !*this->FileName)
  {
    fail(vtkErrorCode::NoFileNameError, "no file name given");
    return;
  }
  const std::string name = this->FileName;

  vtkPoints* points = input->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  vtkDataArray* coords = points ? points->GetData() : nullptr;
  const PlyType coordType =
    (!coords || coords->GetDataType() == VTK_FLOAT) ? PlyType::Float32 : PlyType::Float64;
  std::vector<Column> columns;
  for (int c = 0; c < 3; ++c)
  {
    columns.push_back({ std::string(1, "xyz"[c]), coords, c, coordType, 0 });
  }

  vtkPointData* pd = input->GetPointData();
  vtkDataArray* normals = featurepoints::FindWritableNormals(pd, n);
  PlyType type;
  if (normals && ChooseType(normals, type))
  {
    for (int c = 0; c < 3; ++c)
    {
      columns.push_back({ std::string("n") + "xyz"[c], normals, c, type, 0 });
    }
  }
  vtkDataArray* colours = pd->GetArray("RGB");
  if (!(featurepoints::FitsPoints(colours, 3, n) && colours->GetDataType() == VTK_UNSIGNED_CHAR))
  {
    colours = pd->GetArray("RGBA");
    colours =
      (featurepoints::FitsPoints(colours, 4, n) && colours->GetDataType() == VTK_UNSIGNED_CHAR)
      ? colours
      : nullptr;
  }
  if (colours)
  {
    const char* channels[] = { "red", "green", "blue", "alpha" };
    for (int c = 0; c < colours->GetNumberOfComponents(); ++c)
    {
      columns.push_back({ channels[c], colours, c, PlyType::UInt8, 0 });
    }
  }

  // Names the reader gives a meaning to stay with their arrays; other clashes get a suffix.
  std::set<std::string> used = { "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha" };
  featurepoints::ForEachOtherPointArray(
    pd, n, name, { normals, colours },
    [&type](vtkDataArray* array) { return ChooseType(array, type); },
    [&](vtkDataArray* array) {
      const std::string base = Sanitize(array->GetName());
      const int k = array->GetNumberOfComponents();
      std::vector<std::string> names(k);
      for (int s = 1;; ++s)
      {
        const std::string stem = s == 1 ? base : base + "_" + std::to_string(s);
        for (int c = 0; c < k; ++c)
        {
          names[c] = k == 1 ? stem : stem + "_" + std::to_string(c);
        }
        if (std::none_of(names.begin(), names.end(),
              [&used](const std::string& p) { return used.count(p); }))
        {
          break;
        }
      }
      for (int c = 0; c < k; ++c)
      {
        used.insert(names[c]);
        columns.push_back({ names[c], array, c, type, 0 });
      }
    },
    [this](const std::string& text) { vtkWarningMacro(<< text); });

  const bool ascii = this->FileType == VTK_ASCII;
  std::string header = "ply\nformat ";
  header += ascii ? "ascii 1.0\n" : "binary_little_endian 1.0\n";
  header += "comment written by FeaturePoints (vtkPointCloudPLYWriter)\n";
  header += "element vertex " + std::to_string(n) + "\n";
  size_t rowSize = 0;
  for (Column& c : columns)
  {
    c.Offset = rowSize;
    rowSize += TypeSize(c.Type);
    header += std::string("property ") + TypeName(c.Type) + " " + c.Name + "\n";
  }
  header += "end_header\n";

  errno = 0;
  FILE* file = vtksys::SystemTools::Fopen(name, "wb");
  if (!file)
  {
    fail(vtkErrorCode::CannotOpenFileError,
      name + ": cannot open the file for writing (" +
        (errno ? std::strerror(errno) : "unknown reason") + ")");
    return;
  }
  bool ok = std::fwrite(header.data(), 1, header.size(), file) == header.size();

  // Rows are packed a chunk at a time, then written as they are (binary) or as text.
  const bool swap = featurepoints::HostIsBigEndian();
  const vtkIdType rowsPerChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
  std::vector<char> packed(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
  std::vector<char> text(ascii
      ? static_cast<size_t>(std::min(n, rowsPerChunk)) * (columns.size() * MaxValueChars + 1)
      : 0);
  for (vtkIdType begin = 0; ok && begin < n; begin += rowsPerChunk)
  {
    const vtkIdType end = std::min(n, begin + rowsPerChunk);
    const size_t rows = static_cast<size_t>(end - begin);
    Encode(columns, begin, end, packed.data(), rowSize);
    if (!ascii)
    {
      if (swap)
      {
        for (const Column& c : columns)
        {
          const size_t size = TypeSize(c.Type);
          for (size_t r = 0; r < rows; ++r)
          {
            char* value = packed.data() + r * rowSize + c.Offset;
            std::reverse(value, value + size);
          }
        }
      }
      ok = std::fwrite(packed.data(), 1, rows * rowSize, file) == rows * rowSize;
      continue;
    }
    char* out = text.data();
    char* const last = text.data() + text.size();
    for (size_t r = 0; r < rows; ++r)
    {
      const char* row = packed.data() + r * rowSize;
      for (size_t c = 0; c < columns.size(); ++c)
      {
        if (c > 0)
        {
          *out++ = ' ';
        }
        out = FormatValue(columns[c].Type, row + columns[c].Offset, out, last);
      }
      *out++ = '\n';
    }
    const size_t bytes = static_cast<size_t>(out - text.data());
    ok = std::fwrite(text.data(), 1, bytes, file) == bytes;
  }
  int error = ok ? 0 : errno;
  if (std::fclose(file) != 0 && ok)
  {
    ok = false;
    error = errno;
  }
  if (!ok)
  {
    fail(vtkErrorCode::OutOfDiskSpaceError,
      name + ": cannot write the file (" + (error ? std::strerror(error) : "unknown reason") + ")");
  }
}

void vtkPointCloudPLYWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FileType: " << (this->FileType == VTK_ASCII ? "ASCII" : "Binary") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
