/**
 * @file Batched.h
 * @brief The Batched schedule (docs/ALGORITHM.md, section 7): passes that each make the
 * cheapest BatchFraction of the vertices' chosen collapses, in cost order, skipping those a
 * collapse earlier in the pass made stale, by blocks of the mesh on several threads, then
 * re-cost every affected vertex at once.
 *
 * The affected vertices are those Greedy re-costs, so a batch of one is exactly Greedy; larger
 * batches trade the strict global order for locality and parallelism. The result does not
 * depend on the number of threads.
 */
#ifndef colordecimation_Batched_h
#define colordecimation_Batched_h

#include "engine/Engine.h"

namespace colordecimation
{

/// Collapse until at most stats.TargetTriangles remain, no valid collapse is left or progress
/// returns false (stats.Aborted).
template <typename Metric>
void CollapseInBatches(Engine<Metric>& engine, DecimatorStatistics& stats,
                       const ProgressFunction& progress);

} // namespace colordecimation

#endif
