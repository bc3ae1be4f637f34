/**
 * @file ToolsTest.h
 * @brief The checks of the tools' unit tests (TestPlyWriter, TestLegacyVtk): a failed check
 * prints what failed and is counted; main returns Finish()'s status.
 */
#ifndef colordecimation_tools_ToolsTest_h
#define colordecimation_tools_ToolsTest_h

#include <iostream>
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
} // namespace test
} // namespace tools
} // namespace colordecimation

#endif
