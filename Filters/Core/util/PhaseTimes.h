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

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <utility>
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

  /// The time since the last Lap (or Start) is phase `name`'s (added to it if it is there);
  /// then the observer, if there is one, is called.
  void Lap(const char* name)
  {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - this->Last).count();
    this->Last = now;
    auto phase = std::find_if(this->Phases.begin(), this->Phases.end(),
                              [name](const Phase& p) { return std::strcmp(p.Name, name) == 0; });
    if (phase != this->Phases.end())
    {
      phase->Seconds += seconds;
    }
    else
    {
      this->Phases.push_back({ name, seconds });
    }
    if (this->Observer)
    {
      this->Observer();
    }
  }

  /// Called after each Lap from now on (an empty function: none); the set-up reports its
  /// progress by it.
  void SetObserver(std::function<void()> observer) { this->Observer = std::move(observer); }

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
  std::function<void()> Observer;
};

} // namespace colordecimation

#endif
