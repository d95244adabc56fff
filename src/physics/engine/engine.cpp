#include "cue_sim/physics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "cue_sim/physics/motion.hpp"
#include "physics/engine/held_balls.hpp"
#include "physics/engine/table_geometry.hpp"
#include "physics/models/ball_table/slate_landing.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
Engine<S>::Engine(std::shared_ptr<const TableModel> table, const PhysicsParams<S>& params, const ModelChoice& models,
                  const EngineLimits& limits)
  : table_(std::move(table)),
    params_(params),
    model_choice_(models),
    limits_(limits),
    ball_ball_(makeBallBallModel<S>(models.ball_ball)),
    cushion_(makeCushionModel<S>(models.cushion)),
    ball_table_(makeBallTableModel<S>(models.ball_table)),
    cue_(makeCueModel<S>(models.cue))
{
  const std::string why = params_.validate();
  if (!why.empty())
    throw std::invalid_argument("physics parameter " + why);
  if (ball_ball_->needsCloth())
    ball_ball_in_air_ = makeBallBallModel<S>(ballBallModelNames().front());
  geometry_ = std::make_shared<const TableGeometry<S>>(*table_, params_.ball_radius, params_.cushion_height);
}

template <typename S>
Engine<S>::~Engine() = default;

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
S Engine<S>::energyAt(const TableState<S>& state, S t) const
{
  S energy = S(0);
  for (std::size_t i = 0; i < state.balls.size(); ++i)
  {
    const Ball<S>& b = state.balls[i];
    if (b.inPlay())
      energy += mechanicalEnergy(b.supported() ? b : ballAt(state, i, t), params_);
  }
  return energy;
}

template <typename S>
std::string Engine<S>::whyNotStrikable(const TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const int index = state.indexOf(ball_id);
  if (index < 0)
    return "ball_id " + std::to_string(ball_id) + " is not on the table";
  if (!state.balls[index].inPlay())
    return "ball_id " + std::to_string(ball_id) +
           (state.balls[index].motion == Motion::OffTable ? " is off the table" : " is pocketed");
  if (state.balls[index].airborne())
    return "ball_id " + std::to_string(ball_id) + " is in the air: the cue strikes a ball on the cloth";
  return validateStrike(strike);
}

template <typename S>
void Engine<S>::strike(TableState<S>& state, int ball_id, const CueStrike<S>& strike) const
{
  const std::string why = whyNotStrikable(state, ball_id, strike);
  if (!why.empty())
    throw std::invalid_argument(why);
  // A ball bearing one in the air is struck out of its group: every group comes apart, and forms
  // again at its next contacts.
  if (state.balls[state.indexOf(ball_id)].supported())
  {
    std::vector<int> released;
    releaseSupportedBalls(state, state.time, params_, released);
  }
  Ball<S>& ball = state.balls[state.indexOf(ball_id)];
  ball = evolve(ball, state.time, params_);
  cue_->strike(ball, strike, params_);
  landOnSlate(ball, *ball_table_, params_);  // settles it too: on the cloth, or in the air
  letHeldBallsFallOff(state, state.indexOf(ball_id));
  // The strike is an event: predictions restart from it.
  state.event_time = state.time;
  state.events_this_instant = 0;
}

template <typename S>
std::vector<int> Engine<S>::letHeldBallsFallOff(TableState<S>& state, int index) const
{
  std::vector<int> all(state.balls.size()), fallen;
  for (std::size_t j = 0; j < all.size(); ++j)
    all[j] = static_cast<int>(j);
  // Each ball that falls may hold others up in turn (a stack).
  letHeldBallsFall(state, index, state.time, params_, all, fallen);
  for (std::size_t k = 0; k < fallen.size(); ++k)
    letHeldBallsFall(state, fallen[k], state.time, params_, all, fallen);
  return fallen;
}

template <typename S>
std::vector<int> Engine<S>::letAllHeldBallsFall(TableState<S>& state) const
{
  std::vector<int> fallen;
  releaseSupportedBalls(state, state.time, params_, fallen);
  for (std::size_t j = 0; j < state.balls.size(); ++j)
  {
    Ball<S>& ball = state.balls[j];
    if (ball.held())
    {
      ball.motion = Motion::Airborne;
      ball.time = std::max(ball.time, state.time);
      fallen.push_back(static_cast<int>(j));
    }
  }
  return fallen;
}

namespace
{
/// Empty if the ball on its own is valid on the table: finite, and if in play on the cloth.
template <typename S>
std::string whyBallInvalid(const TableModel& table, const Ball<S>& b, S R, S nose_height, double tolerance)
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
  if (b.airborne())
  {
    if (static_cast<double>(b.r.z() - R) < -tolerance)
      return label + ": a ball in the air has z >= R = " + std::to_string(static_cast<double>(R)) + " m";
    if (b.held() && (b.v != Vec3<S>::Zero() || b.w != Vec3<S>::Zero()))
      return label + ": a ball held in the air is at rest (velocity and angular_velocity 0)";
  }
  else if (std::abs(static_cast<double>(b.r.z() - R)) > tolerance)
    return label + ": a ball on the cloth has z = R = " + std::to_string(static_cast<double>(R)) + " m";
  if (b.airborne() && b.r.z() > nose_height)
  {
    // Above the cushions' noses: over the rails is a place it may be, clear of the walls.
    const std::string where = table.whyInTheWalls(b.r.template cast<double>(), static_cast<double>(R),
                                                  static_cast<double>(nose_height), tolerance);
    return where.empty() ? where : label + ": " + where;
  }
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
    const std::string why = whyBallInvalid(*table_, b, params_.ball_radius, geometry_->nose_height, tolerance);
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
  const std::string why = whyBallInvalid(*table_, ball, params_.ball_radius, geometry_->nose_height, tolerance);
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

template class Engine<double>;
template class Engine<long double>;

}  // namespace physics
}  // namespace cue_sim
