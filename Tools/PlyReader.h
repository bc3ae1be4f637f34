/**
 * @file PlyReader.h
 * @brief A one-pass reader for the binary PLY files that scanners and the tools write most:
 * float x, y, z with, optionally, float nx, ny, nz and uchar red, green, blue[, alpha] per
 * vertex (other scalar properties, such as a scanner's confidence, skipped as vtkPLYReader
 * skips them), and one vertex_indices list per face. It gives the mesh vtkPLYReader gives
 * (float points, "RGB" or "RGBA" scalars, "Normals", the faces as polygons), which reads each
 * value through a callback and takes many times as long; every other file goes to
 * vtkPLYReader.
 */
#ifndef colordecimation_tools_PlyReader_h
#define colordecimation_tools_PlyReader_h

#include "PlyHeader.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>

namespace colordecimation
{
namespace tools
{

/**
 * Whether ReadSimplePly reads a file with this header: binary little-endian on a
 * little-endian machine; the elements "vertex" and then "face" and no other; the vertex's
 * properties x, y, z (float), nx, ny, nz (float, all three or none), red, green, blue (uchar,
 * all three or none), alpha (uchar, with the colours) and other scalar properties but those
 * vtkPLYReader reads as texture coordinates or diffuse colours, and no list; the face's one
 * property vertex_indices, a list of 32-bit integers with an unsigned 8-bit count.
 */
bool IsSimplePly(const PlyHeader& header);

/**
 * Read a file whose header passes IsSimplePly in one pass: the mesh vtkPLYReader gives (the
 * faces' connectivity with 32-bit ids where they fit). Null with `error` empty when the header
 * does not pass IsSimplePly, the file does not start with "ply" (vtkPLYReader's test), or it
 * ends before the elements its header announces (CheckPlyBody then says where); null with
 * `error` when there is no memory for its arrays.
 */
vtkSmartPointer<vtkPolyData> ReadSimplePly(const std::string& path, const PlyHeader& header,
                                           std::string& error);

} // namespace tools
} // namespace colordecimation

#endif
