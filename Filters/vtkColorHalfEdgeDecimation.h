/*=========================================================================

  Program:   ColorDecimation (a VTK module)
  Module:    vtkColorHalfEdgeDecimation.h

  Distributed under the OSI-approved BSD 3-Clause License; see LICENSE.

=========================================================================*/
/**
 * @class   vtkColorHalfEdgeDecimation
 * @brief   reduce the number of triangles of a mesh with vertex colour, keeping shape and colour
 *
 * vtkColorHalfEdgeDecimation simplifies a triangle mesh by half-edge collapses: a vertex v0
 * is merged into a neighbour v1, which stays where it is with its own colour. Collapses are
 * done cheapest first. By default the cost is Hoppe's attribute quadric (the squared
 * distance to the input's triangles plus the squared difference from their colours,
 * area-weighted, at the kept vertex), with Garland and Heckbert's boundary planes holding
 * open boundaries in place, an edge-length term that decimates flat parts evenly, and the
 * Batched schedule on all cores: the setting that measured best on real scans
 * (docs/RESULTS.md). SetPaperDefaults() sets every property of the method to that of Kim, Choi and
 * Lee, "Mesh Simplification with Vertex Color": the cost (1 + quadric error) x (1 + visual
 * importance of v0) x (1 + colour error of the collapse) in the Greedy order. Costs are
 * measured in a frame where the mean edge length is 1, so that the result does not depend on
 * the mesh's units. ErrorMetric also offers the geometric quadric alone and Garland and
 * Heckbert's colour quadric in R^6 (with optional full collapses, OptimalPlacement), and
 * ColorSpace measures every colour term in CIELab instead of RGB.
 *
 * Because no vertex is ever moved or blended (except with the ColorQuadric metric's
 * OptimalPlacement, see there), every point-data array of the surviving points is copied
 * bit-exactly (colours, normals, texture coordinates, ids), and an array
 * (vtkOriginalPointIds by default) maps each output point to its input point (or, composed, to
 * the point an upstream vtkOriginalPointIds array names; see GenerateOriginalPointIds). Cell data
 * of the surviving triangles is copied too, and field data is passed.
 *
 * TargetReduction has the meaning it has in vtkQuadricDecimation: the fraction of the input
 * triangles to remove; TargetNumberOfTriangles, when set, asks for a triangle count instead.
 * ActualReduction reports what was achieved; it can fall short of the target when no valid
 * collapse is left, or when MaximumError stops the run first.
 *
 * Points can be locked: a point-data array selected with SetInputArrayToProcess(1, ...)
 * (none by default) keeps every point whose tuple has a non-zero component where it is,
 * with its triangles' corners (as ghost points are kept).
 *
 * The colour is the array selected with SetInputArrayToProcess(0, ...) (by default the
 * active point scalars): unsigned char RGB/RGBA (/255), float or double RGB (used as they are
 * in [0,1], otherwise scaled by the array's range), other numeric types (scaled by their
 * range), or a grey value (one component, or the first of two: grey and alpha). Alpha is
 * carried through but not measured. Without a colour array the filter decimates by geometry
 * alone (a warning only when an array selected by name is not there, not numeric, or cell or
 * field data rather than point data, or when an array is selected, by name or by attribute
 * type, from a place a vtkPolyData does not have: a graph's vertices or edges, a table's rows).
 *
 * Collapses keep the surface a 2-manifold where it was one (link condition), never flip a
 * triangle normal by more than MaximumNormalAngle, never create a degenerate triangle, and
 * keep the Euler characteristic of closed manifold input (unless a whole piece is removed:
 * see PieceWeight and PruneComponents). Triangles wound both ways are
 * decimated as their piece wound one way (see ConsistentOrientation). Vertices on non-manifold
 * edges, bow-tie vertices and the vertices of non-orientable places are kept, together with
 * their triangles. Attribute seams (open boundaries whose points have, bit for bit, the
 * positions of another boundary's, each side with its own point data, as OBJ and glTF
 * exporters write texture seams) are decimated closed: both sides collapse together and keep
 * their own point data (see PreserveSeams).
 *
 * Composite data (a vtkMultiBlockDataSet of meshes, ...): VTK's pipeline runs the filter on
 * each mesh, so both outputs are composites of the input's structure (the record's holds each
 * mesh's table, for vtkColorHalfEdgeLevelOfDetail), and the statistics (ActualReduction, ...)
 * are those of the last mesh (all 0 when the blocks present hold no mesh; a composite without
 * any block does not run the filter, and leaves them as they were). A block that is not a
 * vtkPolyData gives an empty block, with a warning.
 *
 * Distributed data: when the input is one piece of several (UPDATE_NUMBER_OF_PIECES > 1, as
 * in ParaView run with MPI), the filter asks upstream for one level of ghost cells. Ghost
 * cells are left out and every point they use is kept in place, as are ghost (duplicate)
 * points, so the decimated pieces still meet without cracks. When such a piece comes
 * without any ghost cell, the points it shares with other pieces are not known (ghost points
 * alone do not tell them); they lie on its open boundary, so the whole open boundary of the
 * piece is kept in place instead (genuine mesh boundaries of that piece are then kept as they
 * are).
 *
 * Input: polygons and triangle strips are triangulated (quietly: debug output); vertices and
 * lines are dropped (with a warning). Without point scalars the mesh is decimated by its
 * geometry (a warning only when the array selected is missing, not numeric, or not point
 * data). Triangles that barely share an edge (a triangle soup) cannot collapse: a warning
 * says to merge the points first. Empty input gives empty output. Points with NaN or infinite
 * coordinates, cell point ids out of range, or a colour array whose tuple count differs from
 * the number of points are errors: the output is then empty.
 *
 * Progress: after reading the input (5 %), the set-up's phases report a step each (to 22 %),
 * then the collapses. AbortExecute is read at each of those reports: during the set-up it
 * takes effect at the set-up's end (no collapse is made, the output is the input's
 * triangles), later between the collapse passes (Batched) or every 8,192 collapses (Greedy),
 * the output then being the mesh as far as it got.
 *
 * @sa
 * vtkColorHalfEdgeLevelOfDetail vtkQuadricDecimation vtkDecimatePro vtkQuadricClustering
 */
#ifndef vtkColorHalfEdgeDecimation_h
#define vtkColorHalfEdgeDecimation_h

#include "vtkColorDecimationModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkTable;
namespace colordecimation
{
struct DecimatorStatistics;
class PhaseTimes;
namespace adapter
{
struct InputMesh;
}
}

class VTKCOLORDECIMATION_EXPORT vtkColorHalfEdgeDecimation : public vtkPolyDataAlgorithm
{
public:
  static vtkColorHalfEdgeDecimation* New();
  vtkTypeMacro(vtkColorHalfEdgeDecimation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The cost that orders the collapses.
   * - AttributeQuadric (default): Hoppe's quadric for appearance attributes ("New quadric
   *   metric for simplifying meshes with appearance attributes", 1999): per triangle, its
   *   area times the squared distance to its plane plus the squared difference from its
   *   colour interpolated linearly, colour times ColorWeight, positions in mean-edge-length
   *   units; evaluated at the kept vertex (23 floats per vertex).
   * - HalfEdgeColor: the paper's (1 + Q)(1 + I)(1 + C).
   * - Geometry: the quadric error Q alone (colour ignored), for comparison.
   * - ColorQuadric: Garland and Heckbert's colour quadric (1998), the metric the paper
   *   compares against: every vertex is a point (x, y, z, r, g, b) of R^6 (geometry with
   *   the bounding box of the points the triangles use scaled into the unit cube, colour in
   *   [0,1] times ColorWeight) and holds the area-weighted sum of the squared distances to
   *   its triangles' planes in R^6 (28 floats per vertex, against the paper metric's 12).
   *   Half-edge collapses by default; full collapses with OptimalPlacement on.
   */
  enum ErrorMetrics
  {
    HalfEdgeColor = 0,
    Geometry = 1,
    ColorQuadric = 2,
    AttributeQuadric = 3
  };

  /**
   * Where colour differences are measured (every colour term of every metric).
   * - RGB (default): RGB in [0,1], as the paper's eq. 13.
   * - CIELab: the colours are taken as sRGB and measured in CIE L*a*b* (D65), divided by 100
   *   (so that a distance is the CIE76 difference dE / 100: black to white is 1).
   */
  enum ColorSpaces
  {
    RGB = 0,
    CIELab = 1
  };

  /**
   * Set every property of the method to the paper's (Kim, Choi and Lee): the HalfEdgeColor
   * metric, the Greedy schedule, no boundary planes (BoundaryWeight 0), no edge-length term,
   * GeometryWeight 1, RGB colours, MaximumNormalAngle 90, PreserveBoundary off (and
   * ColorWeight 1, SceneRelativeWeights off, OptimalPlacement off, KeptVertexErrorWeight 1,
   * which the paper's metric does not read; PieceWeight 0).
   * TargetReduction, TargetNumberOfTriangles, MaximumError, PruneComponents,
   * ConsistentOrientation, PreserveSeams, NumberOfThreads, the lock array, the original point
   * ids and GenerateCollapseRecord are left as they are.
   */
  void SetPaperDefaults();

  ///@{
  /**
   * Set/Get the error metric (see ErrorMetrics). Default AttributeQuadric.
   */
  vtkSetClampMacro(ErrorMetric, int, HalfEdgeColor, AttributeQuadric);
  vtkGetMacro(ErrorMetric, int);
  void SetErrorMetricToHalfEdgeColor() { this->SetErrorMetric(HalfEdgeColor); }
  void SetErrorMetricToGeometry() { this->SetErrorMetric(Geometry); }
  void SetErrorMetricToColorQuadric() { this->SetErrorMetric(ColorQuadric); }
  void SetErrorMetricToAttributeQuadric() { this->SetErrorMetric(AttributeQuadric); }
  const char* GetErrorMetricAsString();
  ///@}

  ///@{
  /**
   * Set/Get the colour space of the colour terms (see ColorSpaces). Default RGB.
   */
  vtkSetClampMacro(ColorSpace, int, RGB, CIELab);
  vtkGetMacro(ColorSpace, int);
  void SetColorSpaceToRGB() { this->SetColorSpace(RGB); }
  void SetColorSpaceToCIELab() { this->SetColorSpace(CIELab); }
  const char* GetColorSpaceAsString();
  ///@}

  ///@{
  /**
   * ColorQuadric only. When off (default), collapses are half-edge collapses, as with the
   * other metrics: v0 is merged into v1, which stays where it is with its own colour, at
   * the cost (Q0 + Q1)(x1). When on, they are full collapses: the surviving vertex moves to
   * the point of R^6 that minimises Q0 + Q1 (its new position and colour; the colour brought
   * back into [0,1], the better endpoint when the 6x6 system is singular). The rules against
   * flips and degenerate triangles hold for the new position too.
   *
   * With OptimalPlacement on, moved output points get their new coordinates and their new
   * colour, written in the colour array's own type and range (unsigned char: times 255,
   * rounded; other types through the inverse of the mapping to [0,1]; the alpha of RGBA is
   * copied); every other point-data array of a moved point is copied from the surviving
   * input vertex. "Colours carried exactly" then holds only for the points that did not
   * move.
   */
  vtkSetMacro(OptimalPlacement, vtkTypeBool);
  vtkGetMacro(OptimalPlacement, vtkTypeBool);
  vtkBooleanMacro(OptimalPlacement, vtkTypeBool);
  ///@}

  ///@{
  /**
   * AttributeQuadric and ColorQuadric: the weight of colour against geometry (colours are
   * multiplied by it). Default 1. AttributeQuadric: a colour difference of 1 / ColorWeight
   * weighs as much as a distance of one mean edge length (scaled up on finely sampled meshes:
   * SceneRelativeWeights). ColorQuadric: a unit of colour
   * weighs as much as the whole bounding box's largest side, as in Garland and Heckbert's
   * frame.
   */
  vtkSetClampMacro(ColorWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ColorWeight, double);
  ///@}

  ///@{
  /**
   * Set/Get the weight of boundary constraints (every metric): each open-boundary edge adds
   * to the quadric of its two vertices the plane through the edge perpendicular to its
   * triangle, weighted by BoundaryWeight times the edge's squared length in the metric's
   * frame (Garland and Heckbert's boundary preservation), so that collapses which pull a
   * boundary inwards or cut its corners cost more. Default 16; the AttributeQuadric metric
   * scales it up on finely sampled meshes (SceneRelativeWeights), the others use it as given.
   * 0: none, the paper's metric.
   */
  vtkSetClampMacro(BoundaryWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(BoundaryWeight, double);
  ///@}

  ///@{
  /**
   * Set/Get whether ColorWeight and BoundaryWeight are relative to the scene (AttributeQuadric
   * metric only). On, the default: they apply as given to a mesh whose bounding-box diagonal
   * (of the points its triangles use) is at most 270 mean edge lengths, and a mesh D mean edge
   * lengths across, D above 270, is decimated with ColorWeight times s and BoundaryWeight times
   * s^2, s = D / 270. A scene scanned twice as finely, decimated by the same fraction, then
   * trades colour, open boundaries and shape as it does on the screen, where a colour error or
   * a shifted border covers the same share of a render whatever the sampling
   * (docs/ALGORITHM.md section 12).
   * Off: the weights apply as given, in mean edge lengths. SetPaperDefaults turns it off.
   */
  vtkSetMacro(SceneRelativeWeights, vtkTypeBool);
  vtkGetMacro(SceneRelativeWeights, vtkTypeBool);
  vtkBooleanMacro(SceneRelativeWeights, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the weight of the edge-length term (HalfEdgeColor, Geometry, AttributeQuadric):
   * each triangle adds to its corners' quadrics EdgeLengthWeight times its area times the
   * squared distance from the corner. On flat parts, where the planes cost nothing, the
   * shortest collapses then go first and a vertex that absorbed others costs more to collapse,
   * so flat parts are decimated evenly instead of into fans of needles. Default 0.0001;
   * 0: none, the paper's metric.
   */
  vtkSetClampMacro(EdgeLengthWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EdgeLengthWeight, double);
  ///@}

  ///@{
  /**
   * Set/Get, for the AttributeQuadric metric, the weight in the cost of a collapse v0 -> v1 of
   * the error the kept vertex v1 holds already (what the collapses into it so far added). 0,
   * the default: the cost is the error the collapse adds, Q(v0)(x1), as in meshoptimizer, so
   * a vertex that absorbed a flat region can go on absorbing it, and the triangles saved go to
   * colour and shape detail. 1: Garland and Heckbert's total error (Q(v0) + Q(v1))(x1), which
   * spreads the collapses more evenly: better in colour on most of the smoothly coloured busts
   * of the project's study, worse in colour on the RGB-D kitchen scans (docs/RESULTS.md).
   * In [0, 1]; SetPaperDefaults sets 1.
   */
  vtkSetClampMacro(KeptVertexErrorWeight, double, 0.0, 1.0);
  vtkGetMacro(KeptVertexErrorWeight, double);
  ///@}

  ///@{
  /**
   * Set/Get the weight of removing small connected pieces whole (AttributeQuadric metric
   * only). The fragments of a scan stop collapsing at a few triangles each and would hold a
   * large share of a strongly reduced mesh. Each piece but the largest is given a cost: the
   * metric's cost of collapsing all its points into its best one, plus the area they would
   * move times the squared distance, times PieceWeight; during the
   * run a piece is removed when that cost is at most that of the collapses being made (and the
   * count is above the target: the last may take it below by its own triangles). Pieces with
   * a locked point (lock array, ghost points), an attribute seam or, with PreserveBoundary, an
   * open boundary are kept. The separate parts of a model made of several are pieces too: set
   * 0 to keep every part. Removed pieces count in NumberOfPrunedComponents, their error in
   * ActualError (see MaximumError: pieces beyond it are kept), and they are in the collapse
   * record. Default 10; 0: pieces are never removed during the run (the paper's
   * method).
   */
  vtkSetClampMacro(PieceWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PieceWeight, double);
  ///@}

  /**
   * The order of the collapses. Greedy: one at a time, always the cheapest valid
   * collapse of the whole mesh, as in the paper (and in vtkQuadricDecimation). Batched
   * (default): in passes; each takes the cheapest quarter of the vertices' chosen collapses and
   * makes them in cost order, skipping those whose cost a collapse earlier in the pass made stale,
   * then re-costs every affected vertex. The collapses of a pass run on NumberOfThreads threads, by
   * blocks of the mesh (those that reach across blocks afterwards), and so does the re-costing.
   * Same cost, same rules, so the same guarantees; faster on large meshes, and a result close to
   * Greedy's but not the same. It does not depend on NumberOfThreads.
   */
  enum CollapseSchedules
  {
    Greedy = 0,
    Batched = 1
  };

  ///@{
  /**
   * Set/Get the order of the collapses (see CollapseSchedules). Default Batched.
   */
  vtkSetClampMacro(CollapseSchedule, int, Greedy, Batched);
  vtkGetMacro(CollapseSchedule, int);
  void SetCollapseScheduleToGreedy() { this->SetCollapseSchedule(Greedy); }
  void SetCollapseScheduleToBatched() { this->SetCollapseSchedule(Batched); }
  const char* GetCollapseScheduleAsString();
  ///@}

  ///@{
  /**
   * Set/Get the number of threads of the parallel phases (set-up, costing, and with the
   * Batched schedule the collapses by blocks and the re-costing passes). 0 (default): as
   * many as vtkSMPTools runs (vtkSMPTools::GetEstimatedNumberOfThreads(), which obeys
   * VTK_SMP_MAX_THREADS and ParaView's thread settings). The output does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Set/Get the desired reduction: the fraction of the input triangles to remove, as in
   * vtkQuadricDecimation (0.9 leaves 10 % of the triangles). Default 0.9.
   */
  vtkSetClampMacro(TargetReduction, double, 0.0, 1.0);
  vtkGetMacro(TargetReduction, double);
  ///@}

  /**
   * The name of the point-data array that locks points, selected by name with
   * SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name); null when
   * none is selected (an empty name, or ParaView's "None", selects none).
   */
  const char* GetLockArrayName();

  ///@{
  /**
   * Set/Get the number of triangles to leave, instead of TargetReduction. 0 (default): use
   * TargetReduction. A count at or above the input's leaves the mesh as it is.
   */
  vtkSetClampMacro(TargetNumberOfTriangles, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfTriangles, vtkIdType);
  ///@}

  ///@{
  /**
   * Set/Get the largest geometric error a collapse may have, as a distance in the input's
   * units: the run stops before the first collapse whose error exceeds it (with the Batched
   * schedule: the pass that meets such a collapse is finished without it, and without any
   * other collapse beyond the bound, then the run stops). 0 or negative (default): no bound;
   * NaN or infinite: an error (empty output).
   *
   * The geometric error of a collapse of v0 into v1 is the area-weighted root-mean-square
   * distance from v1's position (its new one under OptimalPlacement) to the planes of the
   * input triangles that met at v1, at v0 and at every vertex merged into them before:
   * sqrt(sum_t A_t d_t^2 / sum_t A_t), each triangle counted once per such vertex it has
   * (Garland and Heckbert's quadric error divided by its area, in distance units). It does not
   * depend on ErrorMetric, which still orders the collapses. A piece removed whole (PieceWeight)
   * has the larger of that error for all its points merged into its best one and the
   * root-mean-square distance its area would move there; a piece beyond the bound is kept, and
   * the run goes on.
   */
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /**
   * Triangles wound both ways within a connected piece (merged scans, some exports) are
   * decimated as if the piece were wound one way: each piece is oriented as
   * vtkPolyDataNormals' consistency step would, keeping the winding of most of its triangles.
   * When off (default), each output triangle keeps its input triangle's winding; when on, it
   * is wound as its piece (consistent output). Only non-orientable places (a Moebius strip's
   * seam) stay locked.
   */
  vtkSetMacro(ConsistentOrientation, vtkTypeBool);
  vtkGetMacro(ConsistentOrientation, vtkTypeBool);
  vtkBooleanMacro(ConsistentOrientation, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Attribute seams: points at exactly (bit for bit) the same position as another boundary
   * point, each side with its own colour, texture coordinates or normal (a UV sphere's
   * meridian, a cube whose faces each have their own points and colour). When on (default),
   * the two sides of a seam collapse together, as one collapse on each side along the seam, so
   * that the output, welded by position, has no open edge the welded input did not have, and
   * each side keeps its own point data bit for bit; the cost of such a pair counts both sides.
   * Points where more than two sides meet (a cube's corners) are kept. When off, each side is
   * an open boundary of its own (decimation then opens cracks along seams). See
   * docs/ALGORITHM.md, section 15.
   */
  vtkSetMacro(PreserveSeams, vtkTypeBool);
  vtkGetMacro(PreserveSeams, vtkTypeBool);
  vtkBooleanMacro(PreserveSeams, vtkTypeBool);
  ///@}

  ///@{
  /**
   * When on, and collapses alone leave more triangles than the target, whole connected pieces
   * (triangles connected through shared points) are removed, smallest area first (ties: fewer
   * triangles first), until the target is met: the small fragments of a scan, each of which
   * collapses cannot take below a few triangles. Pieces with a locked point (lock array, ghost
   * points) are kept, and so is the last piece; non-manifold places do not keep a piece. Not
   * done after an abort, nor when MaximumError stopped the run. Off by default (as
   * meshoptimizer's SimplifyPrune), since it removes parts of the surface. PieceWeight removes
   * small pieces during the run already; this is for targets that collapses and PieceWeight
   * still cannot reach.
   */
  vtkSetMacro(PruneComponents, vtkTypeBool);
  vtkGetMacro(PruneComponents, vtkTypeBool);
  vtkBooleanMacro(PruneComponents, vtkTypeBool);
  ///@}

  /**
   * The number of connected pieces removed whole in the last execution (by PieceWeight during
   * the run, by PruneComponents after it).
   */
  vtkGetMacro(NumberOfPrunedComponents, vtkIdType);

  /**
   * The largest geometric error (see MaximumError) of the collapses and removed pieces of the
   * last execution, in the input's units. Only tracked under a bound or with
   * GenerateCollapseRecord: 0 otherwise (set MaximumError to VTK_DOUBLE_MAX to measure without a
   * bound).
   */
  vtkGetMacro(ActualError, double);

  ///@{
  /**
   * When on, the second output (port 1, a vtkTable) is the record of the collapses made, in
   * the order made: one row per collapse with RemovedPointId (v0) and SurvivingPointId (v1,
   * v0's parent in the vertex hierarchy), both input point ids, the Cost that ordered it, its
   * geometric Error (see MaximumError) and the NumberOfTriangles left after it; its field data
   * identifies the input (point and triangle counts and a checksum). Every prefix of the
   * record is a level of detail of the input, nested in the finer ones: set TargetReduction to
   * 1 to record down to the topological limit, then extract any level with
   * vtkColorHalfEdgeLevelOfDetail. With the Greedy schedule a level is exactly what a direct
   * run to that target gives (without PruneComponents: below). Off (default): the second
   * output is an empty table.
   *
   * Not with the ColorQuadric metric's OptimalPlacement (its collapses move the survivor): the
   * record is then empty, with a warning. The pieces PieceWeight removes are (a row for each
   * of their points, with SurvivingPointId -1); those PruneComponents removes are not in the
   * record, and the levels keep their triangles' input winding (ConsistentOrientation applies
   * to this filter's own output).
   */
  vtkSetMacro(GenerateCollapseRecord, vtkTypeBool);
  vtkGetMacro(GenerateCollapseRecord, vtkTypeBool);
  vtkBooleanMacro(GenerateCollapseRecord, vtkTypeBool);
  ///@}

  /**
   * The collapse record of the last execution (output port 1; see GenerateCollapseRecord).
   * Null for a composite input, whose record is a composite data set of the same structure:
   * GetOutputDataObject(1) returns it.
   */
  vtkTable* GetCollapseRecord();

  ///@{
  /**
   * When on, vertices on the mesh boundary are never removed, so open boundaries keep their
   * exact polyline. When off (default), a boundary vertex may still collapse, but only along
   * the boundary into a neighbouring boundary vertex.
   */
  vtkSetMacro(PreserveBoundary, vtkTypeBool);
  vtkGetMacro(PreserveBoundary, vtkTypeBool);
  vtkBooleanMacro(PreserveBoundary, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Set/Get the largest angle, in degrees, by which a collapse may turn the normal of a
   * surviving triangle (the flip guard). Default 90; 180 disables it (degenerate triangles
   * are refused whatever the angle).
   */
  vtkSetClampMacro(MaximumNormalAngle, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalAngle, double);
  ///@}

  ///@{
  /**
   * Set/Get the weight w of the geometric term (Q' = w Q, in mean-edge-length units).
   * Larger values favour shape over colour. Default 1.
   */
  vtkSetClampMacro(GeometryWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(GeometryWeight, double);
  ///@}

  ///@{
  /**
   * When on (default), the output gets a vtkIdTypeArray point-data array (named by
   * OriginalPointIdsArrayName, default "vtkOriginalPointIds"; an empty name writes that one,
   * with a warning) with each output point's id in the input. When the input already has a point
   * array of that name holding one integer id >= 0 per point (as vtkDataSetSurfaceFilter writes,
   * pointing into the data set it came from), the ids are composed: each output point gets its
   * input point's id from that array, so the link back to the original data set is kept. An input
   * array of that name of another kind is replaced, with a warning.
   */
  vtkSetMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkGetMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkBooleanMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkSetStringMacro(OriginalPointIdsArrayName);
  vtkGetStringMacro(OriginalPointIdsArrayName);
  ///@}

  /**
   * The reduction achieved by the last execution: 1 - output triangles / input triangles
   * (input triangles counted after triangulation of polygons and strips).
   */
  vtkGetMacro(ActualReduction, double);

  /**
   * The number of collapses done by the last execution.
   */
  vtkGetMacro(NumberOfCollapses, vtkIdType);

  /**
   * Bytes held by the decimation's own arrays in the last execution (connectivity, input
   * normals, the metric's per-vertex state, heap or keys, the maps back from the spatial order
   * of large meshes); input and output data sets not included.
   */
  vtkGetMacro(StateMemory, vtkIdType);

  /**
   * The most threads the last execution ran on at once. With NumberOfThreads 0 the filter
   * takes its thread count from vtkSMPTools (so VTK_SMP_MAX_THREADS and ParaView's thread
   * settings apply).
   */
  vtkGetMacro(NumberOfThreadsUsed, int);

  ///@{
  /**
   * The phase breakdown of the last execution: how many phases, and each one's name and
   * wall-clock seconds, in the order they ran. "input" (checks, points, triangles, colours),
   * the decimation's set-up ("spatial order", "connectivity", "frame", "reference normals",
   * "pieces", "metric state", "error planes"), "first costing", the schedule's steps ("collapses"
   * for Greedy; "batch selection", "block collapses", "deferred collapses", "re-costing" for
   * Batched, each summed over the passes), "restore order", "prune" (with PruneComponents)
   * and "output" (the output mesh and the collapse record). Together they cover the
   * execution but for bookkeeping between the filter and the decimation (microseconds). An
   * index out of range gives nullptr and 0.
   */
  int GetNumberOfPhases() const;
  const char* GetPhaseName(int index) const;
  double GetPhaseSeconds(int index) const;
  ///@}

  ///@{
  /**
   * The scale s the last run applied to ColorWeight (times s) and BoundaryWeight (times s^2)
   * under SceneRelativeWeights: D / 270 for a mesh whose bounding-box diagonal is D > 270 mean
   * edge lengths; 1 when the property is off, for metrics other than AttributeQuadric, and for
   * D <= 270.
   */
  vtkGetMacro(SceneWeightScale, double);
  ///@}

protected:
  vtkColorHalfEdgeDecimation();
  ~vtkColorHalfEdgeDecimation() override;

  /// The figures of the last execution back to 0 (ActualReduction, ActualError, ...).
  void ResetStatistics();
  /// The figures of a run into the statistics properties.
  void KeepStatistics(const colordecimation::DecimatorStatistics& stats);
  /// The array selected with SetInputArrayToProcess(index, ...) and its association; null
  /// when the input has none such, or the selection is from a place a vtkPolyData does not
  /// have (a graph's or a table's data, where VTK's own look-up reports an error).
  vtkDataArray* GetSelectedArray(int index, vtkInformationVector** inputVector, int& association);
  /// The colours (unless the metric is Geometry) and the locked points into `mesh`; false
  /// (with an error) for a bad array.
  bool ReadPointArrays(vtkInformationVector** inputVector, vtkPolyData* input, int threads,
                       colordecimation::adapter::InputMesh& mesh);

  /// RequestData's phases on a checked input: read, decimate, write the output.
  void Decimate(vtkInformationVector** inputVector, vtkInformationVector* outputVector,
                vtkPolyData* input, vtkPolyData* output);

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ErrorMetric;
  int CollapseSchedule;
  int NumberOfThreads;
  int ColorSpace;
  vtkTypeBool OptimalPlacement;
  double ColorWeight;
  double BoundaryWeight;
  vtkTypeBool SceneRelativeWeights;
  double EdgeLengthWeight;
  double KeptVertexErrorWeight;
  double PieceWeight;
  double TargetReduction;
  vtkIdType TargetNumberOfTriangles;
  double MaximumError;
  double ActualError;
  vtkTypeBool GenerateCollapseRecord;
  vtkTypeBool PruneComponents;
  vtkTypeBool ConsistentOrientation;
  vtkTypeBool PreserveSeams;
  vtkIdType NumberOfPrunedComponents;
  vtkTypeBool PreserveBoundary;
  double MaximumNormalAngle;
  double GeometryWeight;
  vtkTypeBool GenerateOriginalPointIds;
  char* OriginalPointIdsArrayName;
  double ActualReduction;
  vtkIdType NumberOfCollapses;
  vtkIdType StateMemory;
  int NumberOfThreadsUsed;
  double SceneWeightScale;

private:
  std::unique_ptr<colordecimation::PhaseTimes> Phases;

  vtkColorHalfEdgeDecimation(const vtkColorHalfEdgeDecimation&) = delete;
  void operator=(const vtkColorHalfEdgeDecimation&) = delete;
};

#endif
