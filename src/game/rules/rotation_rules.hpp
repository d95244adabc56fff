// What the rotation games share (9-ball, WPA section 2; 10-ball, section 9): the lowest ball on
// the table is hit first on every shot, the break must pocket a ball or drive four to a rail, the
// shot after a legal break may be a push-out, and the money ball is spotted whenever it drops
// other than as a win. Each game says how a legal shot is ruled. Private to the referee.
#pragma once

#include <string>
#include <vector>

#include "game/rules/rules_factories.hpp"

namespace cue_sim
{
namespace game
{
class RotationRules : public Rules
{
public:
  /// The rule numbers of one rotation game, for the rulings' text.
  struct Sections
  {
    std::string legal_break;  ///< the break's requirements (9-ball "2.3")
    std::string push_out;     ///< the push-out (9-ball "2.4")
    std::string spotting;     ///< the money ball spotted (9-ball "2.6")
  };

  RotationRules(int money_ball, Sections sections);

  bool pushOutAfterBreak() const override { return true; }
  /// The lowest-numbered ball on the table, on every shot including the break (6.2).
  std::vector<int> legalFirst(const GameState& state, const std::vector<int>& on_table) const override;
  /// A declared push-out, the fouls and the break's requirements; a legal shot is the game's own.
  Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const override;

protected:
  /// The ruling on a shot without a foul (the break or not); `money` the money ball dropped.
  virtual Ruling legalShot(const GameState& state, const ShotFacts& facts, bool money) const = 0;
  /// `r` with the money ball spotted if it dropped or left the table, and the rule in its text;
  /// `why` follows the rule's number (", on the break").
  Ruling spotMoneyBall(Ruling r, bool money, const std::string& why = "") const;

private:
  /// WPA 2.3, 9.3: the cue ball must first touch the lowest ball (6.2) and, if nothing is
  /// pocketed, four object balls must reach a rail. Empty rule if the break is legal.
  Ruling breakFoul(int shooter, const ShotFacts& facts, const std::vector<int>& legal_first) const;
  /// WPA 2.4, 9.4: 6.2 and 6.3 are suspended, a scratch or a ball off the table is still a foul,
  /// and what it pockets stays down. The rules let the other player choose who shoots next: the
  /// simulator has the other player shoot.
  Ruling pushOut(int shooter, const ShotFacts& facts) const;

  int money_ball_;
  Sections sections_;
};

}  // namespace game
}  // namespace cue_sim
