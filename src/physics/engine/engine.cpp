#include "cue_sim/physics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "cue_sim/physics/simulation.hpp"
#include "physics/contacts/event_resolution.hpp"
#include "physics/engine/table_geometry.hpp"
#include "physics/search/full_scan.hpp"

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
TableGeometry<S>::TableGeometry(const TableModel& table, S R)
{
  const S margin = S(kBoxMargin);
  const Vec2<S> spread(R + margin, R + margin);
  for (const auto& s : table.segments())
  {
    const Vec2<S> a = s.start.cast<S>(), b = s.end.cast<S>();
    segments.push_back(
        {a, s.direction.cast<S>(), s.normal.cast<S>(), S(s.length), a.cwiseMin(b) - spread, a.cwiseMax(b) + spread});
  }
  for (const auto& c : table.circles())
  {
    const Vec2<S> centre = c.centre.cast<S>(), reach = Vec2<S>::Constant(R + S(c.radius) + margin);
    circles.push_back({centre, S(c.radius), centre - reach, centre + reach});
  }
  for (const auto& p : table.pockets())
  {
    const Vec2<S> centre = p.centre.cast<S>(), reach = Vec2<S>::Constant(S(p.radius) + margin);
    pockets.push_back({centre, S(p.radius), centre - reach, centre + reach});
  }
  const Vec2<S> half(S(table.clothLength() / 2), S(table.clothWidth() / 2));
  cloth_low = table.clothCentre().cast<S>() - half;
  cloth_high = table.clothCentre().cast<S>() + half;
  // The clear box: the cloth, cut back on each side past every obstacle's box that reaches into
  // it (the side it reaches in from is the one nearest the box).
  clear_low = cloth_low;
  clear_high = cloth_high;
  const Vec2<S> centre = table.clothCentre().cast<S>();
  const auto cutBack = [&](const Vec2<S>& low, const Vec2<S>& high) {
    if ((low.array() > clear_high.array()).any() || (high.array() < clear_low.array()).any())
      return;
    // How far the clear box would shrink on each of its four sides to leave the box outside.
    const S cuts[4] = {high.x() - clear_low.x(), clear_high.x() - low.x(), high.y() - clear_low.y(),
                       clear_high.y() - low.y()};
    const int side = static_cast<int>(std::min_element(cuts, cuts + 4) - cuts);
    if (side == 0)
      clear_low.x() = std::min(high.x(), centre.x());
    else if (side == 1)
      clear_high.x() = std::max(low.x(), centre.x());
    else if (side == 2)
      clear_low.y() = std::min(high.y(), centre.y());
    else
      clear_high.y() = std::max(low.y(), centre.y());
  };
  for (const auto& s : segments)
    cutBack(s.low, s.high);
  for (const auto& c : circles)
    cutBack(c.low, c.high);
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
  geometry_ = std::make_shared<const TableGeometry<S>>(*table_, params_.ball_radius);
}

template <typename S>
Engine<S>::~Engine() = default;

template <typename S>
void Engine<S>::advance(TableState<S>& state, S t_end, std::vector<Event<S>>* events) const
{
  Simulation<S> simulation(*this, std::move(state));
  try
  {
    simulation.advance(t_end, events);
  }
  catch (...)
  {
    state = std::move(simulation).release();
    throw;
  }
  state = std::move(simulation).release();
}

template <typename S>
ShotResult<S> Engine<S>::simulateToRest(TableState<S>& state) const
{
  Simulation<S> simulation(*this, std::move(state));
  ShotResult<S> result;
  try
  {
    result = simulation.runToRest();
  }
  catch (...)
  {
    state = std::move(simulation).release();
    throw;
  }
  state = std::move(simulation).release();
  return result;
}

template <typename S>
Event<S> Engine<S>::nextEvent(const TableState<S>& state) const
{
  return scanNextEvent(*this, state);
}

template <typename S>
Event<S> Engine<S>::step(TableState<S>& state) const
{
  const Event<S> event = scanNextEvent(*this, state);
  if (event.valid())
  {
    EventContext<S> context;
    context.index = state.indexOf(event.ball);
    context.other_index = event.other >= 0 ? state.indexOf(event.other) : -1;
    resolveEvent(*this, state, event, context);
    state.time = std::max(state.time, event.time);
  }
  return event;
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
  state.events_this_instant = 0;
}

namespace
{
/// Empty if the ball on its own is valid on the table: finite, and if in play on the cloth.
template <typename S>
std::string whyBallInvalid(const TableModel& table, const Ball<S>& b, S R, double tolerance)
{
  const std::string label = "ball " + std::to_string(b.id);
  if (b.id < 0)
    return label + ": id must be >= 0";
  if (!isFinite(b.r) || !isFinite(b.v) || !isFinite(b.w) || !std::isfinite(static_cast<double>(b.time)))
    return label + ": position, velocity, angular velocity and time must be finite";
  if (!b.inPlay())
    return {};
  const double speed = static_cast<double>(b.v.norm()), spin = static_cast<double>(b.w.norm());
  if (speed > BallLimits::max_speed || spin > BallLimits::max_spin)
  {
    std::ostringstream why;
    why << label << ": speed " << speed << " m/s and spin " << spin << " rad/s must be at most "
        << BallLimits::max_speed << " m/s and " << BallLimits::max_spin << " rad/s";
    return why.str();
  }
  if (std::abs(static_cast<double>(b.r.z() - R)) > tolerance)
    return label + ": a ball on the cloth has z = R = " + std::to_string(static_cast<double>(R)) + " m";
  const std::string where =
      table.whyNotPlaceable(b.r.template head<2>().template cast<double>(), static_cast<double>(R), tolerance);
  return where.empty() ? where : label + ": " + where;
}

/// Empty if the balls, both at time t, do not overlap.
template <typename S>
std::string whyOverlapping(const Ball<S>& a, const Ball<S>& b, S R, double tolerance)
{
  if (!a.inPlay() || !b.inPlay())
    return {};
  const double d = static_cast<double>((a.r - b.r).norm());
  if (d >= 2 * static_cast<double>(R) - tolerance)
    return {};
  std::ostringstream why;
  why << "balls " << a.id << " and " << b.id << " overlap: centres " << d
      << " m apart, less than 2R = " << 2 * static_cast<double>(R);
  return why.str();
}
}  // namespace

template <typename S>
std::string Engine<S>::whyInvalid(const TableState<S>& state, double tolerance) const
{
  std::set<int> ids;
  for (const auto& b : state.balls)
  {
    if (b.id >= 0 && !ids.insert(b.id).second)
      return "ball " + std::to_string(b.id) + ": id appears twice";
    const std::string why = whyBallInvalid(*table_, b, params_.ball_radius, tolerance);
    if (!why.empty())
      return why;
  }
  const std::vector<Ball<S>> now = snapshot(state);
  for (std::size_t i = 0; i < now.size(); ++i)
    for (std::size_t j = i + 1; j < now.size(); ++j)
    {
      const std::string why = whyOverlapping(now[i], now[j], params_.ball_radius, tolerance);
      if (!why.empty())
        return why;
    }
  return {};
}

template <typename S>
std::string Engine<S>::whyNotPlaceable(const TableState<S>& state, const Ball<S>& ball, double tolerance) const
{
  const std::string why = whyBallInvalid(*table_, ball, params_.ball_radius, tolerance);
  if (!why.empty())
    return why;
  const Ball<S> placed = evolve(ball, std::max(ball.time, state.time), params_);
  for (std::size_t i = 0; i < state.balls.size(); ++i)
    if (state.balls[i].id != ball.id)
    {
      const std::string overlap = whyOverlapping(placed, ballAt(state, i, placed.time), params_.ball_radius, tolerance);
      if (!overlap.empty())
        return overlap;
    }
  return {};
}

template struct TableGeometry<double>;
template struct TableGeometry<long double>;
template class Engine<double>;
template class Engine<long double>;

}  // namespace physics
}  // namespace cue_sim
