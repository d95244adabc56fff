#include "cue_sim/session/live_table.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "cue_sim/session/shot_preview.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
/// The cue drawn at a strike stops this far short of the ball [m].
constexpr double kCueDrawGap = 0.005;

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
  else if (!(rack_jitter >= 0 && rack_jitter <= rack_gap / 2))
    why << "rack_jitter must be in [0, rack_gap / 2] = [0, " << rack_gap / 2 << "] m, got " << rack_jitter;
  else if (const std::string factor = TableClock::whyBadFactor(real_time_factor); !factor.empty())
    why << factor;
  else if (!noise.validate().empty())
    why << noise.validate();
  else if (limits.max_batch_shots < 1 || limits.max_samples < 1 || limits.max_samples_per_shot < 1 ||
           limits.max_reply_bytes < 1)
    why << "max_batch_shots, max_samples, max_samples_per_shot and max_reply_bytes must be at least 1";
  return why.str();
}

LiveTable::LiveTable(std::shared_ptr<const physics::Engine<double>> engine, const LiveTableOptions& options,
                     const std::string& rack, Stamp now)
  : options_(options),
    clock_(options.real_time_factor, options.paused, now),
    balls_(std::move(engine), options.orientations),
    edits_(options.rack_gap),
    cue_(options.noise_enabled ? options.noise : physics::ExecutionNoise::none(), options.noise_seed)
{
  const std::string why = options_.whyInvalid();
  if (!why.empty())
    throw std::invalid_argument(why);
  RackRequest request;
  request.layout = rack;
  if (rack != "custom" && rack != "empty")
  {
    request.jitter = options.rack_jitter;
    request.seed = options.rack_seed;
  }
  physics::TableState<double> layout;
  const std::string bad_rack = edits_.whyNotRack(request, balls_.engine(), layout);
  if (!bad_rack.empty())
    throw std::invalid_argument("rack: " + bad_rack);
  edits_.racked(layout);
  startFrom(physics::atTimeZero(layout), now);
}

void LiveTable::advanceTo(Stamp now, std::vector<StampedEvent>* events)
{
  clock_.saw(now);
  const double time = std::max(clock_.at(now), balls_.time());
  if (balls_.atRest())
    balls_.advance(time);
  else
  {
    std::vector<physics::Event<double>> happened;
    balls_.advance(time, &happened);
    if (events)
      for (const auto& e : happened)
        events->push_back({e, clock_.stampOf(e.time, now)});
    if (!happened.empty())
      changed(clock_.stampOf(happened.back().time, now));  // events come in time order
    if (game_.shotPending() && balls_.atRest())
    {
      // The game shot's balls rest: the game takes its turn, and the table goes on from the game's.
      const physics::TableState<double> next = physics::atTimeZero(game_.finishShot(balls_.state()));
      clock_.restart(now);
      balls_.startFrom(next);
      changed(now);
    }
  }
  if (balls_.applyPendingPhysics())
  {
    changed(now);
    edits_.onCloth(engine().params().ball_radius);
    game_.setEngine(engine());
  }
  balls_.look();
}

std::vector<physics::Ball<double>> LiveTable::ballsAt(Stamp stamp) const
{
  if (balls_.atRest())
    return balls_.balls();
  LiveBalls then = balls_;
  then.advance(std::max(clock_.at(stamp), then.time()));
  then.look();
  return then.balls();
}

void LiveTable::startFrom(physics::TableState<double> state, Stamp now)
{
  clock_.restart(now);
  balls_.startFrom(std::move(state));
  changed(now);
  advanceTo(now);
}

void LiveTable::restartAtRest(Stamp now)
{
  clock_.restart(now);
  balls_.restartAtRest();
  changed(now);
}

Outcome LiveTable::pause(bool paused, Stamp now)
{
  advanceTo(now);
  clock_.pause(paused, now);
  return Outcome::done(paused ? "paused" : "running");
}

Outcome LiveTable::step(double duration, Stamp now)
{
  if (const std::string why = clock_.whyNotStep(duration); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  clock_.step(duration, now);
  advanceTo(now);
  std::ostringstream message;
  message << "stepped " << duration << " s";
  return Outcome::done(message.str());
}

Outcome LiveTable::setRealTimeFactor(double factor, Stamp now)
{
  if (const std::string why = TableClock::whyBadFactor(factor); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  options_.real_time_factor = factor;
  clock_.setRealTimeFactor(factor, now);
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
    engine = std::make_shared<const physics::Engine<double>>(this->engine().tableShared(), params, models,
                                                             this->engine().limits());
  }
  catch (const std::exception& e)
  {
    return Outcome::refused(e.what());
  }
  advanceTo(now);
  if (const std::string fit = balls_.whyNotFit(*engine); !fit.empty())
    return Outcome::refused("the balls on the table would not fit: " + fit);
  balls_.setPendingPhysics(std::move(engine));
  advanceTo(now);  // applies it if the balls rest
  return Outcome::done(balls_.physicsPending() ? "new physics: applies when the balls rest" : "new physics applied");
}

StrikeOutcome LiveTable::strike(const Shot& shot, Stamp now)
{
  StrikeOutcome outcome;
  outcome.executed = shot;
  advanceTo(now);
  std::string why = whyNotStrikeAt(now);
  if (why.empty() && game_.on())
    why = game_.whyNotShot(shot, balls_.atRest());
  if (why.empty())
    why = engine().whyNotStrikable(balls_.state(), shot.ball_id, shot.strike);
  if (why.empty() && !balls_.atRest() && !options_.allow_strike_while_moving)
    why = "balls are still moving (set ~allow_strike_while_moving to strike anyway)";
  if (!why.empty())
  {
    outcome.message = why;
    return outcome;
  }
  // A strike from rest starts at physics time 0, like a prediction.
  if (balls_.atRest())
    restartAtRest(now);
  physics::NoisyCue cue = cue_;
  const double R = engine().params().ball_radius;
  outcome.executed.strike = cue.execute(shot.strike, R);
  // Run the shot to rest on a copy first: it answers the request, and a shot the engine cannot
  // finish is refused before it touches the table.
  // A carom game draws its points' paths: the struck ball's trajectory is kept from this one run.
  PredictionOptions run;
  run.trajectories = game_.on() && game_.play()->rules().scoresCaroms();
  const ShotPrediction prediction = predictShot(engine(), balls_.state(), outcome.executed, run);
  if (!prediction.success)
  {
    outcome.message = prediction.message;
    return outcome;
  }
  cue_ = cue;
  const physics::Ball<double> before =
      engine().ballAt(balls_.state(), balls_.state().indexOf(shot.ball_id), balls_.time());
  outcome.cue = physics::cueStickFor(before, outcome.executed.strike, engine().params(), kCueDrawGap);
  balls_.strike(shot.ball_id, outcome.executed.strike);
  changed(now);
  const physics::Ball<double>& ball = balls_.state().balls[balls_.state().indexOf(shot.ball_id)];
  outcome.ball_velocity = ball.v;
  outcome.ball_angular_velocity = ball.w;
  outcome.success = true;
  outcome.stamp = now;
  outcome.time_to_rest = prediction.time_to_rest;
  outcome.num_events = prediction.events.size();
  outcome.message = "struck ball " + std::to_string(shot.ball_id) + " at " + seconds(now) + "; " + prediction.message;
  if (game_.on())
  {
    outcome.refereed = true;
    outcome.ruling = game_.struck(shot.ball_id, outcome.executed.strike, prediction.events,
                                  ballPath(prediction, engine().params(), shot.ball_id).points);
    outcome.message += "; " + std::string(outcome.ruling.foul ? "foul: " : "") + outcome.ruling.reason;
  }
  advanceTo(now);
  return outcome;
}

std::string LiveTable::whyNotStrikeAt(Stamp now) const
{
  if (now >= clock_.lastStamp())
    return "";
  if (now < last_change_)
    return "the strike's stamp " + seconds(now) + " is before the table's last change at " + seconds(last_change_) +
           " (a ball placed, struck or come to rest since): the balls were not where they are";
  if (!balls_.atRest())
    return "the strike's stamp " + seconds(now) + " is before the table's latest " + seconds(clock_.lastStamp()) +
           " and balls are moving: it cannot be placed in their motion";
  return "";
}

StrikeOutcome LiveTable::strikeWithCue(const physics::CueStick& cue, double speed, Stamp now, Shot& aimed)
{
  advanceTo(now);
  std::string why = whyNotStrikeAt(now);
  physics::CueAim aim;
  if (why.empty())
    why = physics::aimCue(balls_.balls(), engine().params(), cue, speed, aim);
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
  start.engine = balls_.engineShared();
  if (balls.empty())
  {
    advanceTo(now);
    if (!balls_.atRest())
      return "the live table is moving: predict from it once it rests, or pass the balls to start from";
    start.table = physics::atTimeZero(balls_.state());
    if (game_.on())
    {
      start.game = *game_.play();
      start.game->setEngine(engine());
      start.push_out = game_.pushOutCalled();
    }
    return "";
  }
  std::string why = stateFromInputs(balls, table(), engine().params().ball_radius, start.table);
  if (why.empty())
  {
    why = engine().whyInvalid(start.table);
    if (!why.empty())
      why = "balls: " + why;
  }
  return why;
}

bool predictedRuling(const PredictionStart& start, const ShotPrediction& prediction, game::Ruling& ruling)
{
  if (!start.game || !prediction.success || !start.game->whyNotStrikable(prediction.executed.ball_id).empty())
    return false;
  ruling = start.game->judge(prediction.executed.strike, start.push_out, prediction.events, prediction.executed.ball_id)
               .ruling;
  return true;
}

}  // namespace session
}  // namespace cue_sim
