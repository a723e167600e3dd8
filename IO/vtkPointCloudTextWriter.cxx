#include "vtkPointCloudTextWriter.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPointCloudTextWriter);

namespace
{
// Appends the shortest text that reads back to exactly this value.
template <typename T>
void Append(std::string& out, T value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

void AppendValue(std::string& out, vtkDataArray* array, vtkIdType tuple, int component)
{
  const vtkIdType index = tuple * array->GetNumberOfComponents() + component;
  switch (array->GetDataType())
  {
    case VTK_FLOAT:
      Append(out, static_cast<float*>(array->GetVoidPointer(0))[index]);
      break;
    case VTK_DOUBLE:
      Append(out, static_cast<double*>(array->GetVoidPointer(0))[index]);
      break;
    default:
      // Every integer type of VTK fits a long long except unsigned 64-bit values above its range.
      if (array->GetDataType() == VTK_UNSIGNED_LONG_LONG ||
        (array->GetDataType() == VTK_UNSIGNED_LONG && sizeof(unsigned long) == 8))
      {
        Append(out, static_cast<unsigned long long>(array->GetComponent(tuple, component)));
      }
      else
      {
        Append(out, static_cast<long long>(array->GetComponent(tuple, component)));
      }
  }
}

std::string Lower(std::string text)
{
  for (char& c : text)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

std::string ColumnName(std::string name, char delimiter)
{
  for (char& c : name)
  {
    if (c == delimiter || c == '"' || c == '\'' || c == '\n' || c == '\r')
    {
      c = '_';
    }
  }
  return name;
}
} // namespace

vtkPointCloudTextWriter::vtkPointCloudTextWriter() = default;

vtkPointCloudTextWriter::~vtkPointCloudTextWriter()
{
  this->SetFileName(nullptr);
}

vtkPointSet* vtkPointCloudTextWriter::GetInput()
{
  return vtkPointSet::SafeDownCast(this->GetInputDataObject(0, 0));
}

int vtkPointCloudTextWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkPointCloudTextWriter::WriteData()
{
  this->ErrorMessage.clear();
  const std::string file = this->FileName ? this->FileName : "";
  auto fail = [&](unsigned long code, const std::string& what) {
    this->ErrorMessage = file + ": " + what;
    vtkErrorMacro(<< this->ErrorMessage);
    this->SetErrorCode(code);
  };
  vtkPointSet* input = this->GetInput();
  if (!input)
  {
    fail(vtkErrorCode::UnknownError, "no input to write");
    return;
  }
  if (file.empty())
  {
    fail(vtkErrorCode::NoFileNameError, "no file name given");
    return;
  }
  std::vector<vtkDataArray*> arrays;
  vtkPointData* pd = input->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* abstract = pd->GetAbstractArray(a);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    if (!array || array->GetDataType() == VTK_BIT || !array->GetName())
    {
      vtkWarningMacro(<< file << ": point array '"
                      << (abstract->GetName() ? abstract->GetName() : "(unnamed)")
                      << "' is not numeric or has no name; it is not written.");
      continue;
    }
    arrays.push_back(array);
  }

  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out)
  {
    fail(vtkErrorCode::CannotOpenFileError, std::string("cannot write: ") + std::strerror(errno));
    return;
  }
  const char d = this->Delimiter;
  std::string buffer = std::string("x") + d + "y" + d + "z";
  // Each array's name once, as the reader reads it back: "NAME:K" is component K of NAME, so a
  // name ending in ":digits" has its colon replaced; a name already taken (the coordinates, an
  // earlier array) gets a suffix _2, _3, ...
  std::set<std::string> used = { "x", "y", "z" };
  // Columns nx, ny and nz together are the reader's Normals: beside an array named Normals they
  // are renamed (nx_2, ...), so that the two do not read back as one.
  std::set<std::string> names;
  for (vtkDataArray* array : arrays)
  {
    names.insert(Lower(ColumnName(array->GetName(), d)));
  }
  if (names.count("normals") && names.count("nx") && names.count("ny") && names.count("nz"))
  {
    used.insert({ "nx", "ny", "nz" });
  }
  for (vtkDataArray* array : arrays)
  {
    std::string base = ColumnName(array->GetName(), d);
    const size_t colon = base.rfind(':');
    if (colon != std::string::npos && colon + 1 < base.size() &&
      base.find_first_not_of("0123456789", colon + 1) == std::string::npos)
    {
      base[colon] = '_';
    }
    // A name that reads as a number would make the header read as data.
    char* end = nullptr;
    const double number = std::strtod(base.c_str(), &end);
    if (base.empty() || (end && *end == '\0' && std::isfinite(number)))
    {
      base += "_";
    }
    std::string name = base;
    for (int suffix = 2; used.count(Lower(name)); ++suffix)
    {
      name = base + "_" + std::to_string(suffix);
    }
    used.insert(Lower(name));
    const int nc = array->GetNumberOfComponents();
    for (int k = 0; k < nc; ++k)
    {
      buffer += d;
      buffer += nc == 1 ? name : name + ":" + std::to_string(k);
    }
  }
  buffer += '\n';
  vtkPoints* points = input->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  vtkDataArray* coordinates = points ? points->GetData() : nullptr;
  bool ok = true;
  for (vtkIdType i = 0; i < n && ok; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (c > 0)
      {
        buffer += d;
      }
      AppendValue(buffer, coordinates, i, c);
    }
    for (vtkDataArray* array : arrays)
    {
      for (int k = 0; k < array->GetNumberOfComponents(); ++k)
      {
        buffer += d;
        AppendValue(buffer, array, i, k);
      }
    }
    buffer += '\n';
    if (buffer.size() > (1 << 22))
    {
      errno = 0;
      ok = std::fwrite(buffer.data(), 1, buffer.size(), out) == buffer.size();
      buffer.clear();
      this->UpdateProgress(static_cast<double>(i) / n);
    }
  }
  // The error of the first call that failed (errno is stale where none set it: an earlier,
  // unrelated call's); the buffered bytes may fail only at fclose.
  int error = ok ? 0 : errno;
  if (ok)
  {
    errno = 0;
    ok = std::fwrite(buffer.data(), 1, buffer.size(), out) == buffer.size();
    error = ok ? 0 : errno;
  }
  errno = 0;
  if (std::fclose(out) != 0 && ok)
  {
    ok = false;
    error = errno;
  }
  if (!ok)
  {
    fail(vtkErrorCode::OutOfDiskSpaceError,
      std::string("write failed: ") + (error ? std::strerror(error) : "the disk may be full"));
  }
}

void vtkPointCloudTextWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Delimiter: '" << this->Delimiter << "'\n";
}
