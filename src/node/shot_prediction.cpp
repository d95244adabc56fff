#include "node/shot_prediction.hpp"

#include <cmath>
#include <sstream>

#include "cue_sim/physics/simulation.hpp"
#include "node/ros_conversions.hpp"

namespace cue_sim
{
std::string whyBadSamplePeriod(double period)
{
  if (period == 0 || (period >= 1e-3 && period <= 10))
    return "";
  std::ostringstream why;
  why << "sample_period must be 0 (no samples) or in [0.001, 10] s, got " << period;
  return why.str();
}

Prediction predictShot(const physics::Engine<double>& engine, const physics::TableState<double>& start,
                       const Shot& shot, const PredictionOptions& options)
{
  Prediction prediction;
  prediction.executed = shot;
  prediction.sample_period = options.sample_period;
  const physics::CueStrike<double> planned = toCueStrike(shot);
  const std::string why = engine.whyNotStrikable(start, shot.ball_id, planned);
  if (!why.empty())
  {
    prediction.message = "shot: " + why;
    return prediction;
  }
  physics::CueStrike<double> executed = planned;
  if (options.noise)
    executed = physics::NoisyCue(*options.noise, options.seed).execute(planned, engine.params().ball_radius);
  prediction.executed = toShotMsg(shot.ball_id, executed);

  physics::TableState<double> state = start;
  engine.strike(state, shot.ball_id, executed);
  const physics::TableState<double> struck = state;
  physics::ShotResult<double> result;
  try
  {
    result = engine.simulateToRest(state);
  }
  catch (const physics::EventLimitError& e)
  {
    prediction.message = std::string("the shot was not simulated: ") + e.what();
    return prediction;
  }
  const physics::TableModel& table = engine.table();
  prediction.time_to_rest = result.duration;
  prediction.at_rest = result.at_rest;
  for (const auto& b : engine.snapshot(state))
    prediction.final_balls.push_back(toBallStateMsg(b, table));
  for (const auto& e : result.events)
    prediction.events.push_back(toEventMsg(e, table, ros::Time(), e.time - struck.time));

  if (options.sample_period > 0)
  {
    const double count = std::floor(result.duration / options.sample_period) + 1;
    if (count > kMaxSamples)
    {
      std::ostringstream message;
      message << "sample_period " << options.sample_period << " s gives " << count << " samples of this "
              << result.duration << " s shot; at most " << kMaxSamples;
      prediction.message = message.str();
      return prediction;
    }
    // Advancing in steps processes the same events as one run: the samples lie on the
    // prediction's own trajectories, and the search is kept from sample to sample.
    physics::Simulation<double> sampled(engine, struck);
    for (int k = 0; k < static_cast<int>(count); ++k)
    {
      sampled.advance(struck.time + k * options.sample_period);
      prediction.samples.push_back(toTableStateMsg(sampled.snapshot(), table, ros::Time(), options.frame_id));
    }
  }
  prediction.success = true;
  std::ostringstream message;
  message << (result.at_rest ? "at rest after " : "still moving after ") << result.duration << " s, "
          << result.events.size() << " events";
  prediction.message = message.str();
  return prediction;
}

}  // namespace cue_sim
