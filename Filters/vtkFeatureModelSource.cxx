#include "vtkFeatureModelSource.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointCloudNeighborhoods.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkFeatureModelSource);

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Vec
{
  double X = 0, Y = 0, Z = 0;
};
Vec operator+(const Vec& a, const Vec& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}
Vec operator-(const Vec& a, const Vec& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
Vec operator*(double s, const Vec& a)
{
  return { s * a.X, s * a.Y, s * a.Z };
}
double Dot(const Vec& a, const Vec& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}

// Random numbers defined bit for bit by the standard (mt19937_64) and by this file (the
// conversions), so that a seed gives the same cloud with every standard library.
struct Random
{
  std::mt19937_64 Engine;
  explicit Random(unsigned int seed)
    : Engine(seed)
  {
  }
  double Uniform() { return static_cast<double>(this->Engine() >> 11) * (1.0 / 9007199254740992.0); }
  double Gaussian()
  {
    // Box-Muller; 1 - u keeps the logarithm finite.
    const double u = 1.0 - this->Uniform();
    const double v = this->Uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * Pi * v);
  }
};

// A surface piece that can be sampled uniformly by area.
struct Patch
{
  enum Kind
  {
    Parallelogram, // Origin + a U + b V, a, b in [0, 1]
    Cylinder,      // axis along z through Origin, radius R, z in [Origin.Z + Z0, Origin.Z + Z1]
    Sphere,        // centre Origin, radius R
  } Type;
  Vec Origin, U, V;
  double R = 0, Z0 = 0, Z1 = 0;

  double Area() const
  {
    switch (this->Type)
    {
      case Parallelogram:
        return Norm(Cross(this->U, this->V));
      case Cylinder:
        return 2.0 * Pi * this->R * (this->Z1 - this->Z0);
      default:
        return 4.0 * Pi * this->R * this->R;
    }
  }

  Vec Sample(Random& rng) const
  {
    switch (this->Type)
    {
      case Parallelogram:
      {
        const double a = rng.Uniform();
        const double b = rng.Uniform();
        return this->Origin + a * this->U + b * this->V;
      }
      case Cylinder:
      {
        const double t = 2.0 * Pi * rng.Uniform();
        const double z = this->Z0 + (this->Z1 - this->Z0) * rng.Uniform();
        return this->Origin + Vec{ this->R * std::cos(t), this->R * std::sin(t), z };
      }
      default:
      {
        Vec g;
        double r = 0.0;
        do
        {
          g = { rng.Gaussian(), rng.Gaussian(), rng.Gaussian() };
          r = Norm(g);
        } while (r < 1e-9);
        return this->Origin + (this->R / r) * g;
      }
    }
  }
};

// A feature curve: a segment A-B, or a circle of radius R around a z axis through A.
struct Curve
{
  bool Circle = false;
  Vec A, B;
  double R = 0;

  double Distance(const Vec& p) const
  {
    if (this->Circle)
    {
      const Vec d = p - this->A;
      const double rho = std::sqrt(d.X * d.X + d.Y * d.Y);
      return std::sqrt((rho - this->R) * (rho - this->R) + d.Z * d.Z);
    }
    const Vec ab = this->B - this->A;
    const double t = std::min(1.0, std::max(0.0, Dot(p - this->A, ab) / Dot(ab, ab)));
    return Norm(p - (this->A + t * ab));
  }
};

struct Geometry
{
  std::vector<Patch> Patches;
  std::vector<Curve> Curves;

  double Distance(const Vec& p) const
  {
    double best = VTK_FLOAT_MAX;
    for (const Curve& c : this->Curves)
    {
      best = std::min(best, c.Distance(p));
    }
    return best;
  }
};

// A profile z(x) (polyline through (x_k, z_k)) swept along y over [-w/2, w/2]; its inner
// vertices are the creases.
Geometry Extrusion(const std::vector<double>& x, const std::vector<double>& z, double w)
{
  Geometry g;
  for (size_t k = 0; k + 1 < x.size(); ++k)
  {
    g.Patches.push_back({ Patch::Parallelogram, Vec{ x[k], -0.5 * w, z[k] },
      Vec{ x[k + 1] - x[k], 0.0, z[k + 1] - z[k] }, Vec{ 0.0, w, 0.0 } });
  }
  for (size_t k = 1; k + 1 < x.size(); ++k)
  {
    g.Curves.push_back({ false, Vec{ x[k], -0.5 * w, z[k] }, Vec{ x[k], 0.5 * w, z[k] }, 0.0 });
  }
  return g;
}

Geometry MakeGeometry(int model, double size, double valleySlope)
{
  const double h = 0.5 * size;
  switch (model)
  {
    case vtkFeatureModelSource::MODEL_I:
    {
      const double a = 0.15 * size;
      const double depth = a * std::tan(valleySlope * Pi / 180.0);
      return Extrusion({ -h, -a, 0.0, a, h }, { 0.0, 0.0, -depth, 0.0, 0.0 }, size);
    }
    case vtkFeatureModelSource::MODEL_II:
    {
      const double c = 0.25 * size;          // plateau half-width
      const double H = 0.15 * size;          // plateau height
      const double w = H / std::tan(Pi / 3); // 60-degree walls
      const double e = 0.1 * size;           // ridge half-width
      const double t = e * std::tan(Pi / 12); // 15-degree flanks
      return Extrusion({ -h, -c - w, -c, -e, 0.0, e, c, c + w, h },
        { 0.0, 0.0, H, H, H + t, H, H, 0.0, 0.0 }, size);
    }
    case vtkFeatureModelSource::MODEL_III:
    {
      Geometry g;
      const double r = 0.25 * size;
      g.Patches.push_back({ Patch::Parallelogram, Vec{ -h, -h, 0.0 }, Vec{ size, 0.0, 0.0 },
        Vec{ 0.0, size, 0.0 } });
      Patch cylinder{ Patch::Cylinder, Vec{}, Vec{}, Vec{} };
      cylinder.R = r;
      cylinder.Z0 = -r;
      cylinder.Z1 = r;
      g.Patches.push_back(cylinder);
      g.Curves.push_back({ true, Vec{}, Vec{}, r });
      return g;
    }
    default:
    {
      Geometry g;
      Patch sphere{ Patch::Sphere, Vec{}, Vec{}, Vec{} };
      sphere.R = h;
      g.Patches.push_back(sphere);
      return g;
    }
  }
}
} // namespace

vtkFeatureModelSource::vtkFeatureModelSource()
{
  this->SetNumberOfInputPorts(0);
}

vtkFeatureModelSource::~vtkFeatureModelSource() = default;

const char* vtkFeatureModelSource::GetModelName(int model)
{
  switch (model)
  {
    case MODEL_I:
      return "Model I";
    case MODEL_II:
      return "Model II";
    case MODEL_III:
      return "Model III";
    case SPHERE:
      return "Sphere";
    default:
      return "unknown";
  }
}

vtkIdType vtkFeatureModelSource::GetDefaultNumberOfPoints(int model)
{
  switch (model)
  {
    case MODEL_I:
      return 170000;
    case MODEL_II:
      return 220000;
    case MODEL_III:
      return 130000;
    default:
      return 100000;
  }
}

int vtkFeatureModelSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!output)
  {
    return 0;
  }
  const vtkIdType n =
    this->NumberOfPoints > 0 ? this->NumberOfPoints : GetDefaultNumberOfPoints(this->Model);
  const Geometry geometry = MakeGeometry(this->Model, this->Size, this->ValleySlope);

  std::vector<double> cumulative;
  double area = 0.0;
  for (const Patch& p : geometry.Patches)
  {
    area += p.Area();
    cumulative.push_back(area);
  }
  const double band = this->DenseBandWidth * std::sqrt(area / static_cast<double>(n));
  const double keepOutside = 1.0 / this->FeatureDensityFactor;

  // Clean points by rejection: everywhere uniform, thinned to 1 / factor outside the band.
  Random rng(this->Seed);
  std::vector<Vec> clean(static_cast<size_t>(n));
  std::vector<double> delta(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n;)
  {
    const double pick = area * rng.Uniform();
    const size_t which = std::min(geometry.Patches.size() - 1,
      static_cast<size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
    const Vec p = geometry.Patches[which].Sample(rng);
    const double d = geometry.Distance(p);
    if (d <= band || rng.Uniform() < keepOutside)
    {
      clean[i] = p;
      delta[i] = d;
      ++i;
    }
  }

  vtkNew<vtkPoints> points;
  points->SetDataType(
    this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, clean[i].X, clean[i].Y, clean[i].Z);
  }
  // s of EVALUATION.md: the mean nearest-neighbour distance of the clean cloud.
  vtkNew<vtkPointCloudNeighborhoods> neighborhoods;
  double s = 0.0;
  if (n > 1 && neighborhoods->Build(points))
  {
    s = neighborhoods->ComputeMeanSpacing();
  }
  const double sigma = this->NoiseFactor * s;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Vec noise{ rng.Gaussian(), rng.Gaussian(), rng.Gaussian() };
    const Vec p = clean[i] + sigma * noise;
    points->SetPoint(i, p.X + this->Center[0], p.Y + this->Center[1], p.Z + this->Center[2]);
  }

  vtkNew<vtkDoubleArray> distance;
  distance->SetName("FeatureDistance");
  distance->SetNumberOfValues(n);
  vtkNew<vtkUnsignedCharArray> truth;
  truth->SetName("GroundTruth");
  truth->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    distance->SetValue(i, delta[i]);
    truth->SetValue(i, delta[i] <= 2.0 * s ? 1 : 0);
  }

  output->SetPoints(points);
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  output->GetPointData()->AddArray(distance);
  output->GetPointData()->AddArray(truth);
  output->GetPointData()->SetActiveScalars("GroundTruth");
  vtkNew<vtkDoubleArray> spacing;
  spacing->SetName("CleanMeanSpacing");
  spacing->InsertNextValue(s);
  vtkNew<vtkDoubleArray> noise;
  noise->SetName("NoiseSigma");
  noise->InsertNextValue(sigma);
  output->GetFieldData()->AddArray(spacing);
  output->GetFieldData()->AddArray(noise);
  return 1;
}

void vtkFeatureModelSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: " << GetModelName(this->Model) << "\n";
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
  os << indent << "FeatureDensityFactor: " << this->FeatureDensityFactor << "\n";
  os << indent << "DenseBandWidth: " << this->DenseBandWidth << "\n";
  os << indent << "NoiseFactor: " << this->NoiseFactor << "\n";
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Center: " << this->Center[0] << " " << this->Center[1] << " " << this->Center[2]
     << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "ValleySlope: " << this->ValleySlope << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
