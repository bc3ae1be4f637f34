/**
 * @file ColorSpace.h
 * @brief The colour spaces in which the metrics measure colour: RGB as given, or CIELab.
 *
 * The decimation takes colours as RGB in [0,1] (docs/ALGORITHM.md, sections 2 and 8). With
 * ColorSpace::CIELab every colour term (the visual importance and the collapse colour error of the
 * half-edge metric, the colour part of the colour quadric) is measured on CIELab coordinates
 * instead:
 * - the [0,1] input is taken as sRGB (IEC 61966-2-1): linearised with the sRGB transfer
 *   curve, taken to CIE XYZ with the sRGB primaries and the D65 white point, then to
 *   CIE 1976 L*a*b* relative to D65 (Xn = 0.95047, Yn = 1, Zn = 1.08883);
 * - the metric's coordinates are L*, a*, b* divided by 100 (one common factor, so that
 *   the Euclidean distance is the CIE76 colour difference dE*ab / 100). L* / 100 lies in
 *   [0,1] and a* / 100, b* / 100 in about [-1.1, 1.0]: black to white is 1 (sqrt(3) in RGB),
 *   pure red to pure green 1.7 (sqrt(2) in RGB), so the colour terms stay of the size they
 *   have in RGB and the weights of eq. 17 (the 1 added to each factor, GeometryWeight) keep
 *   their meaning.
 */
#ifndef colordecimation_ColorSpace_h
#define colordecimation_ColorSpace_h

#include "vtkColorDecimationModule.h" // for export macro

namespace colordecimation
{

enum class ColorSpace
{
  RGB = 0,   ///< RGB in [0,1], as given (the paper's eq. 13)
  CIELab = 1 ///< CIELab (D65) divided by 100, see the file comment
};

/// sRGB in [0,1] (not clamped) to CIE XYZ (D65, Y of white = 1).
VTKCOLORDECIMATION_EXPORT void SRGBToXYZ(const double rgb[3], double xyz[3]);
/// CIE XYZ (D65) to sRGB (not clamped).
VTKCOLORDECIMATION_EXPORT void XYZToSRGB(const double xyz[3], double rgb[3]);

/// sRGB in [0,1] to CIE L*a*b* (D65): white is (100, 0, 0).
VTKCOLORDECIMATION_EXPORT void SRGBToLab(const double rgb[3], double lab[3]);
/// CIE L*a*b* (D65) to sRGB (not clamped: colours outside the sRGB gamut leave [0,1]).
VTKCOLORDECIMATION_EXPORT void LabToSRGB(const double lab[3], double rgb[3]);

/// RGB in [0,1] to the metric's coordinates of `space` (RGB: unchanged; CIELab: Lab / 100).
VTKCOLORDECIMATION_EXPORT void RGBToMetricColor(ColorSpace space, const double rgb[3],
                                                double out[3]);
/// The inverse of RGBToMetricColor (not clamped).
VTKCOLORDECIMATION_EXPORT void MetricColorToRGB(ColorSpace space, const double in[3],
                                                double rgb[3]);

/**
 * Bring a colour given in the metric's coordinates of `space` into the displayable range:
 * RGB is clamped to [0,1]; a CIELab colour is taken to sRGB, clamped to [0,1] and back.
 * Returns true when the colour changed.
 */
VTKCOLORDECIMATION_EXPORT bool ClampMetricColor(ColorSpace space, double color[3]);

/// "RGB" or "CIELab".
VTKCOLORDECIMATION_EXPORT const char* ColorSpaceName(ColorSpace space);

} // namespace colordecimation

#endif
