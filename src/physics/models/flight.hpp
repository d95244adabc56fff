// A ball in the air: the centre follows r0 + v0 t - (g/2) t^2 z, a quadratic like every other
// motion here, and the spin is carried unchanged. Private to the motion models.
//
// No air drag: its deceleration is (rho C_d pi R^2 / 2m) v^2 = 4.3e-3 v^2 m/s^2 for a pool ball
// (air at 1.2 kg/m^3, C_d 0.47 at a Reynolds number of 1e4), 0.11 m/s^2 at 5 m/s, so a 0.1 s jump
// at 5 m/s loses 0.2 % of its speed and lands half a millimetre short: far below what a cloth's
// friction, a slate's restitution or a cue's tip varies by. The Magnus force on a spinning ball
// is of the same order and left out with it.
#pragma once

#include "cue_sim/physics/types.hpp"

namespace cue_sim
{
namespace physics
{
/// The centre t [s] after it was at r0 [m] moving at v0 [m/s], in flight under gravity g.
template <typename S>
Vec3<S> flightPosition(const Vec3<S>& r0, const Vec3<S>& v0, S t, S gravity);

/// The velocity t [s] into the same flight.
template <typename S>
Vec3<S> flightVelocity(const Vec3<S>& v0, S t, S gravity);

/// The time [s] at which a centre now at height z0 [m] moving up at vz [m/s] comes down through
/// height h [m] (the descending root of z0 + vz t - g t^2 / 2 = h), or +inf if it never comes down
/// through h (it stays below h, or is below it already and falling). Computed without the
/// cancellation of the textbook root when vz < 0 and the drop is short.
template <typename S>
S timeToHeight(S z0, S vz, S h, S gravity);

/// The highest the centre goes [m]: z0 + vz^2 / 2g when rising, z0 otherwise.
template <typename S>
S apexHeight(S z0, S vz, S gravity);

}  // namespace physics
}  // namespace cue_sim
