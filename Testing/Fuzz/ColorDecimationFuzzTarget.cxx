/**
 * @file ColorDecimationFuzzTarget.cxx
 * @brief libFuzzer entry point (Clang builds with COLORDECIMATION_FUZZ): any broken output
 * invariant aborts, so libFuzzer records the input as a crash.
 */
#include "ColorDecimationFuzz.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  colordecimation::fuzz::Initialize();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::vector<std::string> broken = colordecimation::fuzz::RunOne(data, size);
  if (!broken.empty())
  {
    for (const std::string& message : broken)
    {
      std::fprintf(stderr, "broken invariant: %s\n", message.c_str());
    }
    std::abort();
  }
  return 0;
}
