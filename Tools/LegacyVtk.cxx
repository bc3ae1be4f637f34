#include "LegacyVtk.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace colordecimation
{
namespace tools
{
namespace
{
/// Bytes of a value of a legacy file's type name: -1 for bits (packed), 0 when the size is
/// not known here (strings, variants, long, whose size the writer's platform chose).
int TypeSize(std::string type)
{
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (type == "bit")
  {
    return -1;
  }
  if (type == "unsigned_char" || type == "char" || type == "signed_char")
  {
    return 1;
  }
  if (type == "short" || type == "unsigned_short")
  {
    return 2;
  }
  // vtkIdType: VTK's legacy writer writes ids as 32-bit integers.
  if (type == "int" || type == "unsigned_int" || type == "float" || type == "vtkidtype" ||
      type == "vtktypeint32" || type == "vtktypeuint32")
  {
    return 4;
  }
  if (type == "double" || type == "vtktypeint64" || type == "vtktypeuint64")
  {
    return 8;
  }
  return 0;
}

enum class Step
{
  Read,      ///< the section holds what it announces
  Truncated, ///< the file ends before it does
  Unknown    ///< a section (or a value type) this check does not know: stop checking
};

/// The file, walked a section at a time.
class Walker
{
public:
  Walker(const std::string& path, bool binary, bool offsets, uint64_t size)
    : In(path, std::ios::binary)
    , Binary(binary)
    , Offsets(offsets)
    , Size(size)
  {
  }

  /// The next line that is not blank, as words; false at the end of the file.
  bool Words(std::vector<std::string>& words)
  {
    std::string line;
    while (std::getline(this->In, line))
    {
      std::istringstream split(line);
      words.clear();
      for (std::string word; split >> word;)
      {
        words.push_back(word);
      }
      if (!words.empty())
      {
        return true;
      }
    }
    return false;
  }

  /// Step past `tuples` x `components` values of `type` (binary: bytes; ASCII: words, of
  /// which VTK's reader, reading words, takes `onLine` from the section's own line).
  Step Values(const std::string& type, uint64_t tuples, uint64_t components, size_t onLine = 0)
  {
    const int size = TypeSize(type);
    this->Components = components;
    if (size == 0)
    {
      return Step::Unknown;
    }
    if (components != 0 && tuples > UINT64_MAX / components)
    {
      return Step::Truncated; // more values than any file holds
    }
    const uint64_t count = tuples * components;
    if (!this->Binary)
    {
      std::string word;
      for (uint64_t i = std::min<uint64_t>(onLine, count); i < count; ++i)
      {
        if (!(this->In >> word))
        {
          return Step::Truncated;
        }
      }
      return Step::Read;
    }
    const std::streamoff at = this->In.tellg();
    const uint64_t left = at >= 0 && uint64_t(at) <= this->Size ? this->Size - uint64_t(at) : 0;
    const uint64_t bytes = size < 0    ? count / 8 + (count % 8 != 0 ? 1 : 0)
      : count <= left / uint64_t(size) ? count * uint64_t(size)
                                       : left + 1;
    if (at < 0 || bytes > left)
    {
      return Step::Truncated;
    }
    this->In.seekg(at + std::streamoff(bytes)); // forward only
    return Step::Read;
  }

  /// Colours and lookup tables: bytes in a binary file, floats in an ASCII one.
  Step Colors(uint64_t tuples, uint64_t components, size_t onLine)
  {
    return this->Values(this->Binary ? "unsigned_char" : "float", tuples, components, onLine);
  }

  /// A METADATA block, as VTK's reader reads it: up to an empty line, COMPONENT_NAMES with a
  /// line for each component of the array before it. INFORMATION (keys of many kinds) and
  /// anything else end the check.
  Step Metadata()
  {
    std::string line;
    while (std::getline(this->In, line))
    {
      std::istringstream split(line);
      std::string key;
      if (!(split >> key))
      {
        return Step::Read;
      }
      if (key != "COMPONENT_NAMES")
      {
        return Step::Unknown;
      }
      for (uint64_t c = 0; c < this->Components && std::getline(this->In, line); ++c)
      {
      }
    }
    return Step::Read;
  }

  std::ifstream In;
  const bool Binary;
  const bool Offsets; ///< cells as offsets and connectivity (version 5)
  const uint64_t Size;
  uint64_t Tuples = 0;     ///< of the current POINT_DATA or CELL_DATA
  uint64_t Components = 0; ///< of the last array, for its METADATA's component names
};

uint64_t Number(const std::vector<std::string>& words, size_t i)
{
  return i < words.size() ? std::strtoull(words[i].c_str(), nullptr, 10) : 0;
}

/// The words of a section's line after its first `arity` (values, in an ASCII file).
size_t After(const std::vector<std::string>& words, size_t arity)
{
  return words.size() > arity ? words.size() - arity : 0;
}

std::string Upper(std::string word)
{
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return word;
}

/// Cells (VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS, CELLS) "n size": version 5's OFFSETS
/// (n values; none, and no lines, when n is 0) and CONNECTIVITY (size values), each under its
/// own type line; before, size 32-bit integers.
Step Cells(Walker& walker, const std::vector<std::string>& words)
{
  if (!walker.Offsets)
  {
    return walker.Values("int", Number(words, 2), 1, After(words, 3));
  }
  if (Number(words, 1) == 0)
  {
    return Step::Read;
  }
  for (const char* part : { "OFFSETS", "CONNECTIVITY" })
  {
    std::vector<std::string> line;
    if (!walker.Words(line))
    {
      return Step::Truncated;
    }
    if (Upper(line[0]) != part || line.size() < 2)
    {
      return walker.In.eof() ? Step::Truncated : Step::Unknown; // cut in that line, or other
    }
    const Step step =
      walker.Values(line[1], Number(words, part[0] == 'O' ? 1 : 2), 1, After(line, 2));
    if (step != Step::Read)
    {
      return step;
    }
  }
  return Step::Read;
}

/// FIELD name k: k arrays, each "name components tuples type" and its values (a null array is
/// the line NULL_ARRAY alone); METADATA blocks may come between them.
Step Field(Walker& walker, const std::vector<std::string>& words)
{
  const uint64_t arrays = Number(words, 2);
  for (uint64_t i = 0; i < arrays; ++i)
  {
    std::vector<std::string> line;
    if (!walker.Words(line))
    {
      return Step::Truncated;
    }
    if (Upper(line[0]) == "METADATA")
    {
      const Step step = walker.Metadata();
      if (step != Step::Read)
      {
        return step;
      }
      --i; // the array is still to come
      continue;
    }
    if (line[0] == "NULL_ARRAY")
    {
      continue;
    }
    if (line.size() < 4)
    {
      return Step::Unknown;
    }
    const Step step = walker.Values(line[3], Number(line, 2), Number(line, 1), After(line, 4));
    if (step != Step::Read)
    {
      return step;
    }
  }
  return Step::Read;
}

/// SCALARS name type [components] (a line VTK's reader reads whole), with the optional
/// "LOOKUP_TABLE name" line after it.
Step Scalars(Walker& walker, const std::vector<std::string>& words)
{
  uint64_t components = 1;
  if (words.size() > 3)
  {
    char* end = nullptr;
    const uint64_t given = std::strtoull(words[3].c_str(), &end, 10);
    components = end && *end == '\0' && given > 0 ? given : 1;
  }
  const std::streamoff at = walker.In.tellg();
  std::vector<std::string> next;
  if (!walker.Words(next))
  {
    return walker.Tuples == 0 ? Step::Read : Step::Truncated;
  }
  size_t onLine = After(next, 2);
  if (Upper(next[0]) != "LOOKUP_TABLE")
  {
    walker.In.clear();
    walker.In.seekg(at);
    onLine = 0;
  }
  return walker.Values(words.size() > 2 ? words[2] : "", walker.Tuples, components, onLine);
}

/// An array of the current POINT_DATA or CELL_DATA: "KEY name type" with a fixed number of
/// components, or COLOR_SCALARS "name components", TEXTURE_COORDINATES "name dim type".
Step Attribute(Walker& walker, const std::string& key, const std::vector<std::string>& words)
{
  const uint64_t n = walker.Tuples;
  if (key == "COLOR_SCALARS")
  {
    return walker.Colors(n, Number(words, 2), After(words, 3));
  }
  if (key == "TEXTURE_COORDINATES")
  {
    return walker.Values(words.size() > 3 ? words[3] : "", n, Number(words, 2), After(words, 4));
  }
  const int per = key == "VECTORS" || key == "NORMALS"                    ? 3
    : key == "TENSORS"                                                    ? 9
    : key == "TENSORS6"                                                   ? 6
    : key == "GLOBAL_IDS" || key == "PEDIGREE_IDS" || key == "EDGE_FLAGS" ? 1
                                                                          : 0;
  if (per == 0)
  {
    return Step::Unknown;
  }
  return walker.Values(words.size() > 2 ? words[2] : "", n, per, After(words, 3));
}

/// One section from its keyword line.
Step Section(Walker& walker, const std::vector<std::string>& words)
{
  const std::string key = Upper(words[0]);
  const std::string type = words.size() > 2 ? words[2] : "";
  if (key == "DATASET" || key == "DIMENSIONS" || key == "ORIGIN" || key == "SPACING" ||
      key == "ASPECT_RATIO")
  {
    return Step::Read; // the values are on the line
  }
  if (key == "METADATA")
  {
    return walker.Metadata();
  }
  if (key == "POINT_DATA" || key == "CELL_DATA")
  {
    walker.Tuples = Number(words, 1);
    return Step::Read;
  }
  if (key == "POINTS")
  {
    return walker.Values(type, Number(words, 1), 3, After(words, 3));
  }
  if (key == "X_COORDINATES" || key == "Y_COORDINATES" || key == "Z_COORDINATES")
  {
    return walker.Values(type, Number(words, 1), 1, After(words, 3));
  }
  if (key == "VERTICES" || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS" ||
      key == "CELLS")
  {
    return Cells(walker, words);
  }
  if (key == "CELL_TYPES")
  {
    return walker.Values("int", Number(words, 1), 1, After(words, 2));
  }
  if (key == "FIELD")
  {
    return Field(walker, words);
  }
  if (key == "SCALARS")
  {
    return Scalars(walker, words);
  }
  if (key == "LOOKUP_TABLE")
  {
    return walker.Colors(Number(words, 2), 4, After(words, 3));
  }
  return Attribute(walker, key, words);
}
} // namespace

bool CheckLegacyVtk(const std::string& path, std::string& error)
{
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = probe.tellg();
  probe.seekg(0);
  std::string version, title, format;
  if (!probe || size < 0 || !std::getline(probe, version) || !std::getline(probe, title) ||
      !(probe >> format) || version.rfind("# vtk DataFile Version", 0) != 0)
  {
    return true; // not a legacy file: VTK's reader says so
  }
  // Cells as offsets and connectivity from version 5.0 on, the version read as VTK does.
  int major = 0, minor = 0;
  const bool offsets = std::sscanf(version.c_str() + std::string("# vtk DataFile Version").size(),
                                   "%d.%d", &major, &minor) == 2 &&
    major >= 5;
  Walker walker(path, Upper(format) == "BINARY", offsets, uint64_t(size));
  std::vector<std::string> words;
  for (int skip = 0; skip < 3; ++skip)
  {
    std::getline(walker.In, title); // the version, the title and the format
  }
  while (walker.Words(words))
  {
    const Step step = Section(walker, words);
    if (step == Step::Unknown)
    {
      return true;
    }
    if (step == Step::Truncated)
    {
      error = "'" + path + "' cannot be read: it ends inside its " + words[0] +
        " section (the file is truncated or its header is wrong)";
      return false;
    }
  }
  return true;
}

} // namespace tools
} // namespace colordecimation
