/**
 * @class   vtkFeatureCurveExtraction
 * @brief   Feature curves: polylines through the feature points found by a detector, one per
 *          curve between two ends or junctions.
 *
 * Input: the full output of a feature point detector (vtkCreaseVotingFeatures by default): a point
 * set with the point arrays `FeatureMask` (required, nonzero for a feature point) and, when
 * present, `FeatureType` (vtkCreaseVotingFeatures::FeatureTypes), `CreaseAngle` and `Normals`;
 * the field array `MeanSpacing` gives the mean spacing s (computed from the points when absent).
 * Every length below is in units of s, so the result does not depend on the cloud's units.
 *
 * The curves are built in stages:
 * 1. Tracing. The feature points are the trace points, except the crease points (FeatureType 1
 *    or 2) scored below half the detector's threshold (the input's active scalars and its
 *    `FeatureThreshold` field): points that no fit voted for, marked by the detector's rule for
 *    points no fit explains at any scale. They lie between features as often as on one, and a
 *    trace through them would hop from one crease to the next across the face between them
 *    (parallel creases 8 s apart: 18 polylines for 12 creases with them, 12 without). Where the
 *    trace points form no line while the
 *    normals around them show one crease direction (a strip of feature points over close parallel
 *    creases), only those whose score (the input's active scalars) reaches the median of the
 *    crease points within 2 s: the ridges of the score. Where the normals show one crease
 *    direction but the crease points moved by the detector's `CreaseOffset` (onto the line their
 *    voters agree on) form no line, the neighbourhood holds creases side by side: every crease
 *    point within FitRadius s of such a point is traced where it is moved to (parallel creases
 *    5 s apart: curve F1 0.42 -> 0.80). Where the moved points form one line, a strip is the wide
 *    band of one crease and keeps its ridges. Where they form two lines side by side (across
 *    their line, the best split into two groups leaves a gap wider than 2 sqrt(3) times the
 *    groups' spread, what splitting one even band leaves, and wider than 1.5 s; each group runs
 *    along the whole 1.5 FitRadius ball; and a quarter of the trace points around agree), as
 *    creases 3 s apart or a wall's rim face between its two edges do, the strip is traced on
 *    the moved points too, each trace on the points within half the median gap of its own line,
 *    and its vertices stay on that line (no cross-section fit, which holds both). Border points
 *    that carry a `CreaseOffset` (a wall's rim, typed border from either side's sheet) are moved
 *    as crease points are.
 *    From the most line-like trace point not yet covered, corners (FeatureType 3) aside, a
 *    trace steps StepLength s at a time along the
 *    line fitted (PCA) to the trace points within FitRadius s (1.5 FitRadius where that fit
 *    fails; at most the nearest 4 pi FitRadius^2 of them, four disks' worth at the mean spacing,
 *    where a dense cluster crowds the ball), each new vertex projected across
 *    onto that line: the vertices follow the middle of the band of feature points, not the noisy
 *    points themselves. A trace stops where no trace point lies ahead (an end), where the fit turns
 *    by more than 35 degrees in a step or stops being line-like (a corner, a junction), or where it
 *    comes within 1.5 s of a vertex of another trace (it joins it there: a junction, or the
 *    continuation of the same curve). Where the normals of all points within FitRadius show a
 *    crease (they vary in one plane: least along its normal, the crease's direction), a crease
 *    trace's fit must run within 30 degrees of that direction, and its seed too; where it does
 *    not (stray feature points beside the crease, or the band of a parallel crease nearby), the
 *    line is fitted again on the trace points within 4 band widths of the crease's line through
 *    the step (the band width: the median RMS distance of the trace points from their line fits).
 * 2. Joining. Ends within JoinDistance s of each other meet at the point nearest to the lines they
 *    point along (a corner, where three or more curves meet, or two borders at an angle; at the
 *    ends' mean where no feature point lies within 2 s of that point: ends that hook the same
 *    way put it outside the band), nearest
 *    pairs first and only where all the ends of a junction lie within JoinDistance of each other
 *    (a row of ends along two close creases is not one junction); two ends that point at each
 *    other are bridged (from up to twice that distance when they face each other within 30
 *    degrees, each end's direction taken over 2 FitRadius s back along its curve, the last
 *    quarter of that aside: a trace's last vertices hook towards the side of the band where its
 *    points run out); an end pointing at another curve within JoinDistance joins it. Crease ends
 *    whose lines run side by side (within 30 degrees) further apart than 4 band widths lie on
 *    two parallel creases: they are neither joined nor bridged here.
 *    Curves shorter than JoinDistance between two junctions (a corner traced round as well as
 *    along its edges) collapse into one corner.
 *    After cleaning (stage 3), the ends it freed are joined again in the same way, and gaps along
 *    a crease are bridged from any distance: two free ends that point at each other (within 30
 *    degrees, over 2 FitRadius s: on a shallow crease under noise the traced ends wander by more
 *    than 15; from the ends, or from where those directions start, as the last vertices hook;
 *    each end proposes its 3 nearest such ends) are joined when all the cloud's points
 *    bend across the gap's line: over the whole gap, the two faces hinged on it differ in slope
 *    by more than 3 standard errors, and by a crease's angle (10 degrees) or less than 3
 *    standard errors below it (from the faces' residuals: the cloud's own noise; measured on
 *    the points within 1.5 FitRadius s of the line, or, where that does not tell and each face
 *    stays one plane that far, within 3 FitRadius s, a third of the error: a 15 degree crease
 *    under noise of 0.5 s bends by less than 3 errors of the narrow section over a gap of 20 s),
 *    and no
 *    stretch of 2 FitRadius s along it looks flat (a bend nearer to none than to the gap's, and
 *    off the latter by more than 3 of its own errors, raised for the number of stretches
 *    tested: one in many looks flat by chance). The
 *    detector misses stretches of shallow creases; the cloud still shows them.
 *    Two free border ends that face each other within 30 degrees are joined where the cloud ends
 *    at the gap's line all along it: at every FitRadius s, the points within 2 FitRadius s lie on
 *    one side of the line in their tangent plane (the same side throughout), none beyond it by
 *    more than FitRadius s. Where the sampling recedes from an edge the detector finds no border
 *    point; the cloud still ends there. Conversely, a straight piece on its own or a straight branch
 *    (one end free or both, every vertex within 1 s of its chord, or at most 2 FitRadius s long
 *    along its path, whatever its wiggle; not on a border) is removed
 *    where the cloud does not
 *    bend across it: the two faces hinged on it differ by less than a crease's angle or 3
 *    standard errors, or one quadratic face explains the cross-section as well (the two faces
 *    leave no more than 2 noise variances less, Akaike's criterion): stray feature points on a
 *    smooth face, such as a cylinder's wall.
 * 3. Cleaning. Branches shorter than MinimumLength s that end freely (spurs), and pieces shorter
 *    than that, are removed, and pieces on their own shorter than 2 FitRadius s (no longer than
 *    one line fit's window); so are free branches shorter than 2 FitRadius s whose
 *    feature points are mostly (3 in 4) unsupported: scored below half the detector's threshold
 *    (the input's active scalars and its `FeatureThreshold` field; border points count as
 *    supported), points that a rule other than the vote marked (clean clouds' unexplained fits
 *    beside a crease). Curves are split where they turn by more than 45 degrees within about
 *    3 s (a corner that a trace went round), or within about 6 s where a point the detector
 *    typed corner (FeatureType 3) lies within 2 s (a trace rounds a corner over the corner's
 *    zone, where neither edge's fit holds), and a curve shorter than JoinDistance s left
 *    between two such splits (a rounded corner split at both of its turns) collapses into one
 *    corner; two curves that meet at a junction and go on within
 *    30 degrees of straight (over 2 FitRadius s) are one curve, the others there end on its vertex.
 * 4. Fitting. Each vertex is moved onto the feature as the cloud around it defines it: across a
 *    crease, to the intersection of the two faces' lines fitted to the cross-section of all points
 *    within 1.5 FitRadius s (and 0.75 FitRadius s along the curve), the faces told apart by their
 *    normals, then as k-means with lines, then as a hinge (each point to the face on its side of
 *    the bisector from the crease: the nearest-line split takes one face's noise for the other's
 *    and pulls the crease inside the bend); on a border, to the edge of the one face (the points' distribution across
 *    the edge tells where it lies). Then the vertices are smoothed along the curve (ends fixed) and
 *    fitted again over a longer stretch: the points within 2.5 FitRadius s along the smoothed
 *    curve, each taken in the cross-section of a quadratic (in arc length) fitted to the curve
 *    over twice that stretch, so that the points follow its bend; the fit gives the crease's
 *    offset from that quadratic. Where the input has the detector's `CreaseOffset` (its
 *    CreaseOffsets property; `featurepoints --lines` turns it on), each crease vertex then goes to
 *    the median, across the curve, of the crease points moved by it within the same slab
 *    (0.75 FitRadius s along the curve either side) and 2 s of the vertex, where at least 4 are:
 *    the median of many voters' lines places a crease better than one cross-section's fit (on
 *    the generated parts at sigma 0.5 s, the curves' mean distance to the true ones: median 0.33
 *    s before, 0.22 after; highest 0.50, then 0.32). Corners, borders and the curves' ends keep their fits. Smoothed
 *    again (ends fixed), the curves are resampled StepLength s apart.
 *
 * Output port 0: the input points (a vtkPolyData with vertex cells) with all point arrays and
 * `CurveId` (int): the curve of each feature point within 3 s of one (the nearest), -1 elsewhere.
 * Output port 1: the curves, one polyline cell each (a closed curve repeats its first point);
 * junctions are points shared by the curves that meet there. Cell arrays `CurveId` (0, 1, ...),
 * `FeatureType` (uint8, the majority type of its feature points among convex 1, concave 2 and
 * border 4), `CreaseAngle` (float, degrees, mean over its feature points) and `Length` (double);
 * point array `Tangent` (float, unit, along the curve's order).
 *
 * Errors: an input without `FeatureMask` is refused with one error line; points with a NaN or
 * infinite coordinate are ignored. The result depends on the points only, not on their order
 * (apart from exact ties) or the number of threads.
 *
 * @sa vtkCreaseVotingFeatures vtkFeatureModelSource
 */
#ifndef vtkFeatureCurveExtraction_h
#define vtkFeatureCurveExtraction_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class FEATUREPOINTSFILTERS_EXPORT vtkFeatureCurveExtraction : public vtkPolyDataAlgorithm
{
public:
  static vtkFeatureCurveExtraction* New();
  vtkTypeMacro(vtkFeatureCurveExtraction, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Radius of the local line fits and cross-sections, in mean spacings. Default 4. Where the
   * trace points are sparser (a one-point-wide mask: about one point in two spacings along a
   * crease), the radius in use grows to 1.5 times the median distance from a trace point to its
   * 4th nearest, so that a fit's ball holds about 6 of them.
   */
  vtkSetClampMacro(FitRadius, double, 1.0, 100.0);
  vtkGetMacro(FitRadius, double);
  ///@}

  ///@{
  /** Distance between consecutive vertices, in mean spacings. Default 1. */
  vtkSetClampMacro(StepLength, double, 0.25, 10.0);
  vtkGetMacro(StepLength, double);
  ///@}

  ///@{
  /** How far apart ends are joined or bridged, in mean spacings. Default 8. */
  vtkSetClampMacro(JoinDistance, double, 0.0, 1000.0);
  vtkGetMacro(JoinDistance, double);
  ///@}

  ///@{
  /** Spurs and pieces shorter than this, in mean spacings, are removed. Default 3. */
  vtkSetClampMacro(MinimumLength, double, 0.0, 1e6);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /** Figures of the last run: the mean spacing used, the number of curves and their length. */
  vtkGetMacro(MeanSpacing, double);
  vtkGetMacro(NumberOfCurves, vtkIdType);
  vtkGetMacro(TotalLength, double);
  ///@}

  /** The curves (output port 1). */
  vtkPolyData* GetCurves();

protected:
  vtkFeatureCurveExtraction();
  ~vtkFeatureCurveExtraction() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double FitRadius = 4.0;
  double StepLength = 1.0;
  double JoinDistance = 8.0;
  double MinimumLength = 3.0;

  double MeanSpacing = 0.0;
  vtkIdType NumberOfCurves = 0;
  double TotalLength = 0.0;

private:
  vtkFeatureCurveExtraction(const vtkFeatureCurveExtraction&) = delete;
  void operator=(const vtkFeatureCurveExtraction&) = delete;
};

#endif
