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

/// A rotation's rounding grows by about an ulp a grid point (a stuck phase has at most 4 eta / rate
/// + 8 of them, under 500): an excess within this share of the stretch's scale is computed afresh
/// before its sign is trusted.
constexpr double kRotationTrust = 1e-12;
/// Newton's steps to a stick's end before bisection takes over (from the secant's point in a
/// bracket finer than both oscillations it takes about four).
constexpr int kMaxRootSteps = 16;
/// A Newton step this small relative to psi has reached rounding.
constexpr double kRootSettled = 4e-16;

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
  /// a grid of an eighth of the vibration's half period and of pi/16 in psi, then found to the
  /// last bit (firstExcess).
  void stick(const Phase<S>& phase, TangentState<S>& state) const
  {
    const S kappa = eta_ / phase.rate, quarter_turn = phase.end - phase.begin;  // each phase is pi/2 in psi
    const S step = std::min(quarter_turn / (S(4) * kappa), quarter_turn / S(8));
    const StuckSpring spring(state, kappa, eta_, limit_);
    // The grid turns the spring's phase and psi by fixed rotations: no sine or cosine per point.
    // A rotation's rounding grows by an ulp a point, so a point whose excess is within
    // kRotationTrust of the limit's scale is computed afresh, and the grid starts afresh there.
    const S turn_cos = std::cos(kappa * step), turn_sin = std::sin(kappa * step);
    const S psi_cos = std::cos(step), psi_sin = std::sin(step);
    S before = state.psi, cos_u = 1, sin_u = 0, cos_psi = std::cos(before), sin_psi = std::sin(before);
    Sample held{before, spring.excess(before).value};
    while (before < phase.end)
    {
      S after = before + step;
      Sample next{};
      if (after >= phase.end)
      {
        after = phase.end;
        next = {after, spring.excess(after).value};
      }
      else
      {
        rotate(cos_u, sin_u, turn_cos, turn_sin);
        rotate(cos_psi, sin_psi, psi_cos, psi_sin);
        next = {after, std::abs(spring.stretch(cos_u, sin_u)) - limit_ * sin_psi};
        if (std::abs(next.excess) <= S(kRotationTrust) * (std::abs(spring.amplitude()) + limit_))
        {
          next.excess = spring.excess(after).value;
          spring.phaseAt(after, cos_u, sin_u);
          cos_psi = std::cos(after);
          sin_psi = std::sin(after);
        }
      }
      if (next.excess > S(0))
      {
        slideFrom(state, kappa, firstExcess(spring, held, next));
        return;
      }
      before = after;
      held = next;
    }
    moveStuck(state, kappa, phase.end);
  }

  static void rotate(S& c, S& s, S turn_cos, S turn_sin)
  {
    const S c1 = c * turn_cos - s * turn_sin;
    s = s * turn_cos + c * turn_sin;
    c = c1;
  }

  /// A point's excess: the stretch beyond the friction limit, and its rate in psi.
  struct Excess
  {
    S value, slope;
  };

  /// The spring stuck since psi_a: stretch x(u) = x_a cos u + (s_a / eta) sin u at u = kappa
  /// (psi - psi_a), against the limit `limit` sin(psi).
  class StuckSpring
  {
  public:
    StuckSpring(const TangentState<S>& state, S kappa, S eta, S limit)
      : psi_(state.psi),
        kappa_(kappa),
        eta_(eta),
        x_(state.spring),
        slip_(state.slip),
        v_(state.slip / eta),
        limit_(limit)
    {
    }
    S stretch(S cos_u, S sin_u) const { return x_ * cos_u + v_ * sin_u; }
    /// The contact's slip: s_a cos u - eta x_a sin u.
    S slip(S cos_u, S sin_u) const { return slip_ * cos_u - eta_ * x_ * sin_u; }
    S amplitude() const { return std::hypot(x_, v_); }
    void phaseAt(S psi, S& cos_u, S& sin_u) const
    {
      const S u = kappa_ * (psi - psi_);
      cos_u = std::cos(u);
      sin_u = std::sin(u);
    }
    Excess excess(S psi) const
    {
      S cos_u, sin_u;
      phaseAt(psi, cos_u, sin_u);
      const S x = stretch(cos_u, sin_u), rate = kappa_ * (v_ * cos_u - x_ * sin_u);
      return {std::abs(x) - limit_ * std::sin(psi), (x < S(0) ? -rate : rate) - limit_ * std::cos(psi)};
    }

  private:
    S psi_, kappa_, eta_, x_, slip_, v_, limit_;
  };

  /// A psi and the excess there.
  struct Sample
  {
    S psi, excess;
  };

  /// The first psi in (held, past] where the stretch exceeds the limit: excess(held) <= 0 <
  /// excess(past), with no other crossing between them (the grid is finer than both
  /// oscillations). Newton's steps from the secant's point, kept inside the bracket (a bisection
  /// where one would leave it), each narrowing it; then the bracket's ends walked to adjacent
  /// numbers. The answer is on the side past the limit.
  S firstExcess(const StuckSpring& spring, Sample held, Sample past) const
  {
    S psi = held.psi - held.excess * (past.psi - held.psi) / (past.excess - held.excess);
    for (int n = 0; n < kMaxRootSteps; ++n)
    {
      const S middle = held.psi + (past.psi - held.psi) / 2;
      if (!(middle > held.psi && middle < past.psi))
        return past.psi;
      if (!(psi > held.psi && psi < past.psi))
        psi = middle;
      const Excess at = spring.excess(psi);
      (at.value > S(0) ? past : held) = {psi, at.value};
      const S newton = psi - at.value / at.slope;
      // Converged: the other side is the neighbouring number.
      if (newton == psi || std::abs(newton - psi) <= S(kRootSettled) * std::abs(psi))
        psi = at.value > S(0) ? std::nextafter(psi, held.psi) : std::nextafter(psi, past.psi);
      else
        psi = newton;
    }
    // Rounding keeps Newton from settling: bisection to the last bit.
    for (;;)
    {
      const S middle = held.psi + (past.psi - held.psi) / 2;
      if (!(middle > held.psi && middle < past.psi))
        return past.psi;
      const S value = spring.excess(middle).value;
      (value > S(0) ? past : held) = {middle, value};
    }
  }

  void moveStuck(TangentState<S>& state, S kappa, S psi) const
  {
    const StuckSpring spring(state, kappa, eta_, limit_);
    S cos_u, sin_u;
    spring.phaseAt(psi, cos_u, sin_u);
    state.spring = spring.stretch(cos_u, sin_u);
    state.slip = spring.slip(cos_u, sin_u);
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
