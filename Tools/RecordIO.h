/**
 * @file RecordIO.h
 * @brief The collapse record on disk (VTK XML table, .vtt) and the file names of levels of
 * detail, for the tools.
 */
#ifndef colordecimation_tools_RecordIO_h
#define colordecimation_tools_RecordIO_h

#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <string>

namespace colordecimation
{
namespace tools
{

/// Write a collapse record to a .vtt file (binary, compressed); false and a sentence in
/// `error` on failure.
bool WriteRecord(vtkTable* record, const std::string& path, std::string& error);

/// Read a collapse record from a .vtt file; null and a sentence in `error` on failure (no such
/// file, or not a VTK XML table).
vtkSmartPointer<vtkTable> ReadRecord(const std::string& path, std::string& error);

/// `output` with ".lodN" before its extension: k.ply, 1 -> k.lod1.ply.
std::string LevelPath(const std::string& output, int level);

} // namespace tools
} // namespace colordecimation

#endif
