// What the PLY, PCD and LAS readers and writers share: the host's byte order, loads of file
// values in either byte order, quoting a file's text in messages, and the checks and opening of
// a file to read. Private to FeaturePoints::IO (not installed).
#ifndef vtkPointCloudFiles_h
#define vtkPointCloudFiles_h

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkPointData.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <string_view>

namespace featurepoints
{
// Text of a file in a message: at most 64 characters, control and other non-ASCII bytes shown
// as '?' (a header's raw bytes are never echoed to a terminal); Quote() puts it in quotes.
inline std::string Printable(std::string_view text)
{
  std::string shown(text.substr(0, 64));
  for (char& c : shown)
  {
    c = (c >= 32 && c < 127) ? c : '?';
  }
  return text.size() > 64 ? shown + "..." : shown;
}

inline std::string Quote(std::string_view text)
{
  return "'" + Printable(text) + "'";
}

// Whether a decimal number that std::from_chars finds out of range is below 1 in magnitude (an
// underflow: it rounds to a zero or a subnormal of the type) rather than beyond the type's
// largest value (an overflow), told from its digits and its exponent of any size, whatever the
// locale: "1e-5000" and "0.000...1" with 400 zeros underflow, "1e400" overflows.
inline bool Underflows(std::string_view number)
{
  size_t i = 0;
  const size_t n = number.size();
  auto digit = [&number](size_t at) { return number[at] >= '0' && number[at] <= '9'; };
  if (i < n && (number[i] == '+' || number[i] == '-'))
  {
    ++i;
  }
  // The number lies in [10^(order - 1), 10^order) times 10 to its exponent.
  long long order = 0;
  bool nonzero = false;
  for (; i < n && digit(i); ++i)
  {
    nonzero = nonzero || number[i] != '0';
    order += nonzero ? 1 : 0;
  }
  if (i < n && number[i] == '.')
  {
    for (++i; i < n && digit(i); ++i)
    {
      if (!nonzero && number[i] == '0')
      {
        --order;
      }
      nonzero = nonzero || number[i] != '0';
    }
  }
  long long exponent = 0;
  if (i < n && (number[i] == 'e' || number[i] == 'E'))
  {
    ++i;
    const bool negative = i < n && number[i] == '-';
    i += (i < n && (number[i] == '-' || number[i] == '+')) ? 1 : 0;
    for (; i < n && digit(i); ++i)
    {
      exponent = std::min(exponent * 10 + (number[i] - '0'), 1000000000000000LL);
    }
    exponent = negative ? -exponent : exponent;
  }
  return !nonzero || order + exponent <= 0;
}

inline bool HostIsBigEndian()
{
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

// A value of type T stored at p, its bytes reversed when Swap (the file's byte order is not the
// host's). memcpy: p need not be aligned.
template <typename T, bool Swap>
inline T Load(const char* p)
{
  T value;
  if (Swap)
  {
    char bytes[sizeof(T)];
    for (size_t b = 0; b < sizeof(T); ++b)
    {
      bytes[b] = p[sizeof(T) - 1 - b];
    }
    std::memcpy(&value, bytes, sizeof(T));
  }
  else
  {
    std::memcpy(&value, p, sizeof(T));
  }
  return value;
}

// The same with the byte order known at run time.
template <typename T>
inline T Load(const char* p, bool swap)
{
  return swap ? Load<T, true>(p) : Load<T, false>(p);
}

// The checks every reader makes on its FileName before opening it: a name is given, the file
// exists and is not a folder. Returns vtkErrorCode::NoError, or the error code with `message`
// set to the reader's one-line error.
inline unsigned long CheckReaderFileName(const char* fileName, std::string& message)
{
  if (!fileName || !*fileName)
  {
    message = "no file name given";
    return vtkErrorCode::NoFileNameError;
  }
  const std::string name = fileName;
  if (!vtksys::SystemTools::FileExists(name))
  {
    message = name + ": no such file";
    return vtkErrorCode::CannotOpenFileError;
  }
  if (vtksys::SystemTools::FileIsDirectory(name))
  {
    message = name + ": is a directory, not a file";
    return vtkErrorCode::CannotOpenFileError;
  }
  return vtkErrorCode::NoError;
}

// Opens `name` for binary reading at its start and measures it. Returns vtkErrorCode::NoError,
// or CannotOpenFileError with `message` set (naming the system's reason where there is one).
inline unsigned long OpenReaderFile(
  const std::string& name, vtksys::ifstream& stream, uint64_t& size, std::string& message)
{
  errno = 0;
  stream.open(name.c_str(), std::ios::in | std::ios::binary);
  if (!stream)
  {
    message =
      name + ": cannot open the file (" + (errno ? std::strerror(errno) : "unknown reason") + ")";
    return vtkErrorCode::CannotOpenFileError;
  }
  stream.seekg(0, std::ios::end);
  const std::streamoff end = stream.tellg();
  stream.seekg(0, std::ios::beg);
  if (end < 0 || !stream)
  {
    message = name + ": cannot read the file's size";
    return vtkErrorCode::CannotOpenFileError;
  }
  size = static_cast<uint64_t>(end);
  return vtkErrorCode::NoError;
}

// Whether `array` has `components` components and a tuple for each of n points (at least).
inline bool FitsPoints(vtkDataArray* array, int components, vtkIdType n)
{
  return array && array->GetNumberOfComponents() == components && array->GetNumberOfTuples() >= n;
}

// The normals a writer writes: the point data's normals, else an array named "Normals", with 3
// components and a tuple per point; nullptr when there are none.
inline vtkDataArray* FindWritableNormals(vtkPointData* pd, vtkIdType n)
{
  vtkDataArray* normals = pd->GetNormals();
  if (!FitsPoints(normals, 3, n))
  {
    normals = pd->GetArray("Normals");
    normals = FitsPoints(normals, 3, n) ? normals : nullptr;
  }
  return normals;
}

// The point arrays a writer writes besides those in `written` (normals, colours): add(array) for
// each numeric array that canWrite(array) accepts with a tuple per point; warn(text) for each
// other one, with the file's name and why it is skipped.
template <typename CanWrite, typename Add, typename Warn>
void ForEachOtherPointArray(vtkPointData* pd, vtkIdType n, const std::string& fileName,
  const std::set<vtkDataArray*>& written, CanWrite canWrite, Add add, Warn warn)
{
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* abstract = pd->GetAbstractArray(i);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    if (!abstract || (array && written.count(array)))
    {
      continue;
    }
    const std::string label = abstract->GetName() ? abstract->GetName() : "(unnamed)";
    if (!array || !canWrite(array))
    {
      warn(fileName + ": array '" + label + "' (" + abstract->GetClassName() +
        ") skipped: not numeric");
      continue;
    }
    const int k = array->GetNumberOfComponents();
    if (k < 1 || array->GetNumberOfTuples() < n)
    {
      warn(fileName + ": array '" + label + "' skipped: " +
        std::to_string(array->GetNumberOfTuples()) + " tuples of " + std::to_string(k) +
        " components for " + std::to_string(n) + " points");
      continue;
    }
    add(array);
  }
}
} // namespace featurepoints

#endif
