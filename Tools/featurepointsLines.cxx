#include "featurepointsLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointCloudIO.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace featurepoints
{
namespace
{
// One point per vertex of each curve (a junction once per curve), with its curve's id and the
// tangent: the table the CSV holds.
vtkSmartPointer<vtkPolyData> VertexTable(vtkPolyData* curves)
{
  auto table = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIntArray> ids;
  ids->SetName("CurveId");
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangent");
  tangents->SetNumberOfComponents(3);
  vtkDataArray* tangent = curves->GetPointData()->GetArray("Tangent");
  vtkDataArray* curveId = curves->GetCellData()->GetArray("CurveId");
  vtkNew<vtkIdList> cell;
  for (vtkIdType c = 0; c < curves->GetNumberOfCells(); ++c)
  {
    curves->GetCellPoints(c, cell);
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
    {
      const vtkIdType i = cell->GetId(k);
      points->InsertNextPoint(curves->GetPoint(i));
      ids->InsertNextValue(curveId ? static_cast<int>(curveId->GetTuple1(c)) : static_cast<int>(c));
      double t[3] = { 0, 0, 0 };
      if (tangent)
      {
        tangent->GetTuple(i, t);
      }
      tangents->InsertNextTuple(t);
    }
  }
  table->SetPoints(points);
  table->GetPointData()->AddArray(ids);
  table->GetPointData()->AddArray(tangents);
  return table;
}

bool WriteObj(vtkPolyData* curves, const std::string& fileName, std::string& error)
{
  const std::string target = vtkPointCloudIO::WriteTarget(fileName);
  const std::string temporary = vtkPointCloudIO::CreateTemporaryFile(target, error, true);
  if (temporary.empty())
  {
    return false;
  }
  FILE* file = std::fopen(temporary.c_str(), "w");
  bool ok = file != nullptr;
  if (ok)
  {
    std::fprintf(file, "# feature curves: %lld vertices, %lld polylines\n",
      static_cast<long long>(curves->GetNumberOfPoints()),
      static_cast<long long>(curves->GetNumberOfCells()));
    for (vtkIdType i = 0; i < curves->GetNumberOfPoints(); ++i)
    {
      double x[3];
      curves->GetPoint(i, x);
      std::fprintf(file, "v %.17g %.17g %.17g\n", x[0], x[1], x[2]);
    }
    vtkNew<vtkIdList> cell;
    for (vtkIdType c = 0; c < curves->GetNumberOfCells(); ++c)
    {
      curves->GetCellPoints(c, cell);
      std::fprintf(file, "l");
      for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
      {
        std::fprintf(file, " %lld", static_cast<long long>(cell->GetId(k) + 1));
      }
      std::fprintf(file, "\n");
    }
    ok = !std::ferror(file);
    ok = std::fclose(file) == 0 && ok;
  }
  if (!ok)
  {
    error = fileName + ": cannot write: " + std::strerror(errno);
  }
  else if (std::rename(temporary.c_str(), target.c_str()) != 0)
  {
    error = fileName + ": cannot replace the file: " + std::strerror(errno);
    ok = false;
  }
  if (!ok)
  {
    std::remove(temporary.c_str());
  }
  vtkPointCloudIO::ReleaseTemporaryFile(temporary);
  return ok;
}
} // namespace

bool CanWriteLines(const std::string& extension)
{
  return extension == "vtp" || extension == "vtk" || extension == "csv" || extension == "obj";
}

std::string GetLinesExtensions()
{
  return ".vtp, .vtk, .csv, .obj";
}

bool WriteLines(vtkPolyData* curves, const std::string& fileName, std::string& error,
  const std::string& format)
{
  const std::string extension = format.empty() ? vtkPointCloudIO::GetExtension(fileName) : format;
  if (!CanWriteLines(extension))
  {
    error = fileName + ": cannot write curves in the format of the extension " +
      (extension.empty() ? std::string("(none)") : "'." + extension + "'") + "; curves: " +
      GetLinesExtensions();
    return false;
  }
  if (extension == "obj")
  {
    return WriteObj(curves, fileName, error);
  }
  if (extension == "csv")
  {
    return vtkPointCloudIO::Write(VertexTable(curves), fileName, error, extension);
  }
  return vtkPointCloudIO::Write(curves, fileName, error, extension);
}
}
