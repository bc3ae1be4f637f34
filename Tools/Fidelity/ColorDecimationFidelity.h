/**
 * @file ColorDecimationFidelity.h
 * @brief Render-based fidelity measures between an original coloured mesh and a
 * simplified one: RMS of the per-pixel RGB distance and PSNR, over six axis views.
 *
 * Both meshes are rendered offscreen with the SAME orthographic camera, fitted to the
 * ORIGINAL's bounding box, from the six axis directions (+X, -X, +Y, -Y, +Z, -Z), in two
 * passes:
 * - unlit ("colour alone", the measure of Kim, Choi and Lee, Table 3): lighting off,
 *   ambient 1 / diffuse 0, the colour array mapped directly to RGB (colours interpolated
 *   across each triangle as OpenGL does);
 * - lit ("shape alone"): a uniform grey surface lit by the camera's headlight, flat
 *   shaded (point normals are dropped from both meshes so that neither gets smooth
 *   shading the other lacks).
 *
 * Pixels covered by either mesh count (coverage is found by a separate mask render); a
 * pixel covered by one mesh only is compared with the black background, so silhouette
 * changes count too. For each pass:
 * - RMS  = sqrt( sum over covered pixels of |rgb_o - rgb_s|^2 / covered ), 0-255 scale
 *   (|.| the Euclidean distance of the RGB triplets, as in the paper's Table 3);
 * - PSNR = 10 log10( 255^2 / MSE ), MSE = the per-channel mean squared error over the
 *   covered pixels = RMS^2 / 3 (the usual image PSNR, as in Yildiz et al.), in dB; it is
 *   +infinity when the images are identical (written as null in JSON).
 * The pooled figures sum the six views' pixels; per-view figures are kept as well. A
 * secondary RMS over the pixels covered by BOTH meshes ("common") separates the colour
 * error where the surfaces overlap from silhouette changes.
 *
 * Colours: the array named in Options::ColorArray, or else the active point scalars, or
 * else the first 3/4-component point array (cell arrays are used when no point array
 * fits). They are mapped to RGB by the tools' colour mapping (MeshColors.h, the filter's
 * own rule: unsigned char / 255, values in [0,1] as they are, otherwise the range stretched
 * to [0,1]), chosen on the ORIGINAL's array and applied to both meshes, then clamped and
 * rendered as bytes (times 255). A one-component array is grey. A mesh without colours
 * renders white in the unlit pass.
 *
 * Rendering needs an OpenGL context: on Linux a X display (run under `xvfb-run -a` on a
 * headless machine). CanRender() tells, without crashing, whether one is available.
 */
#ifndef ColorDecimationFidelity_h
#define ColorDecimationFidelity_h

#include "JsonOutput.h"
#include "MeshColors.h"

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkRenderWindow;

namespace colordecimation
{
namespace fidelity
{

/// The camera directions: the camera sits on the named side of the bounding box and looks
/// at its centre. Iso looks from the (+1, +1, +1) octant (snapshots only).
enum class View
{
  PlusX,
  MinusX,
  PlusY,
  MinusY,
  PlusZ,
  MinusZ,
  Iso
};

/// "+X", "-X", ..., "iso".
const char* ViewName(View view);
/// Parses a ViewName() (case-insensitive, "x" means "+X"); false when unknown.
bool ParseView(const std::string& text, View& view);

/// Options of CompareRenders().
struct Options
{
  /// Width and height, in pixels, of each of the six square views.
  int Size = 512;
  /// Compute the unlit (colour) pass.
  bool Unlit = true;
  /// Compute the lit (shape) pass.
  bool Lit = true;
  /// Colour array to use; empty: the active point scalars (see the file comment).
  std::string ColorArray;
  /// When not empty: an existing folder where every view's renders are written as PNG,
  /// `<pass>_<view>_original.png`, `..._simplified.png` and `..._difference.png` (the
  /// per-channel absolute difference times 5, as in Yildiz et al.'s figures), e.g.
  /// `unlit_+X_difference.png`.
  std::string ImageDirectory;
};

/// Figures of one view or of a pooled pass.
struct Measure
{
  std::string View;            ///< view name, or "all" for a pooled pass
  long long CoveredPixels = 0; ///< pixels covered by either mesh
  double SumSquared = 0.0;     ///< sum over covered pixels of |rgb_o - rgb_s|^2
  double Rms = 0.0;            ///< sqrt(SumSquared / CoveredPixels), 0-255
  double Psnr = 0.0;           ///< 10 log10(255^2 / (Rms^2 / 3)), dB; +inf when Rms == 0
  /// Pixels covered by both meshes, and the RMS over those alone: the colour error where
  /// the surfaces overlap, without the silhouette changes (a secondary figure).
  long long CommonPixels = 0;
  double CommonSumSquared = 0.0;
  double CommonRms = 0.0;
};

/// One pass (unlit or lit): pooled figures and the six views.
struct PassResult
{
  bool Computed = false;
  Measure All;
  std::vector<Measure> Views;
};

/// What CompareRenders() returns.
struct Result
{
  bool Ok = false;        ///< false when rendering was impossible (see Error)
  std::string Error;      ///< why, when !Ok
  int Size = 0;           ///< pixels per view side
  std::string ColorArray; ///< the colour array used ("" when the meshes have none)
  vtkIdType OriginalPoints = 0, OriginalTriangles = 0;
  vtkIdType SimplifiedPoints = 0, SimplifiedTriangles = 0;
  PassResult Unlit; ///< colour alone (the paper's Table 3 measure)
  PassResult Lit;   ///< shape alone
};

/**
 * Renders `original` and `simplified` from the six axis views with the original's camera
 * and measures their difference (see the file comment). Both inputs are left unchanged.
 */
Result CompareRenders(vtkPolyData* original, vtkPolyData* simplified, const Options& options = {});

/// The result as a JSON object (PSNR +inf is written as null).
tools::Json ResultJson(const Result& result);

/// ResultJson() as text, `indent` spaces per level.
std::string ToJson(const Result& result, int indent = 2);

/// Options of WriteSnapshot().
struct SnapshotOptions
{
  /// The view shown.
  View ViewDirection = View::Iso;
  /// Draw the labels (mesh, triangle count, pass).
  bool Labels = true;
  /// Colour array (as Options::ColorArray).
  std::string ColorArray;
  /// Label of the right-hand column; empty: "simplified".
  std::string SimplifiedLabel;
  /// Zoom factor (> 1 shows the centre of the view larger: a close-up).
  double Zoom = 1.0;
  /// Where the close-up is centred, in the unit square of the view (0.5, 0.5: the centre).
  double Center[2] = { 0.5, 0.5 };
};

/**
 * Writes a PNG of 2 x 2 panels of `size` x `size` pixels each: original (left) and
 * simplified (right); lit shape (top) and unlit colour (bottom); same camera everywhere,
 * fitted to the original's bounding box. Returns false (and says why in `error`) when the
 * image could not be rendered or written.
 */
bool WriteSnapshot(vtkPolyData* original, vtkPolyData* simplified, const std::string& path,
                   int size = 512, const SnapshotOptions& options = {},
                   std::string* error = nullptr);

/**
 * Places `camera` (made parallel-projection) for `view`, fitted to `bounds` (the
 * ORIGINAL's bounding box) with a 4 % margin, for a square viewport; sets a clipping range
 * that holds anything within 1.5 times the box's half-diagonal of its centre.
 */
void FitCamera(vtkCamera* camera, const double bounds[6], View view);

/// The nearest source point's colour for each target point (MeshColors.h, shared by the
/// tools).
using tools::TransferNearestColors;

/**
 * vtkQuadricDecimation as the peer of the comparisons, to `reduction`: with `attributes`, the
 * colour array as its only attribute (it interpolates colours); without, geometry only, then
 * the nearest original point's colour (TransferNearestColors).
 */
vtkSmartPointer<vtkPolyData> SimplifyWithQuadric(vtkPolyData* input, double reduction,
                                                 bool attributes,
                                                 const std::string& colorArray = std::string());

/**
 * Reads a mesh with the tools' reader (MeshIO.h: .ply, .vtp, .vtu, .vtk, .obj, .stl or a
 * demo: specification) and triangulates it. Returns null and says why in `error` on
 * failure or when it has no triangles.
 */
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string* error = nullptr);

/// Renders `window` and writes it as a PNG (RGB, from the back buffer); false when it cannot
/// be written.
bool SavePng(vtkRenderWindow* window, const std::string& path);

/**
 * True when an OpenGL render window can be opened here. On X11 builds this checks that
 * a display can be reached (VTK 9.1 aborts in XSync otherwise); `why` says what is
 * missing.
 */
bool CanRender(std::string* why = nullptr);

} // namespace fidelity
} // namespace colordecimation

#endif
