// vtkMeshFeatureSampler on meshes built here: a unit cube written as STL writes it (every face
// with its own copies of the vertices, quads triangulated by the filter): 12 convex feature edges,
// 8 corners, exact distances, the type codes, the spacing, noise along the normals and the seed;
// an open valley (a concave edge and borders); bad input.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMeshFeatureSampler.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#define SAMPLER_CHECK(condition, ...)                                                              \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::printf("FAIL: ");                                                                       \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)

namespace
{
// The unit cube [0, 1]^3: six quads, each with its own four points (24 points).
vtkSmartPointer<vtkPolyData> UnitCube()
{
  auto cube = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const int faces[6][4][3] = {
    { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 1, 0, 0 } },
    { { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } },
    { { 0, 1, 0 }, { 0, 1, 1 }, { 1, 1, 1 }, { 1, 1, 0 } },
    { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 }, { 0, 1, 0 } },
    { { 1, 0, 0 }, { 1, 1, 0 }, { 1, 1, 1 }, { 1, 0, 1 } },
  };
  for (const auto& face : faces)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(face[k][0], face[k][1], face[k][2]);
    }
    quads->InsertNextCell(4, ids);
  }
  cube->SetPoints(points);
  cube->SetPolys(quads);
  return cube;
}

// An open valley: the square x in [-1, 0] of the plane z = 0 and a square rising at 45 degrees
// from x = 0 to 1, both facing up: one concave 45-degree edge, six border edges, four corners.
vtkSmartPointer<vtkPolyData> Valley()
{
  auto valley = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1, 0, 0);
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 1);
  points->InsertNextPoint(1, 1, 1);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(-1, 1, 0);
  vtkNew<vtkCellArray> quads;
  const vtkIdType a[4] = { 0, 1, 4, 5 }, b[4] = { 1, 2, 3, 4 };
  quads->InsertNextCell(4, a);
  quads->InsertNextCell(4, b);
  valley->SetPoints(points);
  valley->SetPolys(quads);
  return valley;
}

vtkDataArray* Array(vtkPolyData* data, const char* name)
{
  return data->GetPointData()->GetArray(name);
}

// The error text of a sampler run on `mesh` ("" when none).
std::string ErrorOf(vtkPolyData* mesh)
{
  vtkNew<vtkMeshFeatureSampler> sampler;
  vtkNew<vtkTest::ErrorObserver> observer;
  sampler->AddObserver(vtkCommand::ErrorEvent, observer);
  sampler->SetInputData(mesh);
  sampler->SetNumberOfPoints(1000);
  sampler->Update();
  if (sampler->GetOutput()->GetNumberOfPoints() != 0 ||
    sampler->GetFeatureEdges()->GetNumberOfPoints() != 0)
  {
    return "output not empty";
  }
  std::string message = observer->GetError() ? observer->GetErrorMessage() : "";
  // VTK's text: "ERROR: In FILE, line N\nCLASS (ADDRESS): MESSAGE\n\n"; keep MESSAGE.
  const size_t colon = message.rfind("): ");
  message = colon != std::string::npos ? message.substr(colon + 3) : message;
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}
} // namespace

int TestMeshFeatureSampler(int, char*[])
{
  int failures = 0;
  auto cube = UnitCube();
  vtkNew<vtkMeshFeatureSampler> sampler;
  sampler->SetInputData(cube);
  sampler->SetNumberOfPoints(10000);
  sampler->Update();
  vtkPolyData* cloud = sampler->GetOutput();
  vtkPolyData* edges = sampler->GetFeatureEdges();
  const vtkIdType n = cloud->GetNumberOfPoints();
  SAMPLER_CHECK(n == 10000, "cube: %lld points, not 10000", static_cast<long long>(n));
  SAMPLER_CHECK(cloud->GetNumberOfVerts() == n, "cube: no vertex per point");
  SAMPLER_CHECK(edges->GetNumberOfPoints() == 8, "cube: %lld merged points, not 8",
    static_cast<long long>(edges->GetNumberOfPoints()));
  SAMPLER_CHECK(edges->GetNumberOfLines() == 12, "cube: %lld feature edges, not 12",
    static_cast<long long>(edges->GetNumberOfLines()));
  for (vtkIdType e = 0; e < edges->GetNumberOfLines(); ++e)
  {
    const double type = edges->GetCellData()->GetArray("FeatureType")->GetTuple1(e);
    const double angle = edges->GetCellData()->GetArray("DihedralAngle")->GetTuple1(e);
    SAMPLER_CHECK(type == vtkMeshFeatureSampler::CONVEX_CREASE && std::abs(angle - 90.0) < 1e-9,
      "cube edge %lld: type %g, angle %g, not convex 90", static_cast<long long>(e), type, angle);
  }
  double corners = 0.0;
  for (vtkIdType v = 0; v < edges->GetNumberOfPoints(); ++v)
  {
    corners += edges->GetPointData()->GetArray("Corner")->GetTuple1(v);
  }
  SAMPLER_CHECK(corners == 8.0, "cube: %g corners, not 8", corners);

  // s: a Poisson sampling of a plane has a mean nearest-neighbour distance of half the nominal
  // spacing sqrt(area / points) = sqrt(6 / 10000).
  const double s = cloud->GetFieldData()->GetArray("CleanMeanSpacing")->GetTuple1(0);
  const double nominal = std::sqrt(6.0 / 10000.0);
  SAMPLER_CHECK(std::abs(s / (0.5 * nominal) - 1.0) < 0.1, "cube: s = %g, not about %g", s,
    0.5 * nominal);
  SAMPLER_CHECK(std::abs(cloud->GetFieldData()->GetArray("MeshArea")->GetTuple1(0) - 6.0) < 1e-12,
    "cube: area is not 6");

  // Distances: on the cube, the distance to the nearest edge is the second smallest of the
  // coordinates' distances to {0, 1} (the smallest is the face's, about 0).
  vtkDataArray* distance = Array(cloud, "FeatureDistance");
  vtkDataArray* truth = Array(cloud, "GroundTruth");
  vtkDataArray* type = Array(cloud, "TrueFeatureType");
  double worst = 0.0;
  int counts[5] = { 0, 0, 0, 0, 0 };
  int typeErrors = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], m[3];
    cloud->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      m[k] = std::min(x[k], 1.0 - x[k]);
    }
    std::sort(m, m + 3);
    worst = std::max(worst, std::abs(distance->GetTuple1(i) - m[1]));
    // The nearest cube vertex is at sqrt(m1^2 + m2^2) (the face coordinate is 0).
    const double corner = std::sqrt(m[1] * m[1] + m[2] * m[2]);
    const int expected = m[1] > 2.0 * s ? 0 : (corner <= 2.0 * s ? 3 : 1);
    const int t = static_cast<int>(type->GetTuple1(i));
    typeErrors += t != expected;
    typeErrors += (truth->GetTuple1(i) != 0.0) != (m[1] <= 2.0 * s);
    ++counts[std::min(4, std::max(0, t))];
  }
  SAMPLER_CHECK(worst < 1e-12, "cube: FeatureDistance off by %g", worst);
  vtkDataArray* edgeIds = Array(cloud, "FeatureEdgeId");
  SAMPLER_CHECK(edgeIds && edgeIds->GetRange()[0] == 0.0 && edgeIds->GetRange()[1] == 11.0,
    "cube: FeatureEdgeId missing or not 0-11");
  SAMPLER_CHECK(typeErrors == 0, "cube: %d points with the wrong type or ground truth", typeErrors);
  SAMPLER_CHECK(counts[1] > 800 && counts[3] > 10 && counts[2] == 0 && counts[4] == 0,
    "cube: type counts none %d convex %d concave %d corner %d border %d", counts[0], counts[1],
    counts[2], counts[3], counts[4]);
  std::printf("cube: s = %.5f, distances within %.1e, types: none %d convex %d corner %d\n", s,
    worst, counts[0], counts[1], counts[3]);

  // The same seed gives the same cloud; another seed another one.
  vtkNew<vtkMeshFeatureSampler> again;
  again->SetInputData(cube);
  again->SetNumberOfPoints(10000);
  again->Update();
  vtkNew<vtkMeshFeatureSampler> other;
  other->SetInputData(cube);
  other->SetNumberOfPoints(10000);
  other->SetSeed(2);
  other->Update();
  int same = 0, equalOther = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3], c[3];
    cloud->GetPoint(i, a);
    again->GetOutput()->GetPoint(i, b);
    other->GetOutput()->GetPoint(i, c);
    same += a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    equalOther += a[0] == c[0] && a[1] == c[1] && a[2] == c[2];
  }
  SAMPLER_CHECK(same == n, "seed: %d of %lld points repeat", same, static_cast<long long>(n));
  SAMPLER_CHECK(equalOther == 0, "seed 2: %d points equal seed 1's", equalOther);

  // Noise along the normal: each point leaves its face by a Gaussian of sigma 0.25 s, its
  // FeatureDistance (the clean point's) unchanged.
  vtkNew<vtkMeshFeatureSampler> noisy;
  noisy->SetInputData(cube);
  noisy->SetNumberOfPoints(10000);
  noisy->SetNoiseSigma(0.25);
  noisy->Update();
  double sumSquares = 0.0, tangential = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    cloud->GetPoint(i, a);
    noisy->GetOutput()->GetPoint(i, b);
    double moved[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    std::sort(moved, moved + 3, [](double u, double v) { return std::abs(u) < std::abs(v); });
    sumSquares += moved[2] * moved[2];
    tangential = std::max(tangential, std::abs(moved[1]));
    SAMPLER_CHECK(Array(noisy->GetOutput(), "FeatureDistance")->GetTuple1(i) ==
        distance->GetTuple1(i),
      "noise: point %lld's FeatureDistance changed", static_cast<long long>(i));
  }
  const double rms = std::sqrt(sumSquares / static_cast<double>(n));
  SAMPLER_CHECK(std::abs(rms / (0.25 * s) - 1.0) < 0.05 && tangential < 1e-12,
    "noise: RMS %g (expected %g), largest move along the face %g", rms, 0.25 * s, tangential);
  SAMPLER_CHECK(std::abs(noisy->GetOutput()->GetFieldData()->GetArray("NoiseSigma")->GetTuple1(0) -
                  0.25 * s) < 1e-15,
    "noise: NoiseSigma field is not 0.25 s");

  // The open valley: the fold is concave; borders and the four corners of the outer rim.
  vtkNew<vtkMeshFeatureSampler> valley;
  valley->SetInputData(Valley());
  valley->SetNumberOfPoints(5000);
  valley->Update();
  vtkPolyData* valleyEdges = valley->GetFeatureEdges();
  int concave = 0, border = 0;
  for (vtkIdType e = 0; e < valleyEdges->GetNumberOfLines(); ++e)
  {
    const int t = static_cast<int>(valleyEdges->GetCellData()->GetArray("FeatureType")->GetTuple1(e));
    concave += t == vtkMeshFeatureSampler::CONCAVE_CREASE;
    border += t == vtkMeshFeatureSampler::BORDER;
  }
  double valleyCorners = 0.0;
  for (vtkIdType v = 0; v < valleyEdges->GetNumberOfPoints(); ++v)
  {
    valleyCorners += valleyEdges->GetPointData()->GetArray("Corner")->GetTuple1(v);
  }
  // The fold's two end points have three feature edges each (the fold and two borders).
  SAMPLER_CHECK(concave == 1 && border == 6 && valleyCorners == 6.0,
    "valley: %d concave and %d border edges, %g corners (expected 1, 6, 6)", concave, border,
    valleyCorners);
  int valleyTypes[5] = { 0, 0, 0, 0, 0 };
  for (vtkIdType i = 0; i < valley->GetOutput()->GetNumberOfPoints(); ++i)
  {
    ++valleyTypes[static_cast<int>(Array(valley->GetOutput(), "TrueFeatureType")->GetTuple1(i))];
  }
  SAMPLER_CHECK(valleyTypes[2] > 0 && valleyTypes[3] > 0 && valleyTypes[4] > 0 && valleyTypes[1] == 0,
    "valley: types none %d convex %d concave %d corner %d border %d", valleyTypes[0],
    valleyTypes[1], valleyTypes[2], valleyTypes[3], valleyTypes[4]);

  // Bad input: one error line each, empty output.
  vtkNew<vtkPolyData> empty;
  const std::string noPolygon = ErrorOf(empty);
  SAMPLER_CHECK(noPolygon.find("no polygon") != std::string::npos, "empty mesh: error '%s'",
    noPolygon.c_str());
  auto flat = UnitCube();
  for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
  {
    flat->GetPoints()->SetPoint(i, 0.5, 0.5, 0.5);
  }
  const std::string noArea = ErrorOf(flat);
  SAMPLER_CHECK(noArea.find("non-zero area") != std::string::npos, "collapsed mesh: error '%s'",
    noArea.c_str());
  auto broken = UnitCube();
  broken->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  const std::string notFinite = ErrorOf(broken);
  SAMPLER_CHECK(notFinite.find("not finite") != std::string::npos, "NaN mesh: error '%s'",
    notFinite.c_str());
  std::printf("bad input: '%s' / '%s' / '%s'\n", noPolygon.c_str(), noArea.c_str(),
    notFinite.c_str());
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
