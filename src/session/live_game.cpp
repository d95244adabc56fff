// A game on the live table: started, called and placed through the game, struck like any shot
// but refereed, and made ready for the next shot when its balls rest. The game (game::GamePlay)
// keeps the rules and whose turn it is; the live table keeps the balls and runs the shot in
// real time.
#include <sstream>

#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
namespace session
{

std::string LiveTable::whyNotFreeEdit() const
{
  if (!game_)
    return "";
  return "a game of " + game_->state().rules +
         " is on: the table changes only through the game (~place_cue_ball for ball in hand, ~start_game for a "
         "new game, ~end_game for free play)";
}

std::string LiveTable::whyNotGameShot(const Shot& shot) const
{
  if (const std::string over = game_->whyOver(); !over.empty())
    return over + " (~start_game for another, ~end_game for free play)";
  if (shot.ball_id != 0)
    return "ball_id must be 0 in a game: only the cue ball is struck, got " + std::to_string(shot.ball_id);
  if (!live_.atRest() || pending_turn_)
    return "balls are still moving: a game shot is played from rest";
  return "";
}

Outcome LiveTable::startGame(const GameRequest& request, Stamp now)
{
  const std::vector<std::string> names = game::rulesNames();
  if (std::find(names.begin(), names.end(), request.rules) == names.end())
  {
    std::string known;
    for (const auto& n : names)
      known += (known.empty() ? "" : ", ") + n;
    return Outcome::refused("rules must be one of " + known + "; got '" + request.rules + "'");
  }
  if (request.breaker != 0 && request.breaker != 1)
    return Outcome::refused("first_player must be 0 or 1, got " + std::to_string(request.breaker));
  for (std::size_t i = 0; i < request.players.size(); ++i)
    if (request.players[i].empty())
      return Outcome::refused("players[" + std::to_string(i) + "] must not be empty");
  if (table().pockets().empty())
    return Outcome::refused("a game needs a table with pockets; '" + table().name() + "' has none");
  physics::TableState<double> position;
  if (!request.balls.empty())
  {
    std::string why = stateFromInputs(request.balls, table(), engine_->params().ball_radius, position);
    if (why.empty() && position.anyMoving())
      why = "balls: a game is played from rest; every ball must be at rest";
    if (!why.empty())
      return Outcome::refused(why);
  }
  game::GamePlay started(*engine_, request.rules, request.players, game::gameRack(request.seed), request.breaker);
  if (!request.balls.empty())
    if (const std::string why = started.setPosition(position, false); !why.empty())
      return Outcome::refused("balls: " + why);
  advanceTo(now);
  game_.emplace(std::move(started));
  pending_turn_.reset();
  last_turn_.reset();
  push_out_called_ = false;
  ++game_version_;
  startFrom(physics::atTimeZero(game_->table()), now);
  const game::GameState& state = game_->state();
  return Outcome::done("started " + request.rules + ": " + state.players[0] + " against " + state.players[1] + ", " +
                       state.players[static_cast<std::size_t>(state.turn)] +
                       (state.break_shot ? " to break" : " to shoot"));
}

Outcome LiveTable::endGame(Stamp now)
{
  if (!game_)
    return Outcome::refused("no game is on");
  advanceTo(now);  // a shot still rolling rolls on, in free play, unrefereed
  const std::string rules = game_->state().rules;
  game_.reset();
  pending_turn_.reset();
  push_out_called_ = false;
  ++game_version_;
  return Outcome::done("ended the game of " + rules + "; free play, the balls where they are");
}

Outcome LiveTable::placeCueBall(const Eigen::Vector2d& p, Stamp now)
{
  if (!game_)
    return Outcome::refused("no game is on: ~place_ball moves any ball in free play");
  advanceTo(now);
  if (pending_turn_)
    return Outcome::refused("balls are still moving: the cue ball is placed once they rest");
  if (const std::string over = game_->whyOver(); !over.empty())
    return Outcome::refused(over);
  if (const std::string why = game_->placeCueBall(p); !why.empty())
    return Outcome::refused(why);
  restartAtRest(now);
  physics::Ball<double> cue = game_->table().balls[static_cast<std::size_t>(game_->table().indexOf(0))];
  live_.place(cue);
  balls_at_rest_ = false;
  ++layout_version_;
  ++game_version_;
  advanceTo(now);
  std::ostringstream message;
  message << "cue ball placed at (" << p.x() << ", " << p.y() << ")";
  return Outcome::done(message.str());
}

Outcome LiveTable::callShot(const GameCall& call, Stamp now)
{
  if (!game_)
    return Outcome::refused("no game is on: ~start_game first");
  advanceTo(now);
  if (pending_turn_)
    return Outcome::refused("balls are still moving: call the next shot once they rest");
  if (const std::string over = game_->whyOver(); !over.empty())
    return Outcome::refused(over);
  int pocket = -1;
  if (const std::string why = table().whyNoPocket(call.pocket, pocket); !why.empty())
    return Outcome::refused(why);
  if (call.push_out && !game_->state().push_out_allowed)
    return Outcome::refused(
        "push_out: a push-out may be declared only on the shot right after a legal 9-ball break (WPA 9-ball 2.4)");
  if (const std::string why = game_->call(call.ball, pocket); !why.empty())
    return Outcome::refused(why);
  push_out_called_ = call.push_out;
  ++game_version_;
  std::ostringstream message;
  message << (call.ball >= 0 ? "called ball " + std::to_string(call.ball) : std::string("no ball called"));
  if (pocket >= 0)
    message << " in " << call.pocket;
  if (call.push_out)
    message << ", a push-out";
  return Outcome::done(message.str());
}

bool predictedRuling(const PredictionStart& start, const ShotPrediction& prediction, game::Ruling& ruling)
{
  if (!start.game || !prediction.success || prediction.executed.ball_id != 0 || start.game->state().over)
    return false;
  ruling = start.game->judge(prediction.executed.strike, start.push_out, prediction.events).ruling;
  return true;
}

void LiveTable::finishGameShot(Stamp now)
{
  game_->finish(*pending_turn_, live_.state());
  last_turn_ = std::move(pending_turn_);
  pending_turn_.reset();
  push_out_called_ = false;
  clock_.restart(now);
  live_.reset(physics::atTimeZero(game_->table()));
  balls_at_rest_ = false;
  ++layout_version_;
  ++game_version_;
}

}  // namespace session
}  // namespace cue_sim
