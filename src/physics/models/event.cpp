#include "cue_sim/physics/event.hpp"

namespace cue_sim
{
namespace physics
{
const char* eventKindName(EventKind kind)
{
  switch (kind)
  {
    case EventKind::None:
      return "none";
    case EventKind::SlideToRoll:
      return "slide_to_roll";
    case EventKind::RollToSpin:
      return "roll_to_spin";
    case EventKind::RollToStop:
      return "roll_to_stop";
    case EventKind::SpinToStop:
      return "spin_to_stop";
    case EventKind::SlideToSpin:
      return "slide_to_spin";
    case EventKind::SlideToStop:
      return "slide_to_stop";
    case EventKind::BallBall:
      return "ball_ball";
    case EventKind::BallCushion:
      return "ball_cushion";
    case EventKind::BallCircle:
      return "ball_circle";
    case EventKind::Pocketed:
      return "pocketed";
    case EventKind::BallSlate:
      return "ball_slate";
    case EventKind::OffTable:
      return "off_table";
  }
  return "unknown";
}

const char* offTablePlaceName(int place)
{
  return place == kLandsOnRail ? "rail" : place == kLandsOffTable ? "floor" : "";
}

}  // namespace physics
}  // namespace cue_sim
