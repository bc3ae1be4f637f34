#include "PlyReader.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <sys/stat.h>
#include <vector>

namespace colordecimation
{
namespace tools
{
namespace
{
bool IsFloat(const PlyProperty& p)
{
  return p.CountSize == 0 && (p.Type == "float" || p.Type == "float32");
}

bool IsByte(const PlyProperty& p)
{
  return p.CountSize == 0 && (p.Type == "uchar" || p.Type == "uint8");
}

/// Where each value the reader keeps lies in a vertex record (-1: absent).
struct VertexLayout
{
  int Position[3] = { -1, -1, -1 };
  int Normal[3] = { -1, -1, -1 };
  int Color[4] = { -1, -1, -1, -1 };
  size_t Stride = 0;
  int ColorComponents() const { return this->Color[0] < 0 ? 0 : (this->Color[3] < 0 ? 3 : 4); }
};

/// Whether vtkPLYReader reads a vertex property of this name as something other than points,
/// normals and colours (texture coordinates, diffuse colours).
bool IsOtherVtkProperty(const std::string& name)
{
  for (const char* other :
       { "u", "v", "texture_u", "texture_v", "diffuse_red", "diffuse_green", "diffuse_blue" })
  {
    if (name == other)
    {
      return true;
    }
  }
  return false;
}

/// The layout of the vertex element; false for a property ReadSimplePly does not read. Other
/// scalar properties, which vtkPLYReader leaves out too (a scanner's confidence or quality),
/// are skipped.
bool FindLayout(const PlyElement& vertex, VertexLayout& layout)
{
  static const char* const names[10] = { "x",  "y",   "z",     "nx",   "ny",
                                         "nz", "red", "green", "blue", "alpha" };
  int* slots[10] = { &layout.Position[0], &layout.Position[1], &layout.Position[2],
                     &layout.Normal[0],   &layout.Normal[1],   &layout.Normal[2],
                     &layout.Color[0],    &layout.Color[1],    &layout.Color[2],
                     &layout.Color[3] };
  for (const PlyProperty& p : vertex.Properties)
  {
    int k = 0;
    while (k < 10 && p.Name != names[k])
    {
      ++k;
    }
    if (k == 10 && p.CountSize == 0 && !IsOtherVtkProperty(p.Name))
    {
      layout.Stride += static_cast<size_t>(p.Size); // skipped, as vtkPLYReader does
      continue;
    }
    if (k == 10 || *slots[k] >= 0 || !(k < 6 ? IsFloat(p) : IsByte(p)))
    {
      return false; // a list, one vtkPLYReader reads otherwise, twice the same, another type
    }
    *slots[k] = static_cast<int>(layout.Stride);
    layout.Stride += static_cast<size_t>(p.Size);
  }
  const auto allOrNone = [](const int* offsets)
  { return (offsets[0] < 0) == (offsets[1] < 0) && (offsets[1] < 0) == (offsets[2] < 0); };
  return layout.Position[0] >= 0 && allOrNone(layout.Position) && allOrNone(layout.Normal) &&
    allOrNone(layout.Color) && (layout.Color[3] < 0 || layout.Color[0] >= 0);
}

/// A file read forwards in large chunks.
class ChunkedFile
{
public:
  ChunkedFile(const std::string& path, uint64_t offset, size_t capacity)
    : File(std::fopen(path.c_str(), "rb"), &std::fclose)
    , Bytes(capacity)
  {
    if (this->File && std::fseek(this->File.get(), static_cast<long>(offset), SEEK_SET) != 0)
    {
      this->File.reset();
    }
  }
  bool IsOpen() const { return this->File != nullptr; }
  /// The next n (<= capacity) bytes, or null at the end of the file; valid until the next call.
  const unsigned char* Take(size_t n)
  {
    if (this->At + n > this->Length && !this->Refill(n))
    {
      return nullptr;
    }
    const unsigned char* bytes = this->Bytes.data() + this->At;
    this->At += n;
    return bytes;
  }

private:
  bool Refill(size_t n)
  {
    const size_t left = this->Length - this->At;
    std::memmove(this->Bytes.data(), this->Bytes.data() + this->At, left);
    this->Length =
      left + std::fread(this->Bytes.data() + left, 1, this->Bytes.size() - left, this->File.get());
    this->At = 0;
    return n <= this->Length;
  }

  std::unique_ptr<FILE, int (*)(FILE*)> File;
  std::vector<unsigned char> Bytes;
  size_t At = 0, Length = 0;
};

constexpr size_t ChunkBytes = size_t(1) << 22;

float FloatAt(const unsigned char* record, int offset)
{
  float value;
  std::memcpy(&value, record + offset, sizeof(value));
  return value;
}

/// The vertex element into points, and colours and normals when the file has them.
bool ReadVertices(ChunkedFile& file, const VertexLayout& layout, vtkIdType count, vtkPolyData* mesh)
{
  vtkNew<vtkFloatArray> xyz, normals;
  vtkNew<vtkUnsignedCharArray> colors;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(count);
  const int channels = layout.ColorComponents();
  colors->SetName(channels == 4 ? "RGBA" : "RGB");
  colors->SetNumberOfComponents(channels == 0 ? 3 : channels);
  colors->SetNumberOfTuples(channels == 0 ? 0 : count);
  const bool withNormals = layout.Normal[0] >= 0;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(withNormals ? count : 0);
  if (xyz->GetNumberOfTuples() != count ||
      colors->GetNumberOfTuples() != (channels == 0 ? 0 : count) ||
      normals->GetNumberOfTuples() != (withNormals ? count : 0))
  {
    throw std::bad_alloc();
  }
  const vtkIdType batch = static_cast<vtkIdType>(ChunkBytes / layout.Stride);
  for (vtkIdType first = 0; first < count; first += batch)
  {
    const vtkIdType n = std::min(batch, count - first);
    const unsigned char* records = file.Take(static_cast<size_t>(n) * layout.Stride);
    if (!records)
    {
      return false;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      const unsigned char* record = records + static_cast<size_t>(i) * layout.Stride;
      float* p = xyz->GetPointer(3 * (first + i));
      float* normal = withNormals ? normals->GetPointer(3 * (first + i)) : nullptr;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = FloatAt(record, layout.Position[k]);
        if (normal)
        {
          normal[k] = FloatAt(record, layout.Normal[k]);
        }
      }
      for (int k = 0; k < channels; ++k)
      {
        colors->SetValue(channels * (first + i) + k, record[layout.Color[k]]);
      }
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  mesh->SetPoints(points);
  if (channels > 0)
  {
    mesh->GetPointData()->SetScalars(colors);
  }
  if (withNormals)
  {
    mesh->GetPointData()->SetNormals(normals);
  }
  return true;
}

/// Corners in a block of malloc's, handed to a VTK array without a copy.
struct CornerBuffer
{
  std::unique_ptr<int32_t, decltype(&std::free)> Ids{ nullptr, &std::free };
  size_t Used = 0, Capacity = 0;

  /// Room for n more (std::bad_alloc when there is no memory for them).
  void Reserve(size_t n)
  {
    if (this->Used + n <= this->Capacity)
    {
      return;
    }
    const size_t capacity = std::max(this->Used + n, this->Capacity + this->Capacity / 2);
    void* grown = std::realloc(this->Ids.get(), capacity * sizeof(int32_t));
    if (!grown)
    {
      throw std::bad_alloc();
    }
    this->Ids.release();
    this->Ids.reset(static_cast<int32_t*>(grown));
    this->Capacity = capacity;
  }
};

/// The face element's corner counts and corners (as stored: 32-bit, signed), from `bytes` of
/// the file; false when it ends first.
bool ReadFaces(ChunkedFile& file, uint64_t count, uint64_t bytes, std::vector<uint8_t>& sizes,
               CornerBuffer& corners)
{
  sizes.resize(count);
  // Room for triangles, or for as many corners as the bytes left can hold if fewer.
  corners.Reserve(std::min<uint64_t>(3 * count, (bytes - count) / 4));
  for (uint64_t f = 0; f < count; ++f)
  {
    const unsigned char* head = file.Take(1);
    const size_t size = head ? *head : 0; // read before the next Take moves the bytes
    const unsigned char* items = head ? file.Take(4 * size) : nullptr;
    if (!items)
    {
      return false;
    }
    corners.Reserve(size);
    sizes[f] = static_cast<uint8_t>(size);
    std::memcpy(corners.Ids.get() + corners.Used, items, 4 * size);
    corners.Used += size;
  }
  return true;
}

/// The offsets of the faces' corners.
template <typename Array>
vtkSmartPointer<Array> Offsets(const std::vector<uint8_t>& sizes)
{
  using Id = typename Array::ValueType;
  auto offsets = vtkSmartPointer<Array>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(sizes.size() + 1));
  if (offsets->GetNumberOfValues() != static_cast<vtkIdType>(sizes.size() + 1))
  {
    throw std::bad_alloc();
  }
  Id* offset = offsets->GetPointer(0);
  offset[0] = 0;
  for (size_t f = 0; f < sizes.size(); ++f)
  {
    offset[f + 1] = offset[f] + Id(sizes[f]);
  }
  return offsets;
}

/// The faces as polygons: 32-bit offsets and ids where the corners allow it (the buffer
/// handed over as it is), 64-bit otherwise.
void SetPolygons(const std::vector<uint8_t>& sizes, CornerBuffer& corners, vtkPolyData* mesh)
{
  vtkNew<vtkCellArray> polygons;
  if (corners.Used <= size_t(std::numeric_limits<int32_t>::max()))
  {
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetArray(corners.Ids.release(), static_cast<vtkIdType>(corners.Used), 0,
                           vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    polygons->SetData(Offsets<vtkTypeInt32Array>(sizes), connectivity);
  }
  else
  {
    vtkNew<vtkTypeInt64Array> connectivity;
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(corners.Used));
    if (connectivity->GetNumberOfValues() != static_cast<vtkIdType>(corners.Used))
    {
      throw std::bad_alloc();
    }
    std::copy(corners.Ids.get(), corners.Ids.get() + corners.Used, connectivity->GetPointer(0));
    polygons->SetData(Offsets<vtkTypeInt64Array>(sizes), connectivity);
  }
  mesh->SetPolys(polygons);
}

/// The bytes of the file after its header (0 when it cannot be measured).
uint64_t BodyBytes(const std::string& path, const PlyHeader& header)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && uint64_t(info.st_size) > header.BodyOffset
    ? uint64_t(info.st_size) - header.BodyOffset
    : 0;
}

/// The vertex layout of a header that passes IsSimplePly; false for one that does not.
bool SimpleLayout(const PlyHeader& header, VertexLayout& layout)
{
  const uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  if (header.Format != "binary_little_endian" || first != 1 || header.Elements.size() != 2 ||
      header.Elements[0].Name != "vertex" || header.Elements[1].Name != "face")
  {
    return false;
  }
  const std::vector<PlyProperty>& face = header.Elements[1].Properties;
  return FindLayout(header.Elements[0], layout) && face.size() == 1 &&
    face[0].Name == "vertex_indices" && face[0].CountSize == 1 && !face[0].CountSigned &&
    face[0].Size == 4 && face[0].Type != "float" && face[0].Type != "float32";
}
} // namespace

bool IsSimplePly(const PlyHeader& header)
{
  VertexLayout layout;
  return SimpleLayout(header, layout);
}

vtkSmartPointer<vtkPolyData> ReadSimplePly(const std::string& path, const PlyHeader& header,
                                           std::string& error)
{
  error.clear();
  VertexLayout layout;
  if (!SimpleLayout(header, layout) || !header.PlyAtStart)
  {
    return nullptr;
  }
  const uint64_t numPoints = header.Elements[0].Count, numFaces = header.Elements[1].Count;
  // The least the elements take (a byte a face), checked before their arrays are allocated:
  // a header may announce more than the file holds.
  const uint64_t body = BodyBytes(path, header);
  if (numPoints > body / layout.Stride || numFaces > body - numPoints * layout.Stride ||
      numPoints > uint64_t(std::numeric_limits<vtkIdType>::max()))
  {
    return nullptr;
  }
  ChunkedFile file(path, header.BodyOffset, ChunkBytes);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  std::vector<uint8_t> sizes;
  CornerBuffer corners;
  try
  {
    if (!file.IsOpen() || !ReadVertices(file, layout, static_cast<vtkIdType>(numPoints), mesh) ||
        !ReadFaces(file, numFaces, body - numPoints * layout.Stride, sizes, corners))
    {
      return nullptr;
    }
    SetPolygons(sizes, corners, mesh);
  }
  catch (const std::bad_alloc&)
  {
    error = "there is not enough memory for its " + std::to_string(numPoints) + " points and " +
      std::to_string(numFaces) + " faces";
    return nullptr;
  }
  return mesh;
}

} // namespace tools
} // namespace colordecimation
