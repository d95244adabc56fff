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

ShotFacts readShot(const std::vector<physics::Event<double>>& events, const physics::TableModel* table, int cue_ball)
{
  ShotFacts facts;
  facts.cue_ball = cue_ball;
  if (table)
    for (const auto& p : table->pockets())
      facts.pocket_names.push_back(p.name);
  std::set<int> to_rail;
  int cue_cushions = 0;
  for (const auto& e : events)
  {
    const bool rail = e.kind == EventKind::BallCushion || e.kind == EventKind::BallCircle;
    const bool cue_involved = e.ball == cue_ball || (e.kind == EventKind::BallBall && e.other == cue_ball);
    if (e.kind == EventKind::BallBall && cue_involved)
    {
      const int other = e.ball == cue_ball ? e.other : e.ball;
      if (facts.first_contact < 0)
        facts.first_contact = other;
      else if (facts.second_contact < 0 && other != facts.first_contact)
      {
        facts.second_contact = other;
        facts.cushions_before_second = cue_cushions;
      }
    }
    else if (rail && facts.first_contact >= 0)
      facts.rail_after_contact = true;
    if (rail && e.ball == cue_ball)
      ++cue_cushions;
    if (rail && e.ball != cue_ball)
      to_rail.insert(e.ball);
    if (e.kind == EventKind::OffTable && e.ball == cue_ball)
      facts.cue_ball_off_table = true;
    else if (e.kind == EventKind::OffTable)
      facts.off_table.push_back(e.ball);
    if (e.kind != EventKind::Pocketed)
      continue;
    if (e.ball == cue_ball)
    {
      facts.scratch = true;
      continue;
    }
    facts.pocketed.push_back(e.ball);
    facts.pockets.push_back(e.obstacle);
    to_rail.insert(e.ball);
  }
  if (facts.second_contact < 0)
    facts.cushions_before_second = cue_cushions;
  facts.object_balls_to_rail = static_cast<int>(to_rail.size());
  return facts;
}

}  // namespace game
}  // namespace cue_sim
