/**
 * @class   vtkFeatureModelSource
 * @brief   Noisy point clouds of the paper's kind of test model, with exact ground truth.
 *
 * Generates one of the synthetic models of Huang et al. (2023), Section 3.3, as this project
 * reads their description (the paper shows them only in figures), a smooth shape with no
 * feature, or a closed CAD-like part that the default parameters were not tuned on:
 *
 * - MODEL_I ("a surface with a middle valley", 170,000 points by default): a square sheet of side
 *   Size with a V-shaped valley across its middle: flanks at ValleySlope (30 degrees) from the
 *   plane, 0.3 Size wide. Three straight creases: two convex shoulders (dihedral angle 30 degrees)
 *   and the concave valley floor (60 degrees).
 * - MODEL_II ("a flat top plane with gentle features in the middle", 220,000 points): a plateau
 *   0.5 Size wide standing 0.15 Size above a ground plane, with 60-degree walls, and on its top a
 *   low ridge whose flanks rise at 15 degrees. Seven straight creases: walls' foot (concave, 60)
 *   and top (convex, 60), the ridge's feet (concave, 15) and crest (convex, 30).
 * - MODEL_III ("intersecting surfaces", 130,000 points): a square sheet crossed by an open vertical
 *   cylinder of radius 0.25 Size and height 0.5 Size; both surfaces go through each other. One
 *   curved feature: the circle where they meet (dihedral angle 90 degrees), with the cylinder's
 *   curvature around it.
 * - SPHERE (100,000 points): a sphere of diameter Size, no feature at all.
 * - BOX (100,000 points): a closed box of 1.0 x 0.7 x 0.5 Size (along x, y, z). Twelve straight
 *   creases, its edges: all convex, 90 degrees; they meet by three at the eight corners.
 * - CYLINDER (80,000 points): a closed cylinder of radius 0.3 Size and height 0.6 Size along z,
 *   with flat caps. Two curved features: the caps' rims, circles of radius 0.3 Size (convex, 90
 *   degrees); the side is smooth, curvature radius 0.3 Size.
 * - BRACKET (120,000 points): a closed angle bracket, an L profile in the (x, z) plane extruded
 *   0.5 Size along y with flat end caps. The long leg is 1.0 Size long along x (from x = -0.5 Size),
 *   0.18 Size thick at its free end; its top is a face rising at 20 degrees from the free end for
 *   0.4 Size, then a flat face 0.3 Size wide up to the upright, 0.3 Size thick and 0.6 Size high.
 *   Twenty-one straight creases: along y, the bottom's two edges (convex, 90), the free end's top
 *   (convex, 70), the crease between the two tops (convex, 20), the inner corner at the upright's
 *   foot (concave, 90) and the upright's top two edges (convex, 90); and the fourteen edges of the
 *   end caps (convex, 90).
 * - BLOB (100,000 points): a smooth, star-shaped closed surface without any feature: a sphere of
 *   diameter Size whose radius is modulated by 15% of three low-order spherical harmonics,
 *   r = 0.5 Size (1 + 0.15 (sin^2 phi cos 2 theta + 0.7 sin 2 phi sin theta + 0.6 P3(cos phi))),
 *   from 0.38 to 0.59 Size; principal curvature radii 0.29 Size and more.
 *
 * Four more models stand for situations of real CAD parts: features close together, and features
 * on the border of an open surface. The first two are sized in nominal spacings (below) by
 * FeatureSeparation F:
 *
 * - PARALLEL_CREASES (100,000 points): a square sheet of side Size carrying three parallel
 *   rectangular ribs across its middle, extruded along y. The ribs are F nominal spacings wide
 *   and high, F apart: a row of twelve straight creases, each F from the next (along the surface
 *   and in space), alternately concave (the ribs' feet) and convex (their top edges), all 90
 *   degrees. The ribs stay within the middle 0.8 Size of the sheet: a larger F (above about 36 at
 *   100,000 points) is reduced to fit, with a warning.
 * - THIN_PLATE (100,000 points): a closed flat box of 1.0 x 0.6 Size (along x, y) and F nominal
 *   spacings thick (along z), the thin rim faces included. Twelve straight creases, its edges:
 *   all convex, 90 degrees; they meet by three at the eight corners. With F = 0.5 to 3, the two
 *   edges of each rim face lie within a few spacings of each other.
 * - HALF_CYLINDER (100,000 points): an open surface, the half y >= 0 of a cylinder of radius
 *   0.3 Size around the z axis, 1.0 Size long (z from -0.5 to 0.5 Size), without caps. Its
 *   borders are the features: two straight lines (x = +-0.3 Size, y = 0) and two half circles
 *   (z = +-0.5 Size); they meet at 90 degrees at four corners. The surface is smooth elsewhere,
 *   curvature radius 0.3 Size.
 * - PLATE_WITH_HOLE (100,000 points): an open flat square sheet of side Size in the plane z = 0
 *   with a circular hole of radius 0.2 Size in its middle. Its borders are the features: the
 *   outer square and the hole's circle; the square's sides meet at 90 degrees at four corners.
 *
 * Two more smooth shapes without any feature have the thin and flattened parts of real parts,
 * where a surface curves tightly in one direction only:
 *
 * - TORUS (100,000 points): a ring around the z axis, major radius 0.35 Size, tube radius
 *   0.1 Size. Principal curvature radii: 0.1 Size around the tube; along the ring, 0.45 Size at
 *   the outer equator, -0.25 Size (saddle) at the inner one, unbounded on the top and bottom
 *   circles.
 * - ELLIPSOID (100,000 points): semi-axes 0.5, 0.3 and 0.15 Size along x, y and z. Principal
 *   curvature radii from 0.045 Size (c^2 / a, at the ends of the long axis, across the flat
 *   side) to 1.67 Size (a^2 / c, at the centres of the flat faces).
 *
 * Models I-III and PARALLEL_CREASES stand for pieces of larger surfaces: their sheets' outer
 * edges are not features (the creases run to them, and no corner lies there). The borders of
 * HALF_CYLINDER and PLATE_WITH_HOLE are the edges of open parts, and are features.
 *
 * Sampling: points are drawn independently and uniformly over the surface area (a Poisson
 * sampling, like an unorganized scan; on the blob and the ellipsoid, uniform directions kept in
 * proportion to the exact area density; on the torus, the angle around the tube kept in proportion
 * to 1 + (0.1 / 0.35) cos v), except that the band within DenseBandWidth nominal spacings of a feature
 * curve is sampled FeatureDensityFactor times as densely, as the paper's re-scanned feature
 * regions (1: uniform sampling). The nominal spacing is sqrt(area / number of points);
 * PARALLEL_CREASES and THIN_PLATE, whose area depends on it through FeatureSeparation, are built
 * with the spacing that their own area gives (exactly, not an estimate). Then every point is
 * moved by isotropic Gaussian noise of standard deviation NoiseFactor * s, where s is the mean
 * nearest-neighbour distance of the clean cloud (sigma = 0.5 s by default).
 * Everything follows from Seed: the same parameters give the same cloud on every run and every
 * thread count.
 *
 * Output: a vtkPolyData with one vertex cell per point and the point arrays
 * - `FeatureDistance` (double): the clean (pre-noise) distance delta from the point to the
 *   nearest feature curve (exact, the circles' and the borders' included); VTK_FLOAT_MAX on a
 *   model without features (SPHERE, BLOB, TORUS, ELLIPSOID).
 * - `GroundTruth` (uint8): 1 for the positives of docs/evaluation.md, delta <= 2 s.
 * - `GroundTruthType` (uint8, FeatureTypes): NOT_FEATURE (0) where GroundTruth is 0; else CORNER (3)
 *   within 2 s of a corner (the clean position), else the type of the nearest feature curve:
 *   CONVEX_CREASE (1), CONCAVE_CREASE (2) or BORDER (4). The corners are the points where three
 *   creases meet (the box's, the thin plate's and the bracket's vertices) and where two borders
 *   meet at an angle (the half cylinder's and the plate's four). Model III's circle, where the
 *   sheet and the cylinder cross, is both convex and concave (two of the four angles around it
 *   are each): it is called CONVEX_CREASE.
 * and the field data `CleanMeanSpacing` (s) and `NoiseSigma`.
 *
 * Output port 1 (GetFeatureCurves()): the exact feature curves, one polyline each, vertices no
 * more than s / 4 apart (a circle closes on its first vertex; HALF_CYLINDER's borders are half
 * circles), with the cell arrays `CurveId` (0, 1, ...) and `FeatureType` (as GroundTruthType).
 * The corners are the curves' shared end points. Models without features give no line.
 *
 * @sa vtkFeaturePointEvaluation vtkFeaturePointExtraction
 */
#ifndef vtkFeatureModelSource_h
#define vtkFeatureModelSource_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FEATUREPOINTSFILTERS_EXPORT vtkFeatureModelSource : public vtkPolyDataAlgorithm
{
public:
  static vtkFeatureModelSource* New();
  vtkTypeMacro(vtkFeatureModelSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Models
  {
    MODEL_I = 0,          ///< sheet with a middle valley
    MODEL_II = 1,         ///< plateau with a gentle ridge on its flat top
    MODEL_III = 2,        ///< sheet crossed by a cylinder
    SPHERE = 3,           ///< no feature
    BOX = 4,              ///< closed box: 12 convex 90-degree edges
    CYLINDER = 5,         ///< closed cylinder: 2 circular convex 90-degree rims
    BRACKET = 6,          ///< closed L bracket: convex, concave 90-degree edges, a 20-degree crease
    BLOB = 7,             ///< smooth bumpy closed surface, no feature
    PARALLEL_CREASES = 8, ///< sheet with three ribs: 12 creases FeatureSeparation apart
    THIN_PLATE = 9,       ///< closed plate FeatureSeparation thick: 12 convex edges, 8 corners
    HALF_CYLINDER = 10,   ///< open half cylinder: its borders (2 lines, 2 half circles)
    PLATE_WITH_HOLE = 11, ///< open square sheet with a round hole: its borders
    TORUS = 12,           ///< smooth closed ring, tube radius 0.1 Size, no feature
    ELLIPSOID = 13,       ///< smooth flattened closed surface, no feature
  };

  /** The values of the FeatureType array. */
  enum FeatureTypes
  {
    NOT_FEATURE = 0,    ///< not a positive (GroundTruth 0)
    CONVEX_CREASE = 1,  ///< nearest a convex crease
    CONCAVE_CREASE = 2, ///< nearest a concave crease
    CORNER = 3,         ///< within 2 s of a corner
    BORDER = 4,         ///< nearest a border of an open surface
  };

  ///@{
  /** Which model. Default MODEL_I. */
  vtkSetClampMacro(Model, int, MODEL_I, ELLIPSOID);
  vtkGetMacro(Model, int);
  void SetModelToModelI() { this->SetModel(MODEL_I); }
  void SetModelToModelII() { this->SetModel(MODEL_II); }
  void SetModelToModelIII() { this->SetModel(MODEL_III); }
  void SetModelToSphere() { this->SetModel(SPHERE); }
  void SetModelToBox() { this->SetModel(BOX); }
  void SetModelToCylinder() { this->SetModel(CYLINDER); }
  void SetModelToBracket() { this->SetModel(BRACKET); }
  void SetModelToBlob() { this->SetModel(BLOB); }
  void SetModelToParallelCreases() { this->SetModel(PARALLEL_CREASES); }
  void SetModelToThinPlate() { this->SetModel(THIN_PLATE); }
  void SetModelToHalfCylinder() { this->SetModel(HALF_CYLINDER); }
  void SetModelToPlateWithHole() { this->SetModel(PLATE_WITH_HOLE); }
  void SetModelToTorus() { this->SetModel(TORUS); }
  void SetModelToEllipsoid() { this->SetModel(ELLIPSOID); }
  ///@}

  /** The model's name ("Model I", ..., "Box", ...), and its default number of points. */
  static const char* GetModelName(int model);
  static vtkIdType GetDefaultNumberOfPoints(int model);

  ///@{
  /**
   * Number of points; 0 (default) takes the model's own count (170,000, 220,000, 130,000 for
   * Models I-III as in the paper's Table 1; 100,000 for the sphere, the box, the blob, the
   * four models of close and bordered features, the torus and the ellipsoid; 80,000 for the
   * cylinder; 120,000 for the bracket).
   */
  vtkSetClampMacro(NumberOfPoints, vtkIdType, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * How many times denser the band around the feature curves is sampled than the rest. Default 3;
   * 1 samples the model uniformly.
   */
  vtkSetClampMacro(FeatureDensityFactor, double, 1.0, 100.0);
  vtkGetMacro(FeatureDensityFactor, double);
  ///@}

  ///@{
  /** Half-width of the denser band around each feature curve, in nominal spacings. Default 5. */
  vtkSetClampMacro(DenseBandWidth, double, 0.0, 1000.0);
  vtkGetMacro(DenseBandWidth, double);
  ///@}

  ///@{
  /** Standard deviation of the Gaussian noise, in mean spacings s of the clean cloud. Default 0.5. */
  vtkSetClampMacro(NoiseFactor, double, 0.0, 100.0);
  vtkGetMacro(NoiseFactor, double);
  ///@}

  ///@{
  /**
   * Size of the model (sheet side, sphere and blob diameter, the box's, the bracket's, the thin
   * plate's, the half cylinder's and the ellipsoid's length) in the output's units. Default 100.
   */
  vtkSetClampMacro(Size, double, 1e-12, 1e12);
  vtkGetMacro(Size, double);
  ///@}

  ///@{
  /** Where the model's centre lies. Default (0, 0, 0). */
  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  ///@}

  ///@{
  /** Seed of the random sampling and noise. Default 1. */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /** Slope of Model I's valley flanks, in degrees. Default 30. */
  vtkSetClampMacro(ValleySlope, double, 1.0, 80.0);
  vtkGetMacro(ValleySlope, double);
  ///@}

  ///@{
  /**
   * Distance between the neighbouring creases of PARALLEL_CREASES (the ribs' width, height and
   * gap), and THIN_PLATE's thickness, in nominal spacings. Default 5; other models ignore it.
   */
  vtkSetClampMacro(FeatureSeparation, double, 0.1, 1000.0);
  vtkGetMacro(FeatureSeparation, double);
  ///@}

  /** The exact feature curves of the last update (output port 1; see the class comment). */
  vtkPolyData* GetFeatureCurves();

  ///@{
  /** vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) output points. */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkFeatureModelSource();
  ~vtkFeatureModelSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Model = MODEL_I;
  vtkIdType NumberOfPoints = 0;
  double FeatureDensityFactor = 3.0;
  double DenseBandWidth = 5.0;
  double NoiseFactor = 0.5;
  double Size = 100.0;
  double Center[3] = { 0.0, 0.0, 0.0 };
  unsigned int Seed = 1;
  double ValleySlope = 30.0;
  double FeatureSeparation = 5.0;
  int OutputPointsPrecision = DOUBLE_PRECISION;

private:
  vtkFeatureModelSource(const vtkFeatureModelSource&) = delete;
  void operator=(const vtkFeatureModelSource&) = delete;
};

#endif
