/**
 * @class   vtkCreaseVotingFeatures
 * @brief   Feature points by two-plane crease fits and a neighbourhood vote: the project's
 *          default detector, built to work with default parameters on clouds nobody tuned for.
 *
 * The paper's F (vtkFeaturePointExtraction) ranks points well but gives no rule for where to cut,
 * and its scores spread over a band as wide as the neighbourhood. This filter asks a question
 * whose answer does not depend on the cloud's size, units, noise or sampling:
 * "does the neighbourhood of this point agree that a crease passes through it?"
 *
 * First the outliers (RemoveOutliers): a point that lies off the plane of its NormalNeighbors
 * nearest, or off that of its nearest point's, by more than 12 standard errors, or that is
 * isolated and held by no surface, is left out of everything below (see RemoveOutliers).
 *
 * For each point P_i and its k = NumberOfNeighbors nearest other points (with P_i itself, N = k + 1
 * points):
 *
 * 0. One sheet. Only the neighbours joined to P_i through links count, each point linked to its
 *    5 nearest (either way round): both sides of a wall about 5 spacings thick or more are then
 *    told apart (thin walls, shells, sheet metal). Where the 5 nearest lie on one line with the
 *    point (a cloud sampled in scan lines), it is also linked to its nearest off that line on
 *    either side, so that the rows form one sheet. N below is the number of such points; with
 *    fewer than 8, the whole neighbourhood is used, and so it is where one plane explains the
 *    whole neighbourhood within the noise (the bound of step 2b): the links then split it along
 *    a seam of the sampling, not between a wall's sides. Where one plane explains these points
 *    within the noise (the bound of step 2b), and one plane likewise explains those of each of
 *    its 40 nearest on the sheet, no feature is in view: the point gets that plane and no line
 *    (steps 1-3 are skipped). Where one of those 40 is not explained (a feature in view), the
 *    point gets the hinge of step 1 from its second start alone (the cut through the centroid):
 *    one sheet that one plane explains needs neither the crossing planes nor the sheets' split.
 * 1. Two-plane fit. The points are split in two by the direction in which their normals (PCA of
 *    the NormalNeighbors nearest, as Eq. 3 of the paper) vary most; then, as in k-means with
 *    planes, each side gets its least-squares plane and every point goes to the nearer plane,
 *    until the split no longer changes (at most 8 rounds). These are the "crossing" planes.
 *    Then the hinge, fitted on a split by position: each side of a line gets its plane, the
 *    line is refitted where the planes meet, and the points are split again by the bisector
 *    through it that separates the two faces (3 rounds), from two starts (the crossing planes'
 *    halves, and a cut through the centroid across the direction in which the normals vary);
 *    the lower residual wins. A hinge whose line passes outside the neighbourhood is none.
 *    The nearest-plane split fits noise (each point picks the plane nearer to it: two planes a
 *    noise width above and below a flat patch leave about a third of its residual, and a
 *    45-degree crease under noise hides in that); a split by position across the line gains
 *    only what a hinge gains by chance. The crossing planes count as a model only where they
 *    cross within the neighbourhood: each holds 5 % of the points on either side of the line
 *    farther than 3 sigma from the other plane. There (surfaces crossing), where the hinge
 *    leaves more than the noise explains, the crossing planes are kept instead. Where the
 *    crossing planes come out parallel and several noise widths apart (two sheets the links
 *    did not separate), the fit is redone on P_i's sheet. Where the heights along the plane
 *    fall in two groups far apart for their spread and lying over each other (a wall's two
 *    sides), the k-means starts from those groups: the normals do not vary across a wall. So it
 *    does where a few of the far side's points lie off to one side of the point (a wall about
 *    as thick as the links reach, seen at a smaller scale), when the heights across the plane
 *    of the point's group split so and the groups' planes are parallel and apart.
 * 2. Crease gain G_i = (RSS_Q - RSS_2) / sigma^2: how much better the two planes fit than one
 *    smooth quadric height field over the one-plane fit (RSS: sums of squared distances), in
 *    units of the cloud's noise variance sigma^2. A cylinder or a sphere is explained by the
 *    quadric however curved, a crease is not. sigma^2 comes from the residual per degree of
 *    freedom of the quadric through each point's NormalNeighbors nearest (curvature is
 *    explained at that scale): the median over the cloud, trimmed (the rows within the 95 %
 *    point of pure noise at the estimate, their median scaled to the whole law's, until it
 *    settles: features raise only the rows that see them), or where fewer than half of those
 *    neighbourhoods are free of features (details a few spacings apart) a lower quantile (1/4,
 *    1/10 or 1/20, the smallest estimate) scaled by the chi-square law of pure noise to the
 *    median it implies; never below (0.05 d)^2, d being the mean spacing. Where those nearest
 *    hold both sides of a wall thinner than them (the same test of heights, after a second
 *    split along the plane of the point's group), the quadric is fitted to the point's side,
 *    its residual scaled to the full neighbourhood's degrees of freedom: the wall's thickness
 *    is not noise. Where the noise is large for those nearest (18 sigma^2 above the squared
 *    radius r^2 of their tangent-plane footprint), nearest in space favour the neighbours near
 *    the point's height and their plane tilts into the noise (0.84 of the true sigma at 1.5
 *    spacings): sigma is then measured again on the NormalNeighbors nearest across the surface
 *    among enough nearest in space that none within r lies beyond 3 sqrt(2) sigma in height
 *    (at most NumberOfNeighbors), in the frame of their wider plane, from each new figure while
 *    that number grows (at most 3 searches).
 *    At the widest scale, where neither the quadric, the hinge nor the crossing planes explain
 *    the points within the noise, a cubic height field that does (within the bound of its 10
 *    parameters, fitted to at least 100 points) stands for the smooth surface: a free-form face
 *    whose curvature changes across the neighbourhood (a blend, a blade) is no crease. Not at the
 *    smaller scales of step 2b: a crease seen from a neighbourhood that small is explained by a
 *    cubic.
 * 2b. Scale per point (MultiScale). Where neither the quadric, the hinge nor the crossing planes
 *    explain the k nearest within the noise (a residual of at most dof + 3 sqrt(2 dof) times
 *    sigma^2 for dof degrees of freedom: two creases, a groove, a small face in view), the
 *    neighbourhood is halved (k/2, k/4, ..., and last 20 points) until one
 *    does; that point's fit and vote use that many neighbours. Where none does at any scale, the
 *    largest scale whose curved hinge explains them (each side of the hinge's line its own
 *    quadric, turning by at most a radian over the side's radius: a crease between curved
 *    faces, such as a cylinder's rim, which two planes fit only within the faces' curvature and
 *    never within a clean cloud's noise). Where nothing explains them at any scale, the
 *    smallest scale's fit and vote (the widest fit straddles features that the smallest at
 *    least separates; a vote counted over the widest neighbourhood is diluted by the members
 *    voting for the other features in it), and the point is a feature point (a corner, faces
 *    narrower than the smallest scale) unless the crossing planes fit it within the noise even
 *    where they do not cross.
 * 3. Crease line of the fit: the intersection of the two planes (when they are not parallel).
 * 4. Vote. A point j of P_i's neighbourhood (P_i included) votes for P_i when its two planes
 *    fit better than one (gain above 1), meet at MinimumAngle or more, and its crease line
 *    passes within sqrt((BandWidth d)^2 + (2 sigma)^2) of P_i: the band widened by the noise,
 *    which moves a point across the line as well (within 2 sigma in 86 % of draws under
 *    isotropic noise, 95 % under noise along the normals; on the generated parts at sigma =
 *    0.5 s, F1 median 0.977 -> 0.988, at 1.5 s the box 0.825 -> 0.888; on a clean cloud sigma
 *    is at its floor and the band is BandWidth d). On a cloud sampled in scan lines, within
 *    BandWidth times half the gap to the next row, where that is larger: a crease between two
 *    rows. The score
 *    `CreaseVotes` is the fraction of the N points that vote, counting only the points whose
 *    fit reaches P_i: a member fitted at a smaller scale (step 2c) whose fitted points all lie
 *    nearer to it than P_i does says nothing about P_i, and neither votes nor counts.
 * 5. A point is a feature point when a majority of its neighbourhood votes for it: score > 0.5
 *    (ThresholdMode ABSOLUTE, Threshold 0.5 by default).
 * 6. Hysteresis along the features: a point with more than GrowThreshold (0.3) of the votes
 *    above the cloud's median vote joins the feature points it is connected to through such
 *    points, which closes the gaps that noise leaves along shallow creases. The median is the
 *    background: about 0 on a part, higher on a strongly curved smooth shape, where every point
 *    collects a few votes.
 *
 * Why this holds up on unseen clouds: near a real crease every neighbour's fit finds the same
 * line, so the points within BandWidth of it collect votes from most of their neighbourhood,
 * whatever the crease angle; points further away collect few. On a smooth curved surface a
 * two-plane fit also gains, but each point's line passes through that point in its own direction,
 * so no point gathers a majority. On noise the lines fall anywhere. Everything is measured in
 * units of d and sigma, from the cloud itself: the result does not change when the cloud is
 * scaled or moved, and the neighbourhoods are counts, so denser and sparser regions are treated
 * alike. The fits keep squared lengths in float: a cloud whose extent lies beyond 2^-32 .. 2^32
 * units runs scaled by a power of two, as every detector's does (vtkFeaturePointDetector::
 * RequestData), CreaseOffset and GetNoiseSigma() scaled back: the same mask at any scale from
 * about 10^-289 to 10^298 (without it, 251 of 20,000 points changed at 2^140 and none was found
 * at 2^990).
 *
 * 7. Borders (Borders): a point whose 50 nearest on its sheet leave an empty sector above 120
 *    degrees in their tangent plane is on a border (sets of fewer than 25 connected such points,
 *    the rims of voids in the sampling, are dropped); the points within BandWidth d of it join.
 * 8. FeatureType: BORDER, else CONVEX or CONCAVE by the side of the line the fitted planes'
 *    centroids lie on, against the point's normal, oriented consistently: a minimum spanning
 *    tree over the NormalNeighbors nearest (weights 1 - |cos| of the normals' angle plus the
 *    step's sine out of the tangent plane; no step across a wall thinner than the neighbourhood,
 *    none between normals more than 60 degrees apart) carries each normal's side to the next.
 *    Across an acute crease the blended normals turn the wrong way, so a crease point whose
 *    fitted hinge holds (it votes, explains its points, and both half-planes reach the line)
 *    stands for the hinge: its two faces take one side, and its links give each neighbour's
 *    normal the side of its face. Each tree takes the side that encloses a positive volume with
 *    the bounding box's centre (outward on a closed surface; on an open sheet the side away
 *    from the centre's, a convention). The forest is Kruskal's in a strict order (weight, then
 *    the points' input order), so any thread or process count gives the same one. Then CORNER
 *    where the directions of the
 *    feature points around the point run more than one way. A crease point's direction is its
 *    crease line, where its fit explains its neighbourhood and votes; a border point's is along
 *    the border, in the tangent plane of its 50 nearest on the sheet (on a thin wall's rim the
 *    point's own normal is the rim face's, across the border). Around a corner not even the
 *    smallest scale's fit is explained (three faces), so the creases give no direction within
 *    about that scale's radius of it: the test takes the directions within twice that radius,
 *    and calls the point a corner when at least 6 of them leave more than 0.18 of the mean of
 *    t t^T off its main direction (1 minus its largest eigenvalue: 0.18 is reached by two
 *    curves at right angles sharing the directions 82:18, by three with 82 % on one, or by one
 *    curve bending by 42 degrees either way across the reach), and the point where their lines
 *    meet (least squares; a crease's line, the border through its outermost row) lies within
 *    the radius of its smallest scale: the directions spread wherever the reach holds two
 *    curves, as far along each curve as the reach; the corner is where they meet.
 * 9. ThinFeatures: the crease and corner points whose consensus distance to the crease, the
 *    median over the lines that vote for them (no single noisy fit places the line as well;
 *    only the lines whose fit explains its points, where any votes: a fit straddling two
 *    features, explained at no scale, puts its line between them) of the distance from the
 *    line along the nearer of its two half-planes (0 beyond the line;
 *    noise along a face's normal does not move a point across the face, where the straight
 *    distance to the line grows with it), is within half their local spacing, widened by the
 *    noise (a point at the crease pushed into the solid lies on a face, as far from the line as
 *    the noise moved it): sqrt((s/2)^2 + sigma^2), s = sqrt(pi r^2 / k) the spacing of a
 *    uniform sampling as dense as their NormalNeighbors nearest (r: the distance to the furthest
 *    of them), and whose vote reaches the level the hysteresis trusts (the median is a consensus
 *    only where enough lines vote; fewer mark the points the detail rule added, rough patches of
 *    unevenly noisy clouds). Then the gaps: such a point with no kept point among its 8 nearest
 *    is kept where its consensus distance is the least of theirs, within the standard error of
 *    its median (two creases closer than a fit tells apart put the consensus line between their
 *    rows, both as near as the voters can tell; noise pushes stretches of a row past the limit).
 *    Across each border the outermost.
 *
 * Output arrays: `CreaseVotes` (float, the score, 0-1), `CreaseGain` (float, G_i), `CreaseAngle`
 * (float, the angle between the two fitted planes in degrees, 0 when no line was found),
 * `Normals` (float, 3, the PCA normals of step 1, oriented as in step 8: outward on a closed part),
 * `FeatureType` (uint8, FeatureTypes) and `FeatureMask`. GetNoiseSigma() returns sigma, in the cloud's units.
 *
 * The work per point depends on that point only: the result is identical for any thread count.
 *
 * @sa vtkFeaturePointExtraction vtkFeaturePointDetector vtkPointCloudNeighborhoods
 */
#ifndef vtkCreaseVotingFeatures_h
#define vtkCreaseVotingFeatures_h

#include "FeaturePointsFiltersModule.h" // For export macro
#include "vtkFeaturePointDetector.h"

class FEATUREPOINTSFILTERS_EXPORT vtkCreaseVotingFeatures : public vtkFeaturePointDetector
{
public:
  static vtkCreaseVotingFeatures* New();
  vtkTypeMacro(vtkCreaseVotingFeatures, vtkFeaturePointDetector);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * k: the nearest other points of each two-plane fit and each vote. Default 150 (on a randomly
   * sampled surface, a disc of about 14 d radius). The wide vote is what tells a curved face
   * from a crease: a point's nearest neighbours always see a line near it, a majority of 150
   * only where the line runs on for the neighbourhood's width; and the wide fit reads a
   * 15-degree crease's angle and line through noise of half the spacing. Smaller values (60)
   * keep features closer together than the neighbourhood apart (small, detailed CAD parts such
   * as PCEDNet's ABC models) at the price of more false points on curved faces.
   */
  vtkSetClampMacro(NumberOfNeighbors, int, 8, 1000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  /** Values of the `FeatureType` point array. */
  enum FeatureTypes
  {
    NONE = 0,    ///< not a feature point
    CONVEX = 1,  ///< on a convex crease (the faces fall away from it, against the normal)
    CONCAVE = 2, ///< on a concave crease
    CORNER = 3,  ///< where three or more creases or borders meet
    BORDER = 4,  ///< on the border of an open surface or the rim of a wall thinner than the links
  };

  ///@{
  /**
   * Scale per point. Default on. Where the hinge of the NumberOfNeighbors nearest leaves more
   * than the noise explains (two creases, a groove, a small face in view),
   * the neighbourhood is halved until its hinge explains it, down to 20 points; that point's
   * fit and vote then use that many neighbours.
   */
  vtkSetMacro(MultiScale, bool);
  vtkGetMacro(MultiScale, bool);
  vtkBooleanMacro(MultiScale, bool);
  ///@}

  ///@{
  /**
   * Open borders as feature points (FeatureType BORDER). Default on. A point is on a border
   * when its 50 nearest on its sheet leave an empty sector of more than 120 degrees in their
   * tangent plane: a scan's edge, a hole, the edge of a sheet, the rim of a wall thinner than
   * the one-sheet links (both sides fold back on each other there).
   */
  vtkSetMacro(Borders, bool);
  vtkGetMacro(Borders, bool);
  vtkBooleanMacro(Borders, bool);
  ///@}

  ///@{
  /**
   * One point wide. Default off (the mask is a band about 2 BandWidth d wide). On: only the
   * crease and corner points within half a local spacing of the crease, widened by the noise (by
   * the median distance across the face from the lines that vote for them) are kept, and across each
   * border the outermost: the row of points nearest the edge, as labels that mark edges as
   * lines do (step 9 above).
   */
  vtkSetMacro(ThinFeatures, bool);
  vtkGetMacro(ThinFeatures, bool);
  vtkBooleanMacro(ThinFeatures, bool);
  ///@}

  ///@{
  /**
   * The point array `CreaseOffset` (float, 3 components): from each point to the crease line
   * its voters agree on (the component-wise median of its feet on the lines that vote for it),
   * zero where no line votes for it: a point plus its offset lies on the crease, not spread over
   * the band (on generated parts under noise of 0.5 spacings, a median 0.09-0.23 spacings from
   * the true curves where the points lie 1.2-1.4 from them). Not on parallel creases 3 spacings
   * apart: the lines of both vote and the median falls between them (5 apart: 0.30 spacings).
   * vtkFeatureCurveExtraction places its crease vertices with it where its input carries it
   * (`featurepoints --lines` turns it on). Default off (12 bytes a point; double, 24, for a cloud
   * run scaled, see the class description).
   */
  vtkSetMacro(CreaseOffsets, bool);
  vtkGetMacro(CreaseOffsets, bool);
  vtkBooleanMacro(CreaseOffsets, bool);
  ///@}

  ///@{
  /**
   * Copies scored as one point. Default on. Where at least 1 % of the points lie within 1 % of
   * the median distance to a point's 8th nearest of another point (exact copies; a scan merged
   * with a copy of itself moved by a rounding), the detector runs on the distinct positions and
   * each point takes its position's results: copies would otherwise fill the neighbourhoods (the
   * k nearest of a twice-sampled cloud are k / 2 positions) and near copies would set the mean
   * spacing to their distance. Fewer copies are scored as they are. Distributed runs score every
   * point as it is (as with this off): the positions of a piece's halo would have to agree with
   * their owners'.
   */
  vtkSetMacro(MergeCopies, bool);
  vtkGetMacro(MergeCopies, bool);
  vtkBooleanMacro(MergeCopies, bool);
  ///@}

  ///@{
  /**
   * Outliers left out. Default on. A point is an outlier (a spike of a scan, a stray point above
   * a face, returns from the air) where it lies off the least-squares plane of its
   * NormalNeighbors nearest (each position once) by more than 12 standard errors; or off the
   * plane of its nearest point's nearest by as much (a stray point above a face near an edge
   * has the edge among its own nearest); or where it is isolated (its distance to the nearest
   * other position beyond Tukey's far fence of the cloud's, in logarithms) and no surface holds
   * it (its nearest are no surface, or it lies beyond its nearest point's nearest). The
   * standard error is the others' RMS distance from their plane, at least 0.05 mean spacings
   * (a quarter spacing over the nearest point's plane where the point lies on its own nearest's
   * plane: it may lie just across a crease from them), widened as a regression's prediction
   * interval is for a point away from their centroid. Under Gaussian noise, Student's t with
   * the 12 degrees of freedom of 15 points less the plane's 3 exceeds 12 once in 20 million.
   * Points beside a crease or a corner are not outliers: their nearest do not lie on one plane,
   * so the error is large. An outlier gets 0 in every output array (a zero normal, FeatureMask
   * 0, FeatureType 0) and the detector runs on the other points; where that run finds outliers
   * among them (outliers close together hide each other), it runs again on what is left, at
   * most 3 runs in all. Distributed runs keep every point (as with this off).
   */
  vtkSetMacro(RemoveOutliers, bool);
  vtkGetMacro(RemoveOutliers, bool);
  vtkBooleanMacro(RemoveOutliers, bool);
  ///@}

  /** The outliers the last run left out (see RemoveOutliers). */
  vtkGetMacro(NumberOfOutliers, vtkIdType);

  ///@{
  /** k of the PCA normals that seed the two-plane split. Default 15. */
  vtkSetClampMacro(NormalNeighbors, int, 3, 1000);
  vtkGetMacro(NormalNeighbors, int);
  ///@}

  ///@{
  /**
   * How far from a fitted crease line (or from a border's outermost row) a point still counts as
   * on it, in mean spacings d. Default 2: the project's feature points are those within 2 s of a
   * feature curve. Around a crease line the band is widened by the cloud's noise, in quadrature:
   * sqrt((BandWidth d)^2 + (2 sigma)^2) (step 4). Labels that mark only the row of points nearest
   * the edge (PCEDNet's) call for ThinFeatures.
   */
  vtkSetClampMacro(BandWidth, double, 0.01, 1000.0);
  vtkGetMacro(BandWidth, double);
  ///@}

  ///@{
  /**
   * The smallest bend, in degrees, that counts as a crease: a fit whose two planes meet at a
   * smaller angle casts no vote. Default 12, below the 15 degrees of the shallowest creases this
   * project is judged on; a smooth surface whose curvature radius is well above the
   * neighbourhood's radius bends less than this across one neighbourhood.
   */
  vtkSetClampMacro(MinimumAngle, double, 0.0, 90.0);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /**
   * Hysteresis: a point whose vote fraction exceeds GrowThreshold plus the cloud's median vote
   * is a feature point too when it is connected to a feature point through such points (each
   * point linked to its 8 nearest). Default 0.3. A value at or above the threshold turns the
   * step off.
   */
  vtkSetClampMacro(GrowThreshold, double, 0.0, 1.0);
  vtkGetMacro(GrowThreshold, double);
  ///@}

  /**
   * The growth threshold of the last run: GrowThreshold plus the cloud's median vote. The step
   * ran when this is below GetThresholdUsed().
   */
  vtkGetMacro(GrowThresholdUsed, double);

  /** sigma of the last run, in the cloud's units (see the class comment). */
  vtkGetMacro(NoiseSigma, double);

  /**
   * Distributed runs: the k nearest (the widest of NumberOfNeighbors and NormalNeighbors) over 2
   * generations: a point's fit reads its neighbours' normals and their one-sheet links. What a
   * point reads of its neighbours' own results (whether one plane explains their sheets, their
   * models for the vote, their directions for the corner test, votes, mask, borders, types) is
   * taken from the processes that own them, and the stages that spread across the cloud
   * (hysteresis growth, border components) exchange the halo's values until no process changes.
   */
  bool GetHaloExtent(int& neighbors, int& levels) const override
  {
    neighbors = this->NumberOfNeighbors > this->NormalNeighbors ? this->NumberOfNeighbors
                                                                 : this->NormalNeighbors;
    levels = 2;
    return true;
  }

  /** The score array: "CreaseVotes". ABSOLUTE thresholds are on the vote fraction (default 0.5). */
  const char* GetScoreArrayName() const override { return "CreaseVotes"; }

protected:
  void ListParameters(std::vector<std::pair<const char*, double>>& parameters) const override;
  vtkCreaseVotingFeatures();
  ~vtkCreaseVotingFeatures() override;

  int Run(vtkPointSet* input, vtkPolyData* output) override;
  int GetLengthPower(const char* name) const override; // CreaseOffset: 1
  void ScaleFiguresBack(int exponent) override;        // the noise figure

  /** The detector's steps on `input` (Run()'s work; again on distinct positions or a subset). */
  int Detect(vtkPointSet* input, vtkPolyData* output);

  /**
   * Where points share positions (see FindSites(): `site` maps each input point to one of
   * `sites` distinct positions), the detector's steps on the distinct positions, each point then
   * taking its position's results: copies would otherwise fill the neighbourhoods (k nearest of
   * twice-sampled points are k / 2 positions), and near copies would set the mean spacing to
   * their distance. The output is the input's points, as always.
   */
  int DetectOnSites(vtkPointSet* input, vtkPolyData* output, const std::vector<vtkIdType>& site,
    vtkIdType sites, double tolerance);
  bool OnSites = false;

  /**
   * The outliers (see RemoveOutliers) among the rows `ids` of the k-nearest table `row` (as
   * FindSites() reads it). Where there are any, fills `site` (input point id -> index among the
   * kept points, in input order; -1 for an outlier or an invalid point) and returns the number of
   * points kept; otherwise returns 0 and leaves `site` empty.
   */
  vtkIdType FindOutliers(vtkPointCloudNeighborhoods* neighborhoods,
    const std::vector<vtkIdType>& ids, int width,
    const std::function<const int32_t*(vtkIdType, int32_t*, int)>& row,
    std::vector<vtkIdType>& site, std::vector<unsigned char>& state);

  /**
   * The detector's steps on the `sites` points that `site` maps the input's points to (see
   * DetectOnSites()), each input point then taking its site's results, 0 where it has none.
   * `state` (by input point, optional) says which of the points without a site are outliers.
   */
  int DetectOnSubset(vtkPointSet* input, vtkPolyData* output, const std::vector<vtkIdType>& site,
    vtkIdType sites, const std::vector<unsigned char>* state = nullptr);
  int OutlierRuns = 0; // the runs on kept points that enclose the current one
  vtkIdType NumberOfOutliers = 0;
  // After Detect(): by input point, whether it was scored (empty: every valid point was).
  enum ScoreState : unsigned char
  {
    UNSCORED = 0, // an invalid point
    SCORED = 1,
    OUTLIER = 2
  };
  std::vector<unsigned char> Scored;

  int NumberOfNeighbors = 150;
  int NormalNeighbors = 15;
  double BandWidth = 2.0;
  double GrowThreshold = 0.3;
  double MinimumAngle = 12.0;
  bool MultiScale = true;
  bool Borders = true;
  bool ThinFeatures = false;
  bool CreaseOffsets = false;
  bool MergeCopies = true;
  bool RemoveOutliers = true;
  double NoiseSigma = 0.0;
  double GrowThresholdUsed = 0.0;

private:
  vtkCreaseVotingFeatures(const vtkCreaseVotingFeatures&) = delete;
  void operator=(const vtkCreaseVotingFeatures&) = delete;
};

#endif
