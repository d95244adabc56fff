#include "physics/models/cushion/tangential_compliance.hpp"

#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace physics
{
namespace
{
/// One phase of the normal force m v_n sin(psi): psi runs from `begin` to `end` at `rate` =
/// d psi / d tau (1 in compression, 1/e in restitution).
template <typename S>
struct Phase
{
  S begin, end, rate;
};

/// Where the tangent is at psi: the contact point's slip `slip`, the spring's stretch `spring`
/// times omega_n (a velocity), and whether the spring's far end is stuck; sliding, it slides in
/// `direction` (+1 or -1) and the spring holds the friction limit.
template <typename S>
struct TangentState
{
  S psi, slip, spring;
  bool stuck;
  int direction;
};

/// Transitions at most, for a frequency ratio eta: a stick and a slide each start at most once
/// per half vibration of the spring, about eta of them in an impact; the rest is a margin. Only a
/// tie broken differently by rounding at a transition could loop, and this stops it.
int maxSegments(double eta)
{
  return 64 + 16 * static_cast<int>(std::ceil(std::min(eta, 1e6)));
}

template <typename S>
class CompliantTangent
{
public:
  /// `slide`: mu beta_t v_n, the slip's fall per unit of the normal impulse in units of m v_n;
  /// `limit` = slide / eta^2: the spring's largest stretch (times omega_n) at the peak force.
  CompliantTangent(S slide, S eta) : slide_(slide), limit_(slide / (eta * eta)), eta_(eta) {}

  /// Advances `state` through `phase` to its end or to the next stick or slip, whichever first.
  void advance(const Phase<S>& phase, TangentState<S>& state) const
  {
    if (state.stuck)
      stick(phase, state);
    else
      slip(phase, state);
  }

private:
  /// Sliding, the slip falls as s(psi) = s_a - d (slide / rate)(cos psi_a - cos psi) and the
  /// spring holds d limit sin(psi). The far end keeps sliding while d s exceeds the spring's own
  /// rate d limit rate cos(psi); the difference is linear in cos(psi), so where it vanishes has a
  /// closed form. It falls with psi, and the spring can then hold the far end, only if eta >
  /// rate (else the end slides on: the limit changes faster than the spring can follow).
  void slip(const Phase<S>& phase, TangentState<S>& state) const
  {
    const S d = S(state.direction), r = phase.rate, cos_a = std::cos(state.psi);
    const S slope = slide_ / r - limit_ * r;
    S psi = phase.end;
    bool sticks = false;
    if (slope > S(0))
    {
      const S cos_stick = (slide_ / r * cos_a - d * state.slip) / slope;
      if (cos_stick >= std::cos(phase.end))
      {
        psi = cos_stick >= cos_a ? state.psi : std::acos(std::min(cos_stick, S(1)));
        sticks = true;
      }
    }
    state.slip -= d * slide_ / r * (cos_a - std::cos(psi));
    state.spring = d * limit_ * std::sin(psi);
    state.psi = psi;
    state.stuck = sticks;
  }

  /// Stuck, the spring vibrates freely at eta (eta / rate in psi) from its stretch and rate at
  /// psi_a. It holds while its stretch is within the limit; the first psi past it is bracketed on
  /// a grid of an eighth of the vibration's half period and of pi/16 in psi, then bisected.
  void stick(const Phase<S>& phase, TangentState<S>& state) const
  {
    const S kappa = eta_ / phase.rate, quarter_turn = phase.end - phase.begin;  // each phase is pi/2 in psi
    const S step = std::min(quarter_turn / (S(4) * kappa), quarter_turn / S(8));
    S before = state.psi;
    while (before < phase.end)
    {
      const S after = std::min(before + step, phase.end);
      if (excess(state, kappa, after) > S(0))
      {
        slideFrom(state, kappa, firstExcess(state, kappa, before, after));
        return;
      }
      before = after;
    }
    moveStuck(state, kappa, phase.end);
  }

  /// The stretch beyond the friction limit at psi, stuck since state.psi.
  S excess(const TangentState<S>& state, S kappa, S psi) const
  {
    return std::abs(stretchAt(state, kappa, psi)) - limit_ * std::sin(psi);
  }

  S stretchAt(const TangentState<S>& state, S kappa, S psi) const
  {
    const S u = kappa * (psi - state.psi);
    return state.spring * std::cos(u) + state.slip / eta_ * std::sin(u);
  }

  /// The first psi in (held, past] where the stretch exceeds the limit: excess(held) <= 0 <
  /// excess(past). Bisection to the last bit; the answer is on the side past the limit.
  S firstExcess(const TangentState<S>& state, S kappa, S held, S past) const
  {
    for (;;)
    {
      const S middle = held + (past - held) / 2;
      if (!(middle > held && middle < past))
        return past;
      (excess(state, kappa, middle) > S(0) ? past : held) = middle;
    }
  }

  void moveStuck(TangentState<S>& state, S kappa, S psi) const
  {
    const S u = kappa * (psi - state.psi);
    const S slip = state.slip * std::cos(u) - eta_ * state.spring * std::sin(u);
    state.spring = stretchAt(state, kappa, psi);
    state.slip = slip;
    state.psi = psi;
  }

  /// The far end lets go at psi, in the direction the spring pulls.
  void slideFrom(TangentState<S>& state, S kappa, S psi) const
  {
    moveStuck(state, kappa, psi);
    state.direction = state.spring < S(0) ? -1 : 1;
    state.spring = S(state.direction) * limit_ * std::sin(psi);
    state.stuck = false;
  }

  S slide_, limit_, eta_;
};
}  // namespace

template <typename S>
S slipAfterCompliantImpact(S slip, S approach, S mu, S beta_t, S e, S eta)
{
  if (!(slip > S(0) && approach > S(0)))
    return slip;
  const CompliantTangent<S> tangent(mu * beta_t * approach, eta);
  // Both springs start relaxed; the far end holds if the spring's force grows no faster than the
  // friction limit, slip <= limit d sin(psi)/d tau at psi = 0.
  TangentState<S> state{S(0), slip, S(0), slip <= mu * beta_t * approach / (eta * eta), 1};
  const S pi = std::acos(S(-1));
  // Without restitution (e = 0) the normal force drops at once and the slip cannot change.
  const int phases = e > S(0) ? 2 : 1;
  const Phase<S> phase[2] = {{S(0), pi / 2, S(1)}, {pi / 2, pi, phases == 2 ? S(1) / e : S(1)}};
  const int max_segments = maxSegments(static_cast<double>(eta));
  int segments = 0;
  for (int i = 0; i < phases; ++i)
    while (state.psi < phase[i].end && segments++ < max_segments)
      tangent.advance(phase[i], state);
  return state.slip;
}

template double slipAfterCompliantImpact(double, double, double, double, double, double);
template long double slipAfterCompliantImpact(long double, long double, long double, long double, long double,
                                              long double);

}  // namespace physics
}  // namespace cue_sim
