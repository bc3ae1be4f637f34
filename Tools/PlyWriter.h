/**
 * @file PlyWriter.h
 * @brief A mesh written as binary little-endian PLY, in the layout of vtkPLYWriter's files,
 * block by block.
 *
 * vtkPLYWriter writes value by value through its generic property code and a process-wide
 * heap (one file at a time in a process), longer than extracting a level takes
 * (docs/BENCHMARK.md). This writes the same bytes from whole blocks: the
 * header vtkPLYWriter writes, then each vertex as x y z, nx ny nz (point normals), red green
 * blue [alpha] (point colours), u v (texture coordinates) and each polygon as a byte count,
 * 32-bit ids and red green blue [alpha] (face colours). It keeps what vtkPLYWriter drops:
 * normals (VTK 9.1's writes none; 9.2's only floats) and texture coordinates of any type are
 * written as floats. A polygon of more than 255 corners, whose count a byte cannot hold, is an
 * error. Vertices, lines and strips are not written (PLY's face element holds polygons; the
 * caller triangulates strips).
 */
#ifndef colordecimation_tools_PlyWriter_h
#define colordecimation_tools_PlyWriter_h

#include <string>

class vtkPolyData;
class vtkUnsignedCharArray;

namespace colordecimation
{
namespace tools
{

/**
 * Write `mesh`'s points and polygons to `path`, with `pointColors` (a tuple a point) and
 * `faceColors` (a tuple a polygon), each optional, of 3 or 4 components. False with `error`
 * (and no file left) when it cannot.
 */
bool WritePly(vtkPolyData* mesh, const std::string& path, vtkUnsignedCharArray* pointColors,
              vtkUnsignedCharArray* faceColors, std::string& error);

} // namespace tools
} // namespace colordecimation

#endif
