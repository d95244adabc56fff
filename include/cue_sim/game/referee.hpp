// The referee of a pool game: what a shot did (read off its events), the ruling on it under a
// ruleset, and the state after it. Rulesets are named (rulesNames()); each is one file in
// src/game/rules/. No ROS.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cue_sim/game/game_state.hpp"
#include "cue_sim/physics/event.hpp"
#include "cue_sim/physics/table_model.hpp"
#include "cue_sim/physics/table_state.hpp"

namespace cue_sim
{
namespace game
{
/// What a shot did, as the rules need it.
struct ShotFacts
{
  int first_contact = -1;                 ///< the first object ball the cue ball touched, -1 for none
  std::vector<int> pocketed;              ///< object balls pocketed, in order (not the cue ball)
  std::vector<int> pockets;               ///< the pocket each went into (TableModel::pockets index)
  bool scratch = false;                   ///< the cue ball was pocketed (WPA 6.1)
  bool cue_ball_off_table = false;        ///< the cue ball was driven off the table (WPA 6.1)
  std::vector<int> off_table;             ///< object balls driven off the table, in order (WPA 6.5)
  bool rail_after_contact = false;        ///< a ball met a cushion or jaw after the cue ball's first contact
  int object_balls_to_rail = 0;           ///< distinct object balls that met a cushion or jaw, or were pocketed
  std::vector<std::string> pocket_names;  ///< the table's pockets by index, for the rulings' text

  /// The pocket's name (its URDF link), or "pocket <index>" without the table's names.
  std::string pocketName(int index) const;
};

/// Reads a shot's events in time order (Engine::run's). The cue ball is ball 0. With `table`, the
/// rulings name its pockets.
ShotFacts readShot(const std::vector<physics::Event<double>>& events, const physics::TableModel* table = nullptr);

/// A shot as the referee sees it: what happened, and what the shooter declared.
struct Shot
{
  ShotFacts facts;
  bool push_out = false;  ///< a push-out declared (9-ball, the shot after a legal break; WPA 2.4)
};

/// One ruleset: its rack, the balls a shooter may hit first, and its rulings.
class Rules
{
public:
  virtual ~Rules() = default;
  /// The rack its games start from (physics::rackNames()).
  virtual std::string rack() const = 0;
  /// The object balls the shooter may contact first, from those on the table before the shot.
  virtual std::vector<int> legalFirst(const GameState& state, const std::vector<int>& on_table) const = 0;
  /// The ruling on `shot`, played from `state` with `on_table` the object balls on the table
  /// before it. The ruling's text cites the rule it rests on.
  virtual Ruling judge(const GameState& state, const std::vector<int>& on_table, const Shot& shot) const = 0;
  /// Whether the shooter calls a ball and a pocket, and the referee holds the shot to the call.
  virtual bool callsShots() const = 0;
  /// Whether a pocketed ball counts only when it was called (an uncalled shot is a safety), rather
  /// than counting an uncalled pot as called.
  virtual bool mustCall() const { return false; }
  /// Whether the shot after a legal break may be a push-out.
  virtual bool pushOutAfterBreak() const { return false; }
  /// Whether the players are given groups of balls (8-ball's solids and stripes).
  virtual bool playsGroups() const { return false; }
};

/// The names makeRules() accepts (rulesets.def): eight_ball, nine_ball, ten_ball.
std::vector<std::string> rulesNames();
/// How a ruleset is shown ("8-ball"); the name itself if it is not one.
std::string rulesTitle(const std::string& name);
/// Throws std::invalid_argument naming the unknown ruleset and the known ones.
std::unique_ptr<Rules> makeRules(const std::string& name);

/// The ruling on a shot under `rules`, with what every ruleset shares: a third foul in a row
/// loses the rack (WPA 6.14), and a finished game takes no more shots.
Ruling judgeShot(const Rules& rules, const GameState& state, const std::vector<int>& on_table, const Shot& shot);

/// The state after `ruling`: its next player, ball in hand, groups and fouls; the game over if it
/// says so; the calls cleared for the next shot.
GameState afterRuling(GameState state, const Ruling& ruling);

/// The object balls (ids 1 and up) on the table, in id order.
std::vector<int> objectBallsOnTable(const physics::TableState<double>& state);

/// Spots `ids` (WPA 1.4): each on the long string through the foot spot, as near the spot as it
/// can stand, behind it (towards the foot cushion) first and then in front, frozen to a ball in
/// the way. A spotted ball is at rest and in play.
void spotBalls(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
               physics::TableState<double>& state);

/// The rectangle the cue ball's centre may be placed in with `place` in hand: the cloth kept R
/// from its edges, up to the head string for BehindHeadString; false (and nothing set) for None.
/// Within it whyNotInHand still keeps the cue ball off the pockets' mouths and other balls.
bool inHandRegion(const physics::TableModel& table, double ball_radius, BallInHand place, Eigen::Vector2d& low,
                  Eigen::Vector2d& high);

/// Empty if the cue ball may be placed with its centre at p: on the cloth clear of the cushions,
/// pockets and every other ball, and behind the head string if `place` says so; otherwise why
/// not.
std::string whyNotInHand(const physics::TableModel& table, double ball_radius, const physics::TableState<double>& state,
                         const Eigen::Vector2d& p, BallInHand place);

}  // namespace game
}  // namespace cue_sim
