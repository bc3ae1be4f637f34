/**
 * @file ColorDecimationFuzz.h
 * @brief The body of the fuzz target: bytes -> a small vtkPolyData and filter settings ->
 * vtkColorHalfEdgeDecimation -> the output invariants (Testing/Utilities,
 * ColorDecimationInvariants.h).
 *
 * The same body is linked into the libFuzzer target (Clang builds with COLORDECIMATION_FUZZ)
 * and into ColorDecimationFuzzReplay, a plain executable that replays files (the committed
 * corpus and regressions) in every build.
 *
 * Byte layout (every read past the end gives 0, so any byte string is an input):
 * @verbatim
 *  0  options: bits 0-1 ErrorMetric (raw: 0 HalfEdgeColor, 1 Geometry, 2 ColorQuadric, 3 tests
 *     the clamp), 2 PreserveBoundary,
 *     3 GenerateOriginalPointIds off, 4 double points, 5 colour selected by name,
 *     6 extra point and cell arrays, 7 an input array named vtkOriginalPointIds
 *  1  more options: bit 0 cell ghost array, 1 point ghost array, 2 colour array gets no name,
 *     3 ColorSpace CIELab, 4 OptimalPlacement, 5-6 ColorWeight (1, 0, 1e-3, 1e3),
 *     7 CollapseSchedule Batched
 *  2  TargetReduction   (0..250 -> b/250; 251.. -> -1, 2, NaN, 1e-9, 1-1e-9)
 *  3  MaximumNormalAngle (0..250 -> 180 b/250; 251.. -> -10, 360, NaN, 1e-300, 180)
 *  4  GeometryWeight (table of 16 values incl. 0, tiny, huge, inf, NaN, negative)
 *  5  coordinate scale (table of 8 values: 1, 1e-7, 1e7, 1e-30, 1e30, ...)
 *  6  number of points (b % 251)
 *     points: 3 coordinate codes each: 0..223 -> (b - 112) / 16; 224..255 -> special values
 *     (NaN, +-inf, huge, tiny, denormal, -0, or the next 4 / 8 bytes as a raw float / double)
 *  *  number of triangles (2 bytes, little endian), then 3 point-id codes each:
 *     0..249 -> the id; 250.. -> -1, n, n + 1000, 2^31 - 1, 2^40, -2^40
 *  *  polygons: a count byte, then per polygon a size byte (% 9) and id codes
 *  *  strips: a count byte, then per strip a size byte (% 12) and id codes
 *  *  vertex cells: a count byte, then per cell a size byte (% 4) and id codes
 *  *  line cells: a count byte, then per cell a size byte (% 5) and id codes
 *  *  colour: type byte (% 16: the 13 numeric types char .. double, then vtkIdType,
 *     none, cell data), width byte (1 + b % 5 components; bit 7: raw values), tuple-count
 *     byte (% 8: 0-4 one per point, 5 one fewer, 6 one more, 7 none), then the values
 *     (raw: sizeof(T) bytes each; otherwise one byte each, /255 for floating types)
 *  *  ghost values: one byte per cell, then one per point (when enabled)
 *  *  controls: bits 0-2 MaximumError (0, 1e-9, 1e-3, 0.1, 10, NaN, -1, inf), 3-4
 *     TargetNumberOfTriangles (0, 1, 5, VTK_ID_MAX), 5-6 lock array (none; "Lock" locking every
 *     third point; a name the input lacks; "Lock" with half the tuples), 7 PruneComponents
 *  *  more controls: bit 0 ConsistentOrientation
 * @endverbatim
 *
 * With the environment variable COLORDECIMATION_FUZZ_CONSISTENT_ARRAYS set, the colour array
 * always has one tuple per point (the tuple-count byte is ignored): a way to keep fuzzing
 * past a known problem with short arrays instead of finding it again and again.
 */
#ifndef ColorDecimationFuzz_h
#define ColorDecimationFuzz_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace colordecimation
{
namespace fuzz
{

/// Silence VTK's output window (the filter's own messages go to an observer).
void Initialize();

/**
 * Build the input from `data`, run the filter (twice, to check that it is deterministic)
 * and check the invariants. Returns the broken invariants (empty when all hold).
 */
std::vector<std::string> RunOne(const uint8_t* data, size_t size);

} // namespace fuzz
} // namespace colordecimation

#endif
