/**
 * @file JsonOutput.h
 * @brief The JSON that the tools write (statistics, measures), on nlohmann::json.
 *
 * Keys stay in the order they are set (nlohmann::ordered_json), strings are escaped by the
 * library (text that is not UTF-8, such as a file name in another encoding, has its bad
 * bytes replaced by U+FFFD rather than failing), and numbers that are not finite are
 * written as null.
 */
#ifndef JsonOutput_h
#define JsonOutput_h

#include <nlohmann/json.hpp>

#include <string>

namespace colordecimation
{
namespace tools
{

/// A JSON value whose object keys keep their order.
using Json = nlohmann::ordered_json;

/// `json` as text, `indent` spaces per level, without a final newline.
std::string JsonText(const Json& json, int indent = 2);

/// Writes JsonText(json) and a newline to `path`; false and `error` when it cannot.
bool WriteJsonFile(const Json& json, const std::string& path, std::string& error);

} // namespace tools
} // namespace colordecimation

#endif
