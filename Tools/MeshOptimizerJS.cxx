#include "MeshOptimizerJS.h"

#include "IndexedMesh.h"
#include "JsonOutput.h"
#include "MeshColors.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

#ifndef COLORDECIMATION_MESHOPTIMIZER_JS_DIR
#define COLORDECIMATION_MESHOPTIMIZER_JS_DIR "Tools/MeshOptimizerJS"
#endif

namespace colordecimation
{
namespace tools
{
namespace
{
const uint32_t Magic = 0x4a4d4443; // "CDMJ" read as a little-endian uint32

/// The folder of simplify.mjs and node_modules.
std::string ScriptFolder()
{
  const char* given = std::getenv("COLORDECIMATION_MESHOPTIMIZER_JS");
  return given && *given ? given : COLORDECIMATION_MESHOPTIMIZER_JS_DIR;
}

bool IsFile(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

/// The first executable `name` on PATH, or "".
std::string FindOnPath(const std::string& name)
{
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':'))
  {
    const std::string candidate = (folder.empty() ? "." : folder) + "/" + name;
    if (IsFile(candidate) && ::access(candidate.c_str(), X_OK) == 0)
    {
      return candidate;
    }
  }
  return "";
}

std::string ReadText(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

/// The last line of `text` that is not empty.
std::string LastLine(const std::string& text)
{
  std::istringstream lines(text);
  std::string line, last;
  while (std::getline(lines, line))
  {
    if (!line.empty())
    {
      last = line;
    }
  }
  return last;
}

/// A fresh temporary folder, removed with its files when the object goes.
class TemporaryFolder
{
public:
  TemporaryFolder()
  {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/colordecimation-XXXXXX";
    if (::mkdtemp(&pattern[0]))
    {
      this->Path = pattern;
    }
  }
  ~TemporaryFolder()
  {
    for (const std::string& name : this->Names)
    {
      std::remove(this->File(name).c_str());
    }
    if (!this->Path.empty())
    {
      ::rmdir(this->Path.c_str());
    }
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

  /// The path of file `name` in the folder (removed with it).
  std::string File(const std::string& name)
  {
    if (std::find(this->Names.begin(), this->Names.end(), name) == this->Names.end())
    {
      this->Names.push_back(name);
    }
    return this->Path + "/" + name;
  }

  std::string Path;

private:
  std::vector<std::string> Names;
};

/// What a run of node gave.
struct NodeRun
{
  int Status = -1; // exit status, or -1 when it did not start or did not exit
  std::string Out, Err;
};

/// Runs node with `arguments`, stdout and stderr into files of `folder`.
NodeRun RunNode(const std::string& node, const std::vector<std::string>& arguments,
                TemporaryFolder& folder)
{
  NodeRun run;
  const std::string out = folder.File("stdout.txt"), err = folder.File("stderr.txt");
  std::vector<std::string> words = { node };
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words)
  {
    argv.push_back(&word[0]);
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, node.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned == 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status))
  {
    run.Status = WEXITSTATUS(status);
  }
  run.Out = ReadText(out);
  run.Err = spawned == 0 ? ReadText(err) : std::string("cannot start ") + node;
  return run;
}

/// What the check found: node's path and the description, or why the package cannot run.
struct Availability
{
  std::string Node, Why, Description;
};

Availability Check()
{
  Availability a;
  a.Node = FindOnPath("node");
  const std::string script = ScriptFolder() + "/simplify.mjs";
  if (a.Node.empty())
  {
    a.Why = "node not found on PATH";
    return a;
  }
  if (!IsFile(script))
  {
    a.Why = script + " not found";
    return a;
  }
  TemporaryFolder folder;
  const NodeRun run = RunNode(a.Node, { script, "--version" }, folder);
  const Json json = Json::parse(run.Out, nullptr, false);
  if (run.Status != 0 || !json.is_object())
  {
    const std::string line = LastLine(run.Err);
    a.Why = line.empty() ? "node " + script + " --version failed" : line;
    return a;
  }
  a.Description = "meshoptimizer " + json.value("meshoptimizer", std::string("?")) +
    " (npm package, WebAssembly) on node " + json.value("node", std::string("?"));
  return a;
}

const Availability& Checked()
{
  static const Availability availability = Check();
  return availability;
}

template <typename T>
void Append(std::string& bytes, const std::vector<T>& values)
{
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// The input file: header, positions, colours in [0,1], indices.
bool WriteInput(vtkPolyData* mesh, const std::string& path, size_t& indexCount)
{
  const IndexedMesh indexed = ToIndexedMesh(mesh);
  const size_t n = indexed.Positions.size() / 3;
  std::vector<float> colors(3 * n, 0.0f);
  if (vtkDataArray* scalars = mesh->GetPointData()->GetScalars())
  {
    const ColorMapping mapping = ColorMapping::Of(scalars);
    for (size_t i = 0; i < n; ++i)
    {
      double rgb[3];
      mapping.ToRGB(scalars, static_cast<vtkIdType>(i), rgb);
      std::copy(rgb, rgb + 3, colors.begin() + 3 * i);
    }
  }
  indexCount = indexed.Indices.size();
  std::string bytes;
  Append(
    bytes,
    std::vector<uint32_t>{ Magic, static_cast<uint32_t>(n), static_cast<uint32_t>(indexCount) });
  Append(bytes, indexed.Positions);
  Append(bytes, colors);
  Append(bytes, indexed.Indices);
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(file);
}

/// `count` values of T at `offset` of `bytes`, the offset moved past them; false if short.
template <typename T>
bool Take(const std::string& bytes, size_t& offset, size_t count, std::vector<T>& values)
{
  if (bytes.size() < offset + count * sizeof(T))
  {
    return false;
  }
  values.resize(count);
  std::memcpy(values.data(), bytes.data() + offset, count * sizeof(T));
  offset += count * sizeof(T);
  return true;
}

/// The output file into `result`: the kept indices and, in Update mode, every vertex.
bool ReadOutput(const std::string& path, size_t vertices, MeshOptimizerJSResult& result)
{
  const std::string bytes = ReadText(path);
  std::vector<uint32_t> header;
  size_t offset = 0;
  if (!Take(bytes, offset, 3, header) || header[0] != Magic ||
      (header[1] != 0 && header[1] != vertices) ||
      !Take(bytes, offset, header[2], result.Triangles))
  {
    return false;
  }
  return header[1] == 0 ||
    (Take(bytes, offset, 3 * vertices, result.Positions) &&
     Take(bytes, offset, 3 * vertices, result.Colors));
}

const char* ModeWord(MeshOptimizerJSMode mode)
{
  switch (mode)
  {
    case MeshOptimizerJSMode::Update:
      return "update";
    case MeshOptimizerJSMode::Prune:
      return "prune";
    default:
      return "attributes";
  }
}

std::string Number(double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

/// The figures that simplify.mjs printed, into `result`; false when they are not there.
bool ReadFigures(const std::string& text, MeshOptimizerJSResult& result)
{
  const Json json = Json::parse(LastLine(text), nullptr, false);
  if (!json.is_object() || !json.contains("seconds"))
  {
    return false;
  }
  result.Seconds = json.value("seconds", 0.0);
  result.CpuSeconds = json.value("cpu_seconds", 0.0);
  result.ResultError = json.value("result_error", 0.0);
  result.PeakBytes = json.value("max_rss_bytes", -1LL) - json.value("rss_before_bytes", 0LL);
  return true;
}

/// The colour of `rgb` (in [0,1]) as `colors` stores it, in tuple `i` of `colors`.
void SetColor(vtkDataArray* colors, const ColorMapping& mapping, vtkIdType i, const float* rgb)
{
  const bool integral = colors->GetDataType() != VTK_FLOAT && colors->GetDataType() != VTK_DOUBLE;
  const int components = colors->GetNumberOfComponents();
  const int written = components >= 3 ? 3 : 1;
  for (int k = 0; k < written; ++k)
  {
    const double c = written == 3 ? rgb[k] : (rgb[0] + rgb[1] + rgb[2]) / 3.0;
    const double value = std::min(1.0, std::max(0.0, c)) / mapping.Scale + mapping.Offset;
    colors->SetComponent(i, k, integral ? std::round(value) : value);
  }
}
} // namespace

const std::string& MeshOptimizerJSUnavailable()
{
  return Checked().Why;
}

const std::string& MeshOptimizerJSDescription()
{
  return Checked().Description;
}

const char* MeshOptimizerJSFunction(MeshOptimizerJSMode mode)
{
  switch (mode)
  {
    case MeshOptimizerJSMode::Update:
      return "simplifyWithUpdate";
    case MeshOptimizerJSMode::Prune:
      return "simplifyWithAttributes + Prune";
    default:
      return "simplifyWithAttributes";
  }
}

MeshOptimizerJSResult SimplifyWithMeshOptimizerJS(vtkPolyData* mesh,
                                                  const MeshOptimizerJSSettings& settings)
{
  MeshOptimizerJSResult result;
  result.TargetError = FLT_MAX;
  if (!MeshOptimizerJSUnavailable().empty())
  {
    result.Error = MeshOptimizerJSUnavailable();
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  TemporaryFolder folder;
  const std::string input = folder.File("input.bin"), output = folder.File("output.bin");
  size_t indexCount = 0;
  if (folder.Path.empty() || !WriteInput(mesh, input, indexCount))
  {
    result.Error = "cannot write the mesh for node into a temporary folder";
    return result;
  }
  const std::string target = std::to_string(TargetIndexCount(indexCount / 3, settings.Reduction));
  const std::string weights = Number(settings.Weights[0]) + "," + Number(settings.Weights[1]) +
    "," + Number(settings.Weights[2]);
  // V8 is made to compile the whole module with its optimising compiler when it is loaded,
  // before the call. By default it compiles each function at its first call with its
  // baseline compiler, and one long call runs that slower code to its end (the same result;
  // simplify.mjs's header).
  const NodeRun run =
    RunNode(Checked().Node,
            { "--no-liftoff", "--no-wasm-lazy-compilation", ScriptFolder() + "/simplify.mjs",
              ModeWord(settings.Mode), input, output, "--target-index-count", target,
              "--target-error", Number(result.TargetError), "--weights", weights },
            folder);
  if (run.Status != 0 || !ReadFigures(run.Out, result) ||
      !ReadOutput(output, static_cast<size_t>(mesh->GetNumberOfPoints()), result))
  {
    const std::string line = LastLine(run.Err);
    result.Error = line.empty() ? "simplify.mjs failed" : line;
    return result;
  }
  result.RoundTripSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

vtkSmartPointer<vtkPolyData> MakeMeshOptimizerJSOutput(vtkPolyData* mesh,
                                                       const MeshOptimizerJSResult& result)
{
  if (result.Positions.empty())
  {
    return MeshOnKeptTriangles(mesh, result.Triangles);
  }
  // Update: the input with the moved points and colours, then its kept triangles.
  vtkNew<vtkPolyData> moved;
  moved->ShallowCopy(mesh);
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, &result.Positions[3 * i]);
  }
  moved->SetPoints(points);
  if (vtkDataArray* colors = mesh->GetPointData()->GetScalars())
  {
    vtkSmartPointer<vtkDataArray> updated = vtk::TakeSmartPointer(colors->NewInstance());
    updated->DeepCopy(colors);
    updated->SetName(colors->GetName());
    const ColorMapping mapping = ColorMapping::Of(colors);
    for (vtkIdType i = 0; i < n; ++i)
    {
      SetColor(updated, mapping, i, &result.Colors[3 * i]);
    }
    moved->GetPointData()->SetScalars(updated);
  }
  return MeshOnKeptTriangles(moved, result.Triangles);
}

} // namespace tools
} // namespace colordecimation
