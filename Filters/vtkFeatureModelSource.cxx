#include "vtkFeatureModelSource.h"
#include "vtkFeaturePointsRandom.h"
#include "vtkFeaturePointsStatistics.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
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

using featurepoints::Random;

Vec UniformDirection(Random& rng)
{
  Vec g;
  double r = 0.0;
  do
  {
    g = { rng.Gaussian(), rng.Gaussian(), rng.Gaussian() };
    r = Norm(g);
  } while (r < 1e-9);
  return (1.0 / r) * g;
}

// The blob: in the unit direction u = (sin phi cos theta, sin phi sin theta, cos phi), radius
// R (1 + BlobAmplitude f(u)) with the three low-order spherical harmonics
//   f = sin^2 phi cos 2 theta + 0.7 sin 2 phi sin theta + 0.6 P3(cos phi)
//     = x^2 - y^2 + 1.4 y z + 0.3 (5 z^3 - 3 z).
// Radius 0.76 R to 1.17 R, smallest curvature radius about 0.6 R, normals within 26 degrees of u.
constexpr double BlobAmplitude = 0.15;
constexpr double BlobShapeBound = 1.0 + 0.7 + 0.6; // |f| on the unit sphere, term by term
// |grad f| of the polynomial form on the unit sphere, term by term (it bounds grad_S f, its
// tangential part).
constexpr double BlobGradientBound = 2.0 + 0.7 * 2.0 + 0.6 * 6.0;

// f(u), and the gradient of its polynomial form at u.
double BlobShape(const Vec& u, Vec& gradient)
{
  const double x = u.X, y = u.Y, z = u.Z;
  gradient = { 2.0 * x, -2.0 * y + 1.4 * z, 1.4 * y + 0.3 * (15.0 * z * z - 3.0) };
  return x * x - y * y + 1.4 * y * z + 0.3 * (5.0 * z * z * z - 3.0 * z);
}

// The blob's radius r in the unit direction u, and the area density dA/dOmega =
// r sqrt(r^2 + |grad_S r|^2) there (grad_S: the gradient along the unit sphere).
double BlobRadius(const Vec& u, double R, double* areaDensity)
{
  Vec g;
  const double r = R * (1.0 + BlobAmplitude * BlobShape(u, g));
  if (areaDensity)
  {
    const Vec tangential = BlobAmplitude * R * (g - Dot(g, u) * u);
    *areaDensity = r * std::sqrt(r * r + Dot(tangential, tangential));
  }
  return r;
}

// An upper bound of the area density over all directions, from the bounds of |f| and |grad f|.
double BlobMaxAreaDensity(double R)
{
  const double r = 1.0 + BlobAmplitude * BlobShapeBound;
  const double g = BlobAmplitude * BlobGradientBound;
  return R * R * r * std::sqrt(r * r + g * g);
}

// The integral of an area density over the sphere of directions: midpoint rule in phi and theta,
// relative error of order 1e-5 on the smooth shapes (their area only sets the nominal spacing).
template <typename Density>
double SphereIntegral(const Density& density)
{
  const int nPhi = 256, nTheta = 512;
  const double dPhi = Pi / nPhi, dTheta = 2.0 * Pi / nTheta;
  double sum = 0.0;
  for (int i = 0; i < nPhi; ++i)
  {
    const double phi = (i + 0.5) * dPhi;
    double ring = 0.0;
    for (int j = 0; j < nTheta; ++j)
    {
      const double theta = (j + 0.5) * dTheta;
      ring += density(
        Vec{ std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi) });
    }
    sum += ring * std::sin(phi);
  }
  return sum * dPhi * dTheta;
}

// The blob's area.
double BlobArea(double R)
{
  return SphereIntegral([R](const Vec& u) {
    double density = 0.0;
    BlobRadius(u, R, &density);
    return density;
  });
}

// The ellipsoid with semi-axes e = (a, b, c) is the image of the unit sphere under
// u -> (a ux, b uy, c uz); its area density over the sphere of directions is
// dA/dOmega = a b c |(ux / a, uy / b, uz / c)|, at most a b c / min(a, b, c).
double EllipsoidAreaDensity(const Vec& u, const Vec& e)
{
  const Vec g{ u.X / e.X, u.Y / e.Y, u.Z / e.Z };
  return e.X * e.Y * e.Z * Norm(g);
}

// The ellipsoid's area.
double EllipsoidArea(const Vec& e)
{
  return SphereIntegral([&e](const Vec& u) { return EllipsoidAreaDensity(u, e); });
}

// A surface piece that can be sampled uniformly by area.
struct Patch
{
  enum Kind
  {
    Parallelogram, // Origin + a U + b V, a, b in [0, 1]
    Cylinder,      // axis along z through Origin, radius R, z in [Origin.Z + Z0, Origin.Z + Z1],
                   // azimuth in [0, Angle]
    Sphere,        // centre Origin, radius R
    Triangle,      // Origin + a U + b V, a, b >= 0, a + b <= 1
    Disk,          // in the plane z = Origin.Z, centre Origin, radius R
    Blob,          // centre Origin, radius R (1 + BlobAmplitude BlobShape(u)) in direction u
    Perforated,    // the Parallelogram less the disk of radius R around its centre (U, V
                   // orthogonal, the disk inside)
    Torus,         // around the z axis through Origin: major radius R, tube radius TubeR
    Ellipsoid,     // centre Origin, semi-axes U.X, U.Y, U.Z along x, y, z
  } Type;
  Vec Origin, U, V;
  double R = 0, Z0 = 0, Z1 = 0;
  double TubeR = 0; // the Torus's
  double Angle = 2.0 * Pi; // the Cylinder's range of azimuths

  double Area() const
  {
    switch (this->Type)
    {
      case Parallelogram:
        return Norm(Cross(this->U, this->V));
      case Cylinder:
        return this->Angle * this->R * (this->Z1 - this->Z0);
      case Triangle:
        return 0.5 * Norm(Cross(this->U, this->V));
      case Disk:
        return Pi * this->R * this->R;
      case Blob:
        return BlobArea(this->R);
      case Perforated:
        return Norm(Cross(this->U, this->V)) - Pi * this->R * this->R;
      case Torus:
        return 4.0 * Pi * Pi * this->R * this->TubeR;
      case Ellipsoid:
        return EllipsoidArea(this->U);
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
        const double t = this->Angle * rng.Uniform();
        const double z = this->Z0 + (this->Z1 - this->Z0) * rng.Uniform();
        return this->Origin + Vec{ this->R * std::cos(t), this->R * std::sin(t), z };
      }
      case Triangle:
      {
        // A point of the parallelogram, folded back into the triangle when beyond the diagonal.
        double a = rng.Uniform();
        double b = rng.Uniform();
        if (a + b > 1.0)
        {
          a = 1.0 - a;
          b = 1.0 - b;
        }
        return this->Origin + a * this->U + b * this->V;
      }
      case Disk:
      {
        const double r = this->R * std::sqrt(rng.Uniform());
        const double t = 2.0 * Pi * rng.Uniform();
        return this->Origin + Vec{ r * std::cos(t), r * std::sin(t), 0.0 };
      }
      case Perforated:
      {
        // Uniform over the parallelogram, drawn again inside the hole.
        const Vec centre = this->Origin + 0.5 * (this->U + this->V);
        for (;;)
        {
          const double a = rng.Uniform();
          const double b = rng.Uniform();
          const Vec p = this->Origin + a * this->U + b * this->V;
          if (Norm(p - centre) >= this->R)
          {
            return p;
          }
        }
      }
      case Torus:
      {
        // At the azimuth t around z and the angle v around the tube (v = 0 outermost), the area
        // element is R r (1 + (r / R) cos v) dt dv: t uniform, v kept with probability
        // (1 + (r / R) cos v) / (1 + r / R).
        const double ratio = this->TubeR / this->R;
        const double t = 2.0 * Pi * rng.Uniform();
        double v = 0.0;
        do
        {
          v = 2.0 * Pi * rng.Uniform();
        } while (rng.Uniform() * (1.0 + ratio) > 1.0 + ratio * std::cos(v));
        const double rho = this->R + this->TubeR * std::cos(v);
        return this->Origin +
          Vec{ rho * std::cos(t), rho * std::sin(t), this->TubeR * std::sin(v) };
      }
      case Ellipsoid:
      {
        // A uniform direction u, kept with probability dA/dOmega(u) over its maximum: the kept
        // images are uniform over the ellipsoid's area.
        const Vec& e = this->U;
        const double bound = e.X * e.Y * e.Z / std::min(e.X, std::min(e.Y, e.Z));
        for (;;)
        {
          const Vec u = UniformDirection(rng);
          if (rng.Uniform() * bound <= EllipsoidAreaDensity(u, e))
          {
            return this->Origin + Vec{ e.X * u.X, e.Y * u.Y, e.Z * u.Z };
          }
        }
      }
      case Blob:
      {
        // A uniform direction u, kept with probability dA/dOmega(u) / BlobMaxAreaDensity: the
        // kept points are uniform over the blob's area.
        const double bound = BlobMaxAreaDensity(this->R);
        for (;;)
        {
          const Vec u = UniformDirection(rng);
          double density = 0.0;
          const double r = BlobRadius(u, this->R, &density);
          if (rng.Uniform() * bound <= density)
          {
            return this->Origin + r * u;
          }
        }
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

// A feature curve of a FeatureType: a segment A-B, or a circle of radius R around a z axis
// through A.
struct Curve
{
  bool Circle = false;
  Vec A, B;
  double R = 0;
  unsigned char Type = vtkFeatureModelSource::CONVEX_CREASE;
  // The part of a circle that is a feature, for the true curves only: azimuths 0 to Sweep (the
  // distances use the whole circle, see HALF_CYLINDER).
  double Sweep = 2.0 * Pi;

  // Points along the curve no more than `step` apart, ends included (a whole circle closes on
  // its first point).
  std::vector<Vec> Sample(double step) const
  {
    const double length = this->Circle ? this->Sweep * this->R : Norm(this->B - this->A);
    const int segments = std::max(1, static_cast<int>(std::ceil(length / step)));
    std::vector<Vec> points;
    for (int k = 0; k <= segments; ++k)
    {
      const double t = static_cast<double>(k) / segments;
      if (this->Circle)
      {
        const double a = t * this->Sweep;
        points.push_back(this->A + Vec{ this->R * std::cos(a), this->R * std::sin(a), 0.0 });
      }
      else
      {
        points.push_back(this->A + t * (this->B - this->A));
      }
    }
    return points;
  }

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

Curve Segment(const Vec& a, const Vec& b, unsigned char type)
{
  return { false, a, b, 0.0, type };
}
Curve Circle(const Vec& centre, double r, unsigned char type)
{
  return { true, centre, Vec{}, r, type };
}

struct Geometry
{
  std::vector<Patch> Patches;
  std::vector<Curve> Curves;
  std::vector<Vec> Corners; // where three creases, or two borders at an angle, meet

  // The distance from p to the nearest feature curve, and that curve's type.
  double Distance(const Vec& p, unsigned char& type) const
  {
    double best = VTK_FLOAT_MAX;
    type = vtkFeatureModelSource::NOT_FEATURE;
    for (const Curve& c : this->Curves)
    {
      const double d = c.Distance(p);
      if (d < best)
      {
        best = d;
        type = c.Type;
      }
    }
    return best;
  }

  // The FeatureType of a positive point p whose nearest curve is of the type `nearest`.
  unsigned char PositiveType(const Vec& p, unsigned char nearest, double radius) const
  {
    for (const Vec& c : this->Corners)
    {
      if (Norm(p - c) <= radius)
      {
        return vtkFeatureModelSource::CORNER;
      }
    }
    return nearest;
  }

  // The area of the patches 0 to k, for each k.
  std::vector<double> CumulativeAreas() const
  {
    std::vector<double> cumulative;
    double area = 0.0;
    for (const Patch& p : this->Patches)
    {
      area += p.Area();
      cumulative.push_back(area);
    }
    return cumulative;
  }
};

// A profile z(x) (polyline through (x_k, z_k), x never decreasing) swept along y over
// [-w/2, w/2], the outside towards +z; its inner vertices are the creases, convex where the
// profile turns clockwise.
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
    const double turn =
      (x[k] - x[k - 1]) * (z[k + 1] - z[k]) - (z[k] - z[k - 1]) * (x[k + 1] - x[k]);
    g.Curves.push_back(Segment(Vec{ x[k], -0.5 * w, z[k] }, Vec{ x[k], 0.5 * w, z[k] },
      turn < 0.0 ? vtkFeatureModelSource::CONVEX_CREASE : vtkFeatureModelSource::CONCAVE_CREASE));
  }
  return g;
}

// A closed box of edges ex, ey, ez along x, y, z, centred on the origin: six faces, twelve convex
// edges, eight corners.
Geometry Box(double ex, double ey, double ez)
{
  Geometry g;
  const Vec e[3] = { { ex, 0, 0 }, { 0, ey, 0 }, { 0, 0, ez } };
  const Vec corner = -0.5 * (e[0] + e[1] + e[2]);
  for (int k = 0; k < 3; ++k)
  {
    const Vec& a = e[(k + 1) % 3];
    const Vec& b = e[(k + 2) % 3];
    // The two faces normal to axis k, and the four edges along it.
    g.Patches.push_back({ Patch::Parallelogram, corner, a, b });
    g.Patches.push_back({ Patch::Parallelogram, corner + e[k], a, b });
    for (int m = 0; m < 4; ++m)
    {
      const Vec start = corner + static_cast<double>(m & 1) * a + static_cast<double>(m >> 1) * b;
      g.Curves.push_back(Segment(start, start + e[k], vtkFeatureModelSource::CONVEX_CREASE));
    }
  }
  for (int m = 0; m < 8; ++m)
  {
    g.Corners.push_back(corner + static_cast<double>(m & 1) * e[0] +
      static_cast<double>((m >> 1) & 1) * e[1] + static_cast<double>(m >> 2) * e[2]);
  }
  return g;
}

// PARALLEL_CREASES: RibCount ribs as wide and high as their pitch, a pitch apart, within the
// middle RibSpan of the sheet.
constexpr int RibCount = 3;
constexpr double RibSpan = 0.8; // in Size
double MaxRibPitch(double size)
{
  return RibSpan * size / (2 * RibCount - 1);
}

// The profile of the ribs with the pitch d, centred on x = 0.
Geometry Ribs(double size, double d)
{
  const double h = 0.5 * size;
  std::vector<double> x{ -h }, z{ 0.0 };
  for (int k = 0; k < RibCount; ++k)
  {
    const double left = (2 * k - 0.5 * (2 * RibCount - 1)) * d;
    x.insert(x.end(), { left, left, left + d, left + d });
    z.insert(z.end(), { 0.0, d, d, 0.0 });
  }
  x.push_back(h);
  z.push_back(0.0);
  return Extrusion(x, z, size);
}

// The model's surface patches, feature curves and corners; `separation` is the length of
// FeatureSeparation nominal spacings, for PARALLEL_CREASES and THIN_PLATE.
Geometry MakeGeometry(int model, double size, double valleySlope, double separation)
{
  const double h = 0.5 * size;
  switch (model)
  {
    case vtkFeatureModelSource::MODEL_I:
    {
      const double a = 0.15 * size;
      const double depth = a * std::tan(vtkMath::RadiansFromDegrees(valleySlope));
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
      // Two of the four angles around the circle are convex, two concave: called convex.
      g.Curves.push_back(Circle(Vec{}, r, vtkFeatureModelSource::CONVEX_CREASE));
      return g;
    }
    case vtkFeatureModelSource::BOX:
      return Box(1.0 * size, 0.7 * size, 0.5 * size);
    case vtkFeatureModelSource::THIN_PLATE:
      return Box(1.0 * size, 0.6 * size, separation);
    case vtkFeatureModelSource::PARALLEL_CREASES:
      // Capped so that the ribs stay on the sheet; RequestData warns.
      return Ribs(size, std::min(separation, MaxRibPitch(size)));
    case vtkFeatureModelSource::CYLINDER:
    {
      Geometry g;
      const double r = 0.3 * size, z = 0.3 * size;
      Patch side{ Patch::Cylinder, Vec{}, Vec{}, Vec{} };
      side.R = r;
      side.Z0 = -z;
      side.Z1 = z;
      g.Patches.push_back(side);
      for (const double c : { -z, z })
      {
        Patch cap{ Patch::Disk, Vec{ 0.0, 0.0, c }, Vec{}, Vec{} };
        cap.R = r;
        g.Patches.push_back(cap);
        g.Curves.push_back(Circle(Vec{ 0.0, 0.0, c }, r, vtkFeatureModelSource::CONVEX_CREASE));
      }
      return g;
    }
    case vtkFeatureModelSource::BRACKET:
    {
      // The L profile in the (x, z) plane, counter-clockwise: bottom, free end, sloped and flat
      // tops of the long leg, inner face, top and back of the upright.
      const double zc = (-0.12 + 0.4 * std::tan(vtkMath::RadiansFromDegrees(20.0))) * size; // the crease's height
      const double x[7] = { -0.5 * size, 0.5 * size, 0.5 * size, 0.1 * size, -0.2 * size,
        -0.2 * size, -0.5 * size };
      const double z[7] = { -0.3 * size, -0.3 * size, -0.12 * size, zc, zc, 0.3 * size,
        0.3 * size };
      const double w = 0.5 * size; // along y
      Geometry g;
      for (int k = 0; k < 7; ++k)
      {
        const int l = (k + 1) % 7, j = (k + 6) % 7;
        const Vec a{ x[k], -0.5 * w, z[k] };
        const Vec b{ x[l], -0.5 * w, z[l] };
        const Vec y{ 0.0, w, 0.0 };
        // The profile runs counter-clockwise: convex where it turns counter-clockwise.
        const double turn = (x[k] - x[j]) * (z[l] - z[k]) - (z[k] - z[j]) * (x[l] - x[k]);
        g.Patches.push_back({ Patch::Parallelogram, a, b - a, y });
        // The edge along y at the profile's vertex k, and the end caps' edges.
        const unsigned char along = turn > 0.0 ? vtkFeatureModelSource::CONVEX_CREASE
                                               : vtkFeatureModelSource::CONCAVE_CREASE;
        g.Curves.push_back(Segment(a, a + y, along));
        g.Curves.push_back(Segment(a, b, vtkFeatureModelSource::CONVEX_CREASE));
        g.Curves.push_back(Segment(a + y, b + y, vtkFeatureModelSource::CONVEX_CREASE));
        g.Corners.push_back(a);
        g.Corners.push_back(a + y);
      }
      // The end caps: the upright's rectangle, the long leg's rectangles under the free end's
      // top and under the flat top, and the triangle under the sloped top.
      for (const double y : { -0.5 * w, 0.5 * w })
      {
        g.Patches.push_back({ Patch::Parallelogram, Vec{ x[0], y, z[0] }, Vec{ x[4] - x[0], 0, 0 },
          Vec{ 0, 0, z[5] - z[0] } });
        g.Patches.push_back({ Patch::Parallelogram, Vec{ x[4], y, z[0] }, Vec{ x[1] - x[4], 0, 0 },
          Vec{ 0, 0, z[2] - z[0] } });
        g.Patches.push_back({ Patch::Parallelogram, Vec{ x[4], y, z[2] }, Vec{ x[3] - x[4], 0, 0 },
          Vec{ 0, 0, z[3] - z[2] } });
        g.Patches.push_back({ Patch::Triangle, Vec{ x[3], y, z[2] }, Vec{ x[2] - x[3], 0, 0 },
          Vec{ 0, 0, z[3] - z[2] } });
      }
      return g;
    }
    case vtkFeatureModelSource::HALF_CYLINDER:
    {
      // Azimuths 0 to pi (y >= 0) of the cylinder, z from -h to h: its borders are the half
      // circles at both ends and the straight lines at azimuths 0 and pi. The half circles are
      // given as whole circles: from any point of the surface, the nearest point of the circle
      // lies at the point's own azimuth, on the half circle.
      Geometry g;
      const double r = 0.3 * size;
      Patch side{ Patch::Cylinder, Vec{}, Vec{}, Vec{} };
      side.R = r;
      side.Z0 = -h;
      side.Z1 = h;
      side.Angle = Pi;
      g.Patches.push_back(side);
      for (const double z : { -h, h })
      {
        g.Curves.push_back(Circle(Vec{ 0.0, 0.0, z }, r, vtkFeatureModelSource::BORDER));
        g.Curves.back().Sweep = Pi;
      }
      for (const double x : { -r, r })
      {
        g.Curves.push_back(
          Segment(Vec{ x, 0.0, -h }, Vec{ x, 0.0, h }, vtkFeatureModelSource::BORDER));
        g.Corners.push_back(Vec{ x, 0.0, -h });
        g.Corners.push_back(Vec{ x, 0.0, h });
      }
      return g;
    }
    case vtkFeatureModelSource::PLATE_WITH_HOLE:
    {
      Geometry g;
      Patch plate{ Patch::Perforated, Vec{ -h, -h, 0.0 }, Vec{ size, 0.0, 0.0 },
        Vec{ 0.0, size, 0.0 } };
      plate.R = 0.2 * size;
      g.Patches.push_back(plate);
      // Its borders: the hole's rim and the outer square, whose vertices are the corners.
      g.Curves.push_back(Circle(Vec{}, plate.R, vtkFeatureModelSource::BORDER));
      const Vec corners[4] = { { -h, -h, 0.0 }, { h, -h, 0.0 }, { h, h, 0.0 }, { -h, h, 0.0 } };
      for (int k = 0; k < 4; ++k)
      {
        g.Curves.push_back(
          Segment(corners[k], corners[(k + 1) % 4], vtkFeatureModelSource::BORDER));
        g.Corners.push_back(corners[k]);
      }
      return g;
    }
    case vtkFeatureModelSource::TORUS:
    {
      Geometry g;
      Patch torus{ Patch::Torus, Vec{}, Vec{}, Vec{} };
      torus.R = 0.35 * size;
      torus.TubeR = 0.1 * size;
      g.Patches.push_back(torus);
      return g;
    }
    case vtkFeatureModelSource::ELLIPSOID:
    {
      Geometry g;
      g.Patches.push_back(
        { Patch::Ellipsoid, Vec{}, Vec{ 0.5 * size, 0.3 * size, 0.15 * size }, Vec{} });
      return g;
    }
    case vtkFeatureModelSource::BLOB:
    {
      Geometry g;
      Patch blob{ Patch::Blob, Vec{}, Vec{}, Vec{} };
      blob.R = h;
      g.Patches.push_back(blob);
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

// The exact feature curves of output port 1: one polyline per curve, a vertex at most every `step`,
// moved by `center`.
void MakeFeatureCurves(const Geometry& geometry, double step, const double center[3],
  vtkPolyData* curves)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("FeatureType");
  vtkNew<vtkIntArray> ids;
  ids->SetName("CurveId");
  for (const Curve& c : geometry.Curves)
  {
    const std::vector<Vec> samples = c.Sample(step);
    const bool closed = c.Circle && c.Sweep >= 2.0 * Pi;
    const vtkIdType first = points->GetNumberOfPoints();
    const size_t count = closed ? samples.size() - 1 : samples.size();
    lines->InsertNextCell(static_cast<vtkIdType>(closed ? count + 1 : count));
    for (size_t k = 0; k < count; ++k)
    {
      lines->InsertCellPoint(points->InsertNextPoint(samples[k].X + center[0],
        samples[k].Y + center[1], samples[k].Z + center[2]));
    }
    if (closed)
    {
      lines->InsertCellPoint(first);
    }
    types->InsertNextValue(c.Type);
    ids->InsertNextValue(static_cast<int>(ids->GetNumberOfTuples()));
  }
  curves->SetPoints(points);
  curves->SetLines(lines);
  curves->GetCellData()->AddArray(ids);
  curves->GetCellData()->AddArray(types);
}

// The length L = F x, F = FeatureSeparation, that PARALLEL_CREASES and THIN_PLATE are built with,
// where x is the nominal spacing sqrt(area / n) of the model so built. Their area is affine in L
// (the ribs' walls, the plate's rim; below the ribs' cap), area = A0 + A1 L, so x is the positive
// root of n x^2 - A1 F x - A0 = 0; A0 and A1 come from the geometry itself, at L = 0 and at a
// small L, rather than from a second copy of its formulas.
double SeparationLength(int model, double size, vtkIdType n, double factor)
{
  const double probe = 0.01 * size; // well below MaxRibPitch
  // (The valley slope is Model I's only.)
  const double a0 = MakeGeometry(model, size, 0.0, 0.0).CumulativeAreas().back();
  const double a1 = (MakeGeometry(model, size, 0.0, probe).CumulativeAreas().back() - a0) / probe;
  const double b = a1 * factor, count = static_cast<double>(n);
  return factor * (b + std::sqrt(b * b + 4.0 * count * a0)) / (2.0 * count);
}
} // namespace

vtkFeatureModelSource::vtkFeatureModelSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

vtkPolyData* vtkFeatureModelSource::GetFeatureCurves()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
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
    case BOX:
      return "Box";
    case CYLINDER:
      return "Cylinder";
    case BRACKET:
      return "Bracket";
    case BLOB:
      return "Blob";
    case PARALLEL_CREASES:
      return "Parallel creases";
    case THIN_PLATE:
      return "Thin plate";
    case HALF_CYLINDER:
      return "Half cylinder";
    case PLATE_WITH_HOLE:
      return "Plate with hole";
    case TORUS:
      return "Torus";
    case ELLIPSOID:
      return "Ellipsoid";
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
    case BOX:
      return 100000;
    case CYLINDER:
      return 80000;
    case BRACKET:
      return 120000;
    case BLOB:
    case PARALLEL_CREASES:
    case THIN_PLATE:
    case HALF_CYLINDER:
    case PLATE_WITH_HOLE:
    case TORUS:
    case ELLIPSOID:
      return 100000;
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
  if (const char* nan = featurepoints::FirstNaN({ { "FeatureDensityFactor",
                                                    this->FeatureDensityFactor },
        { "DenseBandWidth", this->DenseBandWidth }, { "NoiseFactor", this->NoiseFactor },
        { "Size", this->Size }, { "ValleySlope", this->ValleySlope },
        { "FeatureSeparation", this->FeatureSeparation } }))
  {
    vtkErrorMacro(<< nan << " is NaN: give it a number. The output is empty.");
    output->Initialize();
    return 1;
  }
  if (!std::isfinite(this->Center[0]) || !std::isfinite(this->Center[1]) ||
    !std::isfinite(this->Center[2]))
  {
    vtkErrorMacro(<< "Center (" << this->Center[0] << ", " << this->Center[1] << ", "
                  << this->Center[2] << ") is not finite: give it numbers. The output is empty.");
    output->Initialize();
    return 1;
  }
  const vtkIdType n =
    this->NumberOfPoints > 0 ? this->NumberOfPoints : GetDefaultNumberOfPoints(this->Model);
  const bool separated = this->Model == PARALLEL_CREASES || this->Model == THIN_PLATE;
  const double separation =
    separated ? SeparationLength(this->Model, this->Size, n, this->FeatureSeparation) : 0.0;
  if (this->Model == PARALLEL_CREASES && separation > MaxRibPitch(this->Size))
  {
    vtkWarningMacro("FeatureSeparation " << this->FeatureSeparation
                                         << " would take the ribs beyond the middle "
                                         << RibSpan << " Size of the sheet: their pitch is "
                                         << "reduced to " << MaxRibPitch(this->Size) << ".");
  }
  const Geometry geometry =
    MakeGeometry(this->Model, this->Size, this->ValleySlope, separation);

  const std::vector<double> cumulative = geometry.CumulativeAreas();
  const double area = cumulative.back();
  const double band = this->DenseBandWidth * std::sqrt(area / static_cast<double>(n));
  const double keepOutside = 1.0 / this->FeatureDensityFactor;

  // Clean points by rejection: everywhere uniform, thinned to 1 / factor outside the band.
  Random rng(this->Seed);
  std::vector<Vec> clean(static_cast<size_t>(n));
  std::vector<double> delta(static_cast<size_t>(n));
  std::vector<unsigned char> nearestType(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n;)
  {
    const double pick = area * rng.Uniform();
    const size_t which = std::min(geometry.Patches.size() - 1,
      static_cast<size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
    const Vec p = geometry.Patches[which].Sample(rng);
    unsigned char type = NOT_FEATURE;
    const double d = geometry.Distance(p, type);
    if (d <= band || rng.Uniform() < keepOutside)
    {
      clean[i] = p;
      delta[i] = d;
      nearestType[i] = type;
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
  // s of docs/evaluation.md: the mean nearest-neighbour distance of the clean cloud.
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
  vtkNew<vtkUnsignedCharArray> type;
  type->SetName("GroundTruthType");
  type->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool positive = delta[i] <= 2.0 * s;
    distance->SetValue(i, delta[i]);
    truth->SetValue(i, positive ? 1 : 0);
    type->SetValue(i,
      positive ? geometry.PositiveType(clean[i], nearestType[i], 2.0 * s)
               : static_cast<unsigned char>(NOT_FEATURE));
  }

  output->SetPoints(points);
  output->SetVerts(vtkPointCloudNeighborhoods::MakeVertexCells(n));
  output->GetPointData()->AddArray(distance);
  output->GetPointData()->AddArray(truth);
  output->GetPointData()->AddArray(type);
  output->GetPointData()->SetActiveScalars("GroundTruth");
  vtkNew<vtkDoubleArray> spacing;
  spacing->SetName("CleanMeanSpacing");
  spacing->InsertNextValue(s);
  vtkNew<vtkDoubleArray> noise;
  noise->SetName("NoiseSigma");
  noise->InsertNextValue(sigma);
  output->GetFieldData()->AddArray(spacing);
  output->GetFieldData()->AddArray(noise);

  vtkPolyData* curves = vtkPolyData::GetData(outputVector, 1);
  if (curves)
  {
    MakeFeatureCurves(geometry, s > 0.0 ? 0.25 * s : 1e-3 * this->Size, this->Center, curves);
  }
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
  os << indent << "FeatureSeparation: " << this->FeatureSeparation << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
