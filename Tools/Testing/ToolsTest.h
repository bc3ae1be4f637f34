/**
 * @file ToolsTest.h
 * @brief What the tools' unit tests (TestPlyWriter, TestPlyReader, TestLegacyVtk) share: the
 * scratch folder from the command line (Start), checks that print what failed and are counted
 * (Expect), a file's bytes, the exit status (Finish), and a main made of these (Run).
 */
#ifndef colordecimation_tools_ToolsTest_h
#define colordecimation_tools_ToolsTest_h

#include <fstream>
#include <initializer_list>
#include <iostream>
#include <iterator>
#include <string>

namespace colordecimation
{
namespace tools
{
namespace test
{
/// The test's name, for its messages (set by main).
inline std::string Name = "test";
inline int Failures = 0;

/// The test's scratch folder, its only argument; empty (after the usage) when it is not given.
inline std::string Start(int argc, char* argv[], const std::string& name)
{
  Name = name;
  if (argc != 2)
  {
    std::cerr << "Usage: " << name << " DIRECTORY" << std::endl;
    return std::string();
  }
  return argv[1];
}

/// The whole content of the file at `path` (empty if there is none).
inline std::string FileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void Expect(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << Name << ": FAILED: " << what << std::endl;
    ++Failures;
  }
}

/// The exit status: 0 when every check passed.
inline int Finish()
{
  if (Failures == 0)
  {
    std::cout << Name << ": all passed" << std::endl;
  }
  return Failures == 0 ? 0 : 1;
}

/// A test's main: each of `tests` given the scratch folder, then the exit status (2 without
/// the folder).
inline int Run(int argc, char* argv[], const std::string& name,
               std::initializer_list<void (*)(const std::string&)> tests)
{
  const std::string dir = Start(argc, argv, name);
  if (dir.empty())
  {
    return 2;
  }
  for (const auto test : tests)
  {
    test(dir);
  }
  return Finish();
}
} // namespace test
} // namespace tools
} // namespace colordecimation

#endif
