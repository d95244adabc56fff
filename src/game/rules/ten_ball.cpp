// 10-ball under the WPA World Standardized Rules (Rules of Play, 2016): section 9 (ten ball),
// 1.4-1.5 (spotting, ball in hand) and 6 (fouls).
//
// A rotation game like 9-ball (the lowest ball first, push-out after the break, three fouls in a
// row lose), but every shot after the break is called: one ball and one pocket (9.5). Where the
// rules leave a choice to a player, or ask what the shooter meant, the simulator decides:
// - a shot with no ball and pocket called is a safety (9.6): the simulator cannot judge what is
//   obvious, so whatever it pockets is pocketed wrongfully (9.7);
// - after a wrongfully pocketed ball, and after a push-out without a foul, the incoming player
//   may shoot or hand the shot back (9.4, 9.7): here the incoming player shoots;
// - the called 10 wins whenever it drops in its pocket on a legal shot, not only as the last
//   ball (9.5, 9.8); the lowest ball must still be hit first.
#include "game/rules/rotation_rules.hpp"

namespace cue_sim
{
namespace game
{
namespace
{
constexpr int kTen = 10;

/// Whether `ball` dropped in `pocket` on this shot.
bool pocketedIn(const ShotFacts& f, int ball, int pocket)
{
  for (std::size_t k = 0; k < f.pocketed.size(); ++k)
    if (f.pocketed[k] == ball && f.pockets[k] == pocket)
      return true;
  return false;
}

class TenBall : public RotationRules
{
public:
  TenBall() : RotationRules(kTen, {"9.3", "9.4", "9.9"}) {}
  std::string rack() const override { return "ten"; }
  bool callsShots() const override { return true; }
  bool mustCall() const override { return true; }

protected:
  Ruling legalShot(const GameState& state, const ShotFacts& f, bool ten) const override
  {
    return state.break_shot ? legalBreak(state.turn, f, ten) : calledShot(state, f, ten);
  }

  /// WPA 9.3, 9.8: nothing is called on the break; any ball it pockets counts and the shooter
  /// continues, the 10 spotted. The next shot may be a push-out (9.4).
  Ruling legalBreak(int shooter, const ShotFacts& f, bool ten) const
  {
    Ruling r;
    r.rule = "WPA 9.3";
    r.push_out_next = true;
    r.continues = !f.pocketed.empty();
    r.next_player = r.continues ? shooter : 1 - shooter;
    r.reason = "legal break (WPA 9.3); " +
               (r.continues ? ballList(f.pocketed) + " pocketed on the break: the shooter continues (WPA 9.8)"
                            : std::string("nothing pocketed: the turn passes (WPA 9.8)"));
    return spotMoneyBall(r, ten, ", on the break");
  }

  /// WPA 9.5-9.8: the called ball in the called pocket continues the inning, or, the 10, wins
  /// the rack; anything else pocketed stays down (the 10 spotted) and the turn passes.
  Ruling calledShot(const GameState& state, const ShotFacts& f, bool ten) const
  {
    const int shooter = state.turn;
    const bool called = state.called_ball >= 0 && state.called_pocket >= 0;
    const bool made = called && pocketedIn(f, state.called_ball, state.called_pocket);
    Ruling r;
    if (made && state.called_ball == kTen)
    {
      r.rule = "WPA 9.8";
      r.game_over = true;
      r.winner = shooter;
      r.next_player = 1 - shooter;
      r.reason = "the called 10-ball dropped in " + f.pocketName(state.called_pocket) +
                 " on a legal shot (WPA 9.5, 9.8): the shooter wins the rack";
      return r;
    }
    if (made)
    {
      r.rule = "WPA 9.5";
      r.continues = true;
      r.next_player = shooter;
      r.reason = "the called ball " + std::to_string(state.called_ball) + " dropped in " +
                 f.pocketName(state.called_pocket) + " (WPA 9.5): the shooter continues";
      std::vector<int> others;
      for (const int id : f.pocketed)
        if (id != state.called_ball && id != kTen)
          others.push_back(id);
      if (!others.empty())
        r.reason += "; " + ballList(others) + " also pocketed, and stay down (WPA 9.5)";
      return spotMoneyBall(r, ten, ", not called");
    }
    r.next_player = 1 - shooter;
    if (f.pocketed.empty())
    {
      r.rule = "WPA 9.8";
      r.reason = "nothing pocketed: the turn passes (WPA 9.8)";
      return r;
    }
    r.rule = "WPA 9.7";
    r.reason = ballList(f.pocketed) +
               (called ? " pocketed, not as called (ball " + std::to_string(state.called_ball) + " in " +
                             f.pocketName(state.called_pocket) + ")"
                       : std::string(" pocketed on a shot with nothing called, a safety (WPA 9.6)")) +
               ": pocketed wrongfully (WPA 9.7), they stay down and the turn passes; the incoming player may hand "
               "the shot back, and the simulator has the incoming player shoot";
    return spotMoneyBall(r, ten);
  }
};
}  // namespace

std::unique_ptr<Rules> make_rules_ten_ball()
{
  return std::make_unique<TenBall>();
}

}  // namespace game
}  // namespace cue_sim
