// The referee of a game: what a shot did (read off its events), the ruling on it under a
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
/// What a shot did, as the rules need it. "The cue ball" is the ball struck.
struct ShotFacts
{
  int cue_ball = 0;         ///< the ball struck
  int first_contact = -1;   ///< the first object ball the cue ball touched, -1 for none
  int second_contact = -1;  ///< the first other object ball it touched after that, -1 for none
  /// The cue ball's impacts with cushions (or jaws) before it touched second_contact (all of them
  /// without one). Every impact counts, on the same cushion or not (UMB Art. 83).
  int cushions_before_second = 0;
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

/// Reads a shot's events in time order (Engine::run's); `cue_ball` is the ball struck. With
/// `table`, the rulings name its pockets.
ShotFacts readShot(const std::vector<physics::Event<double>>& events, const physics::TableModel* table = nullptr,
                   int cue_ball = 0);

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
  /// Whether the break must open the rack (pool: driven hard into it); snooker's break-off is a
  /// shot like any other.
  virtual bool breaksOpen() const { return true; }
  /// Whether a third foul in a row loses the game (WPA 6.14).
  virtual bool threeFoulsLose() const { return true; }

  // Carom games: each player strikes a cue ball of their own, on a table without pockets, for
  // points. Pool's defaults: ball 0 for both, pockets, no score.
  /// The ball `player` strikes.
  virtual int cueBall(int /*player*/) const { return 0; }
  /// Whether `ball` may be struck at all in a game (a refusal otherwise); striking one the rules
  /// allow but not the shooter's own is theirs to rule on.
  virtual bool strikable(int ball) const { return ball == 0; }
  /// Whether the game is played on a table with pockets (pool) or without (carom).
  virtual bool needsPockets() const { return true; }
  /// Where the breaker may place the cue ball: behind the head string in pool; carom's starting
  /// position has no ball in hand.
  virtual BallInHand ballInHandOnBreak() const { return BallInHand::BehindHeadString; }
  /// The points that win, where the game is a race to them; 0 for none.
  virtual int defaultTarget() const { return 0; }
  /// Whether the game keeps a score: a race's (three-cushion), or a frame's (snooker, no target).
  virtual bool keepsScore() const { return defaultTarget() > 0; }
  /// Whether a shot scores by caroms (the cue ball meeting both object balls), which planners
  /// then search for, rather than by pots.
  virtual bool scoresCaroms() const { return false; }
  /// Sets the balls for a break by `breaker` (the rack's layout as given): the cue ball one radius
  /// behind the head spot (breakSpot()) by default.
  virtual void placeForBreak(const physics::TableModel& table, double ball_radius, int breaker,
                             physics::TableState<double>& balls) const;
  /// Puts the balls a ruling re-spots back on the table, `state` the game after the ruling: on
  /// the long string by default (WPA 1.4, spotBalls()).
  virtual void respot(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
                      const GameState& state, physics::TableState<double>& balls) const;
  /// What the rules do before `state`'s next shot, with the balls at rest (three-cushion re-spots
  /// a cue ball frozen to an object ball; snooker calls a free ball into `state`); empty if
  /// nothing, otherwise what was done and why.
  virtual std::string beforeShot(const physics::TableModel& /*table*/, double /*ball_radius*/, GameState& /*state*/,
                                 physics::TableState<double>& /*balls*/) const
  {
    return "";
  }
};

/// The names makeRules() accepts (rulesets.def).
std::vector<std::string> rulesNames();
/// How a ruleset is shown ("8-ball"); the name itself if it is not one.
std::string rulesTitle(const std::string& name);
/// The bundled table its games are played on unless told otherwise ("7ft", "carom"); empty if
/// it is not a ruleset.
std::string rulesTable(const std::string& name);
/// Throws std::invalid_argument naming the unknown ruleset and the known ones.
std::unique_ptr<Rules> makeRules(const std::string& name);
/// Empty if a game of `rules` (named `name`) can be played on `table`: pool on a table with
/// pockets, carom on one without; otherwise why not.
std::string whyNotPlayableOn(const Rules& rules, const std::string& name, const physics::TableModel& table);

/// The ruling on a shot under `rules`, with what the rulesets share: a third foul in a row
/// loses the rack where the rules say so (WPA 6.14), and a finished game takes no more shots.
Ruling judgeShot(const Rules& rules, const GameState& state, const std::vector<int>& on_table, const Shot& shot);

/// The state after `ruling`: its next player, ball in hand, groups and fouls, the shooter's
/// points and a new inning when the turn passes; the game over if it says so; the calls cleared
/// for the next shot.
GameState afterRuling(GameState state, const Ruling& ruling);

/// The object balls on the table, every ball in play but `cue_ball`, in id order.
std::vector<int> objectBallsOnTable(const physics::TableState<double>& state, int cue_ball = 0);

/// Spots `ids` (WPA 1.4): each on the long string through the foot spot, as near the spot as it
/// can stand, behind it (towards the foot cushion) first and then in front, frozen to a ball in
/// the way. A spotted ball is at rest and in play.
void spotBalls(const physics::TableModel& table, double ball_radius, const std::vector<int>& ids,
               physics::TableState<double>& state);

/// The rectangle the cue ball's centre may be placed in with `place` in hand: the cloth kept R
/// from its edges, up to the head string for BehindHeadString, around the D for InD; false (and
/// nothing set) for None.
/// Within it whyNotInHand still keeps the cue ball off the pockets' mouths and other balls.
bool inHandRegion(const physics::TableModel& table, double ball_radius, BallInHand place, Eigen::Vector2d& low,
                  Eigen::Vector2d& high);

/// Empty if the cue ball may be placed with its centre at p: on the cloth clear of the cushions,
/// pockets and every other ball, and behind the head string if `place` says so; otherwise why
/// not. InD asks for the D of the table's snooker markings (physics/snooker_markings.hpp).
std::string whyNotInHand(const physics::TableModel& table, double ball_radius, const physics::TableState<double>& state,
                         const Eigen::Vector2d& p, BallInHand place);

}  // namespace game
}  // namespace cue_sim
