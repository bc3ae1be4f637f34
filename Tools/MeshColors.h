/**
 * @file MeshColors.h
 * @brief The tools' colours: the one mapping of a colour array to RGB in [0,1], bytes made
 * from it, and the nearest point's colour for meshes that lost theirs.
 *
 * The mapping is the filter's (vtkColorHalfEdgeDecimation; README, "Frame"): unsigned char
 * values divided by 255; values of other types as they are when every red, green and blue
 * value (the grey value of a one-component array) lies in [0,1], otherwise stretched from the
 * lowest to the highest of them to [0,1]. Only finite values set the range; NaN and infinite
 * values map to 0. The mapping is chosen on one array (for a comparison, the original's) and
 * may be applied to others (the simplified mesh's), which then are clamped to [0,1].
 */
#ifndef MeshColors_h
#define MeshColors_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <string>

class vtkDataArray;

namespace colordecimation
{
namespace tools
{

/// x -> (x - Offset) * Scale, then clamped to [0,1].
struct ColorMapping
{
  double Offset = 0.0;
  double Scale = 1.0 / 255.0;

  /// The mapping chosen on `colors` (see the file comment); unsigned char's when null.
  static ColorMapping Of(vtkDataArray* colors);

  /// Tuple `i` of `colors` as RGB in [0,1] (a one-component array gives grey).
  void ToRGB(vtkDataArray* colors, vtkIdType i, double rgb[3]) const;
};

/**
 * `colors` mapped by `mapping` to unsigned char RGB (each value times 255, rounded), or
 * RGBA when `keepAlpha` and `colors` has 4 components or 2 (grey and alpha). Alpha is not
 * mapped: unsigned char as it is, other integer types divided by their largest value,
 * floating-point types in [0,1], then times 255. Named "RGB" or "RGBA".
 */
vtkSmartPointer<vtkUnsignedCharArray> ToUnsignedChar(vtkDataArray* colors,
                                                     const ColorMapping& mapping, bool keepAlpha);

/**
 * Gives every point of `target` the colour of the nearest point of `source`
 * (vtkStaticPointLocator): that tuple of the source's colour array (the point array named
 * `colorArray`, or the active scalars when it is empty), of the same type and components and
 * under the same name, made the target's active scalars. For simplifiers that drop colour
 * (vtkQuadricDecimation without attributes). False when `source` has no points or no such
 * array.
 */
bool TransferNearestColors(vtkPolyData* source, vtkPolyData* target,
                           const std::string& colorArray = std::string());

} // namespace tools
} // namespace colordecimation

#endif
