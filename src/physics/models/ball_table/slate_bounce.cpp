#include "physics/models/ball_table/slate_bounce.hpp"

#include <cmath>

#include "cue_sim/physics/motion.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// The ball after a tangential impulse J per unit mass against the slip's direction `along`.
template <typename S>
void applyFriction(Ball<S>& m, const Vec3<S>& along, S impulse, S radius)
{
  m.v -= impulse * along;
  m.w += (S(5) * impulse / (S(2) * radius)) * Vec3<S>(-along.y(), along.x(), S(0));  // (z x along)
}

/// How many whole impacts' friction, k + 1 of them, first reaches `needed` [m/s of slip] when impact
/// j can take `first` e^j: the smallest k with first (1 - e^(k+1)) / (1 - e) >= needed, or -1 if
/// even all of them together (first / (1 - e)) fall short.
template <typename S>
int impactThatStops(S needed, S first, S e)
{
  if (!(first > 0))
    return -1;
  const S short_share = S(1) - needed * (S(1) - e) / first;  // e^(k+1) must be at most this
  if (!(short_share > 0))
    return -1;
  int k = 0;
  if (e > 0 && short_share < S(1))
  {
    const S estimate = std::ceil(std::log(short_share) / std::log(e)) - S(1);
    k = estimate > S(0) ? static_cast<int>(std::fmin(estimate, S(1e6))) : 0;
  }
  // The logarithm's rounding can put k one off: the sum itself decides.
  const auto reaches = [&](int j) { return first * (S(1) - std::pow(e, S(j + 1))) / (S(1) - e) >= needed; };
  while (k > 0 && reaches(k - 1))
    --k;
  while (!reaches(k))
    ++k;
  return k;
}
}  // namespace

template <typename S>
Ball<S> slateImpact(const Ball<S>& in, const SlateContact<S>& contact, S radius)
{
  Ball<S> out = in;
  if (!(in.v.z() < 0))
    return out;
  const S incoming = -in.v.z();
  out.v.z() = contact.restitution * incoming;
  const Vec3<S> slip = slipVelocity(in.v, in.w, radius);
  const S slip_speed = slip.norm();
  if (!(slip_speed > 0) || !(contact.friction > 0))
    return out;
  const S most = contact.friction * (S(1) + contact.restitution) * incoming;
  applyFriction(out, Vec3<S>(slip / slip_speed), std::fmin(most, S(2) / S(7) * slip_speed), radius);
  return out;
}

template <typename S>
BounceSeries<S> bounceSeries(const Ball<S>& in, const SlateContact<S>& contact, S radius, S gravity)
{
  BounceSeries<S> series;
  Ball<S>& end = series.end;
  end = in;
  const S e = contact.restitution, g = gravity;
  const S u0 = in.v.z() < 0 ? -in.v.z() : S(0);        // the first impact's normal speed U_0
  const S flights = S(2) * e * u0 / (g * (S(1) - e));  // sum of 2 e U_k / g
  series.first_rebound = (e * u0) * (e * u0) / (S(2) * g);
  Vec3<S> way(in.v.x() * flights, in.v.y() * flights, S(0));

  const Vec3<S> slip = slipVelocity(in.v, in.w, radius);
  const S slip_speed = slip.norm();
  const S grip = contact.friction * (S(1) + e);  // impact k's friction per unit mass: grip U_k
  if (slip_speed > 0 && grip > 0 && u0 > 0)
  {
    const Vec3<S> along = slip / slip_speed;
    // Impacts before K take their whole friction; K stops the slip (it needs 2/7 of it in all).
    const S needed = S(2) / S(7) * slip_speed;
    const int stop = impactThatStops(needed, grip * u0, e);
    series.slip_stopped_at = stop;
    const bool stops = stop >= 0;
    const S eK = stops ? std::pow(e, S(stop)) : S(0);  // e^K, K the impacts at full friction
    const S e2K = eK * eK;
    // Flight k follows impact k with horizontal velocity v_in - grip S_k along (S_k = sum_{j<=k} U_j)
    // for k < K, then v_in - needed along: the way less v_in's part is
    //   grip sum_{k<K} S_k T_k + needed sum_{k>=K} T_k, T_k = 2 e U_0 e^k / g,
    // with sum_{k<K} S_k T_k = 2 e U_0^2 / (g (1-e)) ((1-e^K)/(1-e) - e (1-e^2K)/(1-e^2)).
    const S held =
        S(2) * e * u0 * u0 / (g * (S(1) - e)) * ((S(1) - eK) / (S(1) - e) - e * (S(1) - e2K) / (S(1) - e * e));
    const S tail = S(2) * e * u0 * eK / (g * (S(1) - e));
    way -= (grip * held + (stops ? needed * tail : S(0))) * along;
    applyFriction(end, along, stops ? needed : grip * u0 / (S(1) - e), radius);
  }
  end.time = in.time + flights;
  end.r = in.r + way;
  settleMotion(end, radius);  // on the cloth: z = R, v_z = 0, the motion its v and w imply
  return series;
}

#define CUE_SIM_INSTANTIATE_SLATE_BOUNCE(S)                                                                            \
  template Ball<S> slateImpact(const Ball<S>&, const SlateContact<S>&, S);                                             \
  template BounceSeries<S> bounceSeries(const Ball<S>&, const SlateContact<S>&, S, S);
CUE_SIM_INSTANTIATE_SLATE_BOUNCE(double)
CUE_SIM_INSTANTIATE_SLATE_BOUNCE(long double)

}  // namespace physics
}  // namespace cue_sim
