#include "PlyWriter.h"

#include "vtkByteSwap.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkEndian.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <vector>

namespace colordecimation
{
namespace tools
{
namespace
{
/// Bytes gathered before each write to the file.
constexpr size_t BlockBytes = size_t(1) << 20;

/// `array` as floats: itself when it holds floats, else a converted copy (as static_cast).
vtkSmartPointer<vtkFloatArray> AsFloats(vtkDataArray* array)
{
  if (!array)
  {
    return nullptr;
  }
  if (auto* floats = vtkFloatArray::FastDownCast(array))
  {
    return floats;
  }
  auto copy = vtkSmartPointer<vtkFloatArray>::New();
  copy->DeepCopy(array);
  return copy;
}

/// `array` when it has `tuples` tuples of `components` components, else none.
vtkDataArray* Fitting(vtkDataArray* array, vtkIdType tuples, int components)
{
  return array && array->GetNumberOfTuples() == tuples &&
      array->GetNumberOfComponents() == components
    ? array
    : nullptr;
}

/// Copy `count` 4-byte values to `out`, little-endian; the end of what was written.
char* Put4(char* out, const void* values, size_t count)
{
  std::memcpy(out, values, 4 * count);
#ifdef VTK_WORDS_BIGENDIAN
  vtkByteSwap::Swap4LERange(out, count);
#endif
  return out + 4 * count;
}

/// The output file: blocks appended, the first failure kept.
class File
{
public:
  explicit File(const std::string& path)
    : Path(path)
    , Handle(std::fopen(path.c_str(), "wb"))
    , Opened(this->Handle != nullptr)
  {
    this->Fail(!this->Opened);
  }
  ~File()
  {
    if (this->Handle)
    {
      std::fclose(this->Handle);
    }
  }
  void Write(const void* bytes, size_t size)
  {
    this->Fail(!this->Error.empty() || std::fwrite(bytes, 1, size, this->Handle) != size);
  }
  /// Close the file; false with `error` (and the file removed) when anything failed.
  bool Close(std::string& error)
  {
    if (this->Handle)
    {
      this->Fail(std::fclose(this->Handle) != 0);
      this->Handle = nullptr;
    }
    if (!this->Error.empty())
    {
      if (this->Opened)
      {
        std::remove(this->Path.c_str()); // what this wrote, never what was there
      }
      error = this->Error;
    }
    return this->Error.empty();
  }
  void SetError(const std::string& error) { this->Error = error; }
  bool Failed() const { return !this->Error.empty(); }

private:
  void Fail(bool failed)
  {
    if (failed && this->Error.empty())
    {
      this->Error = "cannot write '" + this->Path + "': " + std::strerror(errno);
    }
  }
  std::string Path;
  std::FILE* Handle;
  bool Opened;
  std::string Error;
};

/// What each vertex record holds, in vtkPLYWriter's order.
struct VertexColumns
{
  vtkSmartPointer<vtkFloatArray> Points;
  vtkSmartPointer<vtkFloatArray> Normals; ///< or none
  vtkUnsignedCharArray* Colors = nullptr; ///< or none
  vtkSmartPointer<vtkFloatArray> TCoords; ///< or none

  size_t RecordBytes() const
  {
    return 12 + (this->Normals ? 12 : 0) +
      (this->Colors ? size_t(this->Colors->GetNumberOfComponents()) : 0) + (this->TCoords ? 8 : 0);
  }
};

void AddColorProperties(std::string& header, vtkUnsignedCharArray* colors)
{
  if (colors)
  {
    header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    header += colors->GetNumberOfComponents() == 4 ? "property uchar alpha\n" : "";
  }
}

std::string Header(const VertexColumns& vertex, vtkIdType faces, vtkUnsignedCharArray* faceColors)
{
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment VTK generated PLY File\n"
                       "obj_info vtkPolyData points and polygons: vtk4.0\n";
  header += "element vertex " + std::to_string(vertex.Points->GetNumberOfTuples()) + "\n";
  header += "property float x\nproperty float y\nproperty float z\n";
  header += vertex.Normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "";
  AddColorProperties(header, vertex.Colors);
  header += vertex.TCoords ? "property float u\nproperty float v\n" : "";
  header += "element face " + std::to_string(faces) + "\n";
  header += "property list uchar int vertex_indices\n";
  AddColorProperties(header, faceColors);
  return header + "end_header\n";
}

void WriteVertices(File& file, const VertexColumns& columns)
{
  const vtkIdType n = columns.Points->GetNumberOfTuples();
  const size_t record = columns.RecordBytes();
  const int colorBytes = columns.Colors ? columns.Colors->GetNumberOfComponents() : 0;
  const vtkIdType perBlock = vtkIdType(BlockBytes / record);
  std::vector<char> block(size_t(perBlock) * record);
  for (vtkIdType first = 0; first < n && !file.Failed(); first += perBlock)
  {
    const vtkIdType last = std::min(n, first + perBlock);
    char* out = block.data();
    for (vtkIdType i = first; i < last; ++i)
    {
      out = Put4(out, columns.Points->GetPointer(3 * i), 3);
      if (columns.Normals)
      {
        out = Put4(out, columns.Normals->GetPointer(3 * i), 3);
      }
      if (colorBytes > 0)
      {
        std::memcpy(out, columns.Colors->GetPointer(colorBytes * i), colorBytes);
        out += colorBytes;
      }
      if (columns.TCoords)
      {
        out = Put4(out, columns.TCoords->GetPointer(2 * i), 2);
      }
    }
    file.Write(block.data(), size_t(out - block.data()));
  }
}

/// Each polygon as its byte count, its ids as 32-bit integers and its colour, if any.
void WriteFaces(File& file, vtkCellArray* polys, vtkUnsignedCharArray* colors)
{
  const int colorBytes = colors ? colors->GetNumberOfComponents() : 0;
  std::vector<char> block(BlockBytes + 1 + 4 * 255 + 4);
  char* out = block.data();
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  vtkIdType face = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal() && !file.Failed(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts > 255)
    {
      file.SetError("polygon " + std::to_string(face) + " has " + std::to_string(npts) +
                    " corners: a PLY face counts its corners with a byte (at most 255)");
      return;
    }
    *out++ = static_cast<char>(npts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const int id = static_cast<int>(pts[k]);
      out = Put4(out, &id, 1);
    }
    if (colorBytes > 0)
    {
      std::memcpy(out, colors->GetPointer(colorBytes * face), colorBytes);
      out += colorBytes;
    }
    ++face;
    if (size_t(out - block.data()) >= BlockBytes)
    {
      file.Write(block.data(), size_t(out - block.data()));
      out = block.data();
    }
  }
  file.Write(block.data(), size_t(out - block.data()));
}

/// The colours when they fit (a tuple of 3 or 4 bytes per item); an error otherwise.
bool CheckColors(vtkUnsignedCharArray* colors, vtkIdType items, const char* what,
                 std::string& error)
{
  if (colors && !Fitting(colors, items, 3) && !Fitting(colors, items, 4))
  {
    error = std::string("the ") + what + " colours are not 3 or 4 bytes for each of the " +
      std::to_string(items) + " " + what + "s";
    return false;
  }
  return true;
}
} // namespace

bool WritePly(vtkPolyData* mesh, const std::string& path, vtkUnsignedCharArray* pointColors,
              vtkUnsignedCharArray* faceColors, std::string& error)
{
  if (!mesh || !mesh->GetPoints())
  {
    error = "cannot write '" + path + "': the mesh has no points";
    return false;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkCellArray* polys = mesh->GetPolys();
  if (n > INT_MAX || !CheckColors(pointColors, n, "point", error) ||
      !CheckColors(faceColors, polys->GetNumberOfCells(), "polygon", error))
  {
    error = "cannot write '" + path +
      "': " + (n > INT_MAX ? std::string("PLY's 32-bit ids cannot number its points") : error);
    return false;
  }
  VertexColumns columns;
  columns.Points = AsFloats(mesh->GetPoints()->GetData());
  columns.Normals = AsFloats(Fitting(mesh->GetPointData()->GetNormals(), n, 3));
  columns.Colors = pointColors;
  columns.TCoords = AsFloats(Fitting(mesh->GetPointData()->GetTCoords(), n, 2));
  File file(path);
  const std::string header = Header(columns, polys->GetNumberOfCells(), faceColors);
  file.Write(header.data(), header.size());
  WriteVertices(file, columns);
  WriteFaces(file, polys, faceColors);
  return file.Close(error);
}

} // namespace tools
} // namespace colordecimation
