#include "game/rules/rotation_rules.hpp"

#include <algorithm>

namespace cue_sim
{
namespace game
{
namespace
{
bool contains(const std::vector<int>& ids, int id)
{
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

std::string ballName(int id)
{
  return std::to_string(id) + "-ball";
}
}  // namespace

RotationRules::RotationRules(int money_ball, Sections sections)
  : money_ball_(money_ball), sections_(std::move(sections))
{
}

std::vector<int> RotationRules::legalFirst(const GameState&, const std::vector<int>& on_table) const
{
  if (on_table.empty())
    return {};
  return {*std::min_element(on_table.begin(), on_table.end())};
}

Ruling RotationRules::judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const
{
  const ShotFacts& f = shot.facts;
  // Other object balls driven off the table stay off: rotation games spot only the money ball.
  const bool money = contains(f.pocketed, money_ball_) || contains(f.off_table, money_ball_);
  if (shot.push_out && state.push_out_allowed && !state.break_shot)
    return spotMoneyBall(pushOut(state.turn, f), money);
  Ruling r = generalFoul(state.turn, f, legalFirst(state, on_table), !state.break_shot);
  if (!r.foul && state.break_shot)
    r = breakFoul(state.turn, f, legalFirst(state, on_table));
  if (r.foul)
    return spotMoneyBall(r, money);
  return legalShot(state, f, money);
}

Ruling RotationRules::spotMoneyBall(Ruling r, bool money, const std::string& why) const
{
  if (money)
  {
    r.respot = {money_ball_};
    r.reason += "; the " + ballName(money_ball_) + " is spotted (WPA " + sections_.spotting + why + ")";
  }
  return r;
}

Ruling RotationRules::breakFoul(int shooter, const ShotFacts& f, const std::vector<int>& legal_first) const
{
  if (f.first_contact < 0 || !contains(legal_first, f.first_contact))
    return standardFoul(
        shooter, "WPA 6.2",
        "foul on the break (WPA 6.2, wrong ball first): the cue ball must first touch " + ballList(legal_first));
  const std::string rule = "WPA " + sections_.legal_break;
  if (f.pocketed.empty() && f.object_balls_to_rail < 4)
    return standardFoul(shooter, rule,
                        "illegal break (" + rule + "): nothing was pocketed and only " +
                            std::to_string(f.object_balls_to_rail) + " object balls reached a rail (4 needed)");
  return {};
}

Ruling RotationRules::pushOut(int shooter, const ShotFacts& f) const
{
  Ruling r = generalFoul(shooter, f, {}, false);
  if (!r.foul)
  {
    r.rule = "WPA " + sections_.push_out;
    r.next_player = 1 - shooter;
    r.reason = "push-out (" + r.rule +
               "): rules 6.2 and 6.3 are suspended; the other player chooses who shoots next, and the simulator has "
               "the other player shoot";
  }
  return r;
}

}  // namespace game
}  // namespace cue_sim
