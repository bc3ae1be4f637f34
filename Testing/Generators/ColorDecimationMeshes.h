/**
 * @file ColorDecimationMeshes.h
 * @brief Coloured test meshes generated in code (no data files needed).
 *
 * Every mesh is a vtkPolyData of triangles with an unsigned char "RGB" point array set as
 * the active scalars. Shapes:
 * - Icosphere: closed, genus 0, valence 5/6 (subdivided icosahedron), radius 1;
 * - UVSphere: vtkSphereSource's latitude-longitude sphere (two high-valence poles; closed unless
 *   360 / r * r falls short of 360, as for r = 700: then a seam of near-coincident points),
 *   the benchmark's "coloured sphere", made here on all cores (the same points and triangles);
 * - Torus: closed, genus 1 (radii 1 and 0.35);
 * - Grid: an open, gently waved square sheet in [-1,1]^2 with one boundary loop;
 * - FlatGrid: the same sheet, flat (z = 0).
 * Colour patterns are functions of the position (so they are resolution-independent):
 * - SharpRegions: a few flat-coloured regions with sharp borders;
 * - SmoothGradient: a smooth colour ramp;
 * - FineDetail: thin stripes and letter-like strokes, fine colour detail;
 * - Constant: one colour everywhere.
 */
#ifndef ColorDecimationMeshes_h
#define ColorDecimationMeshes_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <vector>

namespace colordecimation
{
namespace meshes
{

enum class Pattern
{
  SharpRegions,
  SmoothGradient,
  FineDetail,
  Constant
};

/// Colour of a point (x, y, z) for a pattern, in 0..255.
void PatternColor(Pattern pattern, const double p[3], unsigned char rgb[3]);

/// (Re)colour every point of `mesh` with the pattern, as active "RGB" scalars.
void ApplyPattern(vtkPolyData* mesh, Pattern pattern);

/// 20 * 4^level triangles.
vtkSmartPointer<vtkPolyData> Icosphere(int level, Pattern pattern);
/// vtkSphereSource's sphere of theta and phi resolution `resolution`, bit for bit (made on all
/// cores; cells with 32-bit ids where they fit, unless `compactIds` is false): 2 r (r - 2)
/// triangles.
vtkSmartPointer<vtkPolyData> UVSphere(int resolution, Pattern pattern, bool compactIds = true);
/// 2 nu nv triangles.
vtkSmartPointer<vtkPolyData> Torus(int nu, int nv, Pattern pattern);
/// 2 nx ny triangles.
vtkSmartPointer<vtkPolyData> Grid(int nx, int ny, Pattern pattern);
/// Grid's points at z = 0 (every quadric of a flat mesh is singular), 2 nx ny triangles.
vtkSmartPointer<vtkPolyData> FlatGrid(int nx, int ny, Pattern pattern);

/**
 * A mesh without colours of the points `xyz` (3 coordinates each, double) and the triangles
 * `triangles` (3 point ids each), as the shapes above are made.
 */
vtkSmartPointer<vtkPolyData> FromTriangles(const std::vector<double>& xyz,
                                           const std::vector<vtkIdType>& triangles);

/**
 * A latitude-longitude sphere of `resolution` rows and columns (2 r (r - 1) triangles) whose
 * points along one meridian are duplicated, as OBJ and glTF exporters write a texture seam:
 * the first and the last column of points have bit-identical positions but their own
 * texture coordinates "TCoords" (u = 0 and u = 1) and colours (RGB, a function of u and v);
 * the poles are shared. Closed once welded by position; 2 (r - 1) twinned seam points.
 */
vtkSmartPointer<vtkPolyData> SeamSphere(int resolution);

/**
 * The cube [-1,1]^3, each face an n x n grid of quads (12 n^2 triangles) with its own points,
 * its own colour (RGB) and texture coordinates, as CAD exporters write hard colour seams:
 * points on the cube's edges are bit-identical to the neighbouring face's. Closed once
 * welded by position; 24 (n - 1) twinned seam points, 24 corner points of three faces.
 */
vtkSmartPointer<vtkPolyData> ColorCube(int n);

/// A UV sphere with about `triangles` triangles (for benchmarks at a given size).
vtkSmartPointer<vtkPolyData> UVSphereWithTriangles(long long triangles, Pattern pattern);

} // namespace meshes
} // namespace colordecimation

#endif
