// What the live table's tests share: stamps, an engine on a bundled table, shots and balls as a
// request gives them.
#pragma once

#include <memory>
#include <string>

#include "cue_sim/session/live_table.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace session
{
namespace fixtures
{
constexpr Stamp kSecond = 1000000000;
constexpr Stamp kStart = 1000 * kSecond;

inline std::shared_ptr<const physics::Engine<double>> engineOn(const std::string& table,
                                                               const physics::PhysicsParams<double>& params = {})
{
  return std::make_shared<const physics::Engine<double>>(
      std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath(table))), params);
}

inline Shot shot(int id, double speed, double phi, double a = 0, double b = 0)
{
  Shot s;
  s.ball_id = id;
  s.strike.speed = speed;
  s.strike.phi = phi;
  s.strike.a = a;
  s.strike.b = b;
  return s;
}

inline BallInput ballAt(int id, double x, double y)
{
  BallInput b;
  b.id = id;
  b.position = physics::Vec3<double>(x, y, 0);
  return b;
}
}  // namespace fixtures
}  // namespace session
}  // namespace cue_sim
