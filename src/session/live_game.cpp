#include "cue_sim/session/live_game.hpp"

#include <algorithm>

namespace cue_sim
{
namespace session
{
std::string LiveGame::whyNotFreeEdit() const
{
  if (!game_)
    return "";
  return "a game of " + game_->state().rules +
         " is on: the table changes only through the game (~place_cue_ball for ball in hand, ~start_game for a "
         "new game, ~end_game for free play)";
}

std::string LiveGame::whyNotShot(const Shot& shot, bool at_rest) const
{
  if (const std::string over = game_->whyOver(); !over.empty())
    return over + " (~start_game for another, ~end_game for free play)";
  if (const std::string why = game_->whyNotStrikable(shot.ball_id); !why.empty())
    return "ball_id: " + why;
  if (!at_rest || pending_turn_)
    return "balls are still moving: a game shot is played from rest";
  return "";
}

std::string LiveGame::whyNotStart(const GameRequest& request, const physics::Engine<double>& engine,
                                  std::optional<game::GamePlay>& started) const
{
  const std::vector<std::string> names = game::rulesNames();
  if (std::find(names.begin(), names.end(), request.rules) == names.end())
  {
    std::string known;
    for (const auto& n : names)
      known += (known.empty() ? "" : ", ") + n;
    return "rules must be one of " + known + "; got '" + request.rules + "'";
  }
  if (request.breaker != 0 && request.breaker != 1)
    return "first_player must be 0 or 1, got " + std::to_string(request.breaker);
  for (std::size_t i = 0; i < request.players.size(); ++i)
    if (request.players[i].empty())
      return "players[" + std::to_string(i) + "] must not be empty";
  const physics::TableModel& table = engine.table();
  if (const std::string why = game::whyNotPlayableOn(*game::makeRules(request.rules), request.rules, table);
      !why.empty())
    return "rules: " + why;
  physics::TableState<double> position;
  if (!request.balls.empty())
  {
    std::string why = stateFromInputs(request.balls, table, engine.params().ball_radius, position);
    if (why.empty() && position.anyMoving())
      why = "balls: a game is played from rest; every ball must be at rest";
    if (!why.empty())
      return why;
  }
  started.emplace(engine, request.rules, request.players, game::gameRack(request.seed), request.breaker);
  if (request.target != 0)
    if (const std::string why = started->setTarget(request.target); !why.empty())
    {
      started.reset();
      return "target: " + why;
    }
  if (!request.balls.empty())
    if (const std::string why = started->setPosition(position, false); !why.empty())
    {
      started.reset();
      return "balls: " + why;
    }
  return "";
}

void LiveGame::start(game::GamePlay started)
{
  game_.emplace(std::move(started));
  pending_turn_.reset();
  last_turn_.reset();
  pending_path_.clear();
  last_path_.clear();
  push_out_called_ = false;
  ++version_;
}

std::string LiveGame::end()
{
  const std::string rules = game_ ? game_->state().rules : "";
  game_.reset();
  pending_turn_.reset();
  push_out_called_ = false;
  ++version_;
  return rules;
}

std::string LiveGame::placeCueBall(const Eigen::Vector2d& p, physics::Ball<double>& cue)
{
  if (pending_turn_)
    return "balls are still moving: the cue ball is placed once they rest";
  if (const std::string over = game_->whyOver(); !over.empty())
    return over;
  if (const std::string why = game_->placeCueBall(p); !why.empty())
    return why;
  cue = game_->table().balls[static_cast<std::size_t>(game_->table().indexOf(game_->cueBall()))];
  ++version_;
  return "";
}

std::string LiveGame::call(const GameCall& call, const physics::TableModel& table)
{
  if (pending_turn_)
    return "balls are still moving: call the next shot once they rest";
  if (const std::string over = game_->whyOver(); !over.empty())
    return over;
  int pocket = -1;
  if (const std::string why = table.whyNoPocket(call.pocket, pocket); !why.empty())
    return why;
  if (call.push_out && !game_->state().push_out_allowed)
    return "push_out: a push-out may be declared only on the shot right after a legal break, in a game that has "
           "them (9-ball WPA 2.4, 10-ball WPA 9.4)";
  if (const std::string why = game_->call(call.ball, pocket); !why.empty())
    return why;
  push_out_called_ = call.push_out;
  ++version_;
  return "";
}

const game::Ruling& LiveGame::struck(int ball, const physics::CueStrike<double>& strike,
                                     const std::vector<physics::Event<double>>& events,
                                     std::vector<Eigen::Vector2d> path)
{
  pending_turn_ = game_->judge(strike, push_out_called_, events, ball);
  pending_path_ = std::move(path);
  ++version_;
  return pending_turn_->ruling;
}

const physics::TableState<double>& LiveGame::finishShot(const physics::TableState<double>& at_rest)
{
  game_->finish(*pending_turn_, at_rest);
  last_turn_ = std::move(pending_turn_);
  pending_turn_.reset();
  last_path_ = std::move(pending_path_);
  pending_path_.clear();
  push_out_called_ = false;
  ++version_;
  return game_->table();
}

void LiveGame::setEngine(const physics::Engine<double>& engine)
{
  if (game_)
    game_->setEngine(engine);
}

}  // namespace session
}  // namespace cue_sim
