// 9-ball under the WPA World Standardized Rules (Rules of Play, 2016): section 2 (nine ball),
// 1.4-1.5 (spotting, ball in hand) and 6 (fouls).
//
// Where the rules leave a choice to a player, the simulator takes one: after a push-out
// without a foul (2.4) the other player chooses who shoots next, and here the other player
// shoots. A push-out declared when none is allowed is played as a normal shot.
#include <algorithm>

#include "game/rules/rules_factories.hpp"

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

class NineBall : public Rules
{
public:
  std::string rack() const override { return "nine"; }

  /// The lowest-numbered ball on the table, on every shot including the break (6.2).
  std::vector<int> legalFirst(const GameState&, const std::vector<int>& on_table) const override
  {
    if (on_table.empty())
      return {};
    return {*std::min_element(on_table.begin(), on_table.end())};
  }

  Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const override
  {
    const int shooter = state.turn;
    const ShotFacts& f = shot.facts;
    // WPA 2.6: a 9-ball pocketed on a foul or driven off the table is spotted; other object balls
    // driven off the table stay off (they are not spotted in 9-ball).
    const bool nine = contains(f.pocketed, 9) || contains(f.off_table, 9);
    if (shot.push_out && state.push_out_allowed && !state.break_shot)
      return pushOut(shooter, f, nine);
    Ruling r = generalFoul(shooter, f, legalFirst(state, on_table), !state.break_shot);
    if (!r.foul && state.break_shot)
      r = breakFoul(shooter, f, legalFirst(state, on_table));
    if (r.foul)
    {
      if (nine)
      {
        r.respot = {9};
        r.reason += "; the 9-ball is spotted (WPA 2.6)";
      }
      return r;
    }
    r.push_out_next = state.break_shot;  // 2.4: the shot after a legal break may be a push-out
    if (nine)
    {
      r.rule = "WPA 2.5";
      r.game_over = true;
      r.winner = shooter;
      r.next_player = 1 - shooter;
      r.reason = "the 9-ball is pocketed legally (WPA 2.5): the shooter wins the rack";
      return r;
    }
    r.rule = state.break_shot ? "WPA 2.3" : "WPA 2.5";
    r.continues = !f.pocketed.empty();
    r.next_player = r.continues ? shooter : 1 - shooter;
    r.reason = std::string(state.break_shot ? "legal break (WPA 2.3); " : "") +
               (r.continues ? ballList(f.pocketed) + " pocketed legally: the shooter continues (WPA 2.5)"
                            : "nothing pocketed: the turn passes (WPA 2.5)");
    return r;
  }

private:
  /// WPA 2.3: the break must first touch the 1-ball (6.2) and, if it pockets nothing, drive four
  /// object balls to a rail.
  static Ruling breakFoul(int shooter, const ShotFacts& f, const std::vector<int>& legal)
  {
    if (f.first_contact < 0 || !contains(legal, f.first_contact))
      return standardFoul(
          shooter, "WPA 6.2",
          "foul on the break (WPA 6.2, wrong ball first): the cue ball must first touch " + ballList(legal));
    if (f.pocketed.empty() && f.object_balls_to_rail < 4)
      return standardFoul(shooter, "WPA 2.3",
                          "illegal break (WPA 2.3): nothing was pocketed and only " +
                              std::to_string(f.object_balls_to_rail) + " object balls reached a rail (4 needed)");
    return {};
  }

  /// WPA 2.4: a push-out suspends 6.2 and 6.3; a scratch is still a foul. What it pockets stays
  /// down, but the 9-ball is spotted; then the other player shoots.
  static Ruling pushOut(int shooter, const ShotFacts& f, bool nine)
  {
    Ruling r = generalFoul(shooter, f, {}, false);
    if (!r.foul)
    {
      r.rule = "WPA 2.4";
      r.next_player = 1 - shooter;
      r.reason =
          "push-out (WPA 2.4): rules 6.2 and 6.3 are suspended; the other player chooses who shoots next, and "
          "the simulator has the other player shoot";
    }
    if (nine)
    {
      r.respot = {9};
      r.reason += "; the 9-ball is spotted (WPA 2.6)";
    }
    return r;
  }
};
}  // namespace

std::unique_ptr<Rules> make_rules_nine_ball()
{
  return std::make_unique<NineBall>();
}

}  // namespace game
}  // namespace cue_sim
