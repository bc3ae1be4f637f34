#include "QuadricPeer.h"

#include "vtkQuadricDecimation.h"

namespace colordecimation
{
namespace tools
{

void ConfigureQuadricPeer(vtkQuadricDecimation* filter, bool attributes)
{
  filter->SetAttributeErrorMetric(attributes);
  filter->SetScalarsAttribute(attributes);
  filter->SetVectorsAttribute(false);
  filter->SetNormalsAttribute(false);
  filter->SetTCoordsAttribute(false);
  filter->SetTensorsAttribute(false);
}

} // namespace tools
} // namespace colordecimation
