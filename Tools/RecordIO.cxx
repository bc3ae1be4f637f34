#include "RecordIO.h"

#include "MeshIO.h"

#include "vtkNew.h"
#include "vtkXMLTableReader.h"
#include "vtkXMLTableWriter.h"

#include <fstream>

namespace colordecimation
{
namespace tools
{

bool WriteRecord(vtkTable* record, const std::string& path, std::string& error)
{
  MessageCatcher::Scope scope;
  vtkNew<vtkXMLTableWriter> writer;
  writer->SetInputData(record);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1 || !scope.Get()->Errors.empty())
  {
    error = "cannot write the collapse record '" + path + "'" +
      (scope.Get()->Errors.empty() ? std::string() : ": " + scope.Get()->FirstError());
    return false;
  }
  return true;
}

vtkSmartPointer<vtkTable> ReadRecord(const std::string& path, std::string& error)
{
  if (!std::ifstream(path).good())
  {
    error = "cannot open the collapse record '" + path + "'";
    return nullptr;
  }
  MessageCatcher::Scope scope;
  vtkNew<vtkXMLTableReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!scope.Get()->Errors.empty() || !reader->GetOutput())
  {
    error = "cannot read the collapse record '" + path + "' (a VTK XML table, .vtt)" +
      (scope.Get()->Errors.empty() ? std::string() : ": " + scope.Get()->FirstError());
    return nullptr;
  }
  vtkSmartPointer<vtkTable> record = reader->GetOutput();
  return record;
}

std::string LevelPath(const std::string& output, int level)
{
  const std::string::size_type slash = output.find_last_of('/');
  const std::string::size_type dot = output.find_last_of('.');
  const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = hasExtension ? output.substr(0, dot) : output;
  const std::string extension = hasExtension ? output.substr(dot) : std::string();
  return stem + ".lod" + std::to_string(level) + extension;
}

} // namespace tools
} // namespace colordecimation
