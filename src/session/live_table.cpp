#include "cue_sim/session/live_table.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "cue_sim/physics/rack.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
/// The cue drawn at a strike stops this far short of the ball [m].
constexpr double kCueDrawGap = 0.005;

/// The balls in play sitting on the cloth with radius R: where they are under another radius.
physics::TableState<double> onCloth(physics::TableState<double> state, double R)
{
  for (auto& b : state.balls)
    if (b.inPlay())
      b.r.z() = R;
  return state;
}

std::string seconds(Stamp stamp)
{
  std::ostringstream text;
  text << std::fixed << std::setprecision(9) << toSeconds(stamp);
  return text.str();
}
}  // namespace

std::string LiveTableOptions::whyInvalid() const
{
  std::ostringstream why;
  if (!(rack_gap >= 0 && rack_gap < 0.01))
    why << "rack_gap must be in [0, 0.01) m, got " << rack_gap;
  else if (!(real_time_factor > 0 && real_time_factor <= kMaxRealTimeFactor))
    why << "real_time_factor must be in (0, " << kMaxRealTimeFactor << "], got " << real_time_factor;
  else if (!noise.validate().empty())
    why << noise.validate();
  else if (limits.max_batch_shots < 1 || limits.max_samples < 1 || limits.max_samples_per_shot < 1 ||
           limits.max_reply_bytes < 1)
    why << "max_batch_shots, max_samples, max_samples_per_shot and max_reply_bytes must be at least 1";
  return why.str();
}

LiveTable::LiveTable(std::shared_ptr<const physics::Engine<double>> engine, const LiveTableOptions& options,
                     const std::string& rack, Stamp now)
  : engine_(std::move(engine)),
    options_(options),
    live_(engine_, physics::TableState<double>()),
    cue_(options.noise_enabled ? options.noise : physics::ExecutionNoise::none(), options.noise_seed),
    paused_(options.paused)
{
  const std::string why = options_.whyInvalid();
  if (!why.empty())
    throw std::invalid_argument(why);
  RackRequest request;
  request.layout = rack;
  physics::TableState<double> layout;
  const std::string bad_rack = whyNotRack(request, layout);
  if (!bad_rack.empty())
    throw std::invalid_argument("rack: " + bad_rack);
  clock_.setRate(now, paused_ ? 0 : options_.real_time_factor);
  last_rack_ = layout;
  startFrom(physics::atTimeZero(layout), now);
}

void LiveTable::advanceTo(Stamp now, std::vector<StampedEvent>* events)
{
  last_stamp_ = std::max(last_stamp_, now);
  const double time = std::max(clock_.at(now), live_.time());
  if (live_.atRest())
    live_.advance(time);  // nothing moves: no physics to do
  else
  {
    std::vector<physics::Event<double>> happened;
    try
    {
      if (options_.orientations)
        advanceTurning(time, happened);
      else
        live_.advance(time, &happened);
    }
    catch (const physics::EventLimitError&)
    {
      // Not reachable for strikes (they run to rest first) nor for placements at rest; kept so
      // that the table goes on from its last event with a new allowance of events.
      live_.reset(live_.state());
    }
    if (events)
      for (const auto& e : happened)
        events->push_back({e, clock_.stampOf(e.time, now)});
    if (pending_turn_ && live_.atRest())
      finishGameShot(now);
  }
  applyPendingPhysics();
  if (!live_.atRest() || !balls_at_rest_)
  {
    balls_ = live_.snapshot();
    if (options_.orientations)
    {
      orientations_.sync(live_.state().balls, engine_->params());  // after edits too
      orientations_now_ = orientations_.advance(live_.state().balls, live_.time(), engine_->params());
    }
    else
      orientations_now_.assign(balls_.size(), Eigen::Quaterniond::Identity());
    balls_at_rest_ = live_.atRest();
  }
}

void LiveTable::advanceTurning(double time, std::vector<physics::Event<double>>& happened)
{
  // Check by check, so that each ball changes at most once a step and is turned along the
  // motion it had until then. The same calls to advance as one would make, in more steps: the
  // same events and balls, bit for bit.
  for (;;)
  {
    const double next = live_.nextCheck();
    if (!(next <= time))
      break;
    live_.advance(next, &happened);
    orientations_.sync(live_.state().balls, engine_->params());
  }
  live_.advance(time, &happened);
}

void LiveTable::startFrom(physics::TableState<double> state, Stamp now)
{
  clock_.restart(now);
  live_.reset(std::move(state));
  balls_at_rest_ = false;
  ++layout_version_;
  advanceTo(now);
}

void LiveTable::restartAtRest(Stamp now)
{
  clock_.restart(now);
  live_.reset(physics::atTimeZero(live_.state()));
}

void LiveTable::applyPendingPhysics()
{
  if (!pending_engine_ || !live_.atRest())
    return;
  std::shared_ptr<const physics::Engine<double>> engine = std::move(pending_engine_);
  pending_engine_.reset();
  const physics::TableState<double> resting = onCloth(live_.state(), engine->params().ball_radius);
  if (!engine->whyInvalid(resting).empty())
    return;  // the balls changed since and would not fit: setPhysics checks again
  engine_ = std::move(engine);
  live_ = physics::Simulation<double>(engine_, resting);
  last_rack_ = onCloth(last_rack_, engine_->params().ball_radius);
  if (game_)
    game_->setEngine(*engine_);
  ++layout_version_;  // the ball radius or cushion height may have changed
}

Outcome LiveTable::pause(bool paused, Stamp now)
{
  advanceTo(now);
  paused_ = paused;
  clock_.setRate(now, paused_ ? 0 : options_.real_time_factor);
  return Outcome::done(paused_ ? "paused" : "running");
}

Outcome LiveTable::step(double duration, Stamp now)
{
  if (!paused_)
    return Outcome::refused("not paused: a step advances a paused table (~pause first)");
  if (!(duration > 0 && duration <= kMaxStep))
  {
    std::ostringstream why;
    why << "duration must be in (0, " << kMaxStep << "] s, got " << duration;
    return Outcome::refused(why.str());
  }
  advanceTo(now);
  clock_.step(now, duration);
  advanceTo(now);
  std::ostringstream message;
  message << "stepped " << duration << " s";
  return Outcome::done(message.str());
}

Outcome LiveTable::setRealTimeFactor(double factor, Stamp now)
{
  if (!(factor > 0 && factor <= kMaxRealTimeFactor))
  {
    std::ostringstream why;
    why << "real_time_factor must be in (0, " << kMaxRealTimeFactor << "], got " << factor;
    return Outcome::refused(why.str());
  }
  advanceTo(now);
  options_.real_time_factor = factor;
  if (!paused_)
    clock_.setRate(now, factor);
  return Outcome::done("real_time_factor " + std::to_string(factor));
}

Outcome LiveTable::setPhysics(const physics::PhysicsParams<double>& params, const physics::ModelChoice& models,
                              Stamp now)
{
  const std::string why = params.validate();
  if (!why.empty())
    return Outcome::refused(why);
  std::shared_ptr<const physics::Engine<double>> engine;
  try
  {
    engine = std::make_shared<const physics::Engine<double>>(engine_->tableShared(), params, models, engine_->limits());
  }
  catch (const std::exception& e)
  {
    return Outcome::refused(e.what());
  }
  advanceTo(now);
  // A larger ball must still fit where the balls are.
  const std::string fit = engine->whyInvalid(onCloth(live_.state(), params.ball_radius));
  if (!fit.empty())
    return Outcome::refused("the balls on the table would not fit: " + fit);
  pending_engine_ = std::move(engine);
  advanceTo(now);  // applies it if the balls rest
  return Outcome::done(pending_engine_ ? "new physics: applies when the balls rest" : "new physics applied");
}

StrikeOutcome LiveTable::strike(const Shot& shot, Stamp now)
{
  StrikeOutcome outcome;
  outcome.executed = shot;
  advanceTo(now);
  std::string why = game_ ? whyNotGameShot(shot) : "";
  if (why.empty())
    why = live_.whyNotStrikable(shot.ball_id, shot.strike);
  if (why.empty() && !live_.atRest() && !options_.allow_strike_while_moving)
    why = "balls are still moving (set ~allow_strike_while_moving to strike anyway)";
  if (!why.empty())
  {
    outcome.message = why;
    return outcome;
  }
  // A strike from rest starts at physics time 0, like a prediction.
  if (live_.atRest())
    restartAtRest(now);
  physics::NoisyCue cue = cue_;
  outcome.executed.strike = cue.execute(shot.strike, engine_->params().ball_radius);
  // Run the shot to rest on a copy first: it answers the request, and a shot the engine cannot
  // finish is refused before it touches the table.
  const ShotPrediction prediction = predictShot(*engine_, live_.state(), outcome.executed, PredictionOptions{});
  if (!prediction.success)
  {
    outcome.message = prediction.message;
    return outcome;
  }
  cue_ = cue;
  const physics::Ball<double> before = live_.snapshot()[live_.state().indexOf(shot.ball_id)];
  outcome.cue = physics::cueStickFor(before, outcome.executed.strike, engine_->params(), kCueDrawGap);
  orientations_.sync(live_.state().balls, engine_->params());  // before the struck ball's state changes
  live_.strike(shot.ball_id, outcome.executed.strike);
  ++strike_count_;
  balls_at_rest_ = false;
  const physics::Ball<double>& ball = live_.state().balls[live_.state().indexOf(shot.ball_id)];
  outcome.ball_velocity = ball.v;
  outcome.ball_angular_velocity = ball.w;
  outcome.success = true;
  outcome.stamp = now;
  outcome.time_to_rest = prediction.time_to_rest;
  outcome.num_events = prediction.events.size();
  outcome.message = "struck ball " + std::to_string(shot.ball_id) + " at " + seconds(now) + "; " + prediction.message;
  if (game_)
  {
    pending_turn_ = game_->judge(outcome.executed.strike, push_out_called_, prediction.events);
    outcome.refereed = true;
    outcome.ruling = pending_turn_->ruling;
    outcome.message += "; " + std::string(outcome.ruling.foul ? "foul: " : "") + outcome.ruling.reason;
    ++game_version_;
  }
  advanceTo(now);
  return outcome;
}

StrikeOutcome LiveTable::strikeWithCue(const physics::CueStick& cue, double speed, Stamp now, Shot& aimed)
{
  advanceTo(now);
  physics::CueAim aim;
  const std::string why = physics::aimCue(balls_, engine_->params(), cue, speed, aim);
  if (!why.empty())
  {
    StrikeOutcome outcome;
    outcome.message = why;
    return outcome;
  }
  aimed = Shot{aim.ball_id, aim.strike};
  return strike(aimed, now);
}

std::string LiveTable::predictionStart(const std::vector<BallInput>& balls, Stamp now, PredictionStart& start)
{
  start.engine = engine_;
  if (balls.empty())
  {
    advanceTo(now);
    if (!live_.atRest())
      return "the live table is moving: predict from it once it rests, or pass the balls to start from";
    start.table = physics::atTimeZero(live_.state());
    if (game_)
    {
      start.game = *game_;
      start.game->setEngine(*engine_);
      start.push_out = push_out_called_;
    }
    return "";
  }
  std::string why = stateFromInputs(balls, table(), engine_->params().ball_radius, start.table);
  if (why.empty())
  {
    why = engine_->whyInvalid(start.table);
    if (!why.empty())
      why = "balls: " + why;
  }
  return why;
}

}  // namespace session
}  // namespace cue_sim
