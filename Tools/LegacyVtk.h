/**
 * @file LegacyVtk.h
 * @brief A legacy VTK file (.vtk) walked section by section before VTK's reader reads it:
 * that reader crashes on a truncated ASCII file and fills a truncated binary one with what
 * its memory held, without an error.
 */
#ifndef colordecimation_tools_LegacyVtk_h
#define colordecimation_tools_LegacyVtk_h

#include <string>

namespace colordecimation
{
namespace tools
{

/**
 * Check that every section of the legacy VTK file `path` that announces a number of values
 * (points, cells, cell types, point and cell data, field arrays, coordinates) holds them, in
 * ASCII or binary, in the format of version 4 (cells as sizes and ids) or 5 (offsets and
 * connectivity). False with `error` saying which section ends early. A section it does not
 * know (or values of variable size, such as strings) ends the check with true: VTK's reader
 * then judges the rest.
 */
bool CheckLegacyVtk(const std::string& path, std::string& error);

} // namespace tools
} // namespace colordecimation

#endif
