// The factory of every model in contact_models.def, each defined in its model's own file
// (src/physics/models/<kind>/<name>.cpp). Private to the registry and the models.
#pragma once

#include <memory>

#include "cue_sim/physics/collision_models.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
using ModelBase_ball_ball = BallBallModel<S>;
template <typename S>
using ModelBase_cushion = CushionModel<S>;

#define CUE_SIM_MODEL(kind, name, ...)                                                                                 \
  template <typename S>                                                                                                \
  std::unique_ptr<ModelBase_##kind<S>> make_##kind##_##name();
#include "cue_sim/physics/contact_models.def"
#undef CUE_SIM_MODEL

}  // namespace physics
}  // namespace cue_sim
