/**
 * @file IndexedMesh.h
 * @brief A vtkPolyData as the flat arrays that simplifiers outside VTK take (meshoptimizer,
 * native and WebAssembly), and their kept triangles back as a vtkPolyData.
 */
#ifndef IndexedMesh_h
#define IndexedMesh_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <vector>

namespace colordecimation
{
namespace tools
{

/// Points as float x, y, z; triangles as three 32-bit point ids each.
struct IndexedMesh
{
  std::vector<float> Positions;
  std::vector<unsigned int> Indices;
};

/// The points of `mesh` copied to float and its triangles to 32-bit ids (what a VTK user
/// has to do before calling such a simplifier); cells other than triangles are left out.
IndexedMesh ToIndexedMesh(vtkPolyData* mesh);

/// The index count to aim at when `reduction` of `triangles` is to be removed, as
/// vtkQuadricDecimation's TargetReduction means it: 3 × the rounded number of triangles left.
size_t TargetIndexCount(size_t triangles, double reduction);

/// `triangles` (3 point ids of `mesh` each) as a vtkPolyData on the points they use, with
/// every point-data array of those points.
vtkSmartPointer<vtkPolyData> MeshOnKeptTriangles(vtkPolyData* mesh,
                                                 const std::vector<unsigned int>& triangles);

} // namespace tools
} // namespace colordecimation

#endif
