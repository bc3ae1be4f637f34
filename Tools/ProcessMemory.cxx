#include "ProcessMemory.h"

#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>

#if defined(__linux__)
#include <malloc.h>
#endif
#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif

namespace colordecimation
{
namespace tools
{
namespace
{
/// A "VmXXX:   1234 kB" line of /proc/self/status, in bytes (-1 when absent).
int64_t ReadStatusField(const char* field)
{
  std::ifstream status("/proc/self/status");
  if (!status)
  {
    return -1;
  }
  const size_t length = std::strlen(field);
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':')
    {
      long long kb = 0;
      if (std::sscanf(line.c_str() + length + 1, "%lld", &kb) == 1)
      {
        return static_cast<int64_t>(kb) * 1024;
      }
    }
  }
  return -1;
}
} // namespace

int64_t CurrentRSS()
{
  return ReadStatusField("VmRSS");
}

int64_t PeakRSS()
{
  const int64_t hwm = ReadStatusField("VmHWM");
  if (hwm >= 0)
  {
    return hwm;
  }
#if defined(__unix__) || defined(__APPLE__)
  struct rusage usage;
  if (getrusage(RUSAGE_SELF, &usage) == 0)
  {
#if defined(__APPLE__)
    return static_cast<int64_t>(usage.ru_maxrss); // bytes on macOS
#else
    return static_cast<int64_t>(usage.ru_maxrss) * 1024; // kilobytes elsewhere
#endif
  }
#endif
  return -1;
}

bool ResetPeakRSS()
{
  std::FILE* file = std::fopen("/proc/self/clear_refs", "w");
  if (!file)
  {
    return false;
  }
  const bool written = std::fputs("5", file) >= 0;
  return (std::fclose(file) == 0) && written;
}

double ProcessCpuSeconds()
{
  struct timespec now;
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now) == 0)
  {
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
  }
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

void ReleaseFreeMemory()
{
#if defined(__linux__) && defined(__GLIBC__)
  malloc_trim(0);
#endif
}

PeakMemoryProbe::PeakMemoryProbe()
{
  ReleaseFreeMemory();
  this->BaselineBytes = CurrentRSS();
  this->Reset = ResetPeakRSS();
}

int64_t PeakMemoryProbe::PeakAboveBaseline() const
{
  const int64_t peak = PeakRSS();
  if (peak < 0 || this->BaselineBytes < 0)
  {
    return -1;
  }
  return peak > this->BaselineBytes ? peak - this->BaselineBytes : 0;
}

} // namespace tools
} // namespace colordecimation
