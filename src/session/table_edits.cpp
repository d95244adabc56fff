// What is on the live table: racks, the last rack again, the whole table replaced, one ball
// placed, moved or removed. Each request is checked in full before anything changes.
#include <algorithm>
#include <sstream>

#include "cue_sim/physics/rack.hpp"
#include "cue_sim/session/live_table.hpp"

namespace cue_sim
{
namespace session
{
std::string LiveTable::whyNotRack(const RackRequest& request, physics::TableState<double>& rack) const
{
  const double R = engine_->params().ball_radius;
  std::ostringstream why;
  if (!(request.jitter >= 0 && request.jitter <= options_.rack_gap / 2))
  {
    why << "jitter must be in [0, rack_gap / 2] = [0, " << options_.rack_gap / 2 << "] m, got " << request.jitter;
    return why.str();
  }
  rack = physics::TableState<double>();
  if (request.layout == "custom")
  {
    if (request.ids.size() != request.positions.size())
      return "ids and positions must have the same length (got " + std::to_string(request.ids.size()) + " and " +
             std::to_string(request.positions.size()) + ")";
    if (request.jitter != 0)
      return "jitter is for the standard layouts, not 'custom'";
    for (std::size_t i = 0; i < request.ids.size(); ++i)
    {
      BallInput input;
      input.id = request.ids[i];
      input.position = physics::Vec3<double>(request.positions[i].x(), request.positions[i].y(), R);
      physics::Ball<double> b;
      const std::string bad = ballFromInput(input, "balls[" + std::to_string(i) + "]", table(), R, b);
      if (!bad.empty())
        return bad;
      rack.balls.push_back(b);
    }
  }
  else
  {
    if (!request.ids.empty() || !request.positions.empty())
      return "ids and positions are for layout 'custom' only";
    const std::vector<std::string> names = physics::rackNames();
    if (std::find(names.begin(), names.end(), request.layout) == names.end())
      return "layout must be one of eight, nine, empty, custom; got '" + request.layout + "'";
    physics::RackOptions options;
    options.gap = options_.rack_gap;
    options.jitter = request.jitter;
    options.seed = request.seed;
    rack = physics::rackLayout<double>(request.layout, table(), R, options);
  }
  const std::string invalid = engine_->whyInvalid(rack);
  if (invalid.empty())
    return "";
  if (request.layout == "custom")
    return "positions: " + invalid;
  why << "layout '" << request.layout << "' does not fit table '" << table().name() << "' with ball_radius " << R
      << " m: " << invalid;
  return why.str();
}

Outcome LiveTable::rack(const RackRequest& request, Stamp now)
{
  if (const std::string why = whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  physics::TableState<double> layout;
  const std::string why = whyNotRack(request, layout);
  if (!why.empty())
    return Outcome::refused(why);
  last_rack_ = layout;
  startFrom(physics::atTimeZero(layout), now);
  return Outcome::done("racked '" + request.layout + "': " + std::to_string(layout.balls.size()) + " balls");
}

Outcome LiveTable::reset(Stamp now)
{
  if (const std::string why = whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  const std::string why = engine_->whyInvalid(last_rack_);
  if (!why.empty())
    return Outcome::refused("the last rack does not fit the physics now (rack again): " + why);
  startFrom(physics::atTimeZero(last_rack_), now);
  return Outcome::done("back to the last rack (" + std::to_string(last_rack_.balls.size()) + " balls)");
}

Outcome LiveTable::setState(const std::vector<BallInput>& balls, Stamp now)
{
  if (const std::string why = whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  physics::TableState<double> state;
  std::string why = stateFromInputs(balls, table(), engine_->params().ball_radius, state);
  if (why.empty() && state.balls.empty())
    why = "balls: give at least one ball (~set_state replaces every ball on the table)";
  if (why.empty())
  {
    why = engine_->whyInvalid(state);
    if (!why.empty())
      why = "balls: " + why;
  }
  if (!why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  startFrom(state, now);  // every ball at time 0: now
  return Outcome::done("replaced the table by " + std::to_string(state.balls.size()) + " balls" +
                       (state.anyMoving() ? ", some moving" : ", all at rest"));
}

Outcome LiveTable::placeBall(const BallInput& input, Stamp now)
{
  if (const std::string why = whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  physics::Ball<double> ball;
  const std::string why = ballFromInput(input, "ball", table(), engine_->params().ball_radius, ball);
  if (!why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  const std::string where = live_.whyNotPlaceable(ball);
  if (!where.empty())
    return Outcome::refused("ball: " + where);
  const bool moved = live_.state().indexOf(ball.id) >= 0;
  if (live_.atRest())
    restartAtRest(now);
  live_.place(ball);
  balls_at_rest_ = false;
  ++layout_version_;
  advanceTo(now);
  return Outcome::done(std::string(moved ? "moved" : "placed") + " ball " + std::to_string(ball.id));
}

Outcome LiveTable::removeBall(int id, Stamp now)
{
  if (const std::string why = whyNotFreeEdit(); !why.empty())
    return Outcome::refused(why);
  advanceTo(now);
  if (live_.state().indexOf(id) < 0)
  {
    std::string on_table;
    for (const auto& b : live_.state().balls)
      on_table += (on_table.empty() ? "" : ", ") + std::to_string(b.id);
    return Outcome::refused("ball_id " + std::to_string(id) +
                            " is not on the table (on it: " + (on_table.empty() ? "none" : on_table) + ")");
  }
  live_.remove(id);
  balls_at_rest_ = false;
  ++layout_version_;
  advanceTo(now);
  return Outcome::done("removed ball " + std::to_string(id));
}

}  // namespace session
}  // namespace cue_sim
