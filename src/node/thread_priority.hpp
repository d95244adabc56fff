// Background threads of table_node (predictions, the camera) run below the publishing thread, so
// that tf keeps its rate whatever they do.
#pragma once

namespace cue_sim
{
/// Nice value of the node's background threads: below the publishing thread (0).
constexpr int kBackgroundNice = 10;

/// Lowers the calling thread's priority to kBackgroundNice (Linux gives each thread a nice value
/// of its own; raising it needs no privilege).
void lowerThisThreadsPriority();

}  // namespace cue_sim
