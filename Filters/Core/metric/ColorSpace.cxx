#include "metric/ColorSpace.h"

#include <algorithm>
#include <cmath>

namespace colordecimation
{
namespace
{
// sRGB primaries, D65 (IEC 61966-2-1), linear RGB -> XYZ.
constexpr double ToXYZ[3][3] = { { 0.4124564, 0.3575761, 0.1804375 },
                                 { 0.2126729, 0.7151522, 0.0721750 },
                                 { 0.0193339, 0.1191920, 0.9503041 } };
// D65 reference white.
constexpr double White[3] = { 0.95047, 1.0, 1.08883 };
constexpr double Delta = 6.0 / 29.0;

/// The exact inverse of ToXYZ (so that XYZ -> RGB -> XYZ round trips to rounding).
struct InverseMatrix
{
  double M[3][3];
  InverseMatrix()
  {
    const auto& a = ToXYZ;
    const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    this->M[0][0] = c00 / det;
    this->M[1][0] = c01 / det;
    this->M[2][0] = c02 / det;
    this->M[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    this->M[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    this->M[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    this->M[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    this->M[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    this->M[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
  }
};
const InverseMatrix& FromXYZ()
{
  static const InverseMatrix inverse;
  return inverse;
}

double Linearize(double c)
{
  const double s = std::abs(c);
  const double linear = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  return std::copysign(linear, c);
}

double Encode(double c)
{
  const double s = std::abs(c);
  const double encoded = s <= 0.0031308 ? 12.92 * s : 1.055 * std::pow(s, 1.0 / 2.4) - 0.055;
  return std::copysign(encoded, c);
}

double LabF(double t)
{
  return t > Delta * Delta * Delta ? std::cbrt(t) : t / (3.0 * Delta * Delta) + 4.0 / 29.0;
}

double LabFInverse(double t)
{
  return t > Delta ? t * t * t : 3.0 * Delta * Delta * (t - 4.0 / 29.0);
}
} // namespace

void SRGBToXYZ(const double rgb[3], double xyz[3])
{
  const double linear[3] = { Linearize(rgb[0]), Linearize(rgb[1]), Linearize(rgb[2]) };
  for (int i = 0; i < 3; ++i)
  {
    xyz[i] = ToXYZ[i][0] * linear[0] + ToXYZ[i][1] * linear[1] + ToXYZ[i][2] * linear[2];
  }
}

void XYZToSRGB(const double xyz[3], double rgb[3])
{
  const auto& m = FromXYZ().M;
  for (int i = 0; i < 3; ++i)
  {
    rgb[i] = Encode(m[i][0] * xyz[0] + m[i][1] * xyz[1] + m[i][2] * xyz[2]);
  }
}

void SRGBToLab(const double rgb[3], double lab[3])
{
  double xyz[3];
  SRGBToXYZ(rgb, xyz);
  const double fx = LabF(xyz[0] / White[0]);
  const double fy = LabF(xyz[1] / White[1]);
  const double fz = LabF(xyz[2] / White[2]);
  lab[0] = 116.0 * fy - 16.0;
  lab[1] = 500.0 * (fx - fy);
  lab[2] = 200.0 * (fy - fz);
}

void LabToSRGB(const double lab[3], double rgb[3])
{
  const double fy = (lab[0] + 16.0) / 116.0;
  const double fx = fy + lab[1] / 500.0;
  const double fz = fy - lab[2] / 200.0;
  const double xyz[3] = { White[0] * LabFInverse(fx), White[1] * LabFInverse(fy),
                          White[2] * LabFInverse(fz) };
  XYZToSRGB(xyz, rgb);
}

void RGBToMetricColor(ColorSpace space, const double rgb[3], double out[3])
{
  if (space == ColorSpace::CIELab)
  {
    SRGBToLab(rgb, out);
    for (int k = 0; k < 3; ++k)
    {
      out[k] /= 100.0;
    }
    return;
  }
  std::copy(rgb, rgb + 3, out);
}

void MetricColorToRGB(ColorSpace space, const double in[3], double rgb[3])
{
  if (space == ColorSpace::CIELab)
  {
    const double lab[3] = { 100.0 * in[0], 100.0 * in[1], 100.0 * in[2] };
    LabToSRGB(lab, rgb);
    return;
  }
  std::copy(in, in + 3, rgb);
}

bool ClampMetricColor(ColorSpace space, double color[3])
{
  double rgb[3];
  MetricColorToRGB(space, color, rgb);
  bool outside = false;
  for (double& c : rgb)
  {
    // Colours within rounding of the gamut (a CIELab round trip of an sRGB colour) are in.
    if (c < -1e-9 || c > 1.0 + 1e-9)
    {
      outside = true;
    }
    c = std::min(std::max(c, 0.0), 1.0);
  }
  if (outside)
  {
    RGBToMetricColor(space, rgb, color);
  }
  return outside;
}

const char* ColorSpaceName(ColorSpace space)
{
  return space == ColorSpace::CIELab ? "CIELab" : "RGB";
}

} // namespace colordecimation
