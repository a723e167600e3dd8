/**
 * @class   vtkMeshFeatureSampler
 * @brief   A point cloud sampled from a surface mesh, labelled with the mesh's sharp edges.
 *
 * Turns a surface mesh (a CAD part exported as STL, OBJ, PLY or VTP) into a test cloud whose
 * ground truth comes from the mesh itself, as vtkFeatureModelSource does for its analytic models:
 *
 * 1. Duplicate points are merged (coordinates equal bit for bit, as in STL files, which repeat
 *    every vertex in each triangle), polygons and triangle strips are triangulated (concave
 *    polygons too), and triangles of zero area are dropped. Vertices and lines are ignored.
 * 2. The triangles are oriented consistently across every edge shared by two of them; a closed
 *    component is then turned outward (positive volume). An open component keeps the orientation
 *    of its first triangle: there "convex" follows the input's normals.
 * 3. A mesh edge is a feature when it is a boundary edge (one triangle: BORDER), an edge shared by
 *    more than two triangles (non-manifold: CONVEX_CREASE), or when the angle between the normals
 *    of its two triangles is at least FeatureAngle (CONVEX_CREASE or CONCAVE_CREASE, by the side
 *    the second triangle lies on). A corner is a mesh vertex where three or more feature edges
 *    meet, or where two meet at an angle: their directions turn by at least FeatureAngle.
 * 4. NumberOfPoints points are drawn independently and uniformly over the area (a Poisson
 *    sampling), then moved along their triangle's normal by Gaussian noise of standard deviation
 *    NoiseSigma * s, where s is the mean nearest-neighbour distance of the clean cloud (the s of
 *    docs/evaluation.md, about half the nominal spacing sqrt(area / points)).
 *
 * Why FeatureAngle defaults to 30 degrees: a curved face is tessellated into facets whose normals
 * turn by a few degrees from one to the next, and those facet edges must stay below the angle,
 * while the creases a detector is asked to find (the smallest in this project's models are 15 to
 * 30 degrees; most CAD creases are 90) must reach it. The mesh must therefore be fine enough:
 * OpenSCAD's $fn = 96 turns the normals by 360 / 96 = 3.75 degrees per facet, far below 30, while
 * $fn = 12 (30 degrees per facet) would turn every facet edge of a cylinder into a crease.
 *
 * Output port 0: a vtkPolyData with one vertex cell per point (double coordinates) and the point
 * arrays
 * - `FeatureDistance` (double): the clean (pre-noise) point's Euclidean distance to the nearest
 *   feature edge (exact); VTK_FLOAT_MAX when the mesh has no feature edge.
 * - `FeatureEdgeId` (vtkIdType): that edge's cell id in output port 1 (the smaller id on a tie);
 *   -1 when the mesh has no feature edge.
 * - `GroundTruth` (uint8): 1 for the positives of docs/evaluation.md, FeatureDistance <= 2 s.
 * - `TrueFeatureType` (uint8, the codes of vtkCreaseVotingFeatures' FeatureType): 0 where
 *   GroundTruth is 0; else 3 (corner) within 2 s of a corner (the clean position), else the type of
 *   the nearest feature edge: 1 convex crease, 2 concave crease, 4 border.
 * and the field data `CleanMeanSpacing` (s), `NoiseSigma` (the standard deviation, in the mesh's
 * units) and `MeshArea`.
 *
 * Output port 1 (GetFeatureEdges()): the feature edges as lines on the merged mesh points, with the
 * cell arrays `FeatureType` (uint8: 1, 2 or 4) and `DihedralAngle` (double, degrees between the
 * two normals; 180 for a boundary edge, 90 for a non-manifold one) and the point array `Corner`
 * (uint8, 1 at the corners).
 *
 * Everything follows from Seed: the same mesh and parameters give the same cloud on every run and
 * every thread count.
 *
 * @warning Bad input (no polygon, no area, a coordinate that is not finite) gives one error line
 * and empty outputs.
 *
 * @sa vtkFeatureModelSource vtkFeaturePointEvaluation vtkCreaseVotingFeatures
 */
#ifndef vtkMeshFeatureSampler_h
#define vtkMeshFeatureSampler_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FEATUREPOINTSFILTERS_EXPORT vtkMeshFeatureSampler : public vtkPolyDataAlgorithm
{
public:
  static vtkMeshFeatureSampler* New();
  vtkTypeMacro(vtkMeshFeatureSampler, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The values of TrueFeatureType and of the edges' FeatureType. */
  enum FeatureTypes
  {
    NOT_FEATURE = 0,
    CONVEX_CREASE = 1,
    CONCAVE_CREASE = 2,
    CORNER = 3,
    BORDER = 4,
  };

  ///@{
  /** Number of points drawn. Default 100,000. */
  vtkSetClampMacro(NumberOfPoints, vtkIdType, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Standard deviation of the Gaussian noise along the surface normal, in mean spacings s of the
   * clean cloud. Default 0.
   */
  vtkSetClampMacro(NoiseSigma, double, 0.0, 100.0);
  vtkGetMacro(NoiseSigma, double);
  ///@}

  ///@{
  /**
   * Smallest angle between the normals of two triangles, in degrees, for their shared edge to be a
   * feature (see the class comment for why 30). Default 30.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /** Seed of the sampling and the noise. Default 1. */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  /** The feature edges of the last update (output port 1; see the class comment). */
  vtkPolyData* GetFeatureEdges();

protected:
  vtkMeshFeatureSampler();
  ~vtkMeshFeatureSampler() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfPoints = 100000;
  double NoiseSigma = 0.0;
  double FeatureAngle = 30.0;
  unsigned int Seed = 1;

private:
  vtkMeshFeatureSampler(const vtkMeshFeatureSampler&) = delete;
  void operator=(const vtkMeshFeatureSampler&) = delete;
};

#endif
