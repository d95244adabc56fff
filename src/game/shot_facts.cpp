#include <set>

#include "cue_sim/game/referee.hpp"

namespace cue_sim
{
namespace game
{
using physics::EventKind;

ShotFacts readShot(const std::vector<physics::Event<double>>& events)
{
  ShotFacts facts;
  std::set<int> to_rail;
  for (const auto& e : events)
  {
    const bool rail = e.kind == EventKind::BallCushion || e.kind == EventKind::BallCircle;
    if (e.kind == EventKind::BallBall && facts.first_contact < 0 && (e.ball == 0 || e.other == 0))
      facts.first_contact = e.ball == 0 ? e.other : e.ball;
    else if (rail && facts.first_contact >= 0)
      facts.rail_after_contact = true;
    if (rail && e.ball != 0)
      to_rail.insert(e.ball);
    if (e.kind != EventKind::Pocketed)
      continue;
    if (e.ball == 0)
    {
      facts.scratch = true;
      continue;
    }
    facts.pocketed.push_back(e.ball);
    facts.pockets.push_back(e.obstacle);
    to_rail.insert(e.ball);
  }
  facts.object_balls_to_rail = static_cast<int>(to_rail.size());
  return facts;
}

}  // namespace game
}  // namespace cue_sim
