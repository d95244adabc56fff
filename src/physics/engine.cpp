#include "cue_sim/physics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "physics/engine_geometry.hpp"

namespace cue_sim
{
namespace physics
{
const char* eventKindName(EventKind kind)
{
  switch (kind)
  {
    case EventKind::None:
      return "none";
    case EventKind::SlideToRoll:
      return "slide_to_roll";
    case EventKind::RollToSpin:
      return "roll_to_spin";
    case EventKind::RollToStop:
      return "roll_to_stop";
    case EventKind::SpinToStop:
      return "spin_to_stop";
    case EventKind::SlideToSpin:
      return "slide_to_spin";
    case EventKind::SlideToStop:
      return "slide_to_stop";
    case EventKind::BallBall:
      return "ball_ball";
    case EventKind::BallCushion:
      return "ball_cushion";
    case EventKind::BallCircle:
      return "ball_circle";
    case EventKind::Pocketed:
      return "pocketed";
  }
  return "unknown";
}
template <typename S>
Engine<S>::Engine(std::shared_ptr<const TableModel> table, const PhysicsParams<S>& params, const ModelChoice& models,
                  const EngineLimits& limits)
  : table_(std::move(table)),
    params_(params),
    model_choice_(models),
    limits_(limits),
    ball_ball_(makeBallBallModel<S>(models.ball_ball)),
    cushion_(makeCushionModel<S>(models.cushion))
{
  const std::string why = params_.validate();
  if (!why.empty())
    throw std::invalid_argument("physics parameter " + why);
  auto obstacles = std::make_shared<Obstacles>();
  // The boxes are widened by a nanometre, so that rounding never dismisses a touching ball.
  const S R = params_.ball_radius, margin = S(1e-9);
  const Vec2<S> spread(R + margin, R + margin);
  for (const auto& s : table_->segments())
  {
    const Vec2<S> a = s.start.cast<S>(), b = s.end.cast<S>();
    obstacles->segments.push_back(
        {a, s.direction.cast<S>(), s.normal.cast<S>(), S(s.length), a.cwiseMin(b) - spread, a.cwiseMax(b) + spread});
  }
  for (const auto& c : table_->circles())
  {
    const Vec2<S> centre = c.centre.cast<S>(), reach = Vec2<S>::Constant(R + S(c.radius) + margin);
    obstacles->circles.push_back({centre, S(c.radius), centre - reach, centre + reach});
  }
  for (const auto& p : table_->pockets())
  {
    const Vec2<S> centre = p.centre.cast<S>(), reach = Vec2<S>::Constant(S(p.radius) + margin);
    obstacles->pockets.push_back({centre, S(p.radius), centre - reach, centre + reach});
  }
  obstacles_ = obstacles;
}

template <typename S>
Ball<S> Engine<S>::ballAt(const TableState<S>& state, std::size_t index, S t) const
{
  return evolve(state.balls.at(index), t, params_);
}

template <typename S>
std::vector<Ball<S>> Engine<S>::snapshot(const TableState<S>& state) const
{
  std::vector<Ball<S>> balls;
  balls.reserve(state.balls.size());
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    balls.push_back(ballAt(state, i, state.time));
  return balls;
}

template <typename S>
Event<S> Engine<S>::step(TableState<S>& state) const
{
  const Event<S> event = nextEvent(state);
  if (event.valid())
  {
    EventContext context;
    context.index = state.indexOf(event.ball);
    context.other_index = event.other >= 0 ? state.indexOf(event.other) : -1;
    processEvent(state, event, context);
    state.time = std::max(state.time, event.time);
  }
  return event;
}

template <typename S>
ShotResult<S> Engine<S>::simulateToRest(TableState<S>& state) const
{
  const S start = state.time;
  const S stop = start + S(limits_.max_shot_time);
  ShotResult<S> result;
  advance(state, stop, &result.events);
  result.at_rest = !state.anyMoving();
  if (result.at_rest)
    state.time = std::max(start, state.event_time);
  result.duration = state.time - start;
  return result;
}

template <typename S>
std::string Engine<S>::whyNotStrikable(const TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const int index = state.indexOf(ball_id);
  if (index < 0)
    return "ball_id " + std::to_string(ball_id) + " is not on the table";
  if (!state.balls[index].inPlay())
    return "ball_id " + std::to_string(ball_id) + " is pocketed";
  return validateStrike(strike);
}

template <typename S>
void Engine<S>::strike(TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const std::string why = whyNotStrikable(state, ball_id, strike);
  if (!why.empty())
    throw std::invalid_argument(why);
  Ball<S>& ball = state.balls[state.indexOf(ball_id)];
  ball = evolve(ball, state.time, params_);
  applyCueStrike(ball, strike, params_);
  settleMotion(ball, params_.ball_radius);
  // The strike is an event: predictions restart from it.
  state.event_time = state.time;
}

template <typename S>
std::string Engine<S>::whyInvalid(const TableState<S>& state, double tolerance) const
{
  const double R = static_cast<double>(params_.ball_radius);
  std::set<int> ids;
  std::ostringstream why;
  for (const auto& b : state.balls)
  {
    const std::string label = "ball " + std::to_string(b.id);
    if (b.id < 0)
      return label + ": id must be >= 0";
    if (!ids.insert(b.id).second)
      return label + ": id appears twice";
    if (!isFinite(b.r) || !isFinite(b.v) || !isFinite(b.w) || !std::isfinite(static_cast<double>(b.time)))
      return label + ": position, velocity, angular velocity and time must be finite";
    if (!b.inPlay())
      continue;
    if (std::abs(static_cast<double>(b.r.z()) - R) > tolerance)
      return label + ": a ball on the cloth has z = R = " + std::to_string(R) + " m";
    const std::string where = table_->whyNotPlaceable(b.r.template head<2>().template cast<double>(), R);
    if (!where.empty())
      return label + ": " + where;
  }
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    for (std::size_t j = i + 1; j < state.balls.size(); ++j)
    {
      const Ball<S>& a = state.balls[i];
      const Ball<S>& b = state.balls[j];
      if (!a.inPlay() || !b.inPlay())
        continue;
      const double d =
          static_cast<double>((evolve(a, state.time, params_).r - evolve(b, state.time, params_).r).norm());
      if (d < 2 * R - tolerance)
      {
        why << "balls " << a.id << " and " << b.id << " overlap: centres " << d << " m apart, less than 2R = " << 2 * R;
        return why.str();
      }
    }
  return {};
}

template class Engine<double>;
template class Engine<long double>;

}  // namespace physics
}  // namespace cue_sim
