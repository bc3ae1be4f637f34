/**
 * @file ProcessMemory.h
 * @brief Resident memory and CPU time of this process, for the command-line tools.
 *
 * The benchmark measures the peak memory of each run inside one process: before a run it
 * returns freed heap memory to the system (malloc_trim), reads the resident size (the
 * baseline) and resets the high-water mark by writing "5" to /proc/self/clear_refs; after
 * the run, VmHWM - baseline is the memory that run needed at its peak.
 */
#ifndef ProcessMemory_h
#define ProcessMemory_h

#include <cstdint>

namespace colordecimation
{
namespace tools
{

/// Current resident set size (VmRSS) in bytes, or -1 when unknown.
int64_t CurrentRSS();

/// Peak resident set size (VmHWM) in bytes since start or the last ResetPeakRSS(); falls
/// back to getrusage's ru_maxrss; -1 when unknown.
int64_t PeakRSS();

/// Reset VmHWM to the current RSS (Linux >= 4.0). Returns false when not possible.
bool ResetPeakRSS();

/// Give freed heap memory back to the system (glibc malloc_trim), so that the RSS read
/// next is not inflated by a previous run's freed blocks.
void ReleaseFreeMemory();

/// CPU time used by this process so far (all threads, user + system), in seconds. Unlike
/// wall-clock time it does not grow while the process waits for a core on a busy machine.
double ProcessCpuSeconds();

/// Measures the peak resident memory of one run above the resident memory before it.
class PeakMemoryProbe
{
public:
  /// Starts the measurement (trims the heap, reads the baseline, resets the peak).
  PeakMemoryProbe();
  /// Peak above the baseline since construction, in bytes (-1 when unknown).
  int64_t PeakAboveBaseline() const;
  /// Whether the peak was really reset (otherwise PeakAboveBaseline is the process peak
  /// above the baseline, an upper bound).
  bool PeakWasReset() const { return this->Reset; }

private:
  int64_t BaselineBytes;
  bool Reset;
};

} // namespace tools
} // namespace colordecimation

#endif
