#include "cue_sim/session/shot_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
/// A shot run to rest, and the table right after its strike (where its samples start).
struct RunShot
{
  ShotPrediction prediction;
  physics::TableState<double> struck;
};

bool sameState(const physics::Ball<double>& a, const physics::Ball<double>& b)
{
  return a.time == b.time && a.motion == b.motion && a.r == b.r && a.v == b.v && a.w == b.w && a.pocket == b.pocket;
}

/// A new piece for every ball the event at `time` changed.
void recordChanges(const physics::TableState<double>& state, double time, std::vector<BallTrajectory>& trajectories)
{
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    if (!sameState(state.balls[i], trajectories[i].pieces.back().ball))
      trajectories[i].pieces.push_back({time, state.balls[i]});
}

/// simulateToRest, event by event, keeping each ball's trajectory: the same events and state.
physics::ShotResult<double> runRecording(const physics::Engine<double>& engine, physics::TableState<double>& state,
                                         std::vector<BallTrajectory>& trajectories)
{
  trajectories.clear();
  for (const auto& b : state.balls)
    trajectories.push_back({b.id, {{state.time, b}}});
  physics::Simulation<double> simulation(engine, std::move(state));
  const double start = simulation.time(), end = start + engine.limits().max_shot_time;
  physics::ShotResult<double> result;
  try
  {
    while (!simulation.atRest())
    {
      const physics::Event<double> event = simulation.step(end);
      if (!event.valid())
        break;
      result.events.push_back(event);
      recordChanges(simulation.state(), event.time, trajectories);
    }
    result.at_rest = simulation.atRest();
    if (!result.at_rest)
      simulation.advance(end);  // stopped by max_shot_time, as simulateToRest is
  }
  catch (...)
  {
    state = std::move(simulation).release();
    throw;
  }
  result.duration = simulation.time() - start;
  state = std::move(simulation).release();
  return result;
}

RunShot runToRest(const physics::Engine<double>& engine, const physics::TableState<double>& start, const Shot& shot,
                  const PredictionOptions& options, bool record)
{
  RunShot run;
  ShotPrediction& prediction = run.prediction;
  prediction.executed = shot;
  const std::string why = engine.whyNotStrikable(start, shot.ball_id, shot.strike);
  if (!why.empty())
  {
    prediction.message = "shot: " + why;
    return run;
  }
  if (options.noise)
    prediction.executed.strike =
        physics::NoisyCue(*options.noise, options.seed).execute(shot.strike, engine.params().ball_radius);

  physics::TableState<double> state = start;
  engine.strike(state, shot.ball_id, prediction.executed.strike);
  run.struck = state;
  physics::ShotResult<double> result;
  try
  {
    result = record ? runRecording(engine, state, prediction.trajectories) : simulateToRest(engine, state);
  }
  catch (const physics::EventLimitError& e)
  {
    prediction.message = std::string("the shot was not simulated: ") + e.what();
    return run;
  }
  prediction.strike_time = run.struck.time;
  prediction.time_to_rest = result.duration;
  prediction.at_rest = result.at_rest;
  prediction.final_balls = engine.snapshot(state);
  prediction.events = std::move(result.events);
  prediction.success = true;
  std::ostringstream message;
  message << (result.at_rest ? "at rest after " : "still moving after ") << result.duration << " s, "
          << prediction.events.size() << " events";
  prediction.message = message.str();
  return run;
}

/// A shot refused once it has run: only its executed strike and why are kept.
ShotPrediction refusedAfterRun(const ShotPrediction& run, const std::string& why)
{
  ShotPrediction refused;
  refused.executed = run.executed;
  refused.message = why;
  return refused;
}

std::size_t sampleCount(const ShotPrediction& prediction, double period)
{
  if (!prediction.success || period <= 0)
    return 0;
  return static_cast<std::size_t>(std::floor(prediction.time_to_rest / period)) + 1;
}

/// Samples the shot from its balls' trajectories, kept as it ran: closed form, no simulation.
void samplesOfTrajectories(const physics::PhysicsParams<double>& params, double strike_time, double period,
                           ShotPrediction& prediction)
{
  const std::size_t count = sampleCount(prediction, period);
  prediction.samples.reserve(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    const double t = strike_time + static_cast<double>(k) * period;
    std::vector<physics::Ball<double>> sample;
    sample.reserve(prediction.trajectories.size());
    for (const BallTrajectory& trajectory : prediction.trajectories)
      sample.push_back(trajectory.at(t, params));
    prediction.samples.push_back(std::move(sample));
  }
}

/// Samples the shot by running it again: advancing in steps processes the same events as the run
/// to rest, and the search is kept from sample to sample (a batch, which keeps no trajectories).
void takeSamples(const physics::Engine<double>& engine, const physics::TableState<double>& struck, double period,
                 ShotPrediction& prediction)
{
  const std::size_t count = sampleCount(prediction, period);
  prediction.samples.reserve(count);
  physics::Simulation<double> sampled(engine, struck);
  for (std::size_t k = 0; k < count; ++k)
  {
    sampled.advance(struck.time + static_cast<double>(k) * period);
    prediction.samples.push_back(sampled.snapshot());
  }
}
}  // namespace

physics::Ball<double> BallTrajectory::at(double t, const physics::PhysicsParams<double>& params) const
{
  // The last piece that starts at or before t.
  const auto after = std::upper_bound(pieces.begin(), pieces.end(), t,
                                      [](double time, const Piece& piece) { return time < piece.start; });
  const Piece& piece = after == pieces.begin() ? pieces.front() : *(after - 1);
  return physics::evolve(piece.ball, t, params);
}

std::size_t ShotPrediction::replyBytes() const
{
  std::size_t bytes =
      ReplySize::shot + message.size() + ReplySize::event * events.size() + ReplySize::ball * final_balls.size();
  for (const auto& sample : samples)
    bytes += ReplySize::ball * sample.size();
  return bytes;
}

std::string whyBadSamplePeriod(double period)
{
  if (period == 0 || (period >= 1e-3 && period <= 10))
    return "";
  std::ostringstream why;
  why << "sample_period must be 0 (no samples) or in [0.001, 10] s, got " << period;
  return why.str();
}

ShotPrediction predictShot(const physics::Engine<double>& engine, const physics::TableState<double>& start,
                           const Shot& shot, const PredictionOptions& options, const PredictionLimits& limits)
{
  RunShot run = runToRest(engine, start, shot, options, options.trajectories || options.sample_period > 0);
  ShotPrediction& prediction = run.prediction;
  const std::size_t count = sampleCount(prediction, options.sample_period);
  if (count > limits.max_samples_per_shot)
  {
    std::ostringstream message;
    message << "sample_period " << options.sample_period << " s gives " << count << " samples of this "
            << prediction.time_to_rest << " s shot; at most " << limits.max_samples_per_shot;
    prediction = refusedAfterRun(prediction, message.str());
    return prediction;
  }
  if (count > 0)
    samplesOfTrajectories(engine.params(), run.struck.time, options.sample_period, prediction);
  if (!options.trajectories)
    prediction.trajectories.clear();
  return prediction;
}

std::vector<ShotPrediction> predictBatch(const physics::Engine<double>& engine,
                                         const physics::TableState<double>& start, const std::vector<Shot>& shots,
                                         const PredictionOptions& options, const PredictionLimits& limits,
                                         physics::ThreadPool& pool, std::string& why)
{
  std::ostringstream refusal;
  if (shots.size() > limits.max_batch_shots)
  {
    refusal << "shots: " << shots.size() << " shots, at most max_batch_shots = " << limits.max_batch_shots;
    why = refusal.str();
    return {};
  }
  if (options.sample_period > 0 && shots.size() > limits.max_samples)
  {
    refusal << "shots: " << shots.size() << " shots sampled give at least " << shots.size()
            << " samples, at most max_samples = " << limits.max_samples;
    why = refusal.str();
    return {};
  }
  // First every shot to rest, without samples: what they tell decides whether the reply fits.
  std::vector<RunShot> runs(shots.size());
  pool.parallelFor(shots.size(), [&](std::size_t i) {
    PredictionOptions own = options;
    own.seed = options.seed + i;
    runs[i] = runToRest(engine, start, shots[i], own, false);
  });
  std::size_t samples = 0, bytes = 0;
  for (RunShot& run : runs)
  {
    const std::size_t count = sampleCount(run.prediction, options.sample_period);
    if (count > limits.max_samples_per_shot)
    {
      std::ostringstream message;
      message << "sample_period " << options.sample_period << " s gives " << count << " samples of this "
              << run.prediction.time_to_rest << " s shot; at most " << limits.max_samples_per_shot;
      run.prediction = refusedAfterRun(run.prediction, message.str());
      continue;
    }
    samples += count;
    bytes += run.prediction.replyBytes() + count * ReplySize::ball * start.balls.size();
  }
  if (samples > limits.max_samples)
    refusal << "the shots would give " << samples << " samples (sample_period " << options.sample_period
            << " s), at most max_samples = " << limits.max_samples;
  else if (bytes > limits.max_reply_bytes)
    refusal << "the reply would take " << bytes << " bytes, at most max_reply_bytes = " << limits.max_reply_bytes;
  why = refusal.str();
  if (!why.empty())
    return {};
  if (options.sample_period > 0)
    pool.parallelFor(runs.size(), [&](std::size_t i) {
      takeSamples(engine, runs[i].struck, options.sample_period, runs[i].prediction);
    });
  std::vector<ShotPrediction> predictions;
  predictions.reserve(runs.size());
  for (RunShot& run : runs)
    predictions.push_back(std::move(run.prediction));
  return predictions;
}

}  // namespace session
}  // namespace cue_sim
