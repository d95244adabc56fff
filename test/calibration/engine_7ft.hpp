// The engine the calibration tests run on: the bundled 7 ft table, default physics.
#pragma once

#include <memory>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace calibration
{
inline std::shared_ptr<const physics::Engine<double>> engine7ft()
{
  return std::make_shared<const physics::Engine<double>>(
      std::make_shared<const physics::TableModel>(tableFromUrdfFile(tableUrdfPath("7ft"))),
      physics::PhysicsParams<double>());
}
}  // namespace calibration
}  // namespace cue_sim
