#include "physics/supports/support_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/numerics/dormand_prince.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
using dormand_prince::kA;
using dormand_prince::kC;
using dormand_prince::kE;

/// Steps tried before the shortest is taken whatever its error: a step is halved at most this often
/// from its first try.
constexpr int kMaxAttempts = 60;
/// Bisections of a step to find where a mode stops holding: 2^-48 of the step.
constexpr int kBisections = 48;
/// The integration's own error is kept within this share of the contact tolerance, so that the
/// pieces' error is the tolerance the registry declares.
constexpr double kIntegrationShare = 0.1;
/// How far a margin may fall below where it started (or below zero) before its mode is taken to
/// have stopped holding: rounding.
constexpr double kMarginRounding = 1e-10;

/// The derivative of the dynamic bodies' state: velocities, accelerations, angular accelerations.
template <typename S>
struct Rate
{
  std::vector<Vec3<S>> v, a, alpha;
};

template <typename S>
class Integrator
{
public:
  Integrator(const ContactSystem<S>& system, const std::vector<ContactBody<S>>& start,
             const std::vector<ContactLink<S>>& links, const std::vector<LinkMode<S>>& modes,
             const KinematicPaths<S>& kinematic)
    : system_(system), start_(start), links_(links), modes_(modes), kinematic_(kinematic)
  {
    for (std::size_t b = 0; b < start.size(); ++b)
      if (start[b].dynamic)
        dynamic_.push_back(static_cast<int>(b));
    for (std::size_t l = 0; l < links.size(); ++l)
      start_gaps_.push_back(system.geometryOf(links[l], start).gap);
    rate(start_, k_[0]);
    marginsAt(start_, start_margins_);
  }

  /// One try of a step of length h: the end state, its error (scaled: 1 is the tolerance) and the
  /// rate there.
  S tryStep(S h, S tolerance)
  {
    const S T = supportTime(system_.params()), R = system_.params().ball_radius;
    std::vector<ContactBody<S>> y = start_;
    for (int s = 1; s < 7; ++s)
    {
      stageState(h, s, y);
      kinematic_(S(kC[s]) * h, y);
      rate(y, k_[static_cast<std::size_t>(s)]);
    }
    end_ = y;  // stage 7 is the fifth-order solution itself
    const S r_tol = S(kIntegrationShare) * tolerance, v_tol = r_tol / T;
    S error = S(0);
    for (std::size_t d = 0; d < dynamic_.size(); ++d)
    {
      Vec3<S> er = Vec3<S>::Zero(), ev = Vec3<S>::Zero(), ew = Vec3<S>::Zero();
      for (int s = 0; s < 7; ++s)
      {
        const Rate<S>& k = k_[static_cast<std::size_t>(s)];
        er += S(kE[s]) * h * k.v[d];
        ev += S(kE[s]) * h * k.a[d];
        ew += S(kE[s]) * h * k.alpha[d];
      }
      error = std::max({error, er.norm() / r_tol, ev.norm() / v_tol, R * ew.norm() / v_tol});
    }
    return error;
  }

  /// The largest distance of a dynamic body's quadratic piece (through its start and end with its
  /// start velocity) from the cubic through both ends with both velocities: (4/27) h |v1 - v0 - a h|.
  S pieceDeviation(S h) const
  {
    S worst = S(0);
    for (int b : dynamic_)
    {
      const ContactBody<S>&b0 = start_[static_cast<std::size_t>(b)], &b1 = end_[static_cast<std::size_t>(b)];
      const Vec3<S> a = S(2) * (b1.r - b0.r - h * b0.v) / (h * h);
      worst = std::max(worst, S(4) / S(27) * h * (b1.v - b0.v - h * a).norm());
    }
    return worst;
  }

  /// The first point of the step (as a share of it) where a mode stops holding: 0 if none, else
  /// the least share found to have stopped (bisected to kBisections halvings).
  S firstChange(S h)
  {
    // The end, and a few points within (a margin may dip and come back within the step).
    S hi = S(-1);
    for (const S theta : {S(0.25), S(0.5), S(0.75), S(1)})
      if (changedAt(h, theta))
      {
        hi = theta;
        break;
      }
    if (hi < S(0))
      return S(0);
    S lo = S(0);
    for (int i = 0; i < kBisections; ++i)
    {
      const S mid = S(0.5) * (lo + hi);
      (changedAt(h, mid) ? hi : lo) = mid;
    }
    return hi;
  }

  const std::vector<ContactBody<S>>& end() const { return end_; }
  /// The margin found crossed last (at the located point, after firstChange).
  const MarginTag& crossed() const { return crossed_; }
  const std::vector<int>& dynamic() const { return dynamic_; }

private:
  void rate(const std::vector<ContactBody<S>>& bodies, Rate<S>& out)
  {
    std::vector<LinkMode<S>> modes = modes_;
    system_.accelerations(bodies, links_, modes, rates_);
    out.v.resize(dynamic_.size());
    out.a.resize(dynamic_.size());
    out.alpha.resize(dynamic_.size());
    for (std::size_t d = 0; d < dynamic_.size(); ++d)
    {
      const std::size_t b = static_cast<std::size_t>(dynamic_[d]);
      out.v[d] = bodies[b].v;
      out.a[d] = rates_[b].a;
      out.alpha[d] = rates_[b].alpha;
    }
  }

  void stageState(S h, int s, std::vector<ContactBody<S>>& y) const
  {
    for (std::size_t d = 0; d < dynamic_.size(); ++d)
    {
      const std::size_t b = static_cast<std::size_t>(dynamic_[d]);
      Vec3<S> dr = Vec3<S>::Zero(), dv = Vec3<S>::Zero(), dw = Vec3<S>::Zero();
      for (int j = 0; j < s; ++j)
      {
        const Rate<S>& k = k_[static_cast<std::size_t>(j)];
        dr += S(kA[s][j]) * k.v[d];
        dv += S(kA[s][j]) * k.a[d];
        dw += S(kA[s][j]) * k.alpha[d];
      }
      y[b].r = start_[b].r + h * dr;
      y[b].v = start_[b].v + h * dv;
      y[b].w = start_[b].w + h * dw;
    }
  }

  void marginsAt(const std::vector<ContactBody<S>>& bodies, std::vector<S>& out)
  {
    std::vector<LinkMode<S>> modes = modes_;
    system_.accelerations(bodies, links_, modes, rates_);
    system_.margins(bodies, links_, modes, rates_, start_gaps_, out, &tags_);
    // A ball in the air must not come down through the slate within the step.
    for (int b : dynamic_)
      if (start_[static_cast<std::size_t>(b)].r.z() > system_.params().ball_radius)
      {
        out.push_back((bodies[static_cast<std::size_t>(b)].r.z() - system_.params().ball_radius) /
                      system_.params().ball_radius);
        tags_.push_back({-1, MarginKind::Height});
      }
  }

  /// Whether a mode has stopped holding at theta of the step (the bodies there by cubic Hermite
  /// interpolation of the ends: positions from positions and velocities, velocities from
  /// velocities and accelerations, spins from spins and their rates).
  bool changedAt(S h, S theta)
  {
    std::vector<ContactBody<S>> y = end_;
    const S t2 = theta * theta, t3 = t2 * theta;
    const S h00 = S(2) * t3 - S(3) * t2 + S(1), h10 = t3 - S(2) * t2 + theta, h01 = -S(2) * t3 + S(3) * t2,
            h11 = t3 - t2;
    const Rate<S>&k0 = k_[0], &k1 = k_[6];
    for (std::size_t d = 0; d < dynamic_.size(); ++d)
    {
      const std::size_t b = static_cast<std::size_t>(dynamic_[d]);
      const ContactBody<S>&b0 = start_[b], &b1 = end_[b];
      y[b].r = h00 * b0.r + h10 * h * b0.v + h01 * b1.r + h11 * h * b1.v;
      y[b].v = h00 * b0.v + h10 * h * k0.a[d] + h01 * b1.v + h11 * h * k1.a[d];
      y[b].w = h00 * b0.w + h10 * h * k0.alpha[d] + h01 * b1.w + h11 * h * k1.alpha[d];
    }
    kinematic_(theta * h, y);
    marginsAt(y, margins_);
    for (std::size_t i = 0; i < margins_.size() && i < start_margins_.size(); ++i)
      if (margins_[i] < std::min(start_margins_[i], S(0)) - S(kMarginRounding))
      {
        crossed_ = tags_[i];
        return true;
      }
    return false;
  }

  const ContactSystem<S>& system_;
  const std::vector<ContactBody<S>>& start_;
  const std::vector<ContactLink<S>>& links_;
  const std::vector<LinkMode<S>>& modes_;
  const KinematicPaths<S>& kinematic_;
  std::vector<int> dynamic_;
  std::vector<S> start_gaps_, start_margins_, margins_;
  std::vector<MarginTag> tags_;
  MarginTag crossed_;
  std::array<Rate<S>, 7> k_;
  std::vector<BodyRates<S>> rates_;
  std::vector<ContactBody<S>> end_;
};
}  // namespace

template <typename S>
SupportStep<S> stepSupported(const ContactSystem<S>& system, const std::vector<ContactBody<S>>& start,
                             const std::vector<ContactLink<S>>& links, const std::vector<LinkMode<S>>& modes,
                             const KinematicPaths<S>& kinematic, S trial, S longest, S tolerance)
{
  Integrator<S> integrator(system, start, links, modes, kinematic);
  SupportStep<S> out;
  S h = std::min(trial, longest);
  bool located = false;
  for (out.attempts = 1;; ++out.attempts)
  {
    const bool last_try = out.attempts >= kMaxAttempts;
    const S error = integrator.tryStep(h, tolerance);
    // A mode that stops holding within the step is found first: past it the equations change, so
    // the error there says nothing of the step up to it.
    if (!located && !last_try)
    {
      const S theta = integrator.firstChange(h);
      if (theta > S(0))
      {
        // Ended just past where the mode stops holding: the next step starts in the new modes.
        h *= theta;
        located = true;
        continue;
      }
    }
    if (error > S(1) && !last_try)
    {
      h *= std::max(S(0.2), S(0.9) * std::pow(error, S(-0.2)));
      located = false;
      continue;
    }
    const S deviation = integrator.pieceDeviation(h);
    if (deviation > tolerance && !last_try)
    {
      h *= std::max(S(0.2), S(0.9) * std::cbrt(tolerance / deviation));
      located = false;
      continue;
    }
    out.mode_changed = located;
    if (located)
      out.crossed = integrator.crossed();
    break;
  }
  out.h = h;
  out.end = integrator.end();
  for (int b : integrator.dynamic())
  {
    const ContactBody<S>&b0 = start[static_cast<std::size_t>(b)], &b1 = out.end[static_cast<std::size_t>(b)];
    out.a.push_back(S(2) * (b1.r - b0.r - h * b0.v) / (h * h));
    out.alpha.push_back((b1.w - b0.w) / h);
  }
  return out;
}

template SupportStep<double> stepSupported(const ContactSystem<double>&, const std::vector<ContactBody<double>>&,
                                           const std::vector<ContactLink<double>>&,
                                           const std::vector<LinkMode<double>>&, const KinematicPaths<double>&, double,
                                           double, double);
template SupportStep<long double> stepSupported(const ContactSystem<long double>&,
                                                const std::vector<ContactBody<long double>>&,
                                                const std::vector<ContactLink<long double>>&,
                                                const std::vector<LinkMode<long double>>&,
                                                const KinematicPaths<long double>&, long double, long double,
                                                long double);

}  // namespace physics
}  // namespace cue_sim
