/**
 * @file QuadricPeer.h
 * @brief vtkQuadricDecimation set up as the peer of every comparison in the tools.
 */
#ifndef ColorDecimationQuadricPeer_h
#define ColorDecimationQuadricPeer_h

class vtkQuadricDecimation;

namespace colordecimation
{
namespace tools
{

/**
 * With `attributes`, the attribute error metric on the colour (the active scalars) alone; without,
 * geometry only. Vectors, normals, texture coordinates and tensors never weigh in.
 */
void ConfigureQuadricPeer(vtkQuadricDecimation* filter, bool attributes);

} // namespace tools
} // namespace colordecimation

#endif
