#include "physics/models/flight.hpp"

#include <cmath>
#include <limits>

namespace cue_sim
{
namespace physics
{
template <typename S>
Vec3<S> flightPosition(const Vec3<S>& r0, const Vec3<S>& v0, S t, S gravity)
{
  Vec3<S> r = r0 + t * v0;
  r.z() -= S(0.5) * gravity * t * t;
  return r;
}

template <typename S>
Vec3<S> flightVelocity(const Vec3<S>& v0, S t, S gravity)
{
  Vec3<S> v = v0;
  v.z() -= gravity * t;
  return v;
}

template <typename S>
S timeToHeight(S z0, S vz, S h, S gravity)
{
  const S drop = z0 - h;
  const S discriminant = vz * vz + S(2) * gravity * drop;
  if (discriminant < 0 || (drop < 0 && vz <= 0))
    return std::numeric_limits<S>::infinity();
  if (drop == 0 && vz <= 0)
    return S(0);  // there, and not rising
  const S root = std::sqrt(discriminant);
  // The descending root (vz + root) / g; when falling, vz + root cancels, and (vz + root)(root - vz)
  // = 2 g drop gives it as 2 drop / (root - vz).
  return vz > 0 ? (vz + root) / gravity : S(2) * drop / (root - vz);
}

template <typename S>
S apexHeight(S z0, S vz, S gravity)
{
  return vz > 0 ? z0 + vz * vz / (S(2) * gravity) : z0;
}

#define CUE_SIM_INSTANTIATE_FLIGHT(S)                                                                                  \
  template Vec3<S> flightPosition(const Vec3<S>&, const Vec3<S>&, S, S);                                               \
  template Vec3<S> flightVelocity(const Vec3<S>&, S, S);                                                               \
  template S timeToHeight(S, S, S, S);                                                                                 \
  template S apexHeight(S, S, S);
CUE_SIM_INSTANTIATE_FLIGHT(double)
CUE_SIM_INSTANTIATE_FLIGHT(long double)

}  // namespace physics
}  // namespace cue_sim
