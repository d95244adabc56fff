#include "cue_sim/game/game_play.hpp"

#include <stdexcept>

#include "cue_sim/physics/rack.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "cue_sim/physics/snooker_markings.hpp"

namespace cue_sim
{
namespace game
{
physics::RackOptions gameRack(unsigned seed)
{
  physics::RackOptions rack;
  rack.gap = 1e-4;
  rack.jitter = 5e-5;
  rack.seed = seed;
  return rack;
}

GamePlay::GamePlay(const physics::Engine<double>& engine, const std::string& rules,
                   const std::array<std::string, 2>& players, const physics::RackOptions& rack_options, int breaker)
  : engine_(&engine), rules_(makeRules(rules)), rack_(rack_options)
{
  if (breaker != 0 && breaker != 1)
    throw std::invalid_argument("breaker must be 0 or 1, got " + std::to_string(breaker));
  state_.turn = breaker;
  if (const std::string why = whyNotPlayableOn(*rules_, rules, engine.table()); !why.empty())
    throw std::invalid_argument(why);
  state_.rules = rules;
  state_.players = players;
  state_.target = rules_->defaultTarget();
  state_.innings[static_cast<std::size_t>(breaker)] = 1;
  rack();
}

Eigen::Vector2d breakSpot(const physics::TableModel& table, double ball_radius)
{
  return table.headSpot() - Eigen::Vector2d(ball_radius, 0);
}

void GamePlay::rack()
{
  const double R = engine_->params().ball_radius;
  table_ = physics::rackLayout<double>(rules_->rack(), engine_->table(), R, rack_);
  rules_->placeForBreak(engine_->table(), R, state_.turn, table_);
  ++rack_.seed;
  state_.break_shot = true;
  state_.ball_in_hand = rules_->ballInHandOnBreak();
}

std::vector<int> GamePlay::legalFirst() const
{
  return rules_->legalFirst(state_, objectBallsOnTable(table_, cueBall()));
}

std::string GamePlay::setTarget(int points)
{
  if (rules_->defaultTarget() == 0)
    return "a game of " + state_.rules + " keeps no score to set a target for";
  if (points < 1 || points > kMaxTarget)
    return "target " + std::to_string(points) + " must be in [1, " + std::to_string(kMaxTarget) + "]";
  if (points <= std::max(state_.score[0], state_.score[1]))
    return "target " + std::to_string(points) + " must be above the leading score, " +
           std::to_string(std::max(state_.score[0], state_.score[1]));
  state_.target = points;
  return "";
}

std::string GamePlay::setPosition(const physics::TableState<double>& balls, bool break_shot)
{
  const int cue = cueBall();
  if (balls.indexOf(cue) < 0 || !balls.balls[static_cast<std::size_t>(balls.indexOf(cue))].inPlay())
    return "a position needs the shooter's cue ball (id " + std::to_string(cue) + ") on the cloth";
  if (const std::string why = engine_->whyInvalid(balls); !why.empty())
    return why;
  if (balls.anyMoving())
    return "a position is played from rest: every ball must be at rest";
  table_ = physics::atTimeZero(balls);
  state_.break_shot = break_shot;
  state_.ball_in_hand = break_shot ? rules_->ballInHandOnBreak() : BallInHand::None;
  state_.push_out_allowed = false;
  return "";
}

std::string GamePlay::placeCueBall(const Eigen::Vector2d& p)
{
  if (state_.over)
    return "the game is over";
  const double R = engine_->params().ball_radius;
  const int cue = table_.indexOf(cueBall());
  physics::TableState<double> without = table_;
  without.balls.erase(without.balls.begin() + cue);
  const std::string why = whyNotInHand(engine_->table(), R, without, p, state_.ball_in_hand);
  if (!why.empty())
    return why;
  auto& ball = table_.balls[static_cast<std::size_t>(cue)];
  ball.r = physics::Vec3<double>(p.x(), p.y(), R);
  ball.time = table_.time;
  return "";
}

std::string GamePlay::call(int ball, int pocket)
{
  const std::vector<int> on_table = objectBallsOnTable(table_, cueBall());
  if (ball != -1 && std::find(on_table.begin(), on_table.end(), ball) == on_table.end())
    return "called ball " + std::to_string(ball) + " is not on the table";
  if (pocket < -1 || pocket >= static_cast<int>(engine_->table().pockets().size()))
    return "called pocket " + std::to_string(pocket) + " must be in [0, " +
           std::to_string(engine_->table().pockets().size() - 1) + "], or -1 for none";
  state_.called_ball = ball;
  state_.called_pocket = pocket;
  return "";
}

std::string GamePlay::whyNotStrikable(int ball) const
{
  if (state_.over)
    return whyOver();
  if (!rules_->strikable(ball))
    return "ball " + std::to_string(ball) + " is not struck in a game of " + state_.rules + "; the shooter's is " +
           std::to_string(cueBall());
  const int index = table_.indexOf(ball);
  if (index < 0 || !table_.balls[static_cast<std::size_t>(index)].inPlay())
    return "ball " + std::to_string(ball) + " is not on the table";
  return "";
}

Turn GamePlay::shoot(const physics::CueStrike<double>& strike, bool push_out, physics::TableState<double>* at_rest,
                     int ball)
{
  const int struck = ball < 0 ? cueBall() : ball;
  if (const std::string why = whyNotStrikable(struck); !why.empty())
    throw std::invalid_argument(why);
  if (const std::string why = engine_->whyNotStrikable(table_, struck, strike); !why.empty())
    throw std::invalid_argument(why);
  physics::TableState<double> shot = table_;
  engine_->strike(shot, struck, strike);
  std::vector<physics::Event<double>> events = simulateToRest(*engine_, shot).events;
  Turn turn = judge(strike, push_out, std::move(events), struck);
  finish(turn, shot);
  if (at_rest)
    *at_rest = std::move(shot);
  return turn;
}

std::string GamePlay::whyOver() const
{
  if (!state_.over)
    return "";
  return "the game is over: " + std::string(state_.winner >= 0
                                                ? state_.players[static_cast<std::size_t>(state_.winner)] + " won"
                                                : "stopped without a winner");
}

Turn GamePlay::judge(const physics::CueStrike<double>& strike, bool push_out,
                     std::vector<physics::Event<double>> events, int ball) const
{
  Turn turn;
  turn.player = state_.turn;
  turn.ball = ball < 0 ? cueBall() : ball;
  turn.strike = strike;
  turn.push_out = push_out;
  turn.called_ball = state_.called_ball;
  turn.called_pocket = state_.called_pocket;
  turn.events = std::move(events);
  turn.facts = readShot(turn.events, &engine_->table(), turn.ball);
  turn.ruling = judgeShot(*rules_, state_, objectBallsOnTable(table_, cueBall()), Shot{turn.facts, push_out});
  if (max_shots_ > 0 && state_.shots + 1 >= max_shots_ && !turn.ruling.game_over)
  {
    turn.ruling.game_over = true;
    turn.ruling.winner = -1;
    turn.ruling.reason +=
        "; the game is stopped at the cap of " + std::to_string(max_shots_) + " shots, without a winner";
  }
  turn.after = afterRuling(state_, turn.ruling);
  return turn;
}

void GamePlay::finish(const Turn& turn, const physics::TableState<double>& at_rest)
{
  table_ = physics::atTimeZero(at_rest);  // the next shot strikes from rest, as the live table's does
  state_ = turn.after;
  if (turn.ruling.rerack)
    rack();
  else if (!state_.over)
  {
    const double R = engine_->params().ball_radius;
    rules_->respot(engine_->table(), R, turn.ruling.respot, state_, table_);
    if (!table_.balls[static_cast<std::size_t>(table_.indexOf(0))].inPlay())
      returnCueBall();
    state_.before_shot = rules_->beforeShot(engine_->table(), R, state_, table_);
  }
}

void GamePlay::returnCueBall()
{
  const double R = engine_->params().ball_radius;
  auto& cue = table_.balls[static_cast<std::size_t>(table_.indexOf(0))];
  cue.motion = physics::Motion::Stationary;
  cue.pocket = -1;
  cue.v.setZero();
  cue.w.setZero();
  cue.time = table_.time;
  // Where the incoming player has it in hand: in the D (snooker), else behind the head string.
  const BallInHand region = state_.ball_in_hand == BallInHand::InD ? BallInHand::InD : BallInHand::BehindHeadString;
  Eigen::Vector2d start = breakSpot(engine_->table(), R);
  if (region == BallInHand::InD)
  {
    const physics::SnookerMarkings m = physics::snookerMarkings(engine_->table());
    start = m.d_centre - Eigen::Vector2d(0, m.d_radius / 2);  // between the yellow and brown spots
  }
  physics::TableState<double> others = table_;
  others.balls.erase(others.balls.begin() + others.indexOf(0));
  // Stepping back from the start until it stands.
  for (double back = 0; back < engine_->table().clothLength() / 4; back += R)
    for (const double side : {0.0, 2.0 * R, -2.0 * R, 4.0 * R, -4.0 * R})
    {
      const Eigen::Vector2d p(start.x() - back, start.y() + side);
      if (whyNotInHand(engine_->table(), R, others, p, region).empty())
      {
        cue.r = physics::Vec3<double>(p.x(), p.y(), R);
        return;
      }
    }
  throw std::runtime_error(std::string("no room ") +
                           (region == BallInHand::InD ? "in the D" : "behind the head string") + " for the cue ball");
}

}  // namespace game
}  // namespace cue_sim
