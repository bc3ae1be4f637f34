#include "MeshColors.h"

#include "MeshIO.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>

namespace colordecimation
{
namespace tools
{
namespace
{

double Clamp01(double x)
{
  return std::isfinite(x) ? std::min(1.0, std::max(0.0, x)) : 0.0;
}

unsigned char Byte(double unit)
{
  return static_cast<unsigned char>(std::lround(255.0 * Clamp01(unit)));
}

/// Alpha (the last of 2 or 4 components) is carried, not measured: unsigned char as it is,
/// other integer types from 0 to their largest value, floating-point types in [0,1].
unsigned char AlphaByte(vtkDataArray* colors, vtkIdType i)
{
  const double alpha = colors->GetComponent(i, colors->GetNumberOfComponents() - 1);
  const int type = colors->GetDataType();
  if (type == VTK_UNSIGNED_CHAR)
  {
    return static_cast<unsigned char>(alpha);
  }
  const bool real = type == VTK_FLOAT || type == VTK_DOUBLE;
  return Byte(real ? alpha : alpha / colors->GetDataTypeMax());
}
} // namespace

ColorMapping ColorMapping::Of(vtkDataArray* colors)
{
  ColorMapping mapping;
  if (!colors || colors->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    return mapping;
  }
  const int used = colors->GetNumberOfComponents() >= 3 ? 3 : 1;
  double lo = 0.0, hi = 0.0;
  for (int c = 0; c < used; ++c)
  {
    double range[2];
    colors->GetFiniteRange(range, c);
    lo = c == 0 ? range[0] : std::min(lo, range[0]);
    hi = c == 0 ? range[1] : std::max(hi, range[1]);
  }
  const bool unit = lo >= 0.0 && hi <= 1.0;
  mapping.Offset = unit ? 0.0 : lo;
  mapping.Scale = unit ? 1.0 : (hi > lo ? 1.0 / (hi - lo) : 0.0);
  return mapping;
}

void ColorMapping::ToRGB(vtkDataArray* colors, vtkIdType i, double rgb[3]) const
{
  const bool grey = colors->GetNumberOfComponents() < 3;
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = Clamp01((colors->GetComponent(i, grey ? 0 : c) - this->Offset) * this->Scale);
  }
}

vtkSmartPointer<vtkUnsignedCharArray> ToUnsignedChar(vtkDataArray* colors,
                                                     const ColorMapping& mapping, bool keepAlpha)
{
  const int given = colors->GetNumberOfComponents();
  const int components = keepAlpha && (given == 4 || given == 2) ? 4 : 3; // RGBA, grey + alpha
  auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
  bytes->SetName(components == 4 ? "RGBA" : "RGB");
  bytes->SetNumberOfComponents(components);
  bytes->SetNumberOfTuples(colors->GetNumberOfTuples());
  for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); ++i)
  {
    double rgb[3];
    mapping.ToRGB(colors, i, rgb);
    for (int c = 0; c < 3; ++c)
    {
      bytes->SetTypedComponent(i, c, Byte(rgb[c]));
    }
    if (components == 4)
    {
      bytes->SetTypedComponent(i, 3, AlphaByte(colors, i));
    }
  }
  return bytes;
}

bool TransferNearestColors(vtkPolyData* source, vtkPolyData* target, const std::string& colorArray)
{
  vtkDataArray* colors = source && target ? FindColorArray(source, colorArray) : nullptr;
  if (!colors || source->GetNumberOfPoints() == 0)
  {
    return false;
  }
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(source);
  locator->BuildLocator();
  vtkSmartPointer<vtkDataArray> nearest = vtk::TakeSmartPointer(colors->NewInstance());
  nearest->SetName(colors->GetName() ? colors->GetName() : "RGB");
  nearest->SetNumberOfComponents(colors->GetNumberOfComponents());
  nearest->SetNumberOfTuples(target->GetNumberOfPoints());
  for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
  {
    double p[3];
    target->GetPoint(i, p);
    nearest->SetTuple(i, locator->FindClosestPoint(p), colors);
  }
  target->GetPointData()->RemoveArray(nearest->GetName());
  target->GetPointData()->SetScalars(nearest);
  return true;
}

} // namespace tools
} // namespace colordecimation
