// table_node's thread priorities: background threads (predictions, the camera) run below the
// publishing thread, and the publishing thread above everything where the system allows it, so
// that tf keeps its rate whatever else runs.
#pragma once

namespace cue_sim
{
/// Nice value of the node's background threads: below the publishing thread (0).
constexpr int kBackgroundNice = 10;

/// Lowers the calling thread's priority to kBackgroundNice (Linux gives each thread a nice value
/// of its own; raising it needs no privilege).
void lowerThisThreadsPriority();

/// The publishing thread's SCHED_FIFO priority where granted: low among real-time threads (1-99),
/// above every normal one.
constexpr int kPublishingRealTimePriority = 10;

/// Puts the calling thread at kPublishingRealTimePriority (SCHED_FIFO) if the system grants it
/// (root, CAP_SYS_NICE, or an rtprio limit); false, and unchanged, if not. Only for a thread that
/// sleeps every period: a real-time thread that never sleeps starves the rest of its core.
bool raiseThisThreadToRealTime();

}  // namespace cue_sim
