#include <set>

#include "cue_sim/game/referee.hpp"

namespace cue_sim
{
namespace game
{
using physics::EventKind;

std::string ShotFacts::pocketName(int index) const
{
  if (index >= 0 && index < static_cast<int>(pocket_names.size()))
    return pocket_names[static_cast<std::size_t>(index)];
  return "pocket " + std::to_string(index);
}

ShotFacts readShot(const std::vector<physics::Event<double>>& events, const physics::TableModel* table)
{
  ShotFacts facts;
  if (table)
    for (const auto& p : table->pockets())
      facts.pocket_names.push_back(p.name);
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
    if (e.kind == EventKind::OffTable && e.ball == 0)
      facts.cue_ball_off_table = true;
    else if (e.kind == EventKind::OffTable)
      facts.off_table.push_back(e.ball);
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
