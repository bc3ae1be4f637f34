#include "MeshIO.h"

#include "ColorDecimationMeshes.h"
#include "LegacyVtk.h"
#include "MeshColors.h"
#include "PlyHeader.h"
#include "PlyReader.h"
#include "PlyWriter.h"

#include "vtkAbstractArray.h"
#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkErrorCode.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtksys/SystemTools.hxx"
#if COLORDECIMATION_TOOLS_HAVE_SURFACE_FILTER
#include "vtkDataSetSurfaceFilter.h"
#endif

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sys/stat.h>
#include <thread>

namespace colordecimation
{
namespace tools
{
namespace
{
using colordecimation::meshes::Pattern;

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool ParsePattern(const std::string& name, Pattern& pattern, std::string& label)
{
  const std::string n = Lower(name);
  if (n == "sharp" || n == "sharpregions")
  {
    pattern = Pattern::SharpRegions;
    label = "SharpRegions";
  }
  else if (n == "smooth" || n == "smoothgradient")
  {
    pattern = Pattern::SmoothGradient;
    label = "SmoothGradient";
  }
  else if (n == "fine" || n == "finedetail")
  {
    pattern = Pattern::FineDetail;
    label = "FineDetail";
  }
  else if (n == "constant")
  {
    pattern = Pattern::Constant;
    label = "Constant";
  }
  else
  {
    return false;
  }
  return true;
}

/// "ico7" -> ("ico", 7); false when the text is not letters followed by a positive number
/// with an optional k/M suffix.
bool SplitShape(const std::string& text, std::string& shape, long long& number)
{
  size_t i = 0;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i])))
  {
    ++i;
  }
  shape = Lower(text.substr(0, i));
  std::string rest = text.substr(i);
  if (rest.empty())
  {
    number = -1;
    return true;
  }
  double scale = 1;
  const char last = rest.back();
  if (last == 'k' || last == 'K')
  {
    scale = 1e3;
    rest.pop_back();
  }
  else if (last == 'm' || last == 'M')
  {
    scale = 1e6;
    rest.pop_back();
  }
  char* end = nullptr;
  const double value = std::strtod(rest.c_str(), &end);
  if (rest.empty() || end != rest.c_str() + rest.size() || !(value > 0) || value * scale > 1e9)
  {
    return false;
  }
  number = static_cast<long long>(std::llround(value * scale));
  return number > 0;
}

std::string Describe(vtkPolyData* mesh)
{
  return WithThousands(mesh->GetNumberOfPoints()) + " points, " +
    WithThousands(CountTriangles(mesh)) + " triangles";
}

/// The polydata of a reader's output, or the surface of another data set.
vtkSmartPointer<vtkPolyData> AsPolyData(vtkDataObject* data, std::string& error)
{
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    vtkSmartPointer<vtkPolyData> copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(poly);
    return copy;
  }
  auto* dataSet = vtkDataSet::SafeDownCast(data);
  if (!dataSet)
  {
    error = std::string("holds no data set (") + (data ? data->GetClassName() : "nothing") + ")";
    return nullptr;
  }
#if COLORDECIMATION_TOOLS_HAVE_SURFACE_FILTER
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(dataSet);
  surface->Update();
  vtkSmartPointer<vtkPolyData> result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(surface->GetOutput());
  return result;
#else
  error = std::string("holds a ") + dataSet->GetClassName() +
    ", not polygonal data (this build has no surface extraction)";
  return nullptr;
#endif
}
} // namespace

std::string WithThousands(long long value)
{
  std::string digits = std::to_string(value < 0 ? -value : value);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i)
  {
    if (i > 0 && (digits.size() - i) % 3 == 0)
    {
      out += ',';
    }
    out += digits[i];
  }
  return value < 0 ? "-" + out : out;
}

std::string Extension(const std::string& path)
{
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  return Lower(path.substr(dot));
}

bool IsDemoSpec(const std::string& input)
{
  return input == "--demo" || input == "demo" || input.compare(0, 5, "demo:") == 0;
}

const char* DefaultDemoSpec()
{
  return "demo:ico8:fine";
}

std::string DemoHelp()
{
  return "  --demo, demo:           the built-in demo mesh, made in code: an icosphere of level 8\n"
         "                          (1,310,720 triangles, 655,362 points) with the FineDetail\n"
         "                          colours (thin dark stripes and bars on a light ground);\n"
         "                          the same as demo:ico8:fine\n"
         "  demo:SHAPE[:PATTERN]    another generated mesh. SHAPE: ico<level> (20*4^level\n"
         "                          triangles, level 0-10), uv<resolution> (latitude-longitude\n"
         "                          sphere, 2r(r-2) triangles), sphere<count> (UV sphere with\n"
         "                          about count triangles, e.g. sphere1M), torus<n> (n x n/2\n"
         "                          quads), grid<n> (open n x n sheet with a boundary).\n"
         "                          PATTERN: fine (default), sharp, smooth or constant.\n";
}

namespace
{
/// The most triangles the filter takes (their corners are counted in 32 bits), and the largest
/// UV sphere within that: 2 r (r - 2) <= MaximumTriangles.
constexpr long long MaximumTriangles = 715827882;
constexpr int MaximumSphereResolution = 18919;

// The demo mesh of one shape and size (n < 0: the shape's default size), or null with error.
vtkSmartPointer<vtkPolyData> MakeDemoShape(const std::string& shapeText, const std::string& shape,
                                           long long n, Pattern pattern, std::string& what,
                                           std::string& error)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (shape == "ico" || shape == "icosphere")
  {
    n = n < 0 ? 8 : n;
    if (n > 10)
    {
      error = "demo icosphere level must be 0 to 10";
      return nullptr;
    }
    mesh = meshes::Icosphere(static_cast<int>(n), pattern);
    what = "icosphere level " + std::to_string(n);
  }
  else if (shape == "uv")
  {
    n = n < 0 ? 700 : n;
    if (n < 4 || n > MaximumSphereResolution)
    {
      error = "demo UV sphere resolution must be 4 to " + std::to_string(MaximumSphereResolution) +
        " (the filter takes at most " + WithThousands(MaximumTriangles) + " triangles)";
      return nullptr;
    }
    mesh = meshes::UVSphere(static_cast<int>(n), pattern);
    what = "UV sphere of resolution " + std::to_string(n);
  }
  else if (shape == "sphere")
  {
    n = n < 0 ? 1000000 : n;
    const long long largest = 2LL * MaximumSphereResolution * (MaximumSphereResolution - 2);
    if (n > largest)
    {
      error = "demo UV sphere of at most " + WithThousands(largest) +
        " triangles (the largest the filter takes)";
      return nullptr;
    }
    mesh = meshes::UVSphereWithTriangles(n, pattern);
    what = "UV sphere of about " + WithThousands(n) + " triangles";
  }
  else if (shape == "torus")
  {
    n = n < 0 ? 400 : n;
    if (n < 6 || n > 20000)
    {
      error = "demo torus size must be 6 to 20000";
      return nullptr;
    }
    mesh =
      meshes::Torus(static_cast<int>(n), static_cast<int>(std::max<long long>(3, n / 2)), pattern);
    what = "torus " + std::to_string(n) + " x " + std::to_string(std::max<long long>(3, n / 2));
  }
  else if (shape == "grid")
  {
    n = n < 0 ? 300 : n;
    if (n > 20000)
    {
      error = "demo grid size must be 1 to 20000";
      return nullptr;
    }
    mesh = meshes::Grid(static_cast<int>(n), static_cast<int>(n), pattern);
    what = "open grid " + std::to_string(n) + " x " + std::to_string(n);
  }
  else
  {
    error = "unknown demo shape '" + shapeText + "' (expected ico, uv, sphere, torus or grid)";
    return nullptr;
  }
  return mesh;
}
} // namespace

vtkSmartPointer<vtkPolyData> MakeDemo(const std::string& spec, std::string& description,
                                      std::string& error)
{
  std::string body;
  if (spec == "--demo" || spec == "demo" || spec == "demo:")
  {
    body = std::string(DefaultDemoSpec()).substr(5);
  }
  else
  {
    body = spec.substr(5);
  }
  std::string shapeText = body, patternText = "fine";
  const size_t colon = body.find(':');
  if (colon != std::string::npos)
  {
    shapeText = body.substr(0, colon);
    patternText = body.substr(colon + 1);
  }
  if (shapeText.empty())
  {
    shapeText = "ico8";
  }
  Pattern pattern;
  std::string patternLabel;
  if (!ParsePattern(patternText, pattern, patternLabel))
  {
    error = "unknown demo colour pattern '" + patternText +
      "' (expected fine, sharp, smooth or constant)";
    return nullptr;
  }
  std::string shape;
  long long n = 0;
  if (!SplitShape(shapeText, shape, n))
  {
    error = "bad demo shape '" + shapeText + "' (e.g. ico8, uv700, sphere1M, torus400, grid300)";
    return nullptr;
  }
  std::string what;
  vtkSmartPointer<vtkPolyData> mesh = MakeDemoShape(shapeText, shape, n, pattern, what, error);
  if (!mesh)
  {
    return nullptr;
  }
  description = what + ", " + patternLabel + " colours (" + Describe(mesh) + ")";
  return mesh;
}

namespace
{
// Whether path names a readable file (not a directory); error says why not.
bool CheckReadable(const std::string& path, std::string& error)
{
  struct stat info;
  if (::stat(path.c_str(), &info) != 0)
  {
    error = "cannot open '" + path + "': " + std::strerror(errno);
    return false;
  }
  if (S_ISDIR(info.st_mode))
  {
    error = "'" + path + "' is a directory, not a mesh file";
    return false;
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
    {
      error = "cannot open '" + path + "': " + std::strerror(errno);
      return false;
    }
  }
  return true;
}

/// The face's corner list and colours as VTK's PLY reader reads them: a face element needs a
/// vertex_indices (or vertex_index) list, of at most 255 corners (it keeps the count in a
/// byte); colours of the vertex and face elements must be bytes (it converts other types to
/// bytes: 16-bit values wrap, float values in [0, 1] become 0 or 1). "" when the header is
/// one the reader gets right; the corner lists' lengths are left for CheckPlyBody.
std::string CheckPlyElements(PlyHeader& header)
{
  for (PlyElement& element : header.Elements)
  {
    const bool face = element.Name == "face";
    bool corners = false;
    for (PlyProperty& p : element.Properties)
    {
      if (face && p.CountSize > 0 && (p.Name == "vertex_indices" || p.Name == "vertex_index"))
      {
        corners = true;
        p.MaxLength = 255;
      }
      const bool color = (face || element.Name == "vertex") &&
        (p.Name == "red" || p.Name == "green" || p.Name == "blue" || p.Name == "alpha" ||
         (!face &&
          (p.Name == "diffuse_red" || p.Name == "diffuse_green" || p.Name == "diffuse_blue")));
      if (color && p.CountSize == 0 && p.Type != "uchar" && p.Type != "uint8")
      {
        return "it has colours of type " + p.Type + " ('" + element.Name + "' property " + p.Name +
          "), which VTK's PLY reader converts to bytes, losing them: convert the file "
          "to 8-bit colours (uchar) or to .vtp first";
      }
    }
    if (face && !corners)
    {
      return "its 'face' element has no vertex_indices list, which VTK's PLY reader needs";
    }
  }
  return "";
}

/// What VTK's PLY reader would get wrong or crash on, checked first (CheckPlyElements, and a
/// body shorter than its header announces, which it reads past). False with `error`.
bool CheckPly(const std::string& path, std::string& error)
{
  PlyHeader header;
  std::string why;
  if (ReadPlyHeader(path, header, why))
  {
    why = CheckPlyElements(header);
  }
  if (!why.empty() || !CheckPlyBody(path, header, why))
  {
    error = "'" + path + "' cannot be read: " + why;
    return false;
  }
  return true;
}

/// A binary STL file (binary as VTK's reader tells it: by its first bytes) that ends inside a
/// triangle its header counts is truncated. VTK's reader, which reads what is there (header
/// counts are often wrong, so it reads whole triangles to the end), would say nothing.
bool CheckBinaryStl(const std::string& path, std::string& error)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  unsigned char header[84];
  in.seekg(0);
  if (size < 0 || !in.read(reinterpret_cast<char*>(header), sizeof(header)) ||
      vtksys::SystemTools::DetectFileType(path.c_str()) != vtksys::SystemTools::FileTypeBinary)
  {
    return true; // an ASCII file, or none: VTK's reader judges it
  }
  const uint64_t count = uint64_t(header[80]) | uint64_t(header[81]) << 8 |
    uint64_t(header[82]) << 16 | uint64_t(header[83]) << 24;
  const uint64_t body = uint64_t(size) - 84;
  if (body < 50 * count && body % 50 != 0)
  {
    error = "'" + path + "' cannot be read: it ends inside a triangle (" + std::to_string(body) +
      " bytes after its header: " + std::to_string(body / 50) + " triangles and " +
      std::to_string(body % 50) + " bytes, of the " + std::to_string(count) + " its header counts)";
    return false;
  }
  return true;
}

/// The reader of the file's extension, its file name set; null for an extension none reads.
vtkSmartPointer<vtkAlgorithm> ReaderFor(const std::string& path, const std::string& ext)
{
  const auto named = [&path](auto reader)
  {
    reader->SetFileName(path.c_str());
    return vtkSmartPointer<vtkAlgorithm>(reader);
  };
  if (ext == ".ply")
  {
    return named(vtkSmartPointer<vtkPLYReader>::New());
  }
  if (ext == ".vtp")
  {
    return named(vtkSmartPointer<vtkXMLPolyDataReader>::New());
  }
  if (ext == ".vtu")
  {
    return named(vtkSmartPointer<vtkXMLUnstructuredGridReader>::New());
  }
  if (ext == ".vtk")
  {
    return named(vtkSmartPointer<vtkGenericDataObjectReader>::New());
  }
  if (ext == ".obj")
  {
    return named(vtkSmartPointer<vtkOBJReader>::New());
  }
  if (ext == ".stl")
  {
    return named(vtkSmartPointer<vtkSTLReader>::New());
  }
  return nullptr;
}

/// Whether the file is of its extension's type, and holds nothing VTK's reader would crash
/// on or get wrong without a word (CheckPly, CheckLegacyVtk, CheckBinaryStl); false with
/// `error`.
bool CheckBeforeReading(vtkAlgorithm* reader, const std::string& path, const std::string& ext,
                        std::string& error)
{
  if (ext == ".ply" && !vtkPLYReader::CanReadFile(path.c_str()))
  {
    error = "'" + path + "' is not a PLY file (it does not start with a PLY header)";
    return false;
  }
  auto* xml = vtkXMLReader::SafeDownCast(reader);
  if (xml && !xml->CanReadFile(path.c_str()))
  {
    error = "'" + path + "' is not a VTK XML " + (ext == ".vtp" ? "PolyData" : "UnstructuredGrid") +
      " file";
    return false;
  }
  auto* legacy = vtkGenericDataObjectReader::SafeDownCast(reader);
  if (legacy)
  {
    const bool header = legacy->OpenVTKFile() && legacy->ReadHeader();
    legacy->CloseVTKFile();
    if (!header)
    {
      error = "'" + path + "' is not a legacy VTK file (no '# vtk DataFile' header)";
      return false;
    }
  }
  return ext == ".ply" ? CheckPly(path, error)
    : legacy           ? CheckLegacyVtk(path, error)
    : ext == ".stl"    ? CheckBinaryStl(path, error)
                       : true;
}

// The mesh read by the reader of the file's extension, or null with error (the file is
// not of its type) or problem (the reader gave no polygonal mesh).
vtkSmartPointer<vtkPolyData> ReadByExtension(const std::string& path, const std::string& ext,
                                             std::string& problem, std::string& error)
{
  PlyHeader header;
  std::string unread;
  if (ext == ".ply" && ReadPlyHeader(path, header, unread))
  {
    vtkSmartPointer<vtkPolyData> mesh = ReadSimplePly(path, header, unread);
    if (mesh || !unread.empty())
    {
      error = mesh ? "" : "cannot read '" + path + "': " + unread;
      return mesh;
    }
    // Not read: another layout, or a file shorter than its header says (CheckPly, below,
    // says where it ends).
  }
  vtkSmartPointer<vtkAlgorithm> reader = ReaderFor(path, ext);
  if (!reader)
  {
    error = "unsupported input type '" + (ext.empty() ? std::string("(no extension)") : ext) +
      "' for '" + path + "' (expected .ply, .vtp, .vtu, .vtk, .obj, .stl or demo:)";
    return nullptr;
  }
  if (!CheckBeforeReading(reader, path, ext, error))
  {
    return nullptr;
  }
  reader->Update();
  return AsPolyData(reader->GetOutputDataObject(0), problem);
}
} // namespace

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& description,
                                      std::string& error)
{
  if (IsDemoSpec(path))
  {
    return MakeDemo(path, description, error);
  }
  if (!CheckReadable(path, error))
  {
    return nullptr;
  }
  const std::string ext = Extension(path);
  MessageCatcher::Scope scope;
  std::string problem;
  std::string typeError;
  vtkSmartPointer<vtkPolyData> mesh = ReadByExtension(path, ext, problem, typeError);
  if (!typeError.empty())
  {
    error = typeError;
    return nullptr;
  }
  if (!scope.Get()->Errors.empty())
  {
    error = "cannot read '" + path + "': " + scope.Get()->FirstError();
    return nullptr;
  }
  if (!mesh)
  {
    error = "cannot read '" + path + "': " + (problem.empty() ? "the reader failed" : problem);
    return nullptr;
  }
  if (mesh->GetNumberOfPoints() == 0)
  {
    error = "'" + path + "' holds no points: it is not a mesh, or an empty one";
    return nullptr;
  }
  description = Describe(mesh);
  return mesh;
}

bool IsWritableExtension(const std::string& path)
{
  const std::string ext = Extension(path);
  return ext == ".ply" || ext == ".vtp" || ext == ".vtk";
}

namespace
{
/// The mesh as PLY (PlyWriter.h): the point colours as bytes (mapped by `mapping`, or by the
/// array's own range) with the face colours of the same name, or else the face colours alone.
bool WritePlyMesh(vtkPolyData* mesh, const std::string& path, const std::string& colorArrayName,
                  const ColorMapping* mapping, std::string& error)
{
  // PLY's faces are polygons: strips go as their triangles.
  vtkSmartPointer<vtkPolyData> out =
    mesh->GetNumberOfStrips() > 0 ? Triangulated(mesh) : vtkSmartPointer<vtkPolyData>(mesh);
  vtkDataArray* colors = FindColorArray(out, colorArrayName);
  vtkSmartPointer<vtkUnsignedCharArray> pointColors;
  vtkUnsignedCharArray* faceColors = nullptr;
  if (colors && colors->GetNumberOfTuples() == mesh->GetNumberOfPoints())
  {
    const int comps = colors->GetNumberOfComponents();
    pointColors = vtkUnsignedCharArray::SafeDownCast(colors);
    if (!pointColors || (comps != 3 && comps != 4))
    {
      pointColors = ToUnsignedChar(colors, mapping ? *mapping : ColorMapping::Of(colors), true);
    }
    // Face colours of the same name too (PLY's reader names both RGB or RGBA).
    const char* name = colors->GetName();
    faceColors =
      name && *name ? vtkUnsignedCharArray::SafeDownCast(FindFaceColorArray(out, name)) : nullptr;
  }
  else
  {
    faceColors = vtkUnsignedCharArray::SafeDownCast(FindFaceColorArray(out, colorArrayName));
  }
  return WritePly(out, path, pointColors, faceColors, error);
}

/// ": why" a VTK writer failed: its first message, unless the executive's "returned failure"
/// is all there is (vtkXMLWriter out of disk space says no more), then its error code.
std::string WriteFailure(unsigned long code, const MessageCatcher& caught)
{
  for (const std::string& message : caught.Errors)
  {
    if (message.find("returned failure for request") == std::string::npos)
    {
      return ": " + MessageCatcher::Clean(message);
    }
  }
  if (code == vtkErrorCode::OutOfDiskSpaceError)
  {
    return ": out of disk space";
  }
  if (code != vtkErrorCode::NoError)
  {
    return ": " + std::string(vtkErrorCode::GetStringFromErrorCode(code));
  }
  return caught.Errors.empty() ? std::string() : ": " + caught.FirstError();
}
} // namespace

bool WriteMesh(vtkPolyData* mesh, const std::string& path, const std::string& colorArrayName,
               std::string& error, const ColorMapping* mapping)
{
  const std::string ext = Extension(path);
  MessageCatcher::Scope scope;
  int ok = 0;
  unsigned long code = vtkErrorCode::NoError;
  if (ext == ".ply")
  {
    if (!WritePlyMesh(mesh, path, colorArrayName, mapping, error))
    {
      return false;
    }
    ok = 1;
  }
  else if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    // Inline binary rather than appended data: VTK 9.2's reader cannot parse appended data
    // with Debian 12's newer libexpat1 updates (2.5.0-1+deb12u2 and later).
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToZLib();
    writer->SetInputData(mesh);
    ok = writer->Write();
    code = writer->GetErrorCode();
  }
  else if (ext == ".vtk")
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetFileTypeToBinary();
    writer->SetInputData(mesh);
    ok = writer->Write();
    code = writer->GetErrorCode();
  }
  else
  {
    error = "unsupported output type '" + (ext.empty() ? std::string("(no extension)") : ext) +
      "' for '" + path + "' (expected .ply, .vtp or .vtk)";
    return false;
  }
  if (!ok || !scope.Get()->Errors.empty())
  {
    error = "cannot write '" + path + "'" + WriteFailure(code, *scope.Get());
    return false;
  }
  return true;
}

long long CountTriangles(vtkPolyData* mesh)
{
  long long count = 0;
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips() })
  {
    if (!cells || cells->GetNumberOfCells() == 0)
    {
      continue;
    }
    if (cells == mesh->GetPolys() && cells->IsHomogeneous() == 3)
    {
      count += cells->GetNumberOfCells();
      continue;
    }
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      it->GetCurrentCell(npts, pts);
      count += npts >= 3 ? npts - 2 : 0;
    }
  }
  return count;
}

vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* mesh)
{
  vtkCellArray* polys = mesh->GetPolys();
  const bool pure = mesh->GetNumberOfStrips() == 0 && mesh->GetNumberOfVerts() == 0 &&
    mesh->GetNumberOfLines() == 0 &&
    (polys->GetNumberOfCells() == 0 || polys->IsHomogeneous() == 3);
  if (pure)
  {
    return mesh;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(mesh);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(triangles->GetOutput());
  return result;
}

std::string PointArrayNames(vtkPolyData* mesh)
{
  std::string names;
  vtkPointData* pd = mesh->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    const char* name = pd->GetArrayName(i);
    if (!name)
    {
      continue;
    }
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  return names.empty() ? std::string("none") : names;
}

std::string NoNumericPointArray(vtkPolyData* mesh, const std::string& source,
                                const std::string& name)
{
  vtkAbstractArray* other = mesh->GetPointData()->GetAbstractArray(name.c_str());
  if (other)
  {
    return "the point array '" + name + "' of '" + source + "' is a " + other->GetClassName() +
      ", not numbers: colours and locks are numeric arrays";
  }
  return "'" + source + "' has no point array named '" + name +
    "' (point arrays: " + PointArrayNames(mesh) + ")";
}

vtkDataArray* FindFaceColorArray(vtkPolyData* mesh, const std::string& name)
{
  vtkDataArray* faces =
    name.empty() ? mesh->GetCellData()->GetScalars() : mesh->GetCellData()->GetArray(name.c_str());
  const int comps = faces ? faces->GetNumberOfComponents() : 0;
  // A PLY file numbers face colours by polygon: the cells must be polygons alone.
  return faces && faces->GetDataType() == VTK_UNSIGNED_CHAR && (comps == 3 || comps == 4) &&
      faces->GetNumberOfTuples() == mesh->GetNumberOfCells() &&
      mesh->GetNumberOfCells() == mesh->GetNumberOfPolys()
    ? faces
    : nullptr;
}

vtkDataArray* FindColorArray(vtkPolyData* mesh, const std::string& name)
{
  if (name.empty())
  {
    return mesh->GetPointData()->GetScalars();
  }
  return mesh->GetPointData()->GetArray(name.c_str());
}

//------------------------------------------------------------------------------
vtkStandardNewMacro(MessageCatcher);

namespace
{
/// Guards the main thread's scopes and every catcher's lists.
std::mutex CatcherMutex;
/// The thread that made the first scope (the program's main thread), and its scopes alive.
std::thread::id MainThread;
std::vector<MessageCatcher*> MainScopes;
/// The catcher of this thread's innermost scope, if any.
thread_local MessageCatcher* ThreadCatcher = nullptr;

/// The output window from the first scope on: one catcher that hands each message on (Route).
/// Made once and kept (VTK deletes it at exit), so that no thread can call a deleted window.
MessageCatcher* Router()
{
  static MessageCatcher* const router = []
  {
    MainThread = std::this_thread::get_id();
    MessageCatcher* made = MessageCatcher::New();
    vtkOutputWindow::SetInstance(made);
    made->Delete(); // held by VTK
    return made;
  }();
  return router;
}

/// A message of the router to the catcher of the thread's innermost scope; from a thread with
/// none (a worker of a parallel loop), to the main thread's innermost scope's; with neither, to
/// stderr as VTK's own window would. Into `list` (null: a catcher drops it).
void Route(MessageCatcher* self, const char* text, std::vector<std::string> MessageCatcher::*list)
{
  const std::lock_guard<std::mutex> lock(CatcherMutex);
  MessageCatcher* sink = self != Router() ? self
    : ThreadCatcher                       ? ThreadCatcher
    : MainScopes.empty()                  ? nullptr
                                          : MainScopes.back();
  if (!sink)
  {
    std::cerr << (text ? text : "") << std::endl;
  }
  else if (list)
  {
    (sink->*list).emplace_back(text ? text : "");
  }
}
} // namespace

void MessageCatcher::DisplayText(const char* text)
{
  // Plain text from VTK objects (PrintSelf and the like): not expected here; dropped inside a
  // scope, printed outside one.
  Route(this, text, nullptr);
}

void MessageCatcher::DisplayErrorText(const char* text)
{
  Route(this, text, &MessageCatcher::Errors);
}

void MessageCatcher::DisplayWarningText(const char* text)
{
  Route(this, text, &MessageCatcher::Warnings);
}

void MessageCatcher::DisplayGenericWarningText(const char* text)
{
  this->DisplayWarningText(text);
}

void MessageCatcher::DisplayDebugText(const char* text)
{
  Route(this, text, nullptr);
}

std::string MessageCatcher::FirstError() const
{
  return this->Errors.empty() ? std::string() : Clean(this->Errors.front());
}

std::string MessageCatcher::Clean(const std::string& text)
{
  std::string message = text;
  // VTK 9: "ERROR: In /path/file.cxx, line 123\nvtkClass (0x1234): message\n\n"
  if (message.compare(0, 7, "ERROR: ") == 0 || message.compare(0, 9, "Warning: ") == 0 ||
      message.compare(0, 16, "Generic Warning:") == 0)
  {
    const size_t newline = message.find('\n');
    message = (newline == std::string::npos) ? std::string() : message.substr(newline + 1);
  }
  const size_t object = message.find("): ");
  if (object != std::string::npos && message.find(" (0x") != std::string::npos &&
      message.find(" (0x") < object)
  {
    message = message.substr(object + 3);
  }
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
  {
    message.pop_back();
  }
  for (char& c : message)
  {
    c = (c == '\n') ? ' ' : c;
  }
  return message.empty() ? text : message;
}

MessageCatcher::Scope::Scope()
  : Catcher(MessageCatcher::New())
  , Outer(ThreadCatcher)
{
  Router();
  ThreadCatcher = this->Catcher;
  if (std::this_thread::get_id() == MainThread)
  {
    const std::lock_guard<std::mutex> lock(CatcherMutex);
    MainScopes.push_back(this->Catcher);
  }
}

MessageCatcher::Scope::~Scope()
{
  ThreadCatcher = this->Outer;
  if (std::this_thread::get_id() == MainThread)
  {
    const std::lock_guard<std::mutex> lock(CatcherMutex);
    MainScopes.pop_back();
  }
  this->Catcher->Delete();
}

} // namespace tools
} // namespace colordecimation
