#include "cue_sim/session/table_clock.hpp"

#include <algorithm>
#include <sstream>

namespace cue_sim
{
namespace session
{
TableClock::TableClock(double real_time_factor, bool paused, Stamp now) : paused_(paused), factor_(real_time_factor)
{
  clock_.setRate(now, paused_ ? 0 : factor_);
}

void TableClock::saw(Stamp now)
{
  last_stamp_ = std::max(last_stamp_, now);
}

void TableClock::pause(bool paused, Stamp now)
{
  paused_ = paused;
  clock_.setRate(now, paused_ ? 0 : factor_);
}

std::string TableClock::whyNotStep(double duration) const
{
  if (!paused_)
    return "not paused: a step advances a paused table (~pause first)";
  if (duration > 0 && duration <= kMaxStep)
    return "";
  std::ostringstream why;
  why << "duration must be in (0, " << kMaxStep << "] s, got " << duration;
  return why.str();
}

std::string TableClock::whyBadFactor(double factor)
{
  if (factor > 0 && factor <= kMaxRealTimeFactor)
    return "";
  std::ostringstream why;
  why << "real_time_factor must be in (0, " << kMaxRealTimeFactor << "], got " << factor;
  return why.str();
}

void TableClock::setRealTimeFactor(double factor, Stamp now)
{
  factor_ = factor;
  if (!paused_)
    clock_.setRate(now, factor);
}

}  // namespace session
}  // namespace cue_sim
