#include "PlyHeader.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace colordecimation
{
namespace tools
{
namespace
{
/// Bytes of a PLY scalar type; 0 for a name that is none.
int TypeSize(const std::string& type)
{
  static const struct
  {
    const char* Name;
    int Size;
  } types[] = { { "char", 1 },  { "int8", 1 },    { "uchar", 1 },  { "uint8", 1 },
                { "short", 2 }, { "int16", 2 },   { "ushort", 2 }, { "uint16", 2 },
                { "int", 4 },   { "int32", 4 },   { "uint", 4 },   { "uint32", 4 },
                { "float", 4 }, { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  for (const auto& t : types)
  {
    if (type == t.Name)
    {
      return t.Size;
    }
  }
  return 0;
}

/// One line of the header: a "property" line read into `element`; false with `error`.
bool ReadProperty(std::istringstream& words, PlyElement* element, std::string& error)
{
  PlyProperty property;
  std::string type;
  words >> type;
  if (type == "list")
  {
    std::string countType;
    words >> countType >> type;
    property.CountSize = TypeSize(countType);
    property.CountSigned = countType == "char" || countType == "int8" || countType == "short" ||
      countType == "int16" || countType == "int" || countType == "int32";
    if (property.CountSize == 0)
    {
      error = "its header has a list property whose count type '" + countType + "' is unknown";
      return false;
    }
  }
  property.Type = type;
  property.Size = TypeSize(type);
  words >> property.Name;
  if (!element || property.Size == 0 || property.Name.empty())
  {
    error = "its header has a property line that cannot be read (type '" + type + "')";
    return false;
  }
  element->Properties.push_back(property);
  return true;
}

/// A window on the file's bytes, read 1 MiB at a time as the walk goes forward.
struct ByteWindow
{
  std::ifstream In;
  uint64_t Size = 0;
  std::vector<char> Bytes = std::vector<char>(1 << 20);
  uint64_t Start = 0;
  size_t Length = 0;

  /// The `n` (<= 8) bytes at `at`; false past the end of the file.
  bool Get(uint64_t at, int n, unsigned char* out)
  {
    if (at + n > this->Size)
    {
      return false;
    }
    if (at < this->Start || at + n > this->Start + this->Length)
    {
      this->In.clear();
      this->In.seekg(static_cast<std::streamoff>(at));
      this->In.read(this->Bytes.data(), static_cast<std::streamsize>(this->Bytes.size()));
      this->Start = at;
      this->Length = static_cast<size_t>(this->In.gcount());
      if (this->Length < static_cast<size_t>(n))
      {
        return false;
      }
    }
    std::memcpy(out, this->Bytes.data() + (at - this->Start), n);
    return true;
  }
};

/// A list's count, as stored (`size` bytes, either byte order); -1 past the end.
int64_t ReadCount(ByteWindow& window, uint64_t at, int size, bool bigEndian, bool isSigned)
{
  unsigned char bytes[8];
  if (!window.Get(at, size, bytes))
  {
    return -1;
  }
  uint64_t value = 0;
  for (int k = 0; k < size; ++k)
  {
    value |= uint64_t(bytes[bigEndian ? size - 1 - k : k]) << (8 * k);
  }
  if (isSigned && (value >> (8 * size - 1)) != 0)
  {
    return -2; // a negative count
  }
  return static_cast<int64_t>(value);
}

/// A list's length as read: "" if it is one the reader takes, else what is wrong with it.
std::string CheckLength(const PlyElement& element, const PlyProperty& p, uint64_t row,
                        int64_t count)
{
  if (count < 0)
  {
    return "its '" + element.Name + "' element " + std::to_string(row) +
      " has a list of negative length";
  }
  if (uint64_t(count) > p.MaxLength)
  {
    return "its '" + element.Name + "' element " + std::to_string(row) + " has a " + p.Name +
      " list of " + std::to_string(count) + " items, more than the " + std::to_string(p.MaxLength) +
      " VTK's PLY reader takes";
  }
  return "";
}

/// Walk an element's rows from `at` (lists' counts read); false with `error` at a bad place.
bool SkipElement(ByteWindow& window, const PlyElement& element, bool bigEndian, uint64_t& at,
                 std::string& error)
{
  uint64_t fixed = 0;
  bool lists = false;
  for (const PlyProperty& p : element.Properties)
  {
    lists = lists || p.CountSize > 0;
    fixed += p.CountSize > 0 ? 0 : uint64_t(p.Size);
  }
  if (!lists)
  {
    if (fixed > 0 && element.Count > (window.Size - std::min(at, window.Size)) / fixed)
    {
      error = "it ends inside its '" + element.Name + "' elements (" +
        std::to_string(element.Count) + " announced)";
      return false;
    }
    at += element.Count * fixed;
    return true;
  }
  for (uint64_t row = 0; row < element.Count; ++row)
  {
    for (const PlyProperty& p : element.Properties)
    {
      if (p.CountSize == 0)
      {
        at += uint64_t(p.Size);
        continue;
      }
      const int64_t count = ReadCount(window, at, p.CountSize, bigEndian, p.CountSigned);
      error = count == -1 ? "it ends inside its '" + element.Name + "' elements (at " +
          std::to_string(row) + " of " + std::to_string(element.Count) + " announced)"
                          : CheckLength(element, p, row, count == -2 ? -1 : count);
      if (!error.empty())
      {
        return false;
      }
      at += uint64_t(p.CountSize) + uint64_t(count) * uint64_t(p.Size);
    }
  }
  if (at > window.Size)
  {
    error = "it ends inside its last '" + element.Name + "' element";
    return false;
  }
  return true;
}
/// What is wrong with an ASCII row (one line), "" if nothing: it must hold a token for each
/// scalar, and a count the list may have and that many tokens for each list.
std::string CheckRow(const std::string& line, const PlyElement& element, uint64_t row)
{
  const std::string lacking =
    "its '" + element.Name + "' element " + std::to_string(row) + " lacks values";
  const char* c = line.c_str();
  const auto next = [&c]() -> const char*
  {
    while (*c == ' ' || *c == '\t' || *c == '\r')
    {
      ++c;
    }
    if (*c == '\0')
    {
      return nullptr;
    }
    const char* token = c;
    while (*c && *c != ' ' && *c != '\t' && *c != '\r')
    {
      ++c;
    }
    return token;
  };
  for (const PlyProperty& p : element.Properties)
  {
    const char* token = next();
    if (!token)
    {
      return lacking;
    }
    if (p.CountSize > 0)
    {
      const long long count = std::strtoll(token, nullptr, 10);
      const std::string wrong = CheckLength(element, p, row, count);
      if (!wrong.empty())
      {
        return wrong;
      }
      for (long long k = 0; k < count; ++k)
      {
        if (!next())
        {
          return lacking;
        }
      }
    }
  }
  return "";
}

/// Every element of an ASCII body there, one complete row a line.
bool CheckAsciiBody(const std::string& path, const PlyHeader& header, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.BodyOffset));
  std::string line;
  for (const PlyElement& element : header.Elements)
  {
    for (uint64_t row = 0; row < element.Count; ++row)
    {
      error = std::getline(in, line) ? CheckRow(line, element, row)
                                     : "it ends inside its '" + element.Name + "' elements (at " +
          std::to_string(row) + " of " + std::to_string(element.Count) + " announced)";
      if (!error.empty())
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

bool ReadPlyHeader(const std::string& path, PlyHeader& header, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  header = PlyHeader();
  PlyElement* element = nullptr;
  for (int lines = 0; lines < 100000 && std::getline(in, line); ++lines)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (lines == 0 && keyword != "ply")
    {
      break;
    }
    header.PlyAtStart = header.PlyAtStart || (lines == 0 && line.compare(0, 3, "ply") == 0);
    if (keyword == "format")
    {
      words >> header.Format;
    }
    else if (keyword == "element")
    {
      header.Elements.emplace_back();
      element = &header.Elements.back();
      words >> element->Name >> element->Count;
      if (!words)
      {
        error = "its header has an element line that cannot be read ('" + line + "')";
        return false;
      }
    }
    else if (keyword == "property" && !ReadProperty(words, element, error))
    {
      return false;
    }
    else if (keyword == "end_header")
    {
      header.BodyOffset = static_cast<uint64_t>(in.tellg());
      return true;
    }
  }
  error = "it has no complete PLY header (no 'end_header' line)";
  return false;
}

bool CheckPlyBody(const std::string& path, const PlyHeader& header, std::string& error)
{
  if (header.Format == "ascii")
  {
    return CheckAsciiBody(path, header, error);
  }
  if (header.Format != "binary_little_endian" && header.Format != "binary_big_endian")
  {
    error = "its format '" + header.Format + "' is none of PLY's";
    return false;
  }
  struct stat info;
  ByteWindow window;
  window.In.open(path, std::ios::binary);
  if (::stat(path.c_str(), &info) != 0 || !window.In)
  {
    error = "it cannot be read";
    return false;
  }
  window.Size = static_cast<uint64_t>(info.st_size);
  const bool bigEndian = header.Format == "binary_big_endian";
  uint64_t at = header.BodyOffset;
  for (const PlyElement& element : header.Elements)
  {
    if (!SkipElement(window, element, bigEndian, at, error))
    {
      return false;
    }
  }
  return true;
}

} // namespace tools
} // namespace colordecimation
