// One step of a group of balls in sustained contact (internal to the physics core): the contact
// equations (contact_system.hpp) integrated by Dormand and Prince's embedded Runge-Kutta 5(4)
// (Dormand and Prince 1980; Hairer, Norsett and Wanner, "Solving Ordinary Differential Equations I",
// II.4-5) with every contact's modes kept as they are, and the step ended where a mode stops holding
// (found on the step's dense output by bisection). Each integrated ball is then given the quadratic
// piece it follows over the step, within the contact tolerance of the integrated path.
#pragma once

#include <functional>
#include <vector>

#include "physics/supports/contact_system.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
struct SupportStep
{
  S h = S(0);                       ///< the step's length [s]
  std::vector<ContactBody<S>> end;  ///< every body at the step's end (the kinematic ones as their paths say)
  std::vector<Vec3<S>> a, alpha;    ///< each dynamic body's piece: its acceleration and angular acceleration
  bool mode_changed = false;        ///< ended where a contact's mode stopped holding
  MarginTag crossed;                ///< which (when mode_changed)
  int attempts = 0;                 ///< steps tried, the rejected ones included
};

/// Where the kinematic bodies (those whose own closed-form paths move them) are `tau` after the
/// step's start: writes their r, v and w into `bodies`.
template <typename S>
using KinematicPaths = std::function<void(S tau, std::vector<ContactBody<S>>& bodies)>;

/// The step from `start` in the given modes: no longer than `longest`, first tried at `trial`, and
/// short enough that every dynamic body's quadratic piece keeps within `tolerance` [m] of the
/// integrated path (and the integration's own error within a tenth of that).
template <typename S>
SupportStep<S> stepSupported(const ContactSystem<S>& system, const std::vector<ContactBody<S>>& start,
                             const std::vector<ContactLink<S>>& links, const std::vector<LinkMode<S>>& modes,
                             const KinematicPaths<S>& kinematic, S trial, S longest, S tolerance);

/// The natural time of a ball on a support, sqrt(R / g) [s] (0.054 s for a pool ball): the scale of
/// the steps, and what turns a position tolerance into a velocity one.
template <typename S>
S supportTime(const PhysicsParams<S>& p)
{
  return std::sqrt(p.ball_radius / p.gravity);
}

}  // namespace physics
}  // namespace cue_sim
