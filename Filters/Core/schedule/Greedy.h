/**
 * @file Greedy.h
 * @brief The Greedy schedule (docs/ALGORITHM.md, section 6): one collapse at a time, always
 * the cheapest valid one of the whole mesh, from a min-heap of vertices keyed by their
 * cheapest admissible collapse (the paper's order).
 */
#ifndef colordecimation_Greedy_h
#define colordecimation_Greedy_h

#include "engine/Engine.h"

namespace colordecimation
{

/// Collapse until at most stats.TargetTriangles remain, no valid collapse is left or progress
/// returns false (stats.Aborted).
template <typename Metric>
void CollapseGreedily(Engine<Metric>& engine, DecimatorStatistics& stats,
                      const ProgressFunction& progress);

} // namespace colordecimation

#endif
