#include "cue_sim/session/table_edits.hpp"

#include <algorithm>
#include <sstream>

#include "cue_sim/physics/rack.hpp"
#include "cue_sim/session/live_balls.hpp"

namespace cue_sim
{
namespace session
{
namespace
{
/// The balls of a custom rack, each checked as a ball a request gives.
std::string customRack(const RackRequest& request, const physics::Engine<double>& engine,
                       physics::TableState<double>& rack)
{
  const double R = engine.params().ball_radius;
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
    const std::string bad = ballFromInput(input, "balls[" + std::to_string(i) + "]", engine.table(), R, b);
    if (!bad.empty())
      return bad;
    rack.balls.push_back(b);
  }
  return "";
}
}  // namespace

std::string TableEdits::whyNotRack(const RackRequest& request, const physics::Engine<double>& engine,
                                   physics::TableState<double>& rack) const
{
  const double R = engine.params().ball_radius;
  std::ostringstream why;
  if (!(request.jitter >= 0 && request.jitter <= rack_gap_ / 2))
  {
    why << "jitter must be in [0, rack_gap / 2] = [0, " << rack_gap_ / 2 << "] m, got " << request.jitter;
    return why.str();
  }
  rack = physics::TableState<double>();
  if (request.layout == "custom")
  {
    if (const std::string bad = customRack(request, engine, rack); !bad.empty())
      return bad;
  }
  else
  {
    if (!request.ids.empty() || !request.positions.empty())
      return "ids and positions are for layout 'custom' only";
    const std::vector<std::string> names = physics::rackNames();
    if (std::find(names.begin(), names.end(), request.layout) == names.end())
      return "layout must be one of " + physics::rackNamesText() + ", custom; got '" + request.layout + "'";
    physics::RackOptions options;
    options.gap = rack_gap_;
    options.jitter = request.jitter;
    options.seed = request.seed;
    rack = physics::rackLayout<double>(request.layout, engine.table(), R, options);
  }
  const std::string invalid = engine.whyInvalid(rack);
  if (invalid.empty())
    return "";
  if (request.layout == "custom")
    return "positions: " + invalid;
  why << "layout '" << request.layout << "' does not fit table '" << engine.table().name() << "' with ball_radius " << R
      << " m: " << invalid;
  return why.str();
}

std::string TableEdits::whyNotReset(const physics::Engine<double>& engine) const
{
  const std::string why = engine.whyInvalid(last_rack_);
  return why.empty() ? why : "the last rack does not fit the physics now (rack again): " + why;
}

std::string TableEdits::whyNotState(const std::vector<BallInput>& balls, const physics::Engine<double>& engine,
                                    physics::TableState<double>& state) const
{
  std::string why = stateFromInputs(balls, engine.table(), engine.params().ball_radius, state);
  if (why.empty() && state.balls.empty())
    why = "balls: give at least one ball (~set_state replaces every ball on the table)";
  if (why.empty())
  {
    why = engine.whyInvalid(state);
    if (!why.empty())
      why = "balls: " + why;
  }
  return why;
}

std::string TableEdits::whyNotRemovable(int id, const physics::TableState<double>& table)
{
  if (table.indexOf(id) >= 0)
    return "";
  std::string on_table;
  for (const auto& b : table.balls)
    on_table += (on_table.empty() ? "" : ", ") + std::to_string(b.id);
  return "ball_id " + std::to_string(id) + " is not on the table (on it: " + (on_table.empty() ? "none" : on_table) +
         ")";
}

void TableEdits::onCloth(double R)
{
  last_rack_ = session::onCloth(last_rack_, R);
}

}  // namespace session
}  // namespace cue_sim
