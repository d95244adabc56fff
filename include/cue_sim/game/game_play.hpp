// A game played on the physics engine: the table, the game's state, and turns taken by placing
// the cue ball, calling and striking. Each strike runs the shot to rest, the referee rules on
// it, and the table is made ready for the next (balls spotted, a new rack, the cue ball back in
// hand). What the node, `simulate` and self-play share. No ROS.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cue_sim/game/game_state.hpp"
#include "cue_sim/game/referee.hpp"
#include "cue_sim/physics/cue_strike.hpp"
#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/rack.hpp"

namespace cue_sim
{
namespace game
{
/// One shot of a game: what was played and what the referee said.
struct Turn
{
  int player = 0;
  int ball = 0;  ///< the ball struck
  physics::CueStrike<double> strike;
  bool push_out = false;
  int called_ball = -1, called_pocket = -1;
  std::vector<physics::Event<double>> events;
  ShotFacts facts;
  Ruling ruling;
  GameState after;
};

/// How games rack: 0.1 mm gaps with each ball off by up to 0.05 mm, as a real rack is. A
/// perfect rack is symmetric, and a full-ball break into it sends only 2 object balls to a rail
/// at 8 m/s (an illegal break); these racks send 7 to 10. Each new rack of a game takes the next
/// seed.
physics::RackOptions gameRack(unsigned seed = 0);

/// Where a game puts the cue ball for a break: on the long string, one ball radius behind the head
/// spot. Behind the head string is the area between the head rail and the string, not including
/// the string (WPA 8.1), so the head spot itself is not in the kitchen.
Eigen::Vector2d breakSpot(const physics::TableModel& table, double ball_radius);

/// Copyable: a copy plays on from the same position (what a planner tries shots on).
class GamePlay
{
public:
  /// A new game of `rules` on `engine`'s table, racked for `breaker`'s break (0 or 1): in pool
  /// the cue ball on the break spot and in hand behind the head string. Throws
  /// std::invalid_argument for unknown rules, or a table with pockets where the rules need none
  /// or the other way round. The engine must outlive the game.
  GamePlay(const physics::Engine<double>& engine, const std::string& rules,
           const std::array<std::string, 2>& players = {"player 1", "player 2"},
           const physics::RackOptions& rack_options = gameRack(), int breaker = 0);

  const GameState& state() const { return state_; }
  const physics::TableState<double>& table() const { return table_; }
  const Rules& rules() const { return *rules_; }
  /// The ball the player to shoot strikes (Rules::cueBall).
  int cueBall() const { return rules_->cueBall(state_.turn); }
  /// The object balls the player to shoot may hit first.
  std::vector<int> legalFirst() const;
  /// Sets the points that win, where the game keeps a score (a new game takes the rules'
  /// default); empty, or why not.
  std::string setTarget(int points);

  /// Sets up a position to play from: these balls at rest (the shooter's cue ball among them),
  /// the break already played or not, the cue ball where it lies. Empty, or why not (and nothing changes).
  std::string setPosition(const physics::TableState<double>& balls, bool break_shot);
  /// Moves the cue ball in hand to p; empty, or why not (and nothing changes).
  std::string placeCueBall(const Eigen::Vector2d& p);
  /// Calls a ball and pocket for the next shot (-1 for none); empty, or why not.
  std::string call(int ball, int pocket);
  /// Strikes `ball` (-1: the shooter's cue ball), runs the shot to rest and rules on it; throws
  /// std::invalid_argument (and changes nothing) if the game is over, the rules let no one strike
  /// that ball, or the strike cannot be played. At the shot cap
  /// a game not yet over ends without a winner, and the ruling says so. With `at_rest`, the balls
  /// as the shot left them there, before the table is made ready for the next shot.
  Turn shoot(const physics::CueStrike<double>& strike, bool push_out = false,
             physics::TableState<double>* at_rest = nullptr, int ball = -1);
  /// Empty if `ball` may be struck in this game now (not over, a ball the rules let be struck,
  /// on the cloth), otherwise why not.
  std::string whyNotStrikable(int ball) const;

  // A shot run elsewhere (the node's live table runs it in real time): judge it from its
  // events when it is struck, then finish it when its balls rest. shoot() is the two at once.
  /// The turn `strike` of `ball` (-1: the shooter's cue ball) makes with these events
  /// (simulateToRest's, from table()): the ruling, the shot cap's included, and the state after
  /// it. Changes nothing.
  Turn judge(const physics::CueStrike<double>& strike, bool push_out, std::vector<physics::Event<double>> events,
             int ball = -1) const;
  /// Takes the turn judged from table(): the balls as the shot left them at rest, then made
  /// ready for the next shot (balls spotted, a new rack, the cue ball back behind the head
  /// string after a scratch, and what the rules do before a shot: GameState::before_shot).
  void finish(const Turn& turn, const physics::TableState<double>& at_rest);
  /// Empty while the game goes on; once over, who won (for a refusal).
  std::string whyOver() const;
  /// The engine to play on from now on (new physics between shots); it must fit the balls.
  void setEngine(const physics::Engine<double>& engine) { engine_ = &engine; }
  /// Shots a game may take before it is stopped (0: no cap).
  void setShotCap(int max_shots) { max_shots_ = max_shots; }
  const physics::Engine<double>& engine() const { return *engine_; }

  /// The highest target setTarget() takes: a race longer than any match (UMB's longest is 50).
  static constexpr int kMaxTarget = 1000;

private:
  void rack();
  /// The cue ball back on the cloth after a scratch: on the break spot, or the nearest free
  /// place behind it along the head string.
  void returnCueBall();

  const physics::Engine<double>* engine_;
  std::shared_ptr<const Rules> rules_;
  physics::RackOptions rack_;
  int max_shots_ = 0;
  GameState state_;
  physics::TableState<double> table_;
};

}  // namespace game
}  // namespace cue_sim
