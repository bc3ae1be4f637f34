/**
 * @file ColorDecimate.cxx
 * @brief color-decimate: decimate a coloured triangle mesh from the command line with
 * vtkColorHalfEdgeDecimation.
 *
 * Run `color-decimate --help` for the options. Exit status: 0 on success, 1 when a file
 * cannot be read or written or the filter fails, 2 on bad options.
 */
#include "MeshIO.h"
#include "ProcessMemory.h"

#include "ColorDecimationFidelity.h"
#include "vtkColorHalfEdgeDecimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using namespace colordecimation::tools;

const char* const Program = "color-decimate";

struct Options
{
  std::string Input;
  std::string Output;
  double Reduction = 0.9;
  int Metric = vtkColorHalfEdgeDecimation::HalfEdgeColor;
  std::string Array;
  bool PreserveBoundary = false;
  double MaxNormalAngle = 90.0;
  double GeometryWeight = 1.0;
  int Schedule = vtkColorHalfEdgeDecimation::Greedy;
  int Threads = 0;
  std::string Stats;
  std::string Snapshot;
  int SnapshotSize = 512;
  std::string WriteInput;
  bool Quiet = false;
  bool Help = false;
};

void PrintHelp(std::ostream& os)
{
  os
    << "Usage: color-decimate INPUT OUTPUT [options]\n"
       "       color-decimate INPUT --write-demo FILE [options]\n"
       "\n"
       "Decimates a triangle mesh with vertex colours by half-edge collapses ordered by the\n"
       "colour-aware cost of Kim, Choi and Lee (vtkColorHalfEdgeDecimation). Surviving\n"
       "vertices keep their position and colour exactly.\n"
       "\n"
       "INPUT   a .ply, .vtp, .vtu, .vtk (legacy; non-polygonal data sets are reduced to\n"
       "        their surface), .obj or .stl file, or a mesh generated in code:\n"
    << DemoHelp()
    << "OUTPUT  a .ply (binary, colours as uchar red/green/blue[/alpha]), .vtp (binary, with\n"
       "        every point array, including vtkOriginalPointIds) or .vtk (legacy binary) file.\n"
       "\n"
       "Options:\n"
       "  --reduction R           fraction of the triangles to remove, 0 to 1 (default 0.9,\n"
       "                          which keeps 10 %)\n"
       "  --metric M              half-edge-color (default: the paper's colour-aware cost),\n"
       "                          geometry (quadric error only, colours ignored) or\n"
       "                          color-quadric (Garland-Heckbert's 6-D colour quadric, as a\n"
       "                          half-edge collapse)\n"
       "  --array NAME            point array holding the colours (default: the active\n"
       "                          scalars, e.g. the RGB array read from a PLY file)\n"
       "  --preserve-boundary     never remove vertices on open boundaries\n"
       "  --max-normal-angle DEG  largest turn of a triangle normal a collapse may cause,\n"
       "                          0 to 180 (default 90)\n"
       "  --geometry-weight W     weight of the geometric term, >= 0 (default 1; larger keeps\n"
       "                          shape better, smaller keeps colour better)\n"
       "  --schedule S            greedy (default: one collapse at a time, cheapest first,\n"
       "                          as in the paper) or batched (passes of independent\n"
       "                          collapses, cheapest first within each: faster on large\n"
       "                          meshes, close to greedy's result but not the same)\n"
       "  --threads N             threads that cost vertices (default 0: all cores); the\n"
       "                          result does not depend on it\n"
       "  --stats FILE.json       write the figures as JSON (filter_seconds, input/output\n"
       "                          points and triangles, reduction, metric, state and peak memory)\n"
       "  --snapshot FILE.png     write a picture of the input (left) and the result (right),\n"
       "                          lit shape above, unlit colour below, offscreen (needs an X\n"
       "                          display: run under xvfb-run -a on a headless machine)\n"
       "  --snapshot-size N       pixels of each of the picture's four panels (default 512)\n"
       "  --write-demo FILE       also write the input mesh (e.g. the demo) to FILE (.ply, .vtp\n"
       "                          or .vtk); with no OUTPUT, only that is done\n"
       "                          (--write-input is the same option)\n"
       "  --quiet                 print nothing but errors (no figures, no progress bar)\n"
       "  -h, --help              show this help\n"
       "\n"
       "Example (no data file needed):\n"
       "  color-decimate --demo demo_decimated.ply --write-demo demo_input.ply\n"
       "\n"
       "Exit status: 0 success, 1 unreadable/unsupported input or failed output, 2 bad options.\n";
}

bool ParseNumber(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

/// Parses the command line; on error returns false with a message.
bool ParseOptions(int argc, char* argv[], Options& options, std::string& error)
{
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    std::string value;
    bool hasInlineValue = false;
    if (arg.compare(0, 2, "--") == 0)
    {
      const size_t eq = arg.find('=');
      if (eq != std::string::npos)
      {
        value = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        hasInlineValue = true;
      }
    }
    auto takeValue = [&](std::string& out) -> bool
    {
      if (hasInlineValue)
      {
        out = value;
        return true;
      }
      if (i + 1 >= argc)
      {
        error = "option " + arg + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    auto noValue = [&]() -> bool
    {
      if (hasInlineValue)
      {
        error = "option " + arg + " takes no value";
        return false;
      }
      return true;
    };
    std::string text;
    double number = 0;
    if (arg == "-h" || arg == "--help")
    {
      options.Help = true;
    }
    else if (arg == "--demo")
    {
      if (!noValue())
      {
        return false;
      }
      positional.push_back("--demo");
    }
    else if (arg == "--reduction")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (!ParseNumber(text, number) || number < 0 || number > 1)
      {
        error = "--reduction must be a number from 0 to 1 (got '" + text + "')";
        return false;
      }
      options.Reduction = number;
    }
    else if (arg == "--metric")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (text == "half-edge-color" || text == "half-edge-colour" || text == "halfedgecolor" ||
          text == "color" || text == "colour")
      {
        options.Metric = vtkColorHalfEdgeDecimation::HalfEdgeColor;
      }
      else if (text == "geometry")
      {
        options.Metric = vtkColorHalfEdgeDecimation::Geometry;
      }
      else if (text == "color-quadric" || text == "colour-quadric" || text == "colorquadric")
      {
        options.Metric = vtkColorHalfEdgeDecimation::ColorQuadric;
      }
      else
      {
        error = "--metric must be half-edge-color, geometry or color-quadric (got '" + text + "')";
        return false;
      }
    }
    else if (arg == "--array")
    {
      if (!takeValue(options.Array))
      {
        return false;
      }
      if (options.Array.empty())
      {
        error = "--array needs a non-empty array name";
        return false;
      }
    }
    else if (arg == "--preserve-boundary")
    {
      if (!noValue())
      {
        return false;
      }
      options.PreserveBoundary = true;
    }
    else if (arg == "--max-normal-angle")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (!ParseNumber(text, number) || number < 0 || number > 180)
      {
        error = "--max-normal-angle must be a number of degrees from 0 to 180 (got '" + text + "')";
        return false;
      }
      options.MaxNormalAngle = number;
    }
    else if (arg == "--geometry-weight")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (!ParseNumber(text, number) || number < 0)
      {
        error = "--geometry-weight must be a number >= 0 (got '" + text + "')";
        return false;
      }
      options.GeometryWeight = number;
    }
    else if (arg == "--schedule")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (text == "greedy")
      {
        options.Schedule = vtkColorHalfEdgeDecimation::Greedy;
      }
      else if (text == "batched")
      {
        options.Schedule = vtkColorHalfEdgeDecimation::Batched;
      }
      else
      {
        error = "--schedule must be greedy or batched (got '" + text + "')";
        return false;
      }
    }
    else if (arg == "--threads")
    {
      if (!takeValue(text))
      {
        return false;
      }
      if (!ParseNumber(text, number) || number < 0 || number > 1024 || number != std::floor(number))
      {
        error = "--threads must be a whole number from 0 (all cores) to 1024 (got '" + text + "')";
        return false;
      }
      options.Threads = static_cast<int>(number);
    }
    else if (arg == "--stats")
    {
      if (!takeValue(options.Stats))
      {
        return false;
      }
    }
    else if (arg == "--snapshot")
    {
      if (!takeValue(options.Snapshot))
      {
        return false;
      }
    }
    else if (arg == "--snapshot-size")
    {
      std::string text;
      double number = 0;
      if (!takeValue(text))
      {
        return false;
      }
      if (!ParseNumber(text, number) || number < 16 || number > 8192)
      {
        error = "--snapshot-size must be a number of pixels from 16 to 8192 (got '" + text + "')";
        return false;
      }
      options.SnapshotSize = static_cast<int>(number);
    }
    else if (arg == "--write-demo" || arg == "--write-input")
    {
      if (!takeValue(options.WriteInput))
      {
        return false;
      }
    }
    else if (arg == "--quiet" || arg == "-q")
    {
      if (!noValue())
      {
        return false;
      }
      options.Quiet = true;
    }
    else if (arg.size() > 1 && arg[0] == '-')
    {
      error = "unknown option '" + arg + "'";
      return false;
    }
    else
    {
      positional.push_back(arg);
    }
  }
  if (options.Help)
  {
    return true;
  }
  if (positional.empty())
  {
    error = "missing INPUT (a mesh file, or --demo)";
    return false;
  }
  if (positional.size() > 2)
  {
    error = "too many arguments: '" + positional[2] + "' (expected INPUT OUTPUT)";
    return false;
  }
  options.Input = positional[0];
  if (positional.size() == 2)
  {
    options.Output = positional[1];
  }
  else if (options.WriteInput.empty())
  {
    error = "missing OUTPUT (a .ply, .vtp or .vtk file name)";
    return false;
  }
  for (const std::string* path : { &options.Output, &options.WriteInput })
  {
    if (!path->empty() && !IsWritableExtension(*path))
    {
      const std::string ext = Extension(*path);
      error = "unsupported output type '" + (ext.empty() ? std::string("(no extension)") : ext) +
        "' for '" + *path + "' (expected .ply, .vtp or .vtk)";
      return false;
    }
  }
  if (!options.Stats.empty() && options.Stats == options.Output)
  {
    error = "--stats file and OUTPUT are the same file";
    return false;
  }
  return true;
}

std::string JsonString(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
  {
    switch (c)
    {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
        {
          char buffer[8];
          std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
          out += buffer;
        }
        else
        {
          out += c;
        }
    }
  }
  return out + "\"";
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
} // namespace

int main(int argc, char* argv[])
{
  // VTK's messages are caught and reported in one line (MessageCatcher); its logger would
  // print them to stderr a second time, with timestamps.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  Options options;
  std::string error;
  if (!ParseOptions(argc, argv, options, error))
  {
    std::cerr << Program << ": " << error << "\n"
              << "Try 'color-decimate --help'." << std::endl;
    return 2;
  }
  if (options.Help)
  {
    PrintHelp(std::cout);
    return 0;
  }
  const bool verbose = !options.Quiet;

  // Read (or generate) the input.
  auto t0 = std::chrono::steady_clock::now();
  std::string description;
  vtkSmartPointer<vtkPolyData> input = ReadMesh(options.Input, description, error);
  if (!input)
  {
    return Fail(error);
  }
  const double readSeconds = Seconds(t0, std::chrono::steady_clock::now());
  const long long inputTriangles = CountTriangles(input);
  const long long inputPoints = input->GetNumberOfPoints();
  const bool defaultDemo =
    options.Input == "--demo" || options.Input == "demo" || options.Input == "demo:";
  const std::string inputName = defaultDemo ? std::string(DefaultDemoSpec()) : options.Input;
  if (inputTriangles == 0)
  {
    return Fail("'" + options.Input + "' has no triangles (" + std::to_string(inputPoints) +
                " points, " + std::to_string(input->GetNumberOfCells()) +
                " cells that are vertices or lines): nothing to decimate");
  }
  vtkDataArray* colors = FindColorArray(input, options.Array);
  if (!options.Array.empty() && !colors)
  {
    return Fail("'" + options.Input + "' has no point array named '" + options.Array +
                "' (point arrays: " + PointArrayNames(input) + ")");
  }
  if (verbose)
  {
    std::cout << "input   " << inputName << ": " << description << "\n";
  }

  if (!options.WriteInput.empty())
  {
    if (!WriteMesh(input, options.WriteInput, options.Array, error))
    {
      return Fail(error);
    }
    if (verbose)
    {
      std::cout << "wrote   " << options.WriteInput << " (the input mesh)\n";
    }
    if (options.Output.empty())
    {
      return 0;
    }
  }

  // Decimate.
  vtkNew<vtkColorHalfEdgeDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(options.Reduction);
  filter->SetErrorMetric(options.Metric);
  filter->SetPreserveBoundary(options.PreserveBoundary);
  filter->SetMaximumNormalAngle(options.MaxNormalAngle);
  filter->SetGeometryWeight(options.GeometryWeight);
  filter->SetCollapseSchedule(options.Schedule);
  filter->SetNumberOfThreads(options.Threads);
  if (!options.Array.empty())
  {
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                   options.Array.c_str());
  }
  ProgressBar bar;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(&ProgressBar::Callback);
  progress->SetClientData(&bar);
  if (verbose && isatty(fileno(stderr)))
  {
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
  }
  std::vector<std::string> filterWarnings, filterErrors;
  double filterSeconds = 0;
  long long filterPeak = -1;
  {
    MessageCatcher::Scope scope;
    PeakMemoryProbe probe;
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    filterSeconds = Seconds(start, std::chrono::steady_clock::now());
    filterPeak = probe.PeakAboveBaseline();
    filterWarnings = scope.Get()->Warnings;
    filterErrors = scope.Get()->Errors;
  }
  bar.Finish();
  if (verbose)
  {
    for (const std::string& warning : filterWarnings)
    {
      std::cerr << Program << ": warning: " << MessageCatcher::Clean(warning) << std::endl;
    }
  }
  if (!filterErrors.empty())
  {
    return Fail("decimation failed: " + MessageCatcher::Clean(filterErrors.front()));
  }
  vtkPolyData* output = filter->GetOutput();
  const long long outputTriangles = CountTriangles(output);
  const long long outputPoints = output->GetNumberOfPoints();

  // Write.
  t0 = std::chrono::steady_clock::now();
  if (!WriteMesh(output, options.Output, options.Array, error))
  {
    return Fail(error);
  }
  const double writeSeconds = Seconds(t0, std::chrono::steady_clock::now());
  const long long peakRss = PeakRSS();
  const char* metric = options.Metric == vtkColorHalfEdgeDecimation::HalfEdgeColor
    ? "half-edge-color"
    : options.Metric == vtkColorHalfEdgeDecimation::Geometry ? "geometry"
                                                             : "color-quadric";

  if (verbose)
  {
    char line[512];
    std::snprintf(line, sizeof(line),
                  "output  %s: %lld points, %lld triangles\n"
                  "        reduction %.4f (target %.4f), %lld collapses, metric %s\n"
                  "        filter %.3f s (read %.3f s, write %.3f s), decimation state %s, "
                  "peak RSS %s\n",
                  options.Output.c_str(), outputPoints, outputTriangles,
                  filter->GetActualReduction(), options.Reduction,
                  static_cast<long long>(filter->GetNumberOfCollapses()), metric, filterSeconds,
                  readSeconds, writeSeconds, Mib(filter->GetStateMemory()).c_str(),
                  Mib(peakRss).c_str());
    std::cout << line << std::flush;
  }

  if (!options.Stats.empty())
  {
    std::ofstream json(options.Stats);
    if (!json)
    {
      return Fail("cannot write the statistics to '" + options.Stats + "'");
    }
    char buffer[2048];
    std::snprintf(buffer, sizeof(buffer),
                  "{\n"
                  "  \"input\": %s,\n"
                  "  \"output\": %s,\n"
                  "  \"metric\": \"%s\",\n"
                  "  \"schedule\": \"%s\",\n"
                  "  \"target_reduction\": %.6f,\n"
                  "  \"reduction\": %.6f,\n"
                  "  \"input_points\": %lld,\n"
                  "  \"input_triangles\": %lld,\n"
                  "  \"output_points\": %lld,\n"
                  "  \"output_triangles\": %lld,\n"
                  "  \"collapses\": %lld,\n"
                  "  \"filter_seconds\": %.6f,\n"
                  "  \"read_seconds\": %.6f,\n"
                  "  \"write_seconds\": %.6f,\n"
                  "  \"state_memory_bytes\": %lld,\n"
                  "  \"filter_peak_memory_bytes\": %lld,\n"
                  "  \"peak_rss_bytes\": %lld\n"
                  "}\n",
                  JsonString(inputName).c_str(), JsonString(options.Output).c_str(), metric,
                  options.Schedule == vtkColorHalfEdgeDecimation::Batched ? "batched" : "greedy",
                  options.Reduction, filter->GetActualReduction(), inputPoints, inputTriangles,
                  outputPoints, outputTriangles,
                  static_cast<long long>(filter->GetNumberOfCollapses()), filterSeconds,
                  readSeconds, writeSeconds, static_cast<long long>(filter->GetStateMemory()),
                  filterPeak, peakRss);
    json << buffer;
    json.close();
    if (!json)
    {
      return Fail("cannot write the statistics to '" + options.Stats + "'");
    }
  }

  if (!options.Snapshot.empty())
  {
    colordecimation::fidelity::SnapshotOptions snapshot;
    snapshot.ColorArray = options.Array;
    snapshot.SimplifiedLabel = "color-decimate " +
      std::to_string(static_cast<int>(std::lround(100.0 * filter->GetActualReduction()))) + " %";
    std::string why;
    if (!colordecimation::fidelity::WriteSnapshot(input, output, options.Snapshot,
                                                  options.SnapshotSize, snapshot, &why))
    {
      return Fail("cannot write the snapshot '" + options.Snapshot + "': " + why);
    }
    if (verbose)
    {
      std::cout << "wrote   " << options.Snapshot << " (input left, result right)\n";
    }
  }
  return 0;
}
