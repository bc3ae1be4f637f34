/**
 * @file PlyHeader.h
 * @brief A PLY file's header, read to check the file before VTK's reader does: that reader
 * reads past the end of a truncated binary file (a crash) and wraps 16-bit colours modulo 256.
 */
#ifndef colordecimation_tools_PlyHeader_h
#define colordecimation_tools_PlyHeader_h

#include <cstdint>
#include <string>
#include <vector>

namespace colordecimation
{
namespace tools
{

struct PlyProperty
{
  std::string Name;
  int Size = 0;      ///< bytes of a value (of an item, for a list)
  int CountSize = 0; ///< bytes of a list's count; 0 for a scalar property
  bool CountSigned = false;
  uint64_t MaxLength = UINT64_MAX; ///< the longest list a reader takes (checked by CheckPlyBody)
  std::string Type;                ///< as the header names it ("uchar", "float", ...)
};

struct PlyElement
{
  std::string Name;
  uint64_t Count = 0;
  std::vector<PlyProperty> Properties;
};

struct PlyHeader
{
  std::string Format; ///< "ascii", "binary_little_endian" or "binary_big_endian"
  std::vector<PlyElement> Elements;
  uint64_t BodyOffset = 0; ///< where the data starts (after "end_header\n")
  /// The file's first bytes are "ply", as vtkPLYReader asks (this reading allows blanks first).
  bool PlyAtStart = false;
};

/// Read the header of `path`; false with `error` when it is not a complete PLY header.
bool ReadPlyHeader(const std::string& path, PlyHeader& header, std::string& error);

/**
 * Check that a PLY file holds every element its header announces: in a binary file each
 * list's count read and its items skipped, in an ASCII one a complete row a line; and that no
 * list is longer than its property's MaxLength. False with `error` saying where.
 */
bool CheckPlyBody(const std::string& path, const PlyHeader& header, std::string& error);

} // namespace tools
} // namespace colordecimation

#endif
