// PLY's scalar types, shared by vtkPointCloudPLYReader and vtkPointCloudPLYWriter (private).
#ifndef vtkPointCloudPLYTypes_h
#define vtkPointCloudPLYTypes_h

#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace featurepoints
{
namespace ply
{
enum class PlyType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

inline bool TypeFromName(std::string_view name, PlyType& type)
{
  static const struct
  {
    const char* Name;
    PlyType Type;
  } names[] = { { "char", PlyType::Int8 }, { "int8", PlyType::Int8 }, { "uchar", PlyType::UInt8 },
    { "uint8", PlyType::UInt8 }, { "short", PlyType::Int16 }, { "int16", PlyType::Int16 },
    { "ushort", PlyType::UInt16 }, { "uint16", PlyType::UInt16 }, { "int", PlyType::Int32 },
    { "int32", PlyType::Int32 }, { "uint", PlyType::UInt32 }, { "uint32", PlyType::UInt32 },
    { "float", PlyType::Float32 }, { "float32", PlyType::Float32 }, { "double", PlyType::Float64 },
    { "float64", PlyType::Float64 } };
  for (const auto& n : names)
  {
    if (name == n.Name)
    {
      type = n.Type;
      return true;
    }
  }
  return false;
}

inline const char* TypeName(PlyType type)
{
  static const char* names[] = { "char", "uchar", "short", "ushort", "int", "uint", "float",
    "double" };
  return names[static_cast<int>(type)];
}

inline size_t TypeSize(PlyType type)
{
  static const size_t sizes[] = { 1, 1, 2, 2, 4, 4, 4, 8 };
  return sizes[static_cast<int>(type)];
}

inline int VTKType(PlyType type)
{
  // PLY's char is int8 whatever the platform's char is: vtkSignedCharArray, not vtkCharArray.
  static const int types[] = { VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT,
    VTK_INT, VTK_UNSIGNED_INT, VTK_FLOAT, VTK_DOUBLE };
  return types[static_cast<int>(type)];
}

inline bool IsInteger(PlyType type)
{
  return type != PlyType::Float32 && type != PlyType::Float64;
}

// Calls f(T()) with the C++ type of a PLY type.
template <typename F>
inline void WithType(PlyType type, F&& f)
{
  switch (type)
  {
    case PlyType::Int8:
      f(int8_t());
      break;
    case PlyType::UInt8:
      f(uint8_t());
      break;
    case PlyType::Int16:
      f(int16_t());
      break;
    case PlyType::UInt16:
      f(uint16_t());
      break;
    case PlyType::Int32:
      f(int32_t());
      break;
    case PlyType::UInt32:
      f(uint32_t());
      break;
    case PlyType::Float32:
      f(float());
      break;
    case PlyType::Float64:
      f(double());
      break;
  }
}

} // namespace ply
} // namespace featurepoints

#endif
