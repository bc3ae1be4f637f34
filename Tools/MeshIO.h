/**
 * @file MeshIO.h
 * @brief Reading, writing and generating coloured meshes for the command-line tools.
 *
 * Inputs: .ply (PlyReader.h for the common binary layouts, vtkPLYReader for the rest), .vtp
 * (vtkXMLPolyDataReader), .vtu (surface of an unstructured grid), .vtk (legacy: polydata, or
 * the surface of any other data set), .obj (vtkOBJReader), .stl (vtkSTLReader), and "demo:"
 * specifications that build a coloured mesh in code with ColorDecimation::Meshes (see
 * DemoHelp()). Outputs: .ply (binary, with the colour array as uchar red/green/blue[/alpha]),
 * .vtp (binary, every array kept) and .vtk (legacy binary polydata).
 *
 * VTK's own error and warning messages are caught (MessageCatcher) so that the tools can
 * report them in one clear line instead of VTK's multi-line output.
 */
#ifndef MeshIO_h
#define MeshIO_h

#include "MeshColors.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataArray;

namespace colordecimation
{
namespace tools
{

/// The extension of `path`, lower case, with its dot (".ply"), or "" when none.
std::string Extension(const std::string& path);

/// 1234567 as "1,234,567".
std::string WithThousands(long long value);

/// True for "--demo", "demo" and "demo:..." inputs.
bool IsDemoSpec(const std::string& input);

/// The text that --help prints about demo specifications.
std::string DemoHelp();

/// The default demo ("demo:" alone), as a full specification.
const char* DefaultDemoSpec();

/**
 * Builds the mesh of a demo specification "demo:[SHAPE][:PATTERN]". Returns nullptr and
 * sets `error` when the specification is wrong. `description` says what was built.
 */
vtkSmartPointer<vtkPolyData> MakeDemo(const std::string& spec, std::string& description,
                                      std::string& error);

/**
 * Reads a mesh file (or builds a demo mesh). Returns nullptr and sets `error` (one line,
 * no trailing newline) when the file is missing, unreadable, of an unsupported type, or
 * not a mesh. Triangles are not checked here (see CountTriangles).
 */
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& description,
                                      std::string& error);

/// True when `path` has an extension WriteMesh() accepts.
bool IsWritableExtension(const std::string& path);

/**
 * Writes `mesh` to .ply, .vtp or .vtk. For .ply (PlyWriter.h), `colorArrayName` (a point
 * array; may be empty: the active scalars) is written as uchar colours, with the face colours
 * of the same name; other colour arrays are converted by `mapping` (MeshColors.h; null: the
 * mapping chosen on this mesh's array), alpha kept. Without point colours, the face colours
 * (FindFaceColorArray) are written.
 */
bool WriteMesh(vtkPolyData* mesh, const std::string& path, const std::string& colorArrayName,
               std::string& error, const ColorMapping* mapping = nullptr);

/// Number of triangles of the mesh's polygons and strips, counted as after triangulation.
long long CountTriangles(vtkPolyData* mesh);

/**
 * The triangles of `mesh`: `mesh` itself when its cells are triangles only, otherwise a copy
 * with polygons and strips triangulated and vertex and line cells left out (every point-data
 * array kept).
 */
vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* mesh);

/// Names of the point-data arrays, comma separated (for messages).
std::string PointArrayNames(vtkPolyData* mesh);

/**
 * Why `mesh` (read from `source`) has no numeric point array named `name`, for an error: no
 * array of that name (the names it has are listed), or one that is not numbers (text).
 */
std::string NoNumericPointArray(vtkPolyData* mesh, const std::string& source,
                                const std::string& name);

/// The colour array: the named point array, or the active point scalars when `name` is empty.
vtkDataArray* FindColorArray(vtkPolyData* mesh, const std::string& name);

/// Face colours a PLY file can hold: the named cell array (or the active cell scalars), when
/// it is unsigned char RGB or RGBA with a tuple a cell and the cells are all polygons; null
/// otherwise.
vtkDataArray* FindFaceColorArray(vtkPolyData* mesh, const std::string& name);

/**
 * A vtkOutputWindow that keeps VTK's error and warning messages instead of printing them.
 * Install with a MessageCatcher::Scope: it catches the messages of its own thread (scopes on
 * several threads each keep their own); the innermost scope of the main thread (the first to
 * make one) also catches those of threads without a scope (workers of parallel loops); with
 * no scope, messages go to stderr. Read a scope's lists (Get()) on its own thread, once the
 * work it watched is done.
 */
class MessageCatcher : public vtkOutputWindow
{
public:
  static MessageCatcher* New();
  vtkTypeMacro(MessageCatcher, vtkOutputWindow);

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char* text) override;

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;

  /// The first error (cleaned of VTK's file/line/object prefix), or "".
  std::string FirstError() const;

  /// Installs a catcher for the lifetime of the scope.
  class Scope
  {
  public:
    Scope();
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    MessageCatcher* Get() const { return this->Catcher; }

  private:
    MessageCatcher* Catcher;
    MessageCatcher* Outer; ///< this thread's enclosing scope's catcher, if any
  };

  /// "ERROR: In file, line N\nvtkClass (0x...): message" -> "message".
  static std::string Clean(const std::string& text);

protected:
  MessageCatcher() = default;
  ~MessageCatcher() override = default;

private:
  MessageCatcher(const MessageCatcher&) = delete;
  void operator=(const MessageCatcher&) = delete;
};

} // namespace tools
} // namespace colordecimation

#endif
