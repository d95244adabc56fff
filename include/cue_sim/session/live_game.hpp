// A game on the live table: started, called and placed through the game, struck like any shot but
// refereed, and made ready for the next shot when its balls rest. The game (game::GamePlay) keeps
// the rules, whose turn it is and its own table; this keeps the game, the ruling of a shot still
// rolling, the last one, and what has to be published of them. The live table puts the game's
// table on its balls when it starts one and when a shot's balls rest.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cue_sim/game/game_play.hpp"
#include "cue_sim/session/ball_input.hpp"
#include "cue_sim/session/outcome.hpp"
#include "cue_sim/session/shot_prediction.hpp"

namespace cue_sim
{
namespace session
{
/// A game to start on the live table.
struct GameRequest
{
  std::string rules;  ///< game::rulesNames()
  std::array<std::string, 2> players{"player 1", "player 2"};
  int breaker = 0;         ///< who shoots first: 0 or 1
  std::uint32_t seed = 0;  ///< of the rack's jitter (game::gameRack)
  int target = 0;          ///< the points that win where the game keeps a score; 0: the rules' default
  std::vector<BallInput>
      balls;  ///< empty: rack and break; else the position to play on from, at rest, the break played
};

/// What the shooter declares before a game shot.
struct GameCall
{
  int ball = -1;          ///< the object ball called, -1 for none
  std::string pocket;     ///< the pocket called, by its URDF link name (TableModel::pockets()), empty for none
  bool push_out = false;  ///< 9-ball: the shot is a push-out (only the shot after a legal break)
};

class LiveGame
{
public:
  /// The game on the table, or null in free play.
  const game::GamePlay* play() const { return game_ ? &*game_ : nullptr; }
  bool on() const { return game_.has_value(); }
  /// A game shot was struck and its balls are still moving: its ruling is pendingTurn()'s.
  bool shotPending() const { return pending_turn_.has_value(); }
  const std::optional<game::Turn>& pendingTurn() const { return pending_turn_; }
  /// The last game shot whose balls came to rest.
  const std::optional<game::Turn>& lastTurn() const { return last_turn_; }
  /// Its struck ball's path from the strike to rest, where the game draws it (a carom point's);
  /// empty otherwise.
  const std::vector<Eigen::Vector2d>& lastPath() const { return last_path_; }
  /// Whether the next game shot is declared a push-out.
  bool pushOutCalled() const { return push_out_called_; }
  /// Changes whenever the game's state does (a start, a call, a cue ball placed, a strike, a
  /// shot come to rest, the end): what is published of it may have to go out again.
  long version() const { return version_; }

  /// Empty in free play; in a game, why the table changes only through the game.
  std::string whyNotFreeEdit() const;
  /// Why a game shot cannot be struck (empty if it can); `at_rest`: the balls rest.
  std::string whyNotShot(const Shot& shot, bool at_rest) const;

  /// The game a request starts on `engine`'s table, or why not (which field): checked in full,
  /// nothing started.
  std::string whyNotStart(const GameRequest& request, const physics::Engine<double>& engine,
                          std::optional<game::GamePlay>& started) const;
  /// Starts it: the live table then puts started->table() on its balls.
  void start(game::GamePlay started);
  /// Back to free play (a shot in play rolls on, unrefereed). Its rules' name.
  std::string end();
  /// Moves the cue ball in hand to p: the cue ball to place, or why not.
  std::string placeCueBall(const Eigen::Vector2d& p, physics::Ball<double>& cue);
  /// Declares the next shot's call (the pocket by name on `table`), or why not.
  std::string call(const GameCall& call, const physics::TableModel& table);

  /// A game shot was struck: the referee's ruling from its events, which takes effect when the
  /// balls rest; `path` the struck ball's, for lastPath().
  const game::Ruling& struck(int ball, const physics::CueStrike<double>& strike,
                             const std::vector<physics::Event<double>>& events, std::vector<Eigen::Vector2d> path);
  /// The struck shot's balls rest as `at_rest`: the turn is taken, and the game's table (balls
  /// spotted, a new rack, the cue ball in hand) is what the live table goes on from.
  const physics::TableState<double>& finishShot(const physics::TableState<double>& at_rest);
  /// The engine the game reads its table and physics from (new physics).
  void setEngine(const physics::Engine<double>& engine);

private:
  std::optional<game::GamePlay> game_;
  std::optional<game::Turn> pending_turn_, last_turn_;
  std::vector<Eigen::Vector2d> pending_path_, last_path_;
  bool push_out_called_ = false;
  long version_ = 0;
};

}  // namespace session
}  // namespace cue_sim
