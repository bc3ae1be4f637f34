/**
 * @file ColorDecimationFuzzReplay.cxx
 * @brief Replays fuzz inputs through the fuzz target's body, in any build (GCC too).
 *
 * Usage: ColorDecimationFuzzReplay FILE_OR_FOLDER...  Every regular file given, or found
 * directly in a folder given, is one input. Prints one line per input and exits non-zero if
 * any input broke an invariant (a crash ends the process, which fails the test too).
 */
#include "ColorDecimationFuzz.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " FILE_OR_FOLDER...\n";
    return 2;
  }
  colordecimation::fuzz::Initialize();
  std::vector<std::filesystem::path> files;
  for (int a = 1; a < argc; ++a)
  {
    const std::filesystem::path path(argv[a]);
    if (std::filesystem::is_directory(path))
    {
      for (const auto& entry : std::filesystem::directory_iterator(path))
      {
        if (entry.is_regular_file() && entry.path().filename().string()[0] != '.')
        {
          files.push_back(entry.path());
        }
      }
    }
    else if (std::filesystem::is_regular_file(path))
    {
      files.push_back(path);
    }
    else
    {
      std::cerr << "no such file or folder: " << path << "\n";
      return 2;
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
  {
    std::cerr << "no input files\n";
    return 2;
  }
  int failed = 0;
  for (const auto& file : files)
  {
    std::ifstream stream(file, std::ios::binary);
    const std::vector<char> bytes{ std::istreambuf_iterator<char>(stream),
                                   std::istreambuf_iterator<char>() };
    const std::vector<std::string> broken =
      colordecimation::fuzz::RunOne(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    std::cout << (broken.empty() ? "ok     " : "FAILED ") << file.filename().string() << " ("
              << bytes.size() << " bytes)\n";
    for (const std::string& message : broken)
    {
      std::cout << "  broken invariant: " << message << "\n";
    }
    failed += broken.empty() ? 0 : 1;
  }
  std::cout << (files.size() - failed) << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
