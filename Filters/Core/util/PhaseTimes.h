/**
 * @file PhaseTimes.h
 * @brief The wall-clock seconds of each named phase of a run, in the order they ran: the phase
 * breakdown that vtkColorHalfEdgeDecimation reports (GetPhaseName / GetPhaseSeconds) and the
 * CLI writes to --stats.
 *
 * A phase is timed from the previous Lap (or Start) to its own Lap, so consecutive laps cover
 * the run without gaps; a phase lapped again (one of a loop's steps) adds up. Names are string
 * literals.
 */
#ifndef colordecimation_PhaseTimes_h
#define colordecimation_PhaseTimes_h

#include <chrono>
#include <cstring>
#include <vector>

namespace colordecimation
{

class PhaseTimes
{
public:
  struct Phase
  {
    const char* Name;
    double Seconds;
  };

  /// Forget the phases so far; the next Lap measures from now.
  void Start()
  {
    this->Phases.clear();
    this->Last = Clock::now();
  }

  /// The time since the last Lap (or Start) is phase `name`'s (added to it if it is there).
  void Lap(const char* name)
  {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - this->Last).count();
    this->Last = now;
    for (Phase& phase : this->Phases)
    {
      if (std::strcmp(phase.Name, name) == 0)
      {
        phase.Seconds += seconds;
        return;
      }
    }
    this->Phases.push_back({ name, seconds });
  }

  /// Add another run's phases after these; the next Lap measures from now (the time since
  /// this one's last Lap, spent in the other run's set-up before its Start, is not counted).
  void Append(const PhaseTimes& other)
  {
    this->Phases.insert(this->Phases.end(), other.Phases.begin(), other.Phases.end());
    this->Last = Clock::now();
  }

  const std::vector<Phase>& Get() const { return this->Phases; }

private:
  using Clock = std::chrono::steady_clock;
  std::vector<Phase> Phases;
  Clock::time_point Last = Clock::now();
};

} // namespace colordecimation

#endif
