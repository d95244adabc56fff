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
template <typename S>
using ModelBase_ball_table = BallTableModel<S>;
template <typename S>
using ModelBase_cue = CueModel<S>;

#define CUE_SIM_MODEL(kind, name, ...)                                                                                 \
  template <typename S>                                                                                                \
  std::unique_ptr<ModelBase_##kind<S>> make_##kind##_##name();
#include "cue_sim/physics/contact_models.def"
#undef CUE_SIM_MODEL

/// Defines make_<kind>_<name>() for a model's class template, in double and long double: the
/// last line of each model's file.
#define CUE_SIM_MODEL_FACTORY(kind, name, Class)                                                                       \
  template <typename S>                                                                                                \
  std::unique_ptr<ModelBase_##kind<S>> make_##kind##_##name()                                                          \
  {                                                                                                                    \
    return std::make_unique<Class<S>>();                                                                               \
  }                                                                                                                    \
  template std::unique_ptr<ModelBase_##kind<double>> make_##kind##_##name();                                           \
  template std::unique_ptr<ModelBase_##kind<long double>> make_##kind##_##name();

}  // namespace physics
}  // namespace cue_sim
