#include "vtkPointCloudPCDWriter.h"
#include "vtkPointCloudPCDTypes.h"
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

#include <lzf.h>

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

vtkStandardNewMacro(vtkPointCloudPCDWriter);

using namespace featurepoints::pcd;

namespace
{
// The PCD type an array is written in; false for types PCD cannot hold.
bool ChooseType(vtkDataArray* array, PcdType& type)
{
  const int size = array->GetDataTypeSize();
  switch (array->GetDataType())
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_SHORT:
    case VTK_INT:
    case VTK_LONG:
    case VTK_LONG_LONG:
    case VTK_ID_TYPE:
      return TypeFromLetter('I', size, type);
    case VTK_BIT:
      type = PcdType::UInt8;
      return true;
    case VTK_UNSIGNED_CHAR:
    case VTK_UNSIGNED_SHORT:
    case VTK_UNSIGNED_INT:
    case VTK_UNSIGNED_LONG:
    case VTK_UNSIGNED_LONG_LONG:
      return TypeFromLetter('U', size, type);
    case VTK_FLOAT:
    case VTK_DOUBLE:
      return TypeFromLetter('F', size, type);
    default:
      return false;
  }
}

// A field name is one word of the header: anything but letters, digits, '_', '-', '.' is
// replaced; "_" alone is PCL's padding and would not be read.
std::string Sanitize(const char* name)
{
  std::string s = name ? name : "";
  for (char& c : s)
  {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
      c == '_' || c == '-' || c == '.';
    c = keep ? c : '_';
  }
  return (s.empty() || s == "_") ? "unnamed" : s;
}

// One field: components [Component, Component + Count) of an array, or a packed colour.
struct Column
{
  std::string Name;
  vtkDataArray* Array;
  int Component;
  int Count;
  PcdType Type;
  enum
  {
    Values,
    PackedRGB, // F 4 holding 0x00RRGGBB
    PackedRGBA // U 4 holding 0xAARRGGBB
  } Pack = Values;
  size_t Offset = 0; // in a packed row
};

// Writes components [component, component + count) of tuples [begin, end) as D, the first at
// out, the next value `step` bytes further, the next tuple `stride` bytes further.
template <typename D>
struct EncodeWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, int component, int count, vtkIdType begin, vtkIdType end,
    char* out, size_t stride, size_t step) const
  {
    for (const auto tuple : vtk::DataArrayTupleRange(array, begin, end))
    {
      for (int k = 0; k < count; ++k)
      {
        const D value = static_cast<D>(tuple[component + k]);
        std::memcpy(out + k * step, &value, sizeof(D));
      }
      out += stride;
    }
  }
};

// Encodes one column of tuples [begin, end) in host byte order (see EncodeWorker).
void EncodeColumn(
  const Column& c, vtkIdType begin, vtkIdType end, char* out, size_t stride, size_t step)
{
  if (c.Pack != Column::Values)
  {
    const bool alpha = c.Pack == Column::PackedRGBA;
    for (vtkIdType i = begin; i < end; ++i, out += stride)
    {
      auto channel = [&](int k) {
        return static_cast<uint32_t>(static_cast<unsigned char>(c.Array->GetComponent(i, k)));
      };
      const uint32_t packed =
        (alpha ? channel(3) << 24 : 0u) | channel(0) << 16 | channel(1) << 8 | channel(2);
      std::memcpy(out, &packed, 4);
    }
    return;
  }
  WithType(c.Type, [&](auto d) {
    EncodeWorker<decltype(d)> worker;
    if (!vtkArrayDispatch::Dispatch::Execute(
          c.Array, worker, c.Component, c.Count, begin, end, out, stride, step))
    {
      worker(c.Array, c.Component, c.Count, begin, end, out, stride, step);
    }
  });
}

// Appends one value (host byte order at src) as text: integers as integers, floating-point
// values with the shortest text that reads back to the same value, packed colours as the
// integer of their bits.
char* FormatValue(const Column& c, const char* src, char* out, char* end)
{
  if (c.Pack != Column::Values)
  {
    uint32_t bits;
    std::memcpy(&bits, src, 4);
    return std::to_chars(out, end, bits).ptr;
  }
  WithType(c.Type, [&](auto v) {
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

void SwapValues(char* data, size_t count, size_t size)
{
  for (size_t i = 0; i < count; ++i, data += size)
  {
    std::reverse(data, data + size);
  }
}

constexpr size_t ChunkBytes = size_t(4) << 20;
constexpr size_t MaxValueChars = 32; // "-1.7976931348623157e+308" and a separator
} // namespace

vtkPointCloudPCDWriter::vtkPointCloudPCDWriter() = default;

vtkPointCloudPCDWriter::~vtkPointCloudPCDWriter()
{
  this->SetFileName(nullptr);
}

vtkPointSet* vtkPointCloudPCDWriter::GetInput()
{
  return vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
}

int vtkPointCloudPCDWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkPointCloudPCDWriter::WriteData()
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
  const PcdType coordType =
    (!coords || coords->GetDataType() == VTK_FLOAT) ? PcdType::Float32 : PcdType::Float64;
  std::vector<Column> columns;
  for (int c = 0; c < 3; ++c)
  {
    columns.push_back({ std::string(1, "xyz"[c]), coords, c, 1, coordType });
  }

  vtkPointData* pd = input->GetPointData();
  vtkDataArray* normals = featurepoints::FindWritableNormals(pd, n);
  PcdType type;
  if (normals && ChooseType(normals, type))
  {
    for (int c = 0; c < 3; ++c)
    {
      columns.push_back({ std::string("normal_") + "xyz"[c], normals, c, 1, type });
    }
  }
  else
  {
    normals = nullptr;
  }
  std::set<vtkDataArray*> colours;
  for (const char* colourName : { "RGB", "RGBA" })
  {
    const bool alpha = colourName[3] == 'A';
    vtkDataArray* array = pd->GetArray(colourName);
    if (featurepoints::FitsPoints(array, alpha ? 4 : 3, n) &&
      array->GetDataType() == VTK_UNSIGNED_CHAR)
    {
      Column c{ alpha ? "rgba" : "rgb", array, 0, 1, alpha ? PcdType::UInt32 : PcdType::Float32 };
      c.Pack = alpha ? Column::PackedRGBA : Column::PackedRGB;
      columns.push_back(c);
      colours.insert(array);
    }
  }

  // Names the reader gives a meaning to stay with their arrays; other clashes get a suffix.
  std::set<std::string> used = { "x", "y", "z", "normal_x", "normal_y", "normal_z", "rgb", "rgba" };
  std::set<vtkDataArray*> written = colours;
  written.insert(normals);
  featurepoints::ForEachOtherPointArray(
    pd, n, name, written, [&type](vtkDataArray* array) { return ChooseType(array, type); },
    [&](vtkDataArray* array) {
      const std::string base = Sanitize(array->GetName());
      std::string field = base;
      for (int s = 2; used.count(field); ++s)
      {
        field = base + "_" + std::to_string(s);
      }
      used.insert(field);
      columns.push_back({ field, array, 0, array->GetNumberOfComponents(), type });
    },
    [this](const std::string& text) { vtkWarningMacro(<< text); });

  std::string fields = "FIELDS", sizes = "SIZE", types = "TYPE", counts = "COUNT";
  size_t rowSize = 0;
  for (Column& c : columns)
  {
    c.Offset = rowSize;
    rowSize += TypeSize(c.Type) * static_cast<size_t>(c.Count);
    fields += " " + c.Name;
    sizes += " " + std::to_string(TypeSize(c.Type));
    types += std::string(" ") + TypeLetter(c.Type);
    counts += " " + std::to_string(c.Count);
  }
  const char* const formats[] = { "ascii", "binary", "binary_compressed" };
  const std::string header = "# .PCD v0.7 - Point Cloud Data file format (written by "
                             "FeaturePoints, vtkPointCloudPCDWriter)\nVERSION 0.7\n" +
    fields + "\n" + sizes + "\n" + types + "\n" + counts + "\nWIDTH " + std::to_string(n) +
    "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(n) + "\nDATA " +
    formats[this->DataFormat] + "\n";
  if (this->DataFormat == BINARY_COMPRESSED &&
    static_cast<uint64_t>(n) * rowSize > std::numeric_limits<uint32_t>::max())
  {
    fail(vtkErrorCode::UnknownError,
      name + ": " + std::to_string(n) + " points of " + std::to_string(rowSize) +
        " bytes are more than binary_compressed data can hold (4 GiB); write binary instead");
    return;
  }

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
  std::string problem;
  const bool swap = featurepoints::HostIsBigEndian();

  if (ok && this->DataFormat == BINARY_COMPRESSED)
  {
    // The fields one after the other (all the points' values of a field, then the next field),
    // which LZF compresses better than whole points.
    const size_t total = static_cast<size_t>(n) * rowSize;
    std::vector<char> data, packed;
    try
    {
      data.resize(total);
      packed.resize(total + total / 16 + 64);
    }
    catch (const std::bad_alloc&)
    {
      problem = "not enough memory to compress " + std::to_string(total) + " bytes";
    }
    if (problem.empty())
    {
      size_t block = 0;
      for (const Column& c : columns)
      {
        const size_t value = TypeSize(c.Type);
        const size_t perPoint = value * static_cast<size_t>(c.Count);
        EncodeColumn(c, 0, n, data.data() + block, perPoint, value);
        if (swap)
        {
          SwapValues(data.data() + block, static_cast<size_t>(n) * c.Count, value);
        }
        block += perPoint * static_cast<size_t>(n);
      }
      const unsigned int size = total == 0 ? 0
                                           : lzf_compress(data.data(), static_cast<unsigned>(total),
                                               packed.data(), static_cast<unsigned>(packed.size()));
      if (total > 0 && size == 0)
      {
        problem = "LZF compression failed";
      }
      else
      {
        uint32_t sizes2[2] = { size, static_cast<uint32_t>(total) };
        if (swap)
        {
          SwapValues(reinterpret_cast<char*>(sizes2), 2, 4);
        }
        ok =
          std::fwrite(sizes2, 1, 8, file) == 8 && std::fwrite(packed.data(), 1, size, file) == size;
      }
    }
  }
  else if (ok)
  {
    // Points are packed a chunk at a time, then written as they are (binary) or as text.
    const bool ascii = this->DataFormat == ASCII;
    const vtkIdType rowsPerChunk =
      static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / rowSize));
    size_t valuesPerRow = 0;
    for (const Column& c : columns)
    {
      valuesPerRow += static_cast<size_t>(c.Count);
    }
    std::vector<char> packed(static_cast<size_t>(std::min(n, rowsPerChunk)) * rowSize);
    std::vector<char> text(ascii
        ? static_cast<size_t>(std::min(n, rowsPerChunk)) * (valuesPerRow * MaxValueChars + 1)
        : 0);
    for (vtkIdType begin = 0; ok && begin < n; begin += rowsPerChunk)
    {
      const vtkIdType end = std::min(n, begin + rowsPerChunk);
      const size_t rows = static_cast<size_t>(end - begin);
      for (const Column& c : columns)
      {
        EncodeColumn(c, begin, end, packed.data() + c.Offset, rowSize, TypeSize(c.Type));
      }
      if (!ascii)
      {
        if (swap)
        {
          for (const Column& c : columns)
          {
            for (size_t r = 0; r < rows; ++r)
            {
              SwapValues(packed.data() + r * rowSize + c.Offset, c.Count, TypeSize(c.Type));
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
        bool firstValue = true;
        for (const Column& c : columns)
        {
          for (int k = 0; k < c.Count; ++k)
          {
            if (!firstValue)
            {
              *out++ = ' ';
            }
            firstValue = false;
            out = FormatValue(c, row + c.Offset + k * TypeSize(c.Type), out, last);
          }
        }
        *out++ = '\n';
      }
      const size_t bytes = static_cast<size_t>(out - text.data());
      ok = std::fwrite(text.data(), 1, bytes, file) == bytes;
    }
  }
  int error = ok ? 0 : errno;
  if (std::fclose(file) != 0 && ok)
  {
    ok = false;
    error = errno;
  }
  if (!problem.empty())
  {
    fail(vtkErrorCode::UnknownError, name + ": cannot write the file (" + problem + ")");
  }
  else if (!ok)
  {
    fail(vtkErrorCode::OutOfDiskSpaceError,
      name + ": cannot write the file (" + (error ? std::strerror(error) : "unknown reason") + ")");
  }
}

void vtkPointCloudPCDWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  const char* const formats[] = { "ASCII", "Binary", "BinaryCompressed" };
  os << indent << "DataFormat: " << formats[this->DataFormat] << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
