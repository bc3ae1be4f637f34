#include "JsonOutput.h"

#include <fstream>

namespace colordecimation
{
namespace tools
{

std::string JsonText(const Json& json, int indent)
{
  return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

bool WriteJsonFile(const Json& json, const std::string& path, std::string& error)
{
  std::ofstream file(path);
  file << JsonText(json) << "\n";
  file.close();
  if (!file)
  {
    error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}

} // namespace tools
} // namespace colordecimation
