// 9-ball under the WPA World Standardized Rules (Rules of Play, 2016): section 2 (nine ball),
// 1.4-1.5 (spotting, ball in hand) and 6 (fouls).
//
// Where the rules leave a choice to a player, the simulator takes one: after a push-out
// without a foul (2.4) the other player chooses who shoots next, and here the other player
// shoots. A push-out declared when none is allowed is played as a normal shot.
#include "game/rules/rotation_rules.hpp"

namespace cue_sim
{
namespace game
{
namespace
{
class NineBall : public RotationRules
{
public:
  NineBall() : RotationRules(9, {"2.3", "2.4", "2.6"}) {}
  std::string rack() const override { return "nine"; }
  bool callsShots() const override { return false; }

protected:
  /// WPA 2.5: the 9 pocketed legally wins; any ball pocketed legally continues the inning.
  Ruling legalShot(const GameState& state, const ShotFacts& f, bool nine) const override
  {
    const int shooter = state.turn;
    Ruling r;
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
};
}  // namespace

std::unique_ptr<Rules> make_rules_nine_ball()
{
  return std::make_unique<NineBall>();
}

}  // namespace game
}  // namespace cue_sim
