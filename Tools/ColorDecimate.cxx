/**
 * @file ColorDecimate.cxx
 * @brief color-decimate: decimate a coloured triangle mesh from the command line with
 * vtkColorHalfEdgeDecimation.
 *
 * Run `color-decimate --help` for the options. Exit status: 0 on success, 1 when a file
 * cannot be read or written or the filter fails, 2 on bad options.
 */
#include "CommandLine.h"
#include "JsonOutput.h"
#include "MeshIO.h"
#include "ProcessMemory.h"
#include "RecordIO.h"

#include "ColorDecimationFidelity.h"
#include "SmpBackend.h"
#include "vtkColorHalfEdgeDecimation.h"
#include "vtkColorHalfEdgeLevelOfDetail.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using namespace colordecimation::tools;

const char* const Program = "color-decimate";

/// A filter property set from the command line (after --paper, in the order given).
using FilterSetting = std::function<void(vtkColorHalfEdgeDecimation*)>;

struct Options
{
  std::string Input;
  std::string Output;
  bool Demo = false;
  bool Paper = false;
  std::vector<FilterSetting> Settings;
  std::string Array;
  std::string LockArray;
  std::string Stats;
  std::string Snapshot;
  int SnapshotSize = 512;
  std::string WriteInput;
  bool Quiet = false;
  std::vector<double> Levels; ///< --lod: the reductions, in the order given
  std::string SaveRecord;
  std::string FromRecord;
  /// --max-error P%: P percent of the input's bounding-box diagonal, set once it is read (-1:
  /// a distance, or none).
  double MaximumErrorPercent = -1;
  bool ReductionGiven = false;    ///< --reduction on the command line
  std::string MethodOptionsGiven; ///< those of MethodOptions on the command line, for messages
  /// Set once the input is read: its colour array's mapping to bytes, for every PLY file
  /// written (each file's own range would give the same point other bytes in each).
  ColorMapping PlyColors;
};

const char* MetricName(int metric)
{
  switch (metric)
  {
    case vtkColorHalfEdgeDecimation::HalfEdgeColor:
      return "half-edge-color";
    case vtkColorHalfEdgeDecimation::Geometry:
      return "geometry";
    case vtkColorHalfEdgeDecimation::ColorQuadric:
      return "color-quadric";
    default:
      return "attribute-quadric";
  }
}

const char* ScheduleName(int schedule)
{
  return schedule == vtkColorHalfEdgeDecimation::Batched ? "batched" : "greedy";
}

/// A filter at its defaults, for the defaults the help states.
vtkColorHalfEdgeDecimation* Defaults()
{
  static vtkNew<vtkColorHalfEdgeDecimation> defaults;
  return defaults;
}

std::string Number(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/// --NAME X: a filter property from lo to hi, set with `set`.
CLI::Option* AddFilterNumber(CLI::App& app, Options& options, const std::string& name, double lo,
                             double hi, void (vtkColorHalfEdgeDecimation::*set)(double),
                             const std::string& rule, const std::string& help)
{
  return AddValue(
    app, name,
    [&options, lo, hi, set](const std::string& text)
    {
      double value = 0;
      if (!ParseNumber(text, value) || value < lo || value > hi)
      {
        return false;
      }
      options.Settings.push_back([set, value](vtkColorHalfEdgeDecimation* f) { (f->*set)(value); });
      return true;
    },
    RuleComplaint(rule), help);
}

/// --NAME NAME: a point array's name (not empty) into `name`.
void AddArrayName(CLI::App& app, const std::string& option, std::string& name,
                  const std::string& help)
{
  AddValue(
    app, option,
    [&name](const std::string& text)
    {
      name = text;
      return !text.empty();
    },
    FixedComplaint(option + " needs a non-empty array name"), help)
    ->type_name("NAME");
}

/// --NAME N: a whole number from 0 to hi, given to the filter with `set`.
template <typename Count>
CLI::Option* AddFilterCount(CLI::App& app, Options& options, const std::string& name, double hi,
                            void (vtkColorHalfEdgeDecimation::*set)(Count), const std::string& rule,
                            const std::string& help)
{
  return AddValue(
           app, name,
           [&options, hi, set](const std::string& text)
           {
             double count = 0;
             if (!ParseNumber(text, count) || count < 0 || count > hi || count != std::floor(count))
             {
               return false;
             }
             const auto value = static_cast<Count>(count);
             options.Settings.push_back([set, value](vtkColorHalfEdgeDecimation* f)
                                        { (f->*set)(value); });
             return true;
           },
           RuleComplaint(rule), help)
    ->type_name("N");
}

/// --NAME W: a weight of the cost (a number >= 0), set with `set`.
CLI::Option* AddFilterWeight(CLI::App& app, Options& options, const std::string& name,
                             void (vtkColorHalfEdgeDecimation::*set)(double),
                             const std::string& help)
{
  return AddFilterNumber(app, options, name, 0, std::numeric_limits<double>::infinity(), set,
                         name + " must be a number >= 0", help)
    ->type_name("W");
}

/// --NAME WORD: a filter property given by name, set with `set`.
CLI::Option* AddFilterChoice(CLI::App& app, Options& options, const std::string& name,
                             std::vector<std::pair<std::string, int>> choices,
                             void (vtkColorHalfEdgeDecimation::*set)(int), const std::string& rule,
                             const std::string& help)
{
  return AddValue(
    app, name,
    [&options, choices, set](const std::string& text)
    {
      for (const auto& choice : choices)
      {
        if (choice.first == text)
        {
          const int value = choice.second;
          options.Settings.push_back([set, value](vtkColorHalfEdgeDecimation* f)
                                     { (f->*set)(value); });
          return true;
        }
      }
      return false;
    },
    RuleComplaint(rule), help);
}

/// --NAME: a switch of the filter, set with `set`.
void AddFilterFlag(CLI::App& app, Options& options, const std::string& name,
                   void (vtkColorHalfEdgeDecimation::*set)(vtkTypeBool), vtkTypeBool value,
                   const std::string& help)
{
  app.add_flag_callback(
    name,
    [&options, set, value]() {
      options.Settings.push_back([set, value](vtkColorHalfEdgeDecimation* f) { (f->*set)(value); });
    },
    help);
}

/// INPUT, OUTPUT and --demo.
void AddInputOptions(CLI::App& app, Options& options)
{
  app
    .add_option("INPUT", options.Input,
                "a .ply, .vtp, .vtu, .vtk (legacy; non-polygonal data sets are\n"
                "reduced to their surface), .obj or .stl file, or a mesh generated\n"
                "in code: --demo, demo: or demo:SHAPE[:PATTERN] (see below)")
    ->type_name("");
  app
    .add_option("OUTPUT", options.Output,
                "a .ply (binary, float coordinates as VTK writes them, so double-\n"
                "precision points are rounded; colours as uchar red/green/blue[/alpha]),\n"
                ".vtp (binary, with every point array, including vtkOriginalPointIds) or\n"
                ".vtk (legacy binary) file")
    ->type_name("");
  app.add_flag("--demo", options.Demo, "INPUT is the built-in demo mesh (the same as demo:)");
}

/// The filter's settings: which cost, and its weights.
void AddMetricOptions(CLI::App& app, Options& options)
{
  vtkColorHalfEdgeDecimation* d = Defaults();
  using F = vtkColorHalfEdgeDecimation;
  app.add_flag("--paper", options.Paper,
               "the paper's method: every setting below at the paper's value\n"
               "(half-edge-color, greedy, no boundary or edge-length term, no piece\n"
               "removal, RGB, weights not scene-relative);\n"
               "the options given with it still apply on top");
  AddFilterChoice(app, options, "--metric",
                  { { "half-edge-color", F::HalfEdgeColor },
                    { "half-edge-colour", F::HalfEdgeColor },
                    { "geometry", F::Geometry },
                    { "color-quadric", F::ColorQuadric },
                    { "colour-quadric", F::ColorQuadric },
                    { "attribute-quadric", F::AttributeQuadric } },
                  &F::SetErrorMetric,
                  "--metric must be half-edge-color, geometry, color-quadric or attribute-quadric",
                  std::string("attribute-quadric (Hoppe's quadric of position and colour),\n"
                              "half-edge-color (the paper's (1+Q)(1+I)(1+C)), geometry (quadric\n"
                              "error only) or color-quadric (Garland-Heckbert's 6-D quadric)\n"
                              "(default ") +
                    MetricName(d->GetErrorMetric()) + ")")
    ->type_name("M");
  AddFilterWeight(app, options, "--color-weight", &F::SetColorWeight,
                  "weight of colour against geometry (attribute-quadric and\n"
                  "color-quadric; default " +
                    Number(d->GetColorWeight()) + ")");
  AddFilterWeight(app, options, "--geometry-weight", &F::SetGeometryWeight,
                  "weight of the geometric term, >= 0 (default " + Number(d->GetGeometryWeight()) +
                    ")");
  AddFilterWeight(app, options, "--boundary-weight", &F::SetBoundaryWeight,
                  "weight of the boundary planes that keep open boundaries in place\n"
                  "(0: none; default " +
                    Number(d->GetBoundaryWeight()) + ")");
  AddFilterFlag(app, options, "--no-scene-relative-weights", &F::SetSceneRelativeWeights, 0,
                "attribute-quadric: apply --color-weight and --boundary-weight as\n"
                "given; by default, on a mesh whose bounding-box diagonal is D > 270\n"
                "mean edge lengths, they are scaled by s = D / 270 (colour) and s^2\n"
                "(boundary)");
  AddFilterWeight(app, options, "--edge-length-weight", &F::SetEdgeLengthWeight,
                  "weight of the edge-length term that decimates flat parts evenly\n"
                  "(0: none; default " +
                    Number(d->GetEdgeLengthWeight()) + ")");
  AddFilterNumber(app, options, "--kept-vertex-error-weight", 0, 1, &F::SetKeptVertexErrorWeight,
                  "--kept-vertex-error-weight must be a number from 0 to 1",
                  "attribute-quadric: weight of the error the kept vertex holds\n"
                  "already in a collapse's cost, 0 to 1 (1: the total error;\n"
                  "default " +
                    Number(d->GetKeptVertexErrorWeight()) + ")")
    ->type_name("W");
  AddFilterWeight(app, options, "--piece-weight", &F::SetPieceWeight,
                  "weight of the cost of removing a small connected piece whole during\n"
                  "the run (attribute-quadric metric; 0: never; default " +
                    Number(d->GetPieceWeight()) + ")");
  AddFilterChoice(app, options, "--color-space",
                  { { "rgb", F::RGB }, { "cielab", F::CIELab }, { "lab", F::CIELab } },
                  &F::SetColorSpace, "--color-space must be rgb or cielab",
                  std::string("where colour differences are measured: rgb or cielab (default ") +
                    (d->GetColorSpace() == F::CIELab ? "cielab" : "rgb") + ")")
    ->type_name("S");
  AddFilterFlag(app, options, "--placement", &F::SetOptimalPlacement, 1,
                "color-quadric: full collapses that move the survivor (its\n"
                "point and colour are then new)");
}

/// The filter's settings: the target, the rules and the colour array.
void AddFilterOptions(CLI::App& app, Options& options)
{
  using F = vtkColorHalfEdgeDecimation;
  AddFilterNumber(app, options, "--reduction", 0, 1, &F::SetTargetReduction,
                  "--reduction must be a number from 0 to 1",
                  "fraction of the triangles to remove, 0 to 1 (default " +
                    Number(Defaults()->GetTargetReduction()) + ")")
    ->type_name("R");
  AddArrayName(app, "--array", options.Array,
               "point array holding the colours (default: the active scalars,\n"
               "e.g. the RGB array read from a PLY file)");
  AddFilterFlag(app, options, "--preserve-boundary", &F::SetPreserveBoundary, 1,
                "never remove vertices on open boundaries");
  AddFilterNumber(app, options, "--max-normal-angle", 0, 180, &F::SetMaximumNormalAngle,
                  "--max-normal-angle must be a number of degrees from 0 to 180",
                  "largest turn of a triangle normal a collapse may cause, 0 to 180\n"
                  "(default " +
                    Number(Defaults()->GetMaximumNormalAngle()) + ")")
    ->type_name("DEG");
  AddFilterFlag(app, options, "--consistent-orientation", &F::SetConsistentOrientation, 1,
                "wind every output triangle as its piece is wound (input wound both\n"
                "ways is always decimated as if wound one way; by default each\n"
                "output triangle keeps its input triangle's winding)");
  AddFilterFlag(app, options, "--no-seams", &F::SetPreserveSeams, 0,
                "treat each side of an attribute seam (boundary points at identical\n"
                "positions with their own data) as an open boundary of its own; by\n"
                "default both sides collapse together and the seam stays closed");
  AddFilterFlag(app, options, "--no-original-ids", &F::SetGenerateOriginalPointIds, 0,
                "do not add the vtkOriginalPointIds point array");
  AddValue(
    app, "--original-ids-name",
    [&options](const std::string& name)
    {
      options.Settings.push_back([name](vtkColorHalfEdgeDecimation* f)
                                 { f->SetOriginalPointIdsArrayName(name.c_str()); });
      return !name.empty();
    },
    FixedComplaint("--original-ids-name needs a non-empty array name"),
    "name of the array of original point ids (default vtkOriginalPointIds)")
    ->type_name("NAME");
}

/// When the run stops (a triangle count, an error bound) and which points stay.
void AddStopOptions(CLI::App& app, Options& options)
{
  AddFilterCount(app, options, "--target-triangles", 9.2e18,
                 &vtkColorHalfEdgeDecimation::SetTargetNumberOfTriangles,
                 "--target-triangles must be a whole number >= 0",
                 "number of triangles to leave, instead of --reduction (0: use\n"
                 "--reduction)");
  AddValue(
    app, "--max-error",
    [&options](const std::string& text)
    {
      const bool percent = !text.empty() && text.back() == '%';
      double value = 0;
      if (!ParseNumber(percent ? text.substr(0, text.size() - 1) : text, value) || value < 0)
      {
        return false;
      }
      options.MaximumErrorPercent = percent ? value : -1;
      options.Settings.push_back([percent, value](vtkColorHalfEdgeDecimation* f)
                                 { f->SetMaximumError(percent ? 0.0 : value); });
      return true;
    },
    RuleComplaint("--max-error must be a distance >= 0, or a percentage such as 0.1%"),
    "stop before the first collapse whose geometric error (area-weighted\n"
    "RMS distance to the merged input planes) exceeds E, in the input's\n"
    "units, or E% of its bounding-box diagonal (default 0: no bound)")
    ->type_name("E");
  AddFilterFlag(app, options, "--prune-components", &vtkColorHalfEdgeDecimation::SetPruneComponents,
                1,
                "when collapses alone cannot reach the target, remove whole\n"
                "connected pieces, smallest area first (off by default)");
  AddArrayName(app, "--lock-array", options.LockArray,
               "point array whose non-zero values keep their points in place");
}

/// How the collapses are scheduled, on how many threads.
void AddScheduleOptions(CLI::App& app, Options& options)
{
  using F = vtkColorHalfEdgeDecimation;
  AddFilterChoice(app, options, "--schedule",
                  { { "greedy", F::Greedy }, { "batched", F::Batched } }, &F::SetCollapseSchedule,
                  "--schedule must be greedy or batched",
                  std::string("batched (passes of independent collapses by blocks of the\n"
                              "mesh, on all cores) or greedy (one collapse at a time, always\n"
                              "the cheapest: the paper's order) (default ") +
                    ScheduleName(Defaults()->GetCollapseSchedule()) + ")")
    ->type_name("S");
  AddFilterCount(app, options, "--threads", 1024, &vtkColorHalfEdgeDecimation::SetNumberOfThreads,
                 "--threads must be a whole number from 0 (all cores) to 1024",
                 "threads of the parallel phases (default 0: as many as vtkSMPTools\n"
                 "runs, i.e. all cores unless VTK_SMP_MAX_THREADS says fewer); the\n"
                 "result does not depend on it");
}

/// The files written besides OUTPUT, and what is printed.
void AddOutputOptions(CLI::App& app, Options& options)
{
  app
    .add_option("--stats", options.Stats,
                "write the figures as JSON (filter_seconds, input/output points\n"
                "and triangles, reduction, metric, schedule, threads, state and\n"
                "peak memory, the filter's phases and their seconds)")
    ->type_name("FILE.json");
  app
    .add_option("--snapshot", options.Snapshot,
                "write a picture of the input (left) and the result (right), lit\n"
                "shape above, unlit colour below, offscreen (needs an X display:\n"
                "run under xvfb-run -a on a headless machine)")
    ->type_name("FILE.png");
  AddValue(
    app, "--snapshot-size",
    [&options](const std::string& text)
    {
      double pixels = 0;
      const bool ok = ParseNumber(text, pixels) && pixels >= 16 && pixels <= 8192;
      options.SnapshotSize = ok ? static_cast<int>(pixels) : options.SnapshotSize;
      return ok;
    },
    RuleComplaint("--snapshot-size must be a number of pixels from 16 to 8192"),
    "pixels of each of the picture's four panels (default 512)")
    ->type_name("N");
  app
    .add_option("--write-demo,--write-input", options.WriteInput,
                "also write the input mesh (e.g. the demo) to FILE (.ply, .vtp or\n"
                ".vtk); with no OUTPUT, only that is done")
    ->type_name("FILE");
  app.add_flag("-q,--quiet", options.Quiet,
               "print nothing but errors (no figures, no progress bar)");
}

/// Levels of detail from one run, and the collapse record.
void AddLevelOptions(CLI::App& app, Options& options)
{
  AddValue(
    app, "--lod",
    [&options](const std::string& text)
    {
      options.Levels.clear();
      std::stringstream list(text);
      std::string item;
      while (std::getline(list, item, ','))
      {
        double reduction = 0;
        if (!ParseNumber(item, reduction) || reduction < 0 || reduction > 1)
        {
          return false;
        }
        options.Levels.push_back(reduction);
      }
      return !options.Levels.empty();
    },
    RuleComplaint("--lod must be reductions from 0 to 1 separated by commas, e.g. 0.5,0.9,0.97"),
    "levels of detail from one decimation run: a file per reduction, in\n"
    "the order given, named as OUTPUT with .lod1, .lod2, ... before its\n"
    "extension (k.ply -> k.lod1.ply); the run goes to the largest\n"
    "reduction (with --max-error, every level also stops there)")
    ->type_name("R1,R2,...");
  app
    .add_option("--save-record", options.SaveRecord,
                "also write the run's collapse record (every level it passed\n"
                "through) to FILE, a VTK XML table, for --from-record")
    ->type_name("FILE.vtt");
  app
    .add_option("--from-record", options.FromRecord,
                "no decimation: take the level of INPUT that --reduction,\n"
                "--target-triangles and --max-error ask for (or the --lod levels)\n"
                "from the collapse record FILE, saved for this same INPUT")
    ->type_name("FILE.vtt");
}

/// What --help prints after the options.
std::string Footer()
{
  return "Meshes generated in code (INPUT):\n" + DemoHelp() +
    "\n"
    "Example (no data file needed):\n"
    "  color-decimate --demo demo_decimated.ply --write-demo demo_input.ply\n"
    "\n"
    "Exit status: 0 success, 1 unreadable/unsupported input or failed output, 2 bad options.";
}

/// Whether two paths name the same file: the same file on disk (through links) or, for a file
/// not there yet, the same canonical path.
bool SameFile(const std::string& a, const std::string& b)
{
  namespace fs = std::filesystem;
  std::error_code ea, eb;
  if (fs::exists(a, ea) && fs::exists(b, eb))
  {
    return fs::equivalent(a, b, ea) && !ea;
  }
  const fs::path ca = fs::weakly_canonical(a, ea);
  const fs::path cb = fs::weakly_canonical(b, eb);
  return ea || eb ? a == b : ca == cb;
}

using Named = std::pair<std::string, std::string>; // what a file is, its path

/// The files the run may write (a path is empty where the option is not given).
std::vector<Named> WrittenFiles(const Options& options)
{
  std::vector<Named> written;
  for (size_t i = 0; i < options.Levels.size(); ++i)
  {
    written.emplace_back("level " + std::to_string(i + 1) + " file",
                         LevelPath(options.Output, int(i) + 1));
  }
  written.emplace_back("OUTPUT", options.Levels.empty() ? options.Output : std::string());
  written.emplace_back("--stats file", options.Stats);
  written.emplace_back("--snapshot file", options.Snapshot);
  written.emplace_back("--write-demo file", options.WriteInput);
  written.emplace_back("--save-record file", options.SaveRecord);
  return written;
}

/// No file the run writes is a file it reads, nor another file it writes.
std::string CheckCollisions(const Options& options)
{
  std::vector<Named> read;
  if (!IsDemoSpec(options.Input))
  {
    read.emplace_back("INPUT", options.Input);
  }
  read.emplace_back("--from-record file", options.FromRecord);
  const std::vector<Named> written = WrittenFiles(options);
  for (size_t i = 0; i < written.size(); ++i)
  {
    const auto& [what, path] = written[i];
    for (const auto& [source, from] : read)
    {
      if (!path.empty() && !from.empty() && SameFile(path, from))
      {
        return "the " + what + " '" + path + "' is the " + source + ": it would be overwritten";
      }
    }
    for (size_t j = i + 1; j < written.size(); ++j)
    {
      if (!path.empty() && !written[j].second.empty() && SameFile(path, written[j].second))
      {
        return "the " + what + " and the " + written[j].first + " are the same file ('" + path +
          "')";
      }
    }
  }
  return "";
}

/**
 * Every file the run writes goes into a folder that exists: a mistyped folder is reported
 * before the input is read and decimated, not after. (A folder that exists but refuses the
 * file, a full disk, is still reported when the file is written.)
 */
std::string CheckOutputFolders(const Options& options)
{
  namespace fs = std::filesystem;
  for (const auto& [what, path] : WrittenFiles(options))
  {
    const fs::path folder = fs::path(path).parent_path();
    if (path.empty() || folder.empty())
    {
      continue;
    }
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (fs::is_directory(status) || status.type() == fs::file_type::none)
    {
      continue; // a folder, or one that cannot be looked at (the writer then says why)
    }
    const std::string named = what == "OUTPUT" ? std::string() : "the " + what + " ";
    return "cannot write " + named + "'" + path + "': " +
      (status.type() == fs::file_type::not_found ? "no folder '" + folder.string() + "'"
                                                 : "'" + folder.string() + "' is not a folder");
  }
  return "";
}

/// INPUT and OUTPUT after the parse; "" when they are right, otherwise what is wrong.
std::string CheckFiles(Options& options)
{
  std::vector<std::string> positional;
  for (const std::string* given : { &options.Input, &options.Output })
  {
    if (!given->empty())
    {
      positional.push_back(*given);
    }
  }
  if (options.Demo)
  {
    positional.insert(positional.begin(), "demo:");
  }
  if (positional.empty())
  {
    return "missing INPUT (a mesh file, or --demo)";
  }
  if (positional.size() > 2)
  {
    return "too many arguments: '" + positional[2] + "' (expected INPUT OUTPUT)";
  }
  options.Input = positional[0];
  options.Output = positional.size() == 2 ? positional[1] : std::string();
  if (options.Output.empty() && options.WriteInput.empty())
  {
    return "missing OUTPUT (a .ply, .vtp or .vtk file name)";
  }
  for (const std::string* path : { &options.Output, &options.WriteInput })
  {
    if (!path->empty() && !IsWritableExtension(*path))
    {
      const std::string ext = Extension(*path);
      return "unsupported output type '" + (ext.empty() ? std::string("(no extension)") : ext) +
        "' for '" + *path + "' (expected .ply, .vtp or .vtk)";
    }
  }
  if (!options.Snapshot.empty() && Extension(options.Snapshot) != ".png")
  {
    return "the --snapshot file '" + options.Snapshot + "' must be a .png file";
  }
  for (const std::string* record : { &options.SaveRecord, &options.FromRecord })
  {
    if (!record->empty() && Extension(*record) != ".vtt")
    {
      return "the collapse record '" + *record + "' must be a .vtt file";
    }
  }
  if (!options.Snapshot.empty() && (!options.Levels.empty() || !options.FromRecord.empty()))
  {
    return "--snapshot shows one decimation: not with --lod or --from-record";
  }
  if (!options.SaveRecord.empty() && !options.FromRecord.empty())
  {
    return "--save-record and --from-record cannot be combined";
  }
  if (options.ReductionGiven && !options.Levels.empty())
  {
    return "--lod gives the levels' reductions: not with --reduction";
  }
  if ((!options.Levels.empty() || !options.FromRecord.empty()) && options.Output.empty())
  {
    return "missing OUTPUT (the levels' files are named after it)";
  }
  for (const auto& [given, name] : { std::make_pair(&options.Stats, "--stats"),
                                     std::make_pair(&options.SaveRecord, "--save-record"),
                                     std::make_pair(&options.Snapshot, "--snapshot") })
  {
    if (!given->empty() && options.Output.empty())
    {
      return std::string("missing OUTPUT: ") + name +
        " reports a decimation, and --write-demo alone makes none";
    }
  }
  return CheckCollisions(options);
}

std::string Mib(long long bytes)
{
  if (bytes < 0)
  {
    return "unknown";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1f MiB", bytes / (1024.0 * 1024.0));
  return buffer;
}

/// The progress bar drawn on stderr while the filter runs.
struct ProgressBar
{
  int LastPercent = -1;
  bool Drawn = false;

  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ProgressBar*>(clientData);
    const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
    self->Draw(fraction);
  }

  void Draw(double fraction)
  {
    const int percent =
      static_cast<int>(std::floor(100.0 * std::min(1.0, std::max(0.0, fraction))));
    if (percent == this->LastPercent)
    {
      return;
    }
    this->LastPercent = percent;
    const int width = 40;
    const int filled = percent * width / 100;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.append(static_cast<size_t>(width - filled), '.');
    std::fprintf(stderr, "\rdecimating [%s] %3d%%", bar.c_str(), percent);
    std::fflush(stderr);
    this->Drawn = true;
  }

  void Finish()
  {
    if (this->Drawn)
    {
      std::fputc('\n', stderr);
      std::fflush(stderr);
    }
  }
};

int Fail(const std::string& message, int status = 1)
{
  std::cerr << Program << ": " << message << std::endl;
  return status;
}

double Seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

/// Goes on (-1) or stops with an exit status.
constexpr int Continue = -1;

/// The input mesh and what reading it measured.
struct Input
{
  vtkSmartPointer<vtkPolyData> Mesh;
  std::string Name; ///< as the figures call it (the default demo by its full specification)
  double ReadSeconds = 0;
  long long Points = 0;
  long long Triangles = 0;
};

/// One level of detail written (--lod, --from-record).
struct LevelFigures
{
  std::string Path;
  double Asked = 0; ///< the reduction asked for
  double Reduction = 0;
  double Error = 0;
  long long Points = 0;
  long long Triangles = 0;
  long long Collapses = 0;
  double ExtractSeconds = 0;
  double WriteSeconds = 0;
};

/// What the decimation and the writing measured.
struct Figures
{
  std::vector<LevelFigures> Levels;
  double FilterSeconds = 0;
  double WriteSeconds = 0;
  long long FilterPeak = -1;
  long long PeakRss = -1;
  long long OutputPoints = 0;
  long long OutputTriangles = 0;
};

/// Reads (or generates) the input, checks it has triangles and the colour array asked for.
int ReadInput(const Options& options, Input& input)
{
  const auto start = std::chrono::steady_clock::now();
  std::string description, error;
  input.Mesh = ReadMesh(options.Input, description, error);
  if (!input.Mesh)
  {
    return Fail(error);
  }
  input.ReadSeconds = Seconds(start, std::chrono::steady_clock::now());
  input.Triangles = CountTriangles(input.Mesh);
  input.Points = input.Mesh->GetNumberOfPoints();
  const bool defaultDemo =
    options.Input == "--demo" || options.Input == "demo" || options.Input == "demo:";
  input.Name = defaultDemo ? std::string(DefaultDemoSpec()) : options.Input;
  if (input.Triangles == 0)
  {
    return Fail("'" + options.Input + "' has no triangles (" + std::to_string(input.Points) +
                " points, " + std::to_string(input.Mesh->GetNumberOfCells()) +
                " cells that are vertices or lines): nothing to decimate");
  }
  for (const std::string* name : { &options.Array, &options.LockArray })
  {
    if (!name->empty() && !FindColorArray(input.Mesh, *name))
    {
      return Fail(NoNumericPointArray(input.Mesh, options.Input, *name));
    }
  }
  if (!options.Quiet)
  {
    std::cout << "input   " << input.Name << ": " << description << "\n";
  }
  if (!FindColorArray(input.Mesh, options.Array) && FindFaceColorArray(input.Mesh, options.Array))
  {
    std::cerr << Program
              << ": warning: the colours are per face (cell data), which the filter does "
                 "not measure: decimating by geometry alone; each kept face keeps its colour\n";
  }
  return Continue;
}

/// --write-demo: the input as it was read; ends the run when there is no OUTPUT.
int WriteInputCopy(const Options& options, vtkPolyData* input)
{
  std::string error;
  if (!WriteMesh(input, options.WriteInput, options.Array, error, &options.PlyColors))
  {
    return Fail(error);
  }
  if (!options.Quiet)
  {
    std::cout << "wrote   " << options.WriteInput << " (the input mesh)\n";
  }
  return options.Output.empty() ? 0 : Continue;
}

/// The filter's properties from the options (its input is set once read).
void Configure(vtkColorHalfEdgeDecimation* filter, const Options& options)
{
  if (options.Paper)
  {
    filter->SetPaperDefaults();
  }
  for (const FilterSetting& setting : options.Settings)
  {
    setting(filter);
  }
  if (!options.Array.empty())
  {
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                   options.Array.c_str());
  }
  if (!options.LockArray.empty())
  {
    filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                   options.LockArray.c_str());
  }
}

/// Runs the filter (with a progress bar on a terminal); its warnings are printed unless
/// --quiet, its first error ends the run.
int Decimate(vtkColorHalfEdgeDecimation* filter, const Options& options, Figures& figures)
{
  ProgressBar bar;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(&ProgressBar::Callback);
  progress->SetClientData(&bar);
  if (!options.Quiet && isatty(fileno(stderr)))
  {
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
  }
  std::vector<std::string> warnings, errors;
  {
    MessageCatcher::Scope scope;
    PeakMemoryProbe probe;
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    figures.FilterSeconds = Seconds(start, std::chrono::steady_clock::now());
    figures.FilterPeak = probe.PeakAboveBaseline();
    warnings = scope.Get()->Warnings;
    errors = scope.Get()->Errors;
  }
  bar.Finish();
  for (const std::string& warning : options.Quiet ? std::vector<std::string>() : warnings)
  {
    std::cerr << Program << ": warning: " << MessageCatcher::Clean(warning) << std::endl;
  }
  if (!errors.empty())
  {
    return Fail("decimation failed: " + MessageCatcher::Clean(errors.front()));
  }
  figures.OutputTriangles = CountTriangles(filter->GetOutput());
  figures.OutputPoints = filter->GetOutput()->GetNumberOfPoints();
  return Continue;
}

int WriteOutput(vtkColorHalfEdgeDecimation* filter, const Options& options, Figures& figures)
{
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!WriteMesh(filter->GetOutput(), options.Output, options.Array, error, &options.PlyColors))
  {
    return Fail(error);
  }
  figures.WriteSeconds = Seconds(start, std::chrono::steady_clock::now());
  figures.PeakRss = PeakRSS();
  return Continue;
}

void PrintFigures(vtkColorHalfEdgeDecimation* filter, const Options& options, const Input& input,
                  const Figures& figures)
{
  char line[512], target[64];
  if (filter->GetTargetNumberOfTriangles() > 0)
  {
    std::snprintf(target, sizeof(target), "%lld triangles",
                  static_cast<long long>(filter->GetTargetNumberOfTriangles()));
  }
  else
  {
    std::snprintf(target, sizeof(target), "%.4f", filter->GetTargetReduction());
  }
  std::snprintf(
    line, sizeof(line),
    "output  %s: %lld points, %lld triangles\n"
    "        reduction %.4f (target %s), %lld collapses, metric %s\n"
    "        filter %.3f s (read %.3f s, write %.3f s), decimation state %s, "
    "peak RSS %s\n",
    options.Output.c_str(), figures.OutputPoints, figures.OutputTriangles,
    filter->GetActualReduction(), target, static_cast<long long>(filter->GetNumberOfCollapses()),
    MetricName(filter->GetErrorMetric()), figures.FilterSeconds, input.ReadSeconds,
    figures.WriteSeconds, Mib(filter->GetStateMemory()).c_str(), Mib(figures.PeakRss).c_str());
  std::cout << line;
  if (filter->GetNumberOfPrunedComponents() > 0)
  {
    std::snprintf(line, sizeof(line), "        %lld small pieces removed whole\n",
                  static_cast<long long>(filter->GetNumberOfPrunedComponents()));
    std::cout << line;
  }
  if (filter->GetMaximumError() > 0)
  {
    std::snprintf(line, sizeof(line), "        geometric error %g (bound %g)\n",
                  filter->GetActualError(), filter->GetMaximumError());
    std::cout << line;
  }
  std::cout << std::flush;
}

/// The filter's settings as the run used them.
Json Settings(vtkColorHalfEdgeDecimation* filter)
{
  Json settings;
  settings["boundary_weight"] = filter->GetBoundaryWeight();
  settings["scene_relative_weights"] = filter->GetSceneRelativeWeights() != 0;
  settings["edge_length_weight"] = filter->GetEdgeLengthWeight();
  settings["kept_vertex_error_weight"] = filter->GetKeptVertexErrorWeight();
  settings["piece_weight"] = filter->GetPieceWeight();
  settings["geometry_weight"] = filter->GetGeometryWeight();
  settings["color_weight"] = filter->GetColorWeight();
  settings["color_space"] =
    filter->GetColorSpace() == vtkColorHalfEdgeDecimation::CIELab ? "cielab" : "rgb";
  settings["placement"] = filter->GetOptimalPlacement() != 0;
  settings["preserve_boundary"] = filter->GetPreserveBoundary() != 0;
  settings["max_normal_angle"] = filter->GetMaximumNormalAngle();
  settings["original_ids"] = filter->GetGenerateOriginalPointIds() != 0;
  settings["target_triangles"] = static_cast<long long>(filter->GetTargetNumberOfTriangles());
  settings["max_error"] = filter->GetMaximumError();
  settings["prune_components"] = filter->GetPruneComponents() != 0;
  settings["consistent_orientation"] = filter->GetConsistentOrientation() != 0;
  settings["preserve_seams"] = filter->GetPreserveSeams() != 0;
  settings["lock_array"] = filter->GetLockArrayName() ? filter->GetLockArrayName() : "";
  return settings;
}

/// The levels' figures as a JSON list.
Json LevelList(const std::vector<LevelFigures>& levels)
{
  Json list = Json::array();
  for (const LevelFigures& level : levels)
  {
    Json item;
    item["output"] = level.Path;
    item["target_reduction"] = level.Asked;
    item["reduction"] = level.Reduction;
    item["actual_error"] = level.Error;
    item["output_points"] = level.Points;
    item["output_triangles"] = level.Triangles;
    item["collapses"] = level.Collapses;
    item["extract_seconds"] = level.ExtractSeconds;
    item["write_seconds"] = level.WriteSeconds;
    list.push_back(item);
  }
  return list;
}

/// --stats: the figures as JSON.
Json Statistics(vtkColorHalfEdgeDecimation* filter, const Options& options, const Input& input,
                const Figures& figures)
{
  Json stats;
  stats["input"] = input.Name;
  stats["output"] = options.Output;
  // Levels from a saved record: its run's method is not known here.
  const bool fromRecord = !options.FromRecord.empty();
  stats["metric"] = fromRecord ? Json() : Json(MetricName(filter->GetErrorMetric()));
  stats["schedule"] = fromRecord ? Json() : Json(ScheduleName(filter->GetCollapseSchedule()));
  stats["threads"] = filter->GetNumberOfThreadsUsed();
  stats["scene_weight_scale"] = fromRecord ? Json() : Json(filter->GetSceneWeightScale());
  stats["target_reduction"] = filter->GetTargetReduction();
  stats["paper"] = fromRecord ? Json() : Json(options.Paper);
  stats["settings"] = fromRecord ? Json() : Settings(filter);
  stats["reduction"] = filter->GetActualReduction();
  // Measured only under a bound or with the record (null: not measured).
  const bool measured = filter->GetMaximumError() > 0 || filter->GetGenerateCollapseRecord();
  stats["actual_error"] = measured ? Json(filter->GetActualError()) : Json();
  stats["pruned_components"] = static_cast<long long>(filter->GetNumberOfPrunedComponents());
  stats["input_points"] = input.Points;
  stats["input_triangles"] = input.Triangles;
  stats["output_points"] = figures.OutputPoints;
  stats["output_triangles"] = figures.OutputTriangles;
  stats["collapses"] = static_cast<long long>(filter->GetNumberOfCollapses());
  stats["filter_seconds"] = figures.FilterSeconds;
  stats["read_seconds"] = input.ReadSeconds;
  stats["write_seconds"] = figures.WriteSeconds;
  stats["state_memory_bytes"] = static_cast<long long>(filter->GetStateMemory());
  stats["filter_peak_memory_bytes"] = figures.FilterPeak;
  stats["peak_rss_bytes"] = figures.PeakRss;
  stats["phases"] = Json::array(); // the filter's phase breakdown, in order
  for (int i = 0; i < filter->GetNumberOfPhases(); ++i)
  {
    stats["phases"].push_back(
      { { "name", filter->GetPhaseName(i) }, { "seconds", filter->GetPhaseSeconds(i) } });
  }
  if (!options.Levels.empty() || !options.FromRecord.empty())
  {
    stats["levels"] = LevelList(figures.Levels);
    stats["from_record"] = options.FromRecord;
    if (!options.Levels.empty())
    {
      stats["output"] = nullptr; // the levels' files are written instead
    }
  }
  if (!options.FromRecord.empty()) // no decimation ran: only the levels have figures
  {
    for (const char* key : { "threads", "reduction", "actual_error", "pruned_components",
                             "output_points", "output_triangles", "collapses", "filter_seconds",
                             "state_memory_bytes", "filter_peak_memory_bytes", "phases" })
    {
      stats[key] = nullptr;
    }
  }
  return stats;
}

/// --snapshot: input and result side by side.
int Snapshot(vtkColorHalfEdgeDecimation* filter, const Options& options, vtkPolyData* input)
{
  colordecimation::fidelity::SnapshotOptions snapshot;
  snapshot.ColorArray = options.Array;
  snapshot.SimplifiedLabel = "color-decimate " +
    std::to_string(static_cast<int>(std::lround(100.0 * filter->GetActualReduction()))) + " %";
  std::string why;
  if (!colordecimation::fidelity::WriteSnapshot(input, filter->GetOutput(), options.Snapshot,
                                                options.SnapshotSize, snapshot, &why))
  {
    return Fail("cannot write the snapshot '" + options.Snapshot + "': " + why);
  }
  if (!options.Quiet)
  {
    std::cout << "wrote   " << options.Snapshot << " (input left, result right)\n";
  }
  return Continue;
}

/// --lod and --save-record: a run that keeps its collapse record, to the largest level.
int PrepareRecordRun(vtkColorHalfEdgeDecimation* filter, const Options& options)
{
  if (options.Levels.empty() && options.SaveRecord.empty())
  {
    return Continue;
  }
  if (filter->GetOptimalPlacement() &&
      filter->GetErrorMetric() == vtkColorHalfEdgeDecimation::ColorQuadric)
  {
    return Fail("--lod and --save-record need half-edge collapses: not with --placement", 2);
  }
  if (!options.Levels.empty())
  {
    if (filter->GetTargetNumberOfTriangles() > 0)
    {
      return Fail("--lod takes reductions: it cannot be combined with --target-triangles", 2);
    }
    filter->SetTargetReduction(*std::max_element(options.Levels.begin(), options.Levels.end()));
  }
  filter->GenerateCollapseRecordOn();
  return Continue;
}

/// The options of the decimation's method: a level read from a record (--from-record) is the
/// method that made the record's, whatever they say. (--placement and --lock-array have
/// checks of their own.)
const char* const MethodOptions[] = { "--paper",
                                      "--metric",
                                      "--color-weight",
                                      "--geometry-weight",
                                      "--boundary-weight",
                                      "--edge-length-weight",
                                      "--kept-vertex-error-weight",
                                      "--piece-weight",
                                      "--no-scene-relative-weights",
                                      "--color-space",
                                      "--preserve-boundary",
                                      "--no-seams",
                                      "--max-normal-angle",
                                      "--schedule" };

/// Those of MethodOptions given on the command line, comma separated.
std::string GivenMethodOptions(const CLI::App& app)
{
  std::string given;
  for (const char* name : MethodOptions)
  {
    if (app.count(name) > 0)
    {
      given += (given.empty() ? "" : ", ") + std::string(name);
    }
  }
  return given;
}

/// Settings given that the run does not read: said on stderr, not dropped silently.
void WarnUnreadSettings(vtkColorHalfEdgeDecimation* filter, const Options& options)
{
  if (filter->GetOptimalPlacement() &&
      filter->GetErrorMetric() != vtkColorHalfEdgeDecimation::ColorQuadric)
  {
    std::cerr << Program << ": warning: --placement moves points in the color-quadric metric "
              << "only (--metric color-quadric): ignored\n";
  }
  if (!options.FromRecord.empty() && !options.MethodOptionsGiven.empty())
  {
    std::cerr << Program << ": warning: --from-record gives the levels of the method that made "
              << "the record: " << options.MethodOptionsGiven << " ignored\n";
  }
}

/// Levels come from the record, which holds neither the pieces PruneComponents removes after
/// the collapses nor ConsistentOrientation's winding: those options would be ignored. A record
/// saved alone is still the run's, but the levels later taken from it lack them: said.
int CheckLevelOptions(vtkColorHalfEdgeDecimation* filter, const Options& options)
{
  const bool levels = !options.Levels.empty() || !options.FromRecord.empty();
  if (!levels && options.SaveRecord.empty())
  {
    return Continue;
  }
  for (const auto& [on, name] :
       { std::make_pair(filter->GetPruneComponents() != 0, "--prune-components"),
         std::make_pair(filter->GetConsistentOrientation() != 0, "--consistent-orientation") })
  {
    if (on && levels)
    {
      return Fail(std::string("levels from a collapse record (--lod, --from-record) hold only "
                              "its collapses: not with ") +
                    name,
                  2);
    }
    if (on)
    {
      std::cerr << Program << ": warning: --save-record: the record holds the collapses only: "
                << "the levels --from-record takes from it are without " << name
                << " (OUTPUT has it)\n";
    }
  }
  return Continue;
}

/// The decimation (OUTPUT written unless --lod), or with --from-record the record read.
int DecimateOrLoad(vtkColorHalfEdgeDecimation* filter, const Options& options,
                   vtkSmartPointer<vtkTable>& record, Figures& figures)
{
  std::string error;
  if (!options.FromRecord.empty())
  {
    record = ReadRecord(options.FromRecord, error);
    return record ? Continue : Fail(error);
  }
  int status = Decimate(filter, options, figures);
  if (status == Continue && options.Levels.empty())
  {
    status = WriteOutput(filter, options, figures);
  }
  record = filter->GetCollapseRecord();
  if (status == Continue && !options.SaveRecord.empty() &&
      !WriteRecord(record, options.SaveRecord, error))
  {
    return Fail(error);
  }
  if (status == Continue && !options.Quiet && !options.SaveRecord.empty())
  {
    std::cout << "wrote   " << options.SaveRecord << " (the collapse record, "
              << record->GetNumberOfRows() << " collapses)\n";
  }
  return status;
}

/// One level from the record: its figures into `level` and the level into `mesh` (a copy that
/// the next level leaves as it is).
int ExtractLevel(vtkColorHalfEdgeLevelOfDetail* lod, LevelFigures& level,
                 vtkSmartPointer<vtkPolyData>& mesh)
{
  MessageCatcher::Scope scope;
  const auto start = std::chrono::steady_clock::now();
  lod->Update();
  level.ExtractSeconds = Seconds(start, std::chrono::steady_clock::now());
  if (!scope.Get()->Errors.empty())
  {
    return Fail("level of detail failed: " + MessageCatcher::Clean(scope.Get()->Errors.front()));
  }
  mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(lod->GetOutput());
  // Its own field data: a writer may store ranges in the arrays, which the input shares.
  vtkNew<vtkFieldData> field;
  field->DeepCopy(lod->GetOutput()->GetFieldData());
  mesh->SetFieldData(field);
  level.Points = mesh->GetNumberOfPoints();
  level.Triangles = CountTriangles(mesh);
  level.Reduction = lod->GetActualReduction();
  level.Error = lod->GetActualError();
  level.Collapses = static_cast<long long>(lod->GetNumberOfCollapses());
  return Continue;
}

/// A level's file, written on another thread while the next levels are extracted.
struct LevelWrite
{
  LevelFigures Level;
  std::shared_future<std::string> Error; ///< empty when written
};

/// Write the level once `before` (the previous level's file, if valid) is written: one file at
/// a time: levels in .vtp or .vtk go through VTK's writers, which are not run side by side
/// here (their thread safety is not checked).
void StartWrite(LevelWrite& write, vtkSmartPointer<vtkPolyData> mesh, const Options& options,
                std::shared_future<std::string> before)
{
  LevelFigures* level = &write.Level;
  const std::string array = options.Array;
  const ColorMapping colors = options.PlyColors;
  write.Error = std::async(std::launch::async,
                           [level, mesh, array, colors, before]()
                           {
                             if (before.valid())
                             {
                               before.wait();
                             }
                             const auto start = std::chrono::steady_clock::now();
                             std::string error;
                             WriteMesh(mesh, level->Path, array, error, &colors);
                             level->WriteSeconds = Seconds(start, std::chrono::steady_clock::now());
                             return error;
                           });
}

/// Wait for the level's file; its figures printed unless --quiet, and kept in `figures`.
int FinishWrite(LevelWrite& write, const Options& options, Figures& figures)
{
  const std::string& error = write.Error.get();
  if (!error.empty())
  {
    return Fail(error);
  }
  const LevelFigures& level = write.Level;
  if (!options.Quiet)
  {
    char line[512];
    std::snprintf(line, sizeof(line),
                  "level   %s: %lld points, %lld triangles, reduction %.4f (target %.4f), "
                  "%lld collapses, error %g, extract %.3f s, write %.3f s\n",
                  level.Path.c_str(), level.Points, level.Triangles, level.Reduction, level.Asked,
                  level.Collapses, level.Error, level.ExtractSeconds, level.WriteSeconds);
    std::cout << line << std::flush;
  }
  figures.Levels.push_back(level);
  return Continue;
}

/// --lod (each level, from the run's record) or --from-record (OUTPUT, or the --lod levels):
/// the levels' files written one after the other on other threads while the next levels are
/// extracted; the figures in the order given.
int WriteLevels(vtkColorHalfEdgeDecimation* filter, const Options& options, vtkPolyData* input,
                vtkTable* record, Figures& figures)
{
  vtkNew<vtkColorHalfEdgeLevelOfDetail> lod;
  lod->SetInputData(input);
  lod->SetRecordData(record);
  lod->SetMaximumError(filter->GetMaximumError());
  lod->SetGenerateOriginalPointIds(filter->GetGenerateOriginalPointIds());
  lod->SetOriginalPointIdsArrayName(filter->GetOriginalPointIdsArrayName());
  std::vector<double> asked = options.Levels;
  if (!asked.empty() && filter->GetTargetNumberOfTriangles() > 0)
  {
    return Fail("--lod takes reductions: it cannot be combined with --target-triangles", 2);
  }
  if (asked.empty())
  {
    asked.push_back(filter->GetTargetReduction()); // --from-record alone: the options' level
    lod->SetTargetNumberOfTriangles(filter->GetTargetNumberOfTriangles());
  }
  std::vector<LevelWrite> writes(asked.size());
  int status = Continue;
  for (size_t i = 0; i < asked.size() && status == Continue; ++i)
  {
    LevelWrite& write = writes[i];
    write.Level.Asked = asked[i];
    write.Level.Path =
      options.Levels.empty() ? options.Output : LevelPath(options.Output, int(i) + 1);
    lod->SetTargetReduction(asked[i]);
    vtkSmartPointer<vtkPolyData> mesh;
    status = ExtractLevel(lod, write.Level, mesh);
    if (status == Continue)
    {
      StartWrite(write, mesh, options,
                 i > 0 ? writes[i - 1].Error : std::shared_future<std::string>());
    }
  }
  for (LevelWrite& write : writes)
  {
    if (write.Error.valid())
    {
      const int written = FinishWrite(write, options, figures);
      status = status == Continue ? written : status;
    }
  }
  figures.PeakRss = PeakRSS();
  return status;
}

/// Everything after the command line, step by step; the exit status.
int Run(const Options& given)
{
  Options options = given;
  // The settings first, so that combinations the levels cannot honour fail before any reading.
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  Configure(filter, options);
  WarnUnreadSettings(filter, options);
  if (options.ReductionGiven && filter->GetTargetNumberOfTriangles() > 0)
  {
    return Fail("--reduction and --target-triangles each set the target: give one", 2);
  }
  int status = CheckLevelOptions(filter, options);
  status = status == Continue ? PrepareRecordRun(filter, options) : status;
  if (status != Continue)
  {
    return status;
  }
  const std::string folderError = CheckOutputFolders(options);
  if (!folderError.empty())
  {
    return Fail(folderError);
  }
  Input input;
  status = ReadInput(options, input);
  options.PlyColors =
    ColorMapping::Of(input.Mesh ? FindColorArray(input.Mesh, options.Array) : nullptr);
  if (status == Continue && !options.WriteInput.empty())
  {
    status = WriteInputCopy(options, input.Mesh);
  }
  if (status != Continue)
  {
    return status;
  }
  filter->SetInputData(input.Mesh);
  if (options.MaximumErrorPercent >= 0)
  {
    filter->SetMaximumError(options.MaximumErrorPercent / 100.0 * input.Mesh->GetLength());
  }
  Figures figures;
  vtkSmartPointer<vtkTable> record;
  status = DecimateOrLoad(filter, options, record, figures);
  const bool levels = !options.Levels.empty() || !options.FromRecord.empty();
  if (status == Continue && levels)
  {
    status = WriteLevels(filter, options, input.Mesh, record, figures);
  }
  if (status != Continue)
  {
    return status;
  }
  if (!options.Quiet && !levels)
  {
    PrintFigures(filter, options, input, figures);
  }
  std::string error;
  if (!options.Stats.empty() &&
      !WriteJsonFile(Statistics(filter, options, input, figures), options.Stats, error))
  {
    return Fail("cannot write the statistics to '" + options.Stats + "'");
  }
  status = options.Snapshot.empty() || levels ? Continue : Snapshot(filter, options, input.Mesh);
  return status == Continue ? 0 : status;
}
} // namespace

int main(int argc, char* argv[])
{
  UseAllCoresByDefault(); // vtkSMPTools on all cores unless asked otherwise
  // VTK's messages are caught and reported in one line (MessageCatcher); its logger would
  // print them to stderr a second time, with timestamps.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app("Decimates a triangle mesh with vertex colours by half-edge collapses\n"
               "(vtkColorHalfEdgeDecimation), ordered by a colour-aware cost (--metric; --paper\n"
               "for Kim, Choi and Lee's). Surviving vertices keep their position and point data\n"
               "exactly (unless --placement moves them).",
               Program);
  SetUpCommandLine(app,
                   "Usage: color-decimate INPUT OUTPUT [options]\n"
                   "       color-decimate INPUT --write-demo FILE [options]");
  Options options;
  AddInputOptions(app, options);
  AddMetricOptions(app, options);
  AddFilterOptions(app, options);
  AddStopOptions(app, options);
  AddScheduleOptions(app, options);
  AddOutputOptions(app, options);
  AddLevelOptions(app, options);
  app.footer(Footer());
  const int status = ParseCommandLine(app, argc, argv);
  if (status >= 0)
  {
    return status;
  }
  options.ReductionGiven = app.count("--reduction") > 0;
  options.MethodOptionsGiven = GivenMethodOptions(app);
  const std::string error = CheckFiles(options);
  return error.empty() ? Run(options) : ReportUsageError(app, error);
}
