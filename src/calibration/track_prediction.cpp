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
    {
      simulation.advance(t, &events);
      for (const physics::Ball<double>& ball : simulation.snapshot())
      {
        p.positions.push_back(ball.r.x());
        p.positions.push_back(ball.r.y());
        p.on_table.push_back(ball.inPlay() ? 1 : 0);
      }
    }
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
