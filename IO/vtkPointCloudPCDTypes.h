// PCD's scalar types (a TYPE letter I, U or F with a SIZE of 1, 2, 4 or 8 bytes), shared by
// vtkPointCloudPCDReader and vtkPointCloudPCDWriter (private).
#ifndef vtkPointCloudPCDTypes_h
#define vtkPointCloudPCDTypes_h

#include "vtkType.h"

#include <cstddef>
#include <cstdint>

namespace featurepoints
{
namespace pcd
{
enum class PcdType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Int64,
  UInt64,
  Float32,
  Float64
};

// The type of a TYPE letter and a SIZE; false for a combination PCD does not define (F 1, X 4).
inline bool TypeFromLetter(char letter, int size, PcdType& type)
{
  switch (letter)
  {
    case 'I':
    case 'U':
    {
      const bool u = letter == 'U';
      switch (size)
      {
        case 1:
          type = u ? PcdType::UInt8 : PcdType::Int8;
          return true;
        case 2:
          type = u ? PcdType::UInt16 : PcdType::Int16;
          return true;
        case 4:
          type = u ? PcdType::UInt32 : PcdType::Int32;
          return true;
        case 8:
          type = u ? PcdType::UInt64 : PcdType::Int64;
          return true;
        default:
          return false;
      }
    }
    case 'F':
      if (size == 4 || size == 8)
      {
        type = size == 4 ? PcdType::Float32 : PcdType::Float64;
        return true;
      }
      return false;
    default:
      return false;
  }
}

inline char TypeLetter(PcdType type)
{
  static const char letters[] = { 'I', 'U', 'I', 'U', 'I', 'U', 'I', 'U', 'F', 'F' };
  return letters[static_cast<int>(type)];
}

inline size_t TypeSize(PcdType type)
{
  static const size_t sizes[] = { 1, 1, 2, 2, 4, 4, 8, 8, 4, 8 };
  return sizes[static_cast<int>(type)];
}

inline int VTKType(PcdType type)
{
  static const int types[] = { VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT,
    VTK_INT, VTK_UNSIGNED_INT, VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE };
  return types[static_cast<int>(type)];
}

inline bool IsFloatingPoint(PcdType type)
{
  return type == PcdType::Float32 || type == PcdType::Float64;
}

// Calls f(T()) with the C++ type of a PCD type.
template <typename F>
inline void WithType(PcdType type, F&& f)
{
  switch (type)
  {
    case PcdType::Int8:
      f(int8_t());
      break;
    case PcdType::UInt8:
      f(uint8_t());
      break;
    case PcdType::Int16:
      f(int16_t());
      break;
    case PcdType::UInt16:
      f(uint16_t());
      break;
    case PcdType::Int32:
      f(int32_t());
      break;
    case PcdType::UInt32:
      f(uint32_t());
      break;
    case PcdType::Int64:
      f(int64_t());
      break;
    case PcdType::UInt64:
      f(uint64_t());
      break;
    case PcdType::Float32:
      f(float());
      break;
    case PcdType::Float64:
      f(double());
      break;
  }
}

} // namespace pcd
} // namespace featurepoints

#endif
