#include "cue_sim/calibration/track_prediction.hpp"

#include <cmath>
#include <sstream>

#include "cue_sim/physics/simulation.hpp"

namespace cue_sim
{
namespace calibration
{
namespace
{
void countContact(const physics::Event<double>& event, ContactCounts& counts)
{
  using physics::EventKind;
  if (event.kind == EventKind::BallBall)
    ++counts.ball_ball;
  else if (event.kind == EventKind::BallCushion || event.kind == EventKind::BallCircle)
    ++counts.cushion;
  else if (event.kind == EventKind::Pocketed)
    ++counts.pocketed;
}

/// The balls at `t`, each averaged over the exposure around it if an event falls within it (a
/// ball pocketed at the middle counts as off the table; one pocketed during the exposure is
/// averaged over the slices it was still in play).
void observe(physics::Simulation<double>& simulation, double t, double exposure,
             std::vector<physics::Event<double>>& events, TrackPrediction& p)
{
  const double open = t - exposure / 2, close = t + exposure / 2;
  if (exposure > 0)
    simulation.advance(std::max(open, simulation.time()), &events);
  if (exposure <= 0 || simulation.nextCheck() > close)
  {
    simulation.advance(t, &events);
    for (const physics::Ball<double>& ball : simulation.snapshot())
    {
      p.positions.push_back(ball.r.x());
      p.positions.push_back(ball.r.y());
      p.on_table.push_back(ball.inPlay() ? 1 : 0);
    }
    return;
  }
  const std::size_t balls = simulation.state().balls.size();
  std::vector<double> sum(2 * balls, 0.0);
  std::vector<int> seen(balls, 0);
  std::vector<std::uint8_t> at_middle(balls, 0);
  for (int i = 0; i < kExposureSlices; ++i)
  {
    const double slice = open + exposure * (i + 0.5) / kExposureSlices;
    simulation.advance(std::max(slice, simulation.time()), &events);
    const std::vector<physics::Ball<double>> now = simulation.snapshot();
    for (std::size_t b = 0; b < balls; ++b)
    {
      if (!now[b].inPlay())
        continue;
      sum[2 * b] += now[b].r.x();
      sum[2 * b + 1] += now[b].r.y();
      ++seen[b];
      if (i == kExposureSlices / 2)  // the first slice past the middle decides on- or off-table
        at_middle[b] = 1;
    }
  }
  const std::vector<physics::Ball<double>> last = simulation.snapshot();
  for (std::size_t b = 0; b < balls; ++b)
  {
    p.positions.push_back(seen[b] ? sum[2 * b] / seen[b] : last[b].r.x());
    p.positions.push_back(seen[b] ? sum[2 * b + 1] / seen[b] : last[b].r.y());
    p.on_table.push_back(at_middle[b]);
  }
}

TrackPrediction predictOne(const physics::Engine<double>& engine, const TrackRequest& request)
{
  TrackPrediction p;
  if (p.error = whyBadRequest(engine, request); !p.error.empty())
    return p;
  physics::TableState<double> state = request.start;
  if (request.strike)
    engine.strike(state, request.strike->ball_id, request.strike->cue);
  const std::size_t balls = state.balls.size();
  p.positions.reserve(request.times.size() * balls * 2);
  p.on_table.reserve(request.times.size() * balls);
  physics::Simulation<double> simulation(engine, std::move(state));
  std::vector<physics::Event<double>> events;
  try
  {
    for (const double t : request.times)
      observe(simulation, t, request.exposure, events, p);
  }
  catch (const physics::EventLimitError& e)
  {
    p.error = e.what();
  }
  for (const physics::Event<double>& event : events)
    countContact(event, p.contacts);
  return p;
}
}  // namespace

std::string whyBadRequest(const physics::Engine<double>& engine, const TrackRequest& request)
{
  std::ostringstream why;
  if (const std::string bad = engine.whyInvalid(request.start); !bad.empty())
    return "start: " + bad;
  if (!(request.exposure >= 0 && request.exposure <= kMaxExposure))
  {
    why << "exposure: " << request.exposure << " s is outside [0, " << kMaxExposure << "]";
    return why.str();
  }
  double previous = request.start.time;
  for (std::size_t k = 0; k < request.times.size(); ++k)
  {
    const double t = request.times[k];
    if (!std::isfinite(t) || t < previous)
    {
      why << "times[" << k << "]: " << t << " is not finite or comes before " << previous
          << " (the times are ascending, from the start's)";
      return why.str();
    }
    if (k > 0 && t - request.times[k - 1] < request.exposure)
    {
      why << "exposure: " << request.exposure << " s is longer than the " << t - request.times[k - 1]
          << " s between times[" << k - 1 << "] and times[" << k << "] (the exposures may not overlap)";
      return why.str();
    }
    previous = t;
  }
  if (request.strike)
    if (const std::string bad = engine.whyNotStrikable(request.start, request.strike->ball_id, request.strike->cue);
        !bad.empty())
      return "strike: " + bad;
  return "";
}

std::vector<TrackPrediction> predictTracks(const physics::Engine<double>& engine,
                                           const std::vector<TrackRequest>& requests, physics::ThreadPool& pool)
{
  std::vector<TrackPrediction> out(requests.size());
  pool.parallelFor(requests.size(), [&](std::size_t i) { out[i] = predictOne(engine, requests[i]); });
  return out;
}

}  // namespace calibration
}  // namespace cue_sim
