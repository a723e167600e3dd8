#include "vtkMeshFeatureSampler.h"
#include "vtkFeaturePointsRandom.h"
#include "vtkFeaturePointsStatistics.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSmartPointer.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkTriangleStrip.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkMeshFeatureSampler);

namespace
{
using Vec = std::array<double, 3>;
using Triangle = std::array<vtkIdType, 3>;

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

using featurepoints::Random;

// The distance from p to the segment [a, b].
double SegmentDistance(const Vec& p, const Vec& a, const Vec& b)
{
  const Vec ab = Sub(b, a);
  const Vec ap = Sub(p, a);
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0.0 ? std::min(1.0, std::max(0.0, Dot(ap, ab) / length2)) : 0.0;
  const Vec q{ a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1], a[2] + t * ab[2] - p[2] };
  return std::sqrt(Dot(q, q));
}

// One directed edge of a triangle, keyed by its sorted end points.
struct HalfEdge
{
  vtkIdType Low, High;
  vtkIdType Triangle;
  bool Forward; // the triangle runs from Low to High
  bool operator<(const HalfEdge& other) const
  {
    return Low != other.Low ? Low < other.Low
                            : (High != other.High ? High < other.High : Triangle < other.Triangle);
  }
};

struct FeatureEdge
{
  vtkIdType A, B;
  unsigned char Type;
  double Angle; // degrees
};

// The exact distance from each clean point to the nearest feature edge (and that edge's type),
// and to the nearest corner. The edges are cut into pieces no longer than PieceLength; the nearest
// piece midpoint at distance dm bounds the distance d <= dm, and the piece holding the nearest
// point of the nearest edge has its midpoint within d + PieceLength / 2: the edges of the pieces
// within dm + PieceLength / 2 contain the answer.
struct DistanceFunctor
{
  const std::vector<Vec>& Clean;
  const std::vector<Vec>& MeshPoints;
  const std::vector<FeatureEdge>& Edges;
  const std::vector<vtkIdType>& PieceEdge;
  vtkStaticPointLocator* Pieces;
  vtkStaticPointLocator* Corners; // nullptr without corners
  double PieceLength;
  std::vector<double>& Distance;
  std::vector<vtkIdType>& NearestEdge;
  std::vector<unsigned char>& NearestType;
  std::vector<double>& CornerDistance;
  vtkSMPThreadLocalObject<vtkIdList> Found;

  DistanceFunctor(const std::vector<Vec>& clean, const std::vector<Vec>& meshPoints,
    const std::vector<FeatureEdge>& edges, const std::vector<vtkIdType>& pieceEdge,
    vtkStaticPointLocator* pieces, vtkStaticPointLocator* corners, double pieceLength,
    std::vector<double>& distance, std::vector<vtkIdType>& nearestEdge,
    std::vector<unsigned char>& nearestType, std::vector<double>& cornerDistance)
    : Clean(clean)
    , MeshPoints(meshPoints)
    , Edges(edges)
    , PieceEdge(pieceEdge)
    , Pieces(pieces)
    , Corners(corners)
    , PieceLength(pieceLength)
    , Distance(distance)
    , NearestEdge(nearestEdge)
    , NearestType(nearestType)
    , CornerDistance(cornerDistance)
  {
  }

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end)
  {
    vtkIdList* found = this->Found.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      const Vec& p = this->Clean[i];
      double x[3] = { p[0], p[1], p[2] };
      const vtkIdType nearest = this->Pieces->FindClosestPoint(x);
      double m[3];
      this->Pieces->GetDataSet()->GetPoint(nearest, m);
      const double dm = std::sqrt(vtkMath::Distance2BetweenPoints(x, m));
      this->Pieces->FindPointsWithinRadius(dm + 0.5 * this->PieceLength * (1.0 + 1e-9), x, found);
      double best = VTK_DOUBLE_MAX;
      vtkIdType bestEdge = -1;
      for (vtkIdType k = 0; k < found->GetNumberOfIds(); ++k)
      {
        const vtkIdType edge = this->PieceEdge[found->GetId(k)];
        const FeatureEdge& e = this->Edges[edge];
        const double d = SegmentDistance(p, this->MeshPoints[e.A], this->MeshPoints[e.B]);
        // Ties (a shared end point) go to the smaller edge id, whatever the order found.
        if (d < best || (d == best && edge < bestEdge))
        {
          best = d;
          bestEdge = edge;
        }
      }
      const unsigned char type = bestEdge >= 0
        ? this->Edges[bestEdge].Type
        : static_cast<unsigned char>(vtkMeshFeatureSampler::NOT_FEATURE);
      this->Distance[i] = best;
      this->NearestEdge[i] = bestEdge;
      this->NearestType[i] = type;
      if (this->Corners)
      {
        double c[3];
        this->Corners->GetDataSet()->GetPoint(this->Corners->FindClosestPoint(x), c);
        this->CornerDistance[i] = std::sqrt(vtkMath::Distance2BetweenPoints(x, c));
      }
    }
  }

  void Reduce() {}
};
} // namespace

//------------------------------------------------------------------------------
vtkMeshFeatureSampler::vtkMeshFeatureSampler()
{
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkMeshFeatureSampler::~vtkMeshFeatureSampler() = default;

//------------------------------------------------------------------------------
vtkPolyData* vtkMeshFeatureSampler::GetFeatureEdges()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkMeshFeatureSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkMeshFeatureSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* edgesOutput = vtkPolyData::GetData(outputVector, 1);
  if (!input || !output || !edgesOutput)
  {
    return 0;
  }
  output->Initialize();
  edgesOutput->Initialize();
  if (const char* nan = featurepoints::FirstNaN(
        { { "NoiseSigma", this->NoiseSigma }, { "FeatureAngle", this->FeatureAngle } }))
  {
    vtkErrorMacro(<< nan << " is NaN: give it a number. The output is empty.");
    return 1;
  }
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  if (inputPoints == 0 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "The input mesh has no polygon (" << inputPoints << " points, "
                  << input->GetNumberOfPolys() << " polygons, " << input->GetNumberOfStrips()
                  << " strips).");
    return 1;
  }

  // 1. Merge the points equal bit for bit: sort their ids by coordinates.
  std::vector<Vec> coordinates(static_cast<size_t>(inputPoints));
  for (vtkIdType i = 0; i < inputPoints; ++i)
  {
    input->GetPoint(i, coordinates[i].data());
    if (!std::isfinite(coordinates[i][0]) || !std::isfinite(coordinates[i][1]) ||
      !std::isfinite(coordinates[i][2]))
    {
      vtkErrorMacro(<< "Point " << i << " of the input mesh has a coordinate that is not finite.");
      return 1;
    }
  }
  std::vector<vtkIdType> order(static_cast<size_t>(inputPoints));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](vtkIdType a, vtkIdType b) { return coordinates[a] < coordinates[b]; });
  std::vector<vtkIdType> merged(static_cast<size_t>(inputPoints));
  std::vector<Vec> meshPoints;
  for (size_t k = 0; k < order.size(); ++k)
  {
    if (k == 0 || coordinates[order[k]] != coordinates[order[k - 1]])
    {
      meshPoints.push_back(coordinates[order[k]]);
    }
    merged[order[k]] = static_cast<vtkIdType>(meshPoints.size()) - 1;
  }

  // Triangulate the polygons (concave ones too) and the strips; drop triangles of zero area.
  std::vector<Triangle> triangles;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    const Triangle t{ merged[a], merged[b], merged[c] };
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
    {
      const Vec n = Cross(Sub(meshPoints[t[1]], meshPoints[t[0]]),
        Sub(meshPoints[t[2]], meshPoints[t[0]]));
      if (Dot(n, n) > 0.0)
      {
        triangles.push_back(t);
      }
    }
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCurrentCell(n, ids);
    if (n == 3)
    {
      addTriangle(ids[0], ids[1], ids[2]);
    }
    else if (n > 3)
    {
      polygon->PointIds->SetNumberOfIds(n);
      polygon->Points->SetNumberOfPoints(n);
      for (vtkIdType k = 0; k < n; ++k)
      {
        polygon->PointIds->SetId(k, ids[k]);
        polygon->Points->SetPoint(k, coordinates[ids[k]].data());
      }
      local->Reset();
      polygon->Triangulate(local);
      for (vtkIdType k = 0; k + 2 < local->GetNumberOfIds(); k += 3)
      {
        addTriangle(ids[local->GetId(k)], ids[local->GetId(k + 1)], ids[local->GetId(k + 2)]);
      }
    }
  }
  vtkNew<vtkCellArray> stripTriangles;
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    strips->GetCurrentCell(n, ids);
    vtkTriangleStrip::DecomposeStrip(static_cast<int>(n), ids, stripTriangles);
  }
  auto decomposed = vtk::TakeSmartPointer(stripTriangles->NewIterator());
  for (decomposed->GoToFirstCell(); !decomposed->IsDoneWithTraversal(); decomposed->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    decomposed->GetCurrentCell(n, ids);
    addTriangle(ids[0], ids[1], ids[2]);
  }
  if (triangles.empty())
  {
    vtkErrorMacro(<< "The input mesh has no triangle of non-zero area.");
    return 1;
  }
  const vtkIdType nTriangles = static_cast<vtkIdType>(triangles.size());

  // 2. The edges, each as the triangles' directed half-edges sorted by their end points.
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * triangles.size());
  for (vtkIdType t = 0; t < nTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      halfEdges.push_back({ std::min(a, b), std::max(a, b), t, a < b });
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  std::vector<size_t> edgeStart; // the first half-edge of each edge, and the end
  for (size_t k = 0; k < halfEdges.size(); ++k)
  {
    if (k == 0 || halfEdges[k].Low != halfEdges[k - 1].Low ||
      halfEdges[k].High != halfEdges[k - 1].High)
    {
      edgeStart.push_back(k);
    }
  }
  edgeStart.push_back(halfEdges.size());
  const size_t nEdges = edgeStart.size() - 1;

  // Consistent orientation across the manifold edges, component by component (breadth first);
  // a closed component is turned to a positive volume.
  std::vector<std::vector<std::pair<vtkIdType, size_t>>> neighbours(triangles.size());
  for (size_t e = 0; e < nEdges; ++e)
  {
    if (edgeStart[e + 1] - edgeStart[e] == 2)
    {
      const HalfEdge& h0 = halfEdges[edgeStart[e]];
      const HalfEdge& h1 = halfEdges[edgeStart[e] + 1];
      neighbours[h0.Triangle].push_back({ h1.Triangle, e });
      neighbours[h1.Triangle].push_back({ h0.Triangle, e });
    }
  }
  std::vector<int> component(triangles.size(), -1);
  std::vector<bool> flipped(triangles.size(), false);
  std::vector<bool> closed;
  auto forward = [&](vtkIdType t, size_t e) {
    for (size_t k = edgeStart[e]; k < edgeStart[e + 1]; ++k)
    {
      if (halfEdges[k].Triangle == t)
      {
        return halfEdges[k].Forward != flipped[t];
      }
    }
    return false;
  };
  for (vtkIdType seed = 0; seed < nTriangles; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    const int c = static_cast<int>(closed.size());
    std::vector<vtkIdType> queue{ seed };
    component[seed] = c;
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const vtkIdType t = queue[q];
      for (const auto& next : neighbours[t])
      {
        if (component[next.first] < 0)
        {
          component[next.first] = c;
          // Consistent neighbours run through their shared edge in opposite directions.
          flipped[next.first] = forward(t, next.second) == forward(next.first, next.second)
            ? !flipped[next.first]
            : flipped[next.first];
          queue.push_back(next.first);
        }
      }
    }
    closed.push_back(true);
  }
  for (size_t e = 0; e < nEdges; ++e)
  {
    if (edgeStart[e + 1] - edgeStart[e] != 2)
    {
      for (size_t k = edgeStart[e]; k < edgeStart[e + 1]; ++k)
      {
        closed[component[halfEdges[k].Triangle]] = false;
      }
    }
  }
  std::vector<double> volume(closed.size(), 0.0);
  for (vtkIdType t = 0; t < nTriangles; ++t)
  {
    if (flipped[t])
    {
      std::swap(triangles[t][1], triangles[t][2]);
    }
    const Vec& a = meshPoints[triangles[t][0]];
    volume[component[t]] +=
      Dot(a, Cross(meshPoints[triangles[t][1]], meshPoints[triangles[t][2]])) / 6.0;
  }
  std::vector<Vec> normals(triangles.size());
  std::vector<double> cumulativeArea(triangles.size());
  double area = 0.0;
  for (vtkIdType t = 0; t < nTriangles; ++t)
  {
    if (closed[component[t]] && volume[component[t]] < 0.0)
    {
      std::swap(triangles[t][1], triangles[t][2]);
    }
    const Vec& a = meshPoints[triangles[t][0]];
    const Vec n = Cross(Sub(meshPoints[triangles[t][1]], a), Sub(meshPoints[triangles[t][2]], a));
    const double twice = std::sqrt(Dot(n, n));
    normals[t] = { n[0] / twice, n[1] / twice, n[2] / twice };
    area += 0.5 * twice;
    cumulativeArea[t] = area;
  }
  if (!(area > 0.0) || !std::isfinite(area))
  {
    vtkErrorMacro(<< "The input mesh has no area (" << area << ").");
    return 1;
  }

  // 3. Feature edges and corners.
  const double cosFeature = std::cos(vtkMath::RadiansFromDegrees(this->FeatureAngle));
  std::vector<FeatureEdge> edges;
  for (size_t e = 0; e < nEdges; ++e)
  {
    const size_t count = edgeStart[e + 1] - edgeStart[e];
    const HalfEdge& h = halfEdges[edgeStart[e]];
    if (count == 1)
    {
      edges.push_back({ h.Low, h.High, BORDER, 180.0 });
    }
    else if (count > 2)
    {
      edges.push_back({ h.Low, h.High, CONVEX_CREASE, 90.0 });
    }
    else
    {
      const vtkIdType t0 = h.Triangle, t1 = halfEdges[edgeStart[e] + 1].Triangle;
      const double c = std::max(-1.0, std::min(1.0, Dot(normals[t0], normals[t1])));
      if (c <= cosFeature)
      {
        // The vertex of t1 off the edge lies below t0's plane on a convex edge.
        vtkIdType opposite = triangles[t1][0];
        for (const vtkIdType v : triangles[t1])
        {
          opposite = v != h.Low && v != h.High ? v : opposite;
        }
        const double side = Dot(normals[t0], Sub(meshPoints[opposite], meshPoints[h.Low]));
        edges.push_back({ h.Low, h.High,
          static_cast<unsigned char>(side <= 0.0 ? CONVEX_CREASE : CONCAVE_CREASE),
          vtkMath::DegreesFromRadians(std::acos(c)) });
      }
    }
  }
  std::vector<std::vector<vtkIdType>> edgesAt(meshPoints.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    edgesAt[edges[e].A].push_back(static_cast<vtkIdType>(e));
    edgesAt[edges[e].B].push_back(static_cast<vtkIdType>(e));
  }
  std::vector<vtkIdType> corners;
  for (size_t v = 0; v < meshPoints.size(); ++v)
  {
    bool corner = edgesAt[v].size() >= 3;
    if (edgesAt[v].size() == 2)
    {
      // Two feature edges meeting at an angle: their directions away from v turn by 180 degrees
      // minus the angle between them.
      Vec d[2];
      for (int k = 0; k < 2; ++k)
      {
        const FeatureEdge& e = edges[edgesAt[v][k]];
        d[k] = Sub(meshPoints[e.A == static_cast<vtkIdType>(v) ? e.B : e.A], meshPoints[v]);
      }
      const double c = Dot(d[0], d[1]) / std::sqrt(Dot(d[0], d[0]) * Dot(d[1], d[1]));
      corner = c >= -cosFeature;
    }
    if (corner)
    {
      corners.push_back(static_cast<vtkIdType>(v));
    }
  }

  // 4. Sampling: a triangle in proportion to its area, a point uniform on it.
  const vtkIdType n = this->NumberOfPoints;
  Random rng(this->Seed);
  std::vector<Vec> clean(static_cast<size_t>(n));
  std::vector<vtkIdType> from(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double pick = area * rng.Uniform();
    const vtkIdType t = std::min(nTriangles - 1,
      static_cast<vtkIdType>(std::upper_bound(cumulativeArea.begin(), cumulativeArea.end(), pick) -
        cumulativeArea.begin()));
    const double r = std::sqrt(rng.Uniform()), u = rng.Uniform();
    const Vec& a = meshPoints[triangles[t][0]];
    const Vec& b = meshPoints[triangles[t][1]];
    const Vec& c = meshPoints[triangles[t][2]];
    for (int k = 0; k < 3; ++k)
    {
      clean[i][k] = (1.0 - r) * a[k] + r * (1.0 - u) * b[k] + r * u * c[k];
    }
    from[i] = t;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, clean[i].data());
  }
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  double s = 0.0;
  if (n > 1 && neighborhoods->Build(points))
  {
    s = neighborhoods->ComputeMeanSpacing();
  }

  // Distances to the feature edges and the corners, exact (see DistanceFunctor).
  std::vector<double> distance(static_cast<size_t>(n), VTK_FLOAT_MAX);
  std::vector<vtkIdType> nearestEdge(static_cast<size_t>(n), -1);
  std::vector<unsigned char> nearestType(static_cast<size_t>(n), NOT_FEATURE);
  std::vector<double> cornerDistance(static_cast<size_t>(n), VTK_FLOAT_MAX);
  if (!edges.empty())
  {
    const double pieceLength = 0.5 * std::sqrt(area / static_cast<double>(n));
    vtkNew<vtkPoints> midpoints;
    midpoints->SetDataTypeToDouble();
    std::vector<vtkIdType> pieceEdge;
    for (size_t e = 0; e < edges.size(); ++e)
    {
      const Vec& a = meshPoints[edges[e].A];
      const Vec d = Sub(meshPoints[edges[e].B], a);
      const double length = std::sqrt(Dot(d, d));
      const vtkIdType pieces =
        std::max<vtkIdType>(1, static_cast<vtkIdType>(std::ceil(length / pieceLength)));
      for (vtkIdType k = 0; k < pieces; ++k)
      {
        const double f = (static_cast<double>(k) + 0.5) / static_cast<double>(pieces);
        midpoints->InsertNextPoint(a[0] + f * d[0], a[1] + f * d[1], a[2] + f * d[2]);
        pieceEdge.push_back(static_cast<vtkIdType>(e));
      }
    }
    vtkNew<vtkPolyData> pieceSet;
    pieceSet->SetPoints(midpoints);
    vtkNew<vtkStaticPointLocator> pieceLocator;
    pieceLocator->SetDataSet(pieceSet);
    pieceLocator->BuildLocator();
    vtkNew<vtkPoints> cornerPoints;
    cornerPoints->SetDataTypeToDouble();
    for (const vtkIdType v : corners)
    {
      cornerPoints->InsertNextPoint(meshPoints[v].data());
    }
    vtkNew<vtkPolyData> cornerSet;
    cornerSet->SetPoints(cornerPoints);
    vtkNew<vtkStaticPointLocator> cornerLocator;
    if (!corners.empty())
    {
      cornerLocator->SetDataSet(cornerSet);
      cornerLocator->BuildLocator();
    }
    DistanceFunctor functor(clean, meshPoints, edges, pieceEdge, pieceLocator,
      corners.empty() ? nullptr : cornerLocator.GetPointer(), pieceLength, distance, nearestEdge,
      nearestType, cornerDistance);
    vtkSMPTools::For(0, n, functor);
  }

  // Noise along the triangle's normal.
  const double sigma = this->NoiseSigma * s;
  if (sigma > 0.0)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double g = sigma * rng.Gaussian();
      const Vec& normal = normals[from[i]];
      points->SetPoint(
        i, clean[i][0] + g * normal[0], clean[i][1] + g * normal[1], clean[i][2] + g * normal[2]);
    }
  }

  vtkNew<vtkDoubleArray> featureDistance;
  featureDistance->SetName("FeatureDistance");
  featureDistance->SetNumberOfValues(n);
  vtkNew<vtkIdTypeArray> edgeIds;
  edgeIds->SetName("FeatureEdgeId");
  edgeIds->SetNumberOfValues(n);
  vtkNew<vtkUnsignedCharArray> truth;
  truth->SetName("GroundTruth");
  truth->SetNumberOfValues(n);
  vtkNew<vtkUnsignedCharArray> type;
  type->SetName("TrueFeatureType");
  type->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool positive = distance[i] <= 2.0 * s;
    featureDistance->SetValue(i, distance[i]);
    edgeIds->SetValue(i, nearestEdge[i]);
    truth->SetValue(i, positive ? 1 : 0);
    type->SetValue(i,
      positive ? (cornerDistance[i] <= 2.0 * s ? static_cast<unsigned char>(CORNER) : nearestType[i])
               : static_cast<unsigned char>(NOT_FEATURE));
  }
  output->SetPoints(points);
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  output->GetPointData()->AddArray(featureDistance);
  output->GetPointData()->AddArray(edgeIds);
  output->GetPointData()->AddArray(truth);
  output->GetPointData()->AddArray(type);
  output->GetPointData()->SetActiveScalars("TrueFeatureType");
  auto addField = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> field;
    field->SetName(name);
    field->InsertNextValue(value);
    output->GetFieldData()->AddArray(field);
  };
  addField("CleanMeanSpacing", s);
  addField("NoiseSigma", sigma);
  addField("MeshArea", area);

  // The feature edges as lines.
  vtkNew<vtkPoints> edgePoints;
  edgePoints->SetDataTypeToDouble();
  edgePoints->SetNumberOfPoints(static_cast<vtkIdType>(meshPoints.size()));
  for (size_t v = 0; v < meshPoints.size(); ++v)
  {
    edgePoints->SetPoint(static_cast<vtkIdType>(v), meshPoints[v].data());
  }
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> edgeType;
  edgeType->SetName("FeatureType");
  vtkNew<vtkDoubleArray> dihedral;
  dihedral->SetName("DihedralAngle");
  for (const FeatureEdge& e : edges)
  {
    const vtkIdType ids[2] = { e.A, e.B };
    lines->InsertNextCell(2, ids);
    edgeType->InsertNextValue(e.Type);
    dihedral->InsertNextValue(e.Angle);
  }
  vtkNew<vtkUnsignedCharArray> corner;
  corner->SetName("Corner");
  corner->SetNumberOfValues(static_cast<vtkIdType>(meshPoints.size()));
  corner->FillValue(0);
  for (const vtkIdType v : corners)
  {
    corner->SetValue(v, 1);
  }
  edgesOutput->SetPoints(edgePoints);
  edgesOutput->SetLines(lines);
  edgesOutput->GetCellData()->AddArray(edgeType);
  edgesOutput->GetCellData()->AddArray(dihedral);
  edgesOutput->GetPointData()->AddArray(corner);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMeshFeatureSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
  os << indent << "NoiseSigma: " << this->NoiseSigma << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
