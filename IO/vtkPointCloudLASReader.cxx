#include "vtkPointCloudLASReader.h"
#include "vtkPointCloudFiles.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPointCloudLASReader);

using featurepoints::HostIsBigEndian;
using featurepoints::Load;

namespace
{
constexpr size_t ChunkBytes = size_t(4) << 20;

// Offsets in the public header block (LAS 1.4 R15, table 3; the same in 1.0 to 1.3 up to byte
// 227).
constexpr size_t VersionMajorAt = 24;
constexpr size_t VersionMinorAt = 25;
constexpr size_t HeaderSizeAt = 94;
constexpr size_t OffsetToPointDataAt = 96;
constexpr size_t NumberOfVLRsAt = 100;
constexpr size_t PointFormatAt = 104;
constexpr size_t RecordLengthAt = 105;
constexpr size_t LegacyPointCountAt = 107;
constexpr size_t ScaleAt = 131;      // x, y, z: 3 doubles
constexpr size_t OffsetAt = 155;     // x, y, z: 3 doubles
constexpr size_t PointCountAt = 247; // LAS 1.4: unsigned 64-bit
constexpr size_t WaveformStartAt = 227; // LAS 1.3 and later: unsigned 64-bit, 0 where none
constexpr size_t FirstEVLRAt = 235;     // LAS 1.4: unsigned 64-bit, 0 where none
constexpr size_t HeaderSize12 = 227, HeaderSize13 = 235, HeaderSize14 = 375;
// A variable-length record's header: reserved (2 bytes), user ID (16), record ID (2), record
// length after the header (2), description (32).
constexpr size_t VLRHeaderSize = 54;
constexpr size_t VLRLengthAt = 20;

// What a point data record format holds and where (bytes from the start of the record).
struct RecordLayout
{
  size_t Size;   // the standard record length; longer records hold extra bytes
  bool Extended; // formats 6-10: 4-bit return numbers, a whole byte of classification
  int GpsTime;   // -1: none
  int Colour;    // -1: none
  int Nir;       // -1: none
};

const RecordLayout Layouts[11] = {
  { 20, false, -1, -1, -1 }, // 0
  { 28, false, 20, -1, -1 }, // 1
  { 26, false, -1, 20, -1 }, // 2
  { 34, false, 20, 28, -1 }, // 3
  { 57, false, 20, -1, -1 }, // 4: 1 and a wave packet
  { 63, false, 20, 28, -1 }, // 5: 3 and a wave packet
  { 30, true, 22, -1, -1 },  // 6
  { 36, true, 22, 30, -1 },  // 7
  { 38, true, 22, 30, 36 },  // 8
  { 59, true, 22, -1, -1 },  // 9: 6 and a wave packet
  { 67, true, 22, 30, 36 },  // 10: 8 and a wave packet
};

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string Number(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// Walks the `count` variable-length records from the end of the header: each one's header and
// the data it declares must end by the offset to point data (bytes may follow the last one: LAS
// 1.0's start signature, or user data). Their contents are not read. "" when they fit, else what
// is wrong.
std::string CheckVLRs(
  std::istream& stream, uint64_t headerSize, uint64_t pointOffset, uint32_t count, bool swap)
{
  uint64_t at = headerSize;
  char vlr[VLRHeaderSize];
  for (uint32_t i = 0; i < count; ++i)
  {
    const std::string which =
      "VLR " + std::to_string(i + 1) + " of " + std::to_string(count) + " (from byte " +
      std::to_string(at) + ")";
    if (at + VLRHeaderSize > pointOffset)
    {
      return which + ": its " + std::to_string(VLRHeaderSize) +
        "-byte header runs past the offset to point data (byte " + std::to_string(pointOffset) +
        ")";
    }
    stream.clear();
    stream.seekg(static_cast<std::streamoff>(at));
    stream.read(vlr, VLRHeaderSize);
    if (stream.gcount() != static_cast<std::streamsize>(VLRHeaderSize))
    {
      return which + ": read error";
    }
    const uint64_t end = at + VLRHeaderSize + Load<uint16_t>(vlr + VLRLengthAt, swap);
    if (end > pointOffset)
    {
      return which + ": its header and the " + std::to_string(end - at - VLRHeaderSize) +
        " bytes of data it declares end at byte " + std::to_string(end) +
        ", past the offset to point data (byte " + std::to_string(pointOffset) + ")";
    }
    at = end;
  }
  return "";
}

template <typename ArrayT>
vtkSmartPointer<ArrayT> Allocate(const char* name, int components, vtkIdType n)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  if (array->GetNumberOfTuples() != n || (n > 0 && !array->GetVoidPointer(0)))
  {
    return nullptr;
  }
  return array;
}
} // namespace

vtkPointCloudLASReader::vtkPointCloudLASReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkPointCloudLASReader::~vtkPointCloudLASReader()
{
  this->SetFileName(nullptr);
}

int vtkPointCloudLASReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  this->VersionMajor = this->VersionMinor = 0;
  this->PointDataFormat = -1;
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
  const std::string laz = name +
    ": compressed LAS (LAZ) is not supported in this build: it needs the LASzip library, which "
    "Debian 12 does not ship; decompress the file to .las first (laszip, las2las or pdal "
    "translate)";
  if (Lower(vtksys::SystemTools::GetFilenameLastExtension(name)) == ".laz")
  {
    return fail(vtkErrorCode::FileFormatError, laz);
  }
  vtksys::ifstream stream;
  uint64_t fileSize = 0;
  if (const unsigned long code = featurepoints::OpenReaderFile(name, stream, fileSize, message))
  {
    return fail(code, message);
  }
  auto bad = [&](const std::string& what) {
    return fail(vtkErrorCode::FileFormatError, name + ": " + what);
  };

  // The public header block: 227 bytes in LAS 1.0-1.2, 235 in 1.3, 375 in 1.4.
  char header[HeaderSize14] = { 0 };
  stream.read(header, static_cast<std::streamsize>(std::min<uint64_t>(fileSize, HeaderSize14)));
  if (fileSize < 4 || std::memcmp(header, "LASF", 4) != 0)
  {
    return bad("not a LAS file (it does not start with the signature LASF)");
  }
  if (fileSize < HeaderSize12)
  {
    return bad("the file ends in the LAS header (" + std::to_string(HeaderSize12) +
      " bytes at least, the file has " + std::to_string(fileSize) + ")");
  }
  const bool swap = HostIsBigEndian();
  const int major = static_cast<unsigned char>(header[VersionMajorAt]);
  const int minor = static_cast<unsigned char>(header[VersionMinorAt]);
  if (major != 1 || minor > 4)
  {
    return bad("unsupported LAS version " + std::to_string(major) + "." + std::to_string(minor) +
      " (1.0 to 1.4 are read)");
  }
  const unsigned headerSize = Load<uint16_t>(header + HeaderSizeAt, swap);
  const size_t leastHeader = minor >= 4 ? HeaderSize14 : (minor == 3 ? HeaderSize13 : HeaderSize12);
  if (headerSize < leastHeader)
  {
    return bad("header size " + std::to_string(headerSize) + " is impossible for LAS " +
      std::to_string(major) + "." + std::to_string(minor) + " (at least " +
      std::to_string(leastHeader) + " bytes)");
  }
  if (headerSize > fileSize)
  {
    return bad("the LAS " + std::to_string(major) + "." + std::to_string(minor) +
      " header's size field says " + std::to_string(headerSize) + " bytes, more than the file's " +
      std::to_string(fileSize) + " (a file cut short, or a corrupt field)");
  }
  const uint64_t pointOffset = Load<uint32_t>(header + OffsetToPointDataAt, swap);
  if (pointOffset < headerSize || pointOffset > fileSize)
  {
    return bad("the point data cannot start at byte " + std::to_string(pointOffset) +
      " (after the " + std::to_string(headerSize) + "-byte header, in a file of " +
      std::to_string(fileSize) + " bytes)");
  }
  const std::string vlrs = CheckVLRs(
    stream, headerSize, pointOffset, Load<uint32_t>(header + NumberOfVLRsAt, swap), swap);
  if (!vlrs.empty())
  {
    return bad(vlrs);
  }
  const int formatByte = static_cast<unsigned char>(header[PointFormatAt]);
  // LASzip marks its files by setting bit 7 (and 6) of a point data record format 0 to 10 (with
  // another format below, such as 99, the byte is just a format this reader does not know).
  if ((formatByte & 0xC0) && (formatByte & 0x3F) <= 10)
  {
    return fail(vtkErrorCode::FileFormatError, laz);
  }
  const int format = formatByte;
  if (format > 10)
  {
    return bad(
      "unsupported point data record format " + std::to_string(format) + " (0 to 10 are read)");
  }
  if (format >= 6 && minor < 4)
  {
    return bad("point data record format " + std::to_string(format) + " needs LAS 1.4 (the file "
      "is LAS " + std::to_string(major) + "." + std::to_string(minor) + ")");
  }
  const RecordLayout& layout = Layouts[format];
  const size_t recordLength = Load<uint16_t>(header + RecordLengthAt, swap);
  if (recordLength < layout.Size)
  {
    return bad("point record length " + std::to_string(recordLength) +
      " is shorter than point format " + std::to_string(format) + "'s " +
      std::to_string(layout.Size) + " bytes");
  }
  uint64_t count = Load<uint32_t>(header + LegacyPointCountAt, swap);
  if (minor >= 4)
  {
    // A 64-bit count of 0 with a legacy count: the legacy count (writers that fill only that).
    // Otherwise the legacy count is 0 or the same (LAS 1.4: the same for formats 0-5 when it
    // fits, 0 for 6-10; 0 is taken for any format, as some writers write it). Where the count
    // does not fit in 32 bits the legacy field is not read (writers leave 0, the maximum or the
    // low bits there).
    const uint64_t count64 = Load<uint64_t>(header + PointCountAt, swap);
    if (count64 != 0 && count64 <= 0xFFFFFFFFull && count != 0 && count != count64)
    {
      return bad("the legacy point count " + std::to_string(count) +
        " is neither 0 nor the LAS 1.4 point count " + std::to_string(count64));
    }
    count = count64 != 0 ? count64 : count;
  }
  double scale[3], offset[3];
  for (int c = 0; c < 3; ++c)
  {
    scale[c] = Load<double>(header + ScaleAt + 8 * c, swap);
    offset[c] = Load<double>(header + OffsetAt + 8 * c, swap);
    const char axis = "xyz"[c];
    if (!std::isfinite(scale[c]) || scale[c] == 0.0 || !std::isfinite(offset[c]))
    {
      return bad(std::string(1, axis) + " scale factor " + Number(scale[c]) + " and offset " +
        Number(offset[c]) + ": the scale must be finite and not 0, the offset finite");
    }
    // The largest coordinate a 32-bit record can give must be finite.
    if (!std::isfinite(std::fabs(scale[c]) * 2147483648.0 + std::fabs(offset[c])))
    {
      return bad(std::string(1, axis) + " scale factor " + Number(scale[c]) + " and offset " +
        Number(offset[c]) + " overflow double precision");
    }
  }
  const uint64_t room = (fileSize - pointOffset) / recordLength;
  if (count > room)
  {
    return bad("the header declares " + std::to_string(count) + " points of " +
      std::to_string(recordLength) + " bytes from byte " + std::to_string(pointOffset) +
      ", but the file (" + std::to_string(fileSize) + " bytes) holds " + std::to_string(room));
  }
  // Whole records beyond the declared count, up to the end of the file or what may follow the
  // points (1.3's waveform packets, 1.4's extended records), would be dropped unsaid. What
  // follows, where there is something (a start not 0), starts after the declared points.
  const uint64_t declaredEnd = pointOffset + count * recordLength;
  uint64_t pointsEnd = fileSize;
  for (const size_t at : { WaveformStartAt, FirstEVLRAt })
  {
    const uint64_t next = (at == WaveformStartAt ? minor >= 3 && headerSize >= HeaderSize13
                                                 : minor >= 4 && headerSize >= HeaderSize14)
      ? Load<uint64_t>(header + at, swap)
      : 0;
    const char* what = at == WaveformStartAt ? "the waveform data packet record"
                                             : "the first extended VLR";
    if (next != 0 && (next < declaredEnd || next > fileSize))
    {
      return bad(std::string("the header says ") + what + " starts at byte " +
        std::to_string(next) + ", " +
        (next > fileSize ? "past the end of the file (" + std::to_string(fileSize) + " bytes)"
                         : "before the end of the point data (bytes " +
              std::to_string(pointOffset) + " to " + std::to_string(declaredEnd) + ")"));
    }
    if (next > pointOffset && next < pointsEnd)
    {
      pointsEnd = next;
    }
  }
  if ((pointsEnd - pointOffset) / recordLength > count)
  {
    return bad("the header declares " + std::to_string(count) + " points of " +
      std::to_string(recordLength) + " bytes from byte " + std::to_string(pointOffset) +
      ", but " + std::to_string((pointsEnd - pointOffset) / recordLength) +
      " follow there: a wrong point count");
  }
  this->VersionMajor = major;
  this->VersionMinor = minor;
  this->PointDataFormat = format;

  const vtkIdType n = static_cast<vtkIdType>(count);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto intensity = Allocate<vtkUnsignedShortArray>("Intensity", 1, n);
  auto returnNumber = Allocate<vtkUnsignedCharArray>("ReturnNumber", 1, n);
  auto returns = Allocate<vtkUnsignedCharArray>("NumberOfReturns", 1, n);
  auto classification = Allocate<vtkUnsignedCharArray>("Classification", 1, n);
  auto gpsTime = layout.GpsTime >= 0 ? Allocate<vtkDoubleArray>("GpsTime", 1, n) : nullptr;
  auto rgb = layout.Colour >= 0 ? Allocate<vtkUnsignedShortArray>("RGB", 3, n) : nullptr;
  auto nir = layout.Nir >= 0 ? Allocate<vtkUnsignedShortArray>("NIR", 1, n) : nullptr;
  if (points->GetNumberOfPoints() != n || (n > 0 && !points->GetVoidPointer(0)) || !intensity ||
    !returnNumber || !returns || !classification || (layout.GpsTime >= 0 && !gpsTime) ||
    (layout.Colour >= 0 && !rgb) || (layout.Nir >= 0 && !nir))
  {
    return fail(vtkErrorCode::UnknownError,
      name + ": cannot allocate memory for " + std::to_string(n) + " points");
  }

  stream.clear();
  stream.seekg(static_cast<std::streamoff>(pointOffset));
  const vtkIdType perChunk = static_cast<vtkIdType>(std::max<size_t>(1, ChunkBytes / recordLength));
  std::vector<char> chunk(static_cast<size_t>(std::min(n, perChunk)) * recordLength);
  double* xyz = static_cast<double*>(points->GetVoidPointer(0));
  for (vtkIdType first = 0; first < n; first += perChunk)
  {
    const vtkIdType rows = std::min(perChunk, n - first);
    const size_t bytes = static_cast<size_t>(rows) * recordLength;
    stream.read(chunk.data(), static_cast<std::streamsize>(bytes));
    if (static_cast<size_t>(stream.gcount()) != bytes)
    {
      // The file's size was checked: only a read error (or a file that shrank) gets here.
      return bad("read error in point " + std::to_string(first + 1) + " of " + std::to_string(n));
    }
    const char* record = chunk.data();
    for (vtkIdType i = first; i < first + rows; ++i, record += recordLength)
    {
      for (int c = 0; c < 3; ++c)
      {
        xyz[3 * i + c] =
          static_cast<double>(Load<int32_t>(record + 4 * c, swap)) * scale[c] + offset[c];
      }
      intensity->SetValue(i, Load<uint16_t>(record + 12, swap));
      const unsigned char bits = static_cast<unsigned char>(record[14]);
      if (layout.Extended)
      {
        returnNumber->SetValue(i, bits & 0x0f);
        returns->SetValue(i, bits >> 4);
        classification->SetValue(i, static_cast<unsigned char>(record[16]));
      }
      else
      {
        returnNumber->SetValue(i, bits & 0x07);
        returns->SetValue(i, (bits >> 3) & 0x07);
        classification->SetValue(i, static_cast<unsigned char>(record[15]) & 0x1f);
      }
      if (gpsTime)
      {
        gpsTime->SetValue(i, Load<double>(record + layout.GpsTime, swap));
      }
      if (rgb)
      {
        for (int c = 0; c < 3; ++c)
        {
          rgb->SetTypedComponent(i, c, Load<uint16_t>(record + layout.Colour + 2 * c, swap));
        }
      }
      if (nir)
      {
        nir->SetValue(i, Load<uint16_t>(record + layout.Nir, swap));
      }
    }
  }

  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkPointData* pd = cloud->GetPointData();
  pd->AddArray(intensity);
  pd->AddArray(returnNumber);
  pd->AddArray(returns);
  pd->AddArray(classification);
  for (vtkDataArray* optional : { static_cast<vtkDataArray*>(gpsTime),
         static_cast<vtkDataArray*>(rgb), static_cast<vtkDataArray*>(nir) })
  {
    if (optional)
    {
      pd->AddArray(optional);
    }
  }
  if (this->CreateVertexCells)
  {
    vtkSmartPointer<vtkCellArray> verts = vtkPointCloudIO::MakeVertexCells(n);
    if (!verts)
    {
      return fail(vtkErrorCode::UnknownError,
        name + ": cannot allocate memory for " + std::to_string(n) + " vertex cells");
    }
    cloud->SetVerts(verts);
  }
  output->ShallowCopy(cloud);
  return 1;
}

void vtkPointCloudLASReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CreateVertexCells: " << (this->CreateVertexCells ? "On" : "Off") << "\n";
  os << indent << "Version: " << this->VersionMajor << "." << this->VersionMinor << "\n";
  os << indent << "PointDataFormat: " << this->PointDataFormat << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
