// A ball in the air left at rest on its supports (doc/physics.md, "Balls in the air"): gravity
// presses it on, and it has no speed to hop with. It slides down them by a fraction of a
// micrometre, the height it loses paying, exactly, for a hop off them.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contacts/event_resolver.hpp"
#include "physics/contacts/support_hops.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A support touches the ball when their gap is within this [m]: the soak campaign's overlap
/// tolerance, far below any gap a slide may close.
constexpr double kSupportTouch = 1e-9;
/// The longest slide [m]: a ball that would have to slide further to pay for a full hop
/// (nearly on a support's top) hops less. The slide is a step the ball's path does not show.
constexpr double kMaxSlide = 1e-6;
/// A ball on the cloth under a ball being held that still moves slower than this [m/s] is
/// stopped: its speed is rounding's and slides' leftovers, which the held ball's weight on it and
/// their friction take (they would stop it as the held ball settles). A faster support moving
/// away does not hold the ball (it comes down after it); one closing on it holds it until it
/// strikes it.
constexpr double kStoppedUnderHeld = 1e-6;
/// Descent per unit of slide below which the supports are taken to hold the ball (a slide of
/// kMaxSlide would pay for a hop of under a nanometre a second).
constexpr double kLeastDescent = 1e-9;

/// The direction, first order, that loses height fastest while moving away from no support
/// (outward normals `n`), with the height lost per unit length; a descent of 0 if there is none.
template <typename S>
S steepestFreeDescent(const std::vector<Vec3<S>>& n, Vec3<S>& best)
{
  std::vector<Vec3<S>> tries{Vec3<S>(S(0), S(0), S(-1))};
  for (std::size_t i = 0; i < n.size(); ++i)
  {
    tries.push_back(Vec3<S>(S(0), S(0), S(-1)) + n[i].z() * n[i]);
    for (std::size_t j = i + 1; j < n.size(); ++j)
    {
      const Vec3<S> line = n[i].cross(n[j]);
      tries.push_back(line.z() > S(0) ? Vec3<S>(-line) : line);
    }
  }
  S descent = S(0);
  for (const Vec3<S>& t : tries)
  {
    const S length = t.norm();
    if (!(length > S(0)))
      continue;
    const Vec3<S> d = t / length;
    const bool free = std::all_of(n.begin(), n.end(), [&](const Vec3<S>& m) { return d.dot(m) >= -S(kTouchingSlack); });
    if (free && -d.z() > descent)
    {
      descent = -d.z();
      best = d;
    }
  }
  return descent;
}

}  // namespace

template <typename S>
void EventResolver<S>::supportsOf(const Ball<S>& ball, int index, std::vector<Support>& supports, S& nearest) const
{
  const S R = params_.ball_radius;
  const auto note = [&](S gap, const Vec3<S>& normal, int by) {
    // The same wall met twice (a nose's line runs on past the pocket to the next cushion's) is
    // one support: counted twice, it would weigh the ball's hop off them.
    const bool again = std::any_of(supports.begin(), supports.end(), [&](const Support& s) {
      return s.ball < 0 && by < 0 && s.normal.dot(normal) > S(1) - S(kTouchingSlack);
    });
    if (gap <= S(kSupportTouch) && !again)
      supports.push_back({normal, by});
    else if (gap > S(kSupportTouch))
      nearest = std::min(nearest, gap);
  };
  note(ball.r.z() - R, Vec3<S>(S(0), S(0), S(1)), -1);  // the slate
  std::vector<int> near;
  nearBalls(ball.r.template head<2>(), S(2) * R + S(kMaxSlide) + S(kSupportTouch), near);
  for (int j : near)
  {
    if (j == index || !state_.balls[j].inPlay())
      continue;
    // Each ball is where it is at this ball's time (a ball's state is kept at its last event).
    const Ball<S> other = evolve(state_.balls[j], ball.time, params_);
    const Vec3<S> d = ball.r - other.r;
    const S distance = d.norm();
    if ((ball.v - other.v).dot(d) > S(kSustainedContactSpeed) * distance)
      nearest = std::min(nearest, distance - S(2) * R);  // leaving it faster than a hop: no support
    else
      note(distance - S(2) * R, d / distance, j);
  }
  // The walls: a cushion's face below its nose, the nose's edge above it (its whole line, which
  // is never further than the cushion itself), a post's side, rim or top.
  const Vec2<S> p = ball.r.template head<2>();
  const S above = ball.r.z() - geometry_.nose_height;
  for (const auto& seg : geometry_.segments)
  {
    const S out = seg.normal.dot(p - seg.start);
    if (above <= S(0))
      note(out - R, Vec3<S>(seg.normal.x(), seg.normal.y(), S(0)), -1);
    else
    {
      const Vec3<S> d(std::max(out, S(0)) * seg.normal.x(), std::max(out, S(0)) * seg.normal.y(), above);
      note(d.norm() - R, d.normalized(), -1);
    }
  }
  for (const auto& post : geometry_.circles)
  {
    const Vec2<S> from = p - post.centre;
    const S distance = from.norm();
    const S side = std::max(distance - post.radius, S(0));
    const Vec3<S> d(side > S(0) ? side * from.x() / distance : S(0), side > S(0) ? side * from.y() / distance : S(0),
                    std::max(above, S(0)));
    const S length = d.norm();
    if (length > S(0))
      note(length - R, d / length, -1);
  }
}

template <typename S>
bool EventResolver<S>::slideDownSupports(int index)
{
  Ball<S>& ball = state_.balls[index];
  std::vector<Support> supports;
  S nearest = std::numeric_limits<S>::infinity();
  supportsOf(ball, index, supports, nearest);
  if (supports.empty())
    return false;
  std::vector<Vec3<S>> all, fixed;
  for (const Support& s : supports)
  {
    all.push_back(s.normal);
    if (s.ball < 0 || state_.balls[s.ball].airborne())
      fixed.push_back(s.normal);
  }
  Vec3<S> down;
  if (steepestFreeDescent(all, down) > S(kLeastDescent))
    return hopDownSupports(ball, supports, down, nearest);
  // Held by its supports: it may still come down between the balls on the cloth among them by
  // pushing them apart (no static friction holds a ball on the cloth).
  if (steepestFreeDescent(fixed, down) > S(kLeastDescent) && spreadSupports(index, supports, down, nearest))
    return true;
  return slideAfterMovingSupports(index, supports, nearest);
}

template <typename S>
bool EventResolver<S>::movingAway(const Support& support, const Ball<S>& ball) const
{
  if (support.ball < 0)
    return false;
  const Ball<S> b = evolve(state_.balls[support.ball], ball.time, params_);
  return !b.airborne() && b.v.norm() >= S(kStoppedUnderHeld) && !(b.v.dot(support.normal) > zeroSpeed<S>());
}

template <typename S>
bool EventResolver<S>::slideAfterMovingSupports(int index, const std::vector<Support>& supports, S nearest)
{
  // A ball on the cloth that moves and does not close on the ball is on its way out from under
  // it: the ball comes down after it, never nearer to it than half their gap (each landing on
  // the others finds it further off).
  Ball<S>& ball = state_.balls[index];
  std::vector<Support> staying, leaving;
  std::vector<Vec3<S>> normals;
  for (const Support& s : supports)
  {
    const bool away = movingAway(s, ball);
    (away ? leaving : staying).push_back(s);
    if (!away)
      normals.push_back(s.normal);
  }
  Vec3<S> down;
  if (leaving.empty() || staying.empty() || !(steepestFreeDescent(normals, down) > S(kLeastDescent)))
    return false;
  for (const Support& s : leaving)
  {
    const S toward = -down.dot(s.normal);
    if (toward > S(0))
    {
      const Ball<S> b = evolve(state_.balls[s.ball], ball.time, params_);
      nearest = std::min(nearest, std::max((ball.r - b.r).norm() - S(2) * params_.ball_radius, S(0)) / toward);
    }
  }
  return hopDownSupports(ball, staying, down, nearest);
}

template <typename S>
bool EventResolver<S>::hopDownSupports(Ball<S>& ball, const std::vector<Support>& supports, const Vec3<S>& down,
                                       S nearest)
{
  Vec3<S> away = Vec3<S>::Zero();
  for (const Support& s : supports)
    away += s.normal;
  away.normalize();
  if (!std::all_of(supports.begin(), supports.end(), [&](const Support& s) { return away.dot(s.normal) > S(0); }))
    return false;
  // The hop costs (per unit mass) hop (away . v) + hop^2 / 2 of kinetic energy; the slide s
  // down pays g s descent for it.
  const S g = params_.gravity, descent = -down.z(), along = away.dot(ball.v);
  // Never further than half the way to anything it does not touch: it makes no overlap.
  const S longest = std::min(S(kMaxSlide), S(0.5) * nearest);
  const S afforded = g * S(0.5) * longest * descent;
  S hop = S(kSettleSpeed);
  S cost = hop * along + S(0.5) * hop * hop;
  if (cost > afforded)
  {
    hop = -along + std::sqrt(along * along + S(2) * afforded);
    cost = hop * along + S(0.5) * hop * hop;
  }
  if (!(hop >= S(kSmallestHop)))
    return false;
  // A few ulps more height lost than the hop takes, so rounding never makes energy.
  const S slide = std::max(cost, S(0)) / (g * descent) * (S(1) + S(64) * std::numeric_limits<S>::epsilon());
  if (!(slide <= longest))
    return false;
  ball.r += slide * down;
  ball.v += hop * away;
  return true;
}

template <typename S>
bool EventResolver<S>::freeWayOut(const Ball<S>& pushed, int pushed_index, int by, const Vec2<S>& radial,
                                  Vec2<S>& out) const
{
  // Pushed along `radial`, a ball on the cloth against a cushion's face slides along the face (the
  // cushion takes the push's part into it); anything else in the way holds it.
  std::vector<Support> its;
  S its_nearest = std::numeric_limits<S>::infinity();
  supportsOf(pushed, pushed_index, its, its_nearest);
  out = radial;
  for (const Support& s : its)
  {
    if (s.ball == by || s.normal.z() > S(0.5))
      continue;  // the ball above it, or the slate
    const Vec2<S> n = s.normal.template head<2>();
    if (out.dot(n) >= S(0))
      continue;
    if (s.ball >= 0 || std::abs(s.normal.z()) > S(kTouchingSlack))
      return false;  // a ball, a nose's edge or a post: it holds it there
    out -= out.dot(n) * n;
  }
  const S length = out.norm();
  if (!(length > S(kLeastDescent)))
    return false;
  out /= length;
  // Faces met in turn: what is left must leave them all.
  return std::all_of(its.begin(), its.end(), [&](const Support& s) {
    return s.ball == by || s.normal.z() > S(0.5) || out.dot(s.normal.template head<2>()) >= -S(kTouchingSlack);
  });
}

template <typename S>
bool EventResolver<S>::spreadSupports(int index, const std::vector<Support>& supports, const Vec3<S>& down, S nearest)
{
  Ball<S>& ball = state_.balls[index];
  const S R = params_.ball_radius, g = params_.gravity, descent = -down.z();
  // The balls on the cloth it would come down into are pushed out, away from it, at kSettleSpeed.
  struct Push
  {
    int index;
    Ball<S> ball;  ///< at this instant
    Vec2<S> out;
  };
  std::vector<Push> pushes;
  S cost = S(0);
  // The weight, shared evenly over the supports' vertical parts, pushes each ball on the cloth
  // out with share * |n_xy| per unit mass: a ball its rolling resistance holds against that
  // (mu_roll g) is not pushed, and the ball is held (an even share is exact for a symmetric pile,
  // such as a pyramid; a pile whose supports share unevenly is statically indeterminate).
  S lift = S(0);
  for (const Support& s : supports)
    lift += std::max(s.normal.z(), S(0));
  const S share = g / lift;
  for (const Support& s : supports)
    if (s.ball >= 0 && down.dot(s.normal) < S(0))
    {
      const Ball<S> b = evolve(state_.balls[s.ball], ball.time, params_);
      const Vec2<S> radial = (b.r - ball.r).template head<2>().normalized();
      Vec2<S> out;
      if (!freeWayOut(b, s.ball, index, radial, out) ||
          !(share * s.normal.template head<2>().norm() * out.dot(radial) > params_.rollDecel()))
        return false;
      pushes.push_back({s.ball, b, out});
      cost += S(kSettleSpeed) * out.dot(b.v.template head<2>()) + S(0.5) * S(kSettleSpeed * kSettleSpeed);
    }
  const S slide = std::max(cost, S(0)) / (g * descent) * (S(1) + S(64) * std::numeric_limits<S>::epsilon());
  if (pushes.empty() || !(slide <= std::min(S(kMaxSlide), S(0.5) * nearest)))
    return false;
  const Vec3<S> r = ball.r + slide * down;
  // Each pushed ball moves out just far enough to touch it again, if nothing else is in its way.
  std::vector<S> moves;
  for (const Push& push : pushes)
  {
    const Ball<S>& b = push.ball;
    const Vec2<S> w = (b.r - r).template head<2>();
    const S dz = b.r.z() - r.z(), along = w.dot(push.out);
    const S reach = S(4) * R * R - dz * dz - w.squaredNorm() + along * along;
    const S move = reach > S(0) ? std::max(-along + std::sqrt(reach), S(0)) * (S(1) + S(kTouchingSlack)) : S(0);
    std::vector<Support> its;
    S its_nearest = std::numeric_limits<S>::infinity();
    supportsOf(b, push.index, its, its_nearest);
    if (!(move <= S(0.5) * its_nearest))
      return false;
    moves.push_back(move);
  }
  ball.r = r;
  for (std::size_t k = 0; k < pushes.size(); ++k)
  {
    Ball<S> b = pushes[k].ball;
    b.r.template head<2>() += moves[k] * pushes[k].out;
    b.v.template head<2>() += S(kSettleSpeed) * pushes[k].out;
    settleMotion(b, R);
    state_.balls[pushes[k].index] = b;
    changed(pushes[k].index);
  }
  return true;
}

template <typename S>
bool EventResolver<S>::holdInTheAir(int index)
{
  Ball<S>& ball = state_.balls[index];
  if (!ball.airborne() || !(ball.v.norm() < S(kSettleSpeed)))
    return false;
  std::vector<Support> supports;
  S nearest = std::numeric_limits<S>::infinity();
  supportsOf(ball, index, supports, nearest);
  std::vector<Vec3<S>> normals;
  std::vector<int> to_stop;
  for (const Support& s : supports)
  {
    // A ball on the cloth moving out from under it does not hold it; one closing on it holds it
    // until it strikes it (an impact with a held ball frees it).
    if (movingAway(s, ball))
      continue;
    normals.push_back(s.normal);
    if (s.ball < 0 || !state_.balls[s.ball].translating())
      continue;
    const Ball<S> support = evolve(state_.balls[s.ball], ball.time, params_);
    if (support.airborne())
      return false;
    if (support.v.norm() < S(kStoppedUnderHeld))
      to_stop.push_back(s.ball);
  }
  Vec3<S> down;
  if (supports.empty() || steepestFreeDescent(normals, down) > S(kLeastDescent))
    return false;
  for (int j : to_stop)
  {
    Ball<S> support = evolve(state_.balls[j], ball.time, params_);
    support.v.setZero();
    support.w.x() = support.w.y() = S(0);
    settleMotion(support, params_.ball_radius);
    state_.balls[j] = support;
    changed(j);
  }
  // The kinetic energy it had (under that of kSettleSpeed, and its spin) its supports' friction
  // takes.
  ball.v.setZero();
  ball.w.setZero();
  ball.motion = Motion::Held;
  return true;
}

#define CUE_SIM_INSTANTIATE_SUPPORT_SLIDE(S)                                                                           \
  template void EventResolver<S>::supportsOf(const Ball<S>&, int, std::vector<Support>&, S&) const;                    \
  template bool EventResolver<S>::slideDownSupports(int);                                                              \
  template bool EventResolver<S>::hopDownSupports(Ball<S>&, const std::vector<Support>&, const Vec3<S>&, S);           \
  template bool EventResolver<S>::spreadSupports(int, const std::vector<Support>&, const Vec3<S>&, S);                 \
  template bool EventResolver<S>::holdInTheAir(int);                                                                   \
  template bool EventResolver<S>::movingAway(const Support&, const Ball<S>&) const;                                    \
  template bool EventResolver<S>::slideAfterMovingSupports(int, const std::vector<Support>&, S);                       \
  template bool EventResolver<S>::freeWayOut(const Ball<S>&, int, int, const Vec2<S>&, Vec2<S>&) const;
CUE_SIM_INSTANTIATE_SUPPORT_SLIDE(double)
CUE_SIM_INSTANTIATE_SUPPORT_SLIDE(long double)

}  // namespace physics
}  // namespace cue_sim
