// Sustained contact: balls pressed together are joined instead of bouncing without end, and a
// ball pressed onto a wall by its slip is held there (doc/physics.md, "Sustained contact").
#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "physics/contacts/event_resolver.hpp"

namespace cue_sim
{
namespace physics
{
template <typename S>
bool EventResolver<S>::inSustainedContact(const Ball<S>& a, const Ball<S>& b) const
{
  const Trajectory<S> pa = trajectoryFrom(a, a.time, params_), pb = trajectoryFrom(b, b.time, params_);
  const Vec2<S> d = pa.c0 - pb.c0;
  const Vec2<S> n = d.normalized();
  const Vec2<S> v_rel = pa.c1 - pb.c1;
  const S closing = closingSpeed(a, b);
  if (!(closing < S(engine_.limits().sustained_contact_speed)))
    return false;
  // After a bounce that removes the closing speed, the squared distance grows as
  // (|v_t|^2 + d.a_rel) tau^2: negative means the accelerations press the balls back together.
  const Vec2<S> v_t = v_rel + closing * n;
  return v_t.squaredNorm() + d.dot(S(2) * (pa.c2 - pb.c2)) < S(0);
}

template <typename S>
bool EventResolver<S>::growCluster(S time, const Vec3<S>& v, std::vector<int>& cluster)
{
  const S touching = S(2) * params_.ball_radius + S(kTouchingSlack);
  std::vector<int> candidates, nearby;
  for (int c : cluster)
  {
    nearBalls(state_.balls[c].r.template head<2>(), touching, nearby);
    candidates.insert(candidates.end(), nearby.begin(), nearby.end());
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (const int j : candidates)
  {
    if (std::find(cluster.begin(), cluster.end(), j) != cluster.end())
      continue;
    bool near = false;
    for (int c : cluster)
      near = near || !cannotReach(state_.balls[j], state_.balls[c].r, touching, time);
    if (!near)
      continue;
    const Ball<S> at_time = evolve(state_.balls[j], time, params_);
    for (const int member : cluster)
    {
      Ball<S> joined = state_.balls[member];
      joined.v = v;
      const S closing = closingSpeed(at_time, joined);
      if (!at_time.airborne() && (at_time.r - joined.r).template head<2>().norm() <= touching &&
          closing > -zeroSpeed<S>() && closing < S(engine_.limits().sustained_contact_speed))
      {
        state_.balls[j] = at_time;
        cluster.push_back(j);
        return true;
      }
    }
  }
  return false;
}

template <typename S>
void EventResolver<S>::joinPressedCluster(S time, int first, int second)
{
  // Joining only the pair would slow it against a third ball it touches, which would then
  // close on it and be joined, then the pair again, converging without end (a line of balls
  // rolling together). So every ball touching the cluster that the joined motion leaves
  // closing on it, slower than the sustained-contact speed, joins too, until none does.
  std::vector<int> cluster = {first, second};
  Vec3<S> v, w;
  do
  {
    v.setZero();
    w.setZero();
    for (int c : cluster)
    {
      v += state_.balls[c].v;
      w += state_.balls[c].w;
    }
    v /= S(cluster.size());
    w /= S(cluster.size());
  } while (growCluster(time, v, cluster));
  Ball<S> joined = state_.balls[first];
  joined.v = v;
  joined.w = w;
  moveAsOne(joined, cluster);
}

template <typename S>
void EventResolver<S>::moveAsOne(Ball<S>& joined, const std::vector<int>& cluster)
{
  // A wall a cluster ball touches holds the whole cluster as it would hold the ball alone: it
  // stops the joined motion into it (the wall takes momentum; a normal speed within rounding
  // of zero is left, so that walls facing each other do not undo one another), and the cloth
  // friction it balances turns the slip into it into spin (holdAgainstWall); walls facing each
  // other across the cluster hold it both ways (holdAcross). Done once for the joined motion,
  // so the cluster's balls keep moving as one.
  settleMotion(joined, params_.ball_radius);
  std::vector<Vec3<S>> walls;
  for (int c : cluster)
    for (const Vec3<S>& normal : touchingWalls(state_.balls[c]))
      walls.push_back(normal);
  for (const Vec3<S>& normal : walls)
  {
    if (facedAcross(normal, walls))
    {
      holdAcross(joined, normal);  // takes out all the motion and slip across: a hold would be undone
      continue;
    }
    const S into = joined.v.dot(normal);
    if (into < -zeroSpeed<S>())
      joined.v -= into * normal;
    settleMotion(joined, params_.ball_radius);
    holdAgainstWall(joined, normal);
  }
  for (int c : cluster)
  {
    state_.balls[c].v = joined.v;
    state_.balls[c].w = joined.w;
    state_.balls[c].motion = joined.motion;
    changed(c);
  }
}

template <typename S>
void EventResolver<S>::collapse(S time, int first, int second, bool stop)
{
  // Every ball touching the event's balls, transitively, moves as one body from now on, or,
  // past twice the collapse's allowance of events, stops (keeping its spin about z).
  const std::vector<int> group = touchingGroup(time, first, second);
  Ball<S> joined = state_.balls[first];
  joined.v.setZero();
  joined.w.setZero();
  for (int g : group)
  {
    joined.v += state_.balls[g].v / S(group.size());
    joined.w += state_.balls[g].w / S(group.size());
  }
  if (stop)
  {
    joined.v.setZero();
    joined.w.x() = joined.w.y() = S(0);
  }
  moveAsOne(joined, group);
}

template <typename S>
std::vector<Vec3<S>> EventResolver<S>::touchingWalls(const Ball<S>& ball) const
{
  const S R = params_.ball_radius;
  const S tolerance = S(kTouchingSlack);
  std::vector<Vec3<S>> normals;
  const Vec2<S> c = ball.r.template head<2>();
  if ((c.array() > geometry_.clear_low.array()).all() && (c.array() < geometry_.clear_high.array()).all())
    return normals;  // out of every wall's reach
  // Only a wall whose box holds the centre can touch the ball.
  const auto outside = [&](const auto& wall) {
    return (c.array() < wall.low.array()).any() || (c.array() > wall.high.array()).any();
  };
  for (const auto& seg : geometry_.segments)
  {
    if (outside(seg))
      continue;
    const S along = seg.direction.dot(c - seg.start);
    if (along >= S(0) && along <= seg.length && std::abs(seg.normal.dot(c - seg.start) - R) <= tolerance)
      normals.emplace_back(seg.normal.x(), seg.normal.y(), S(0));
  }
  for (const auto& circle : geometry_.circles)
    if (!outside(circle) && std::abs((c - circle.centre).norm() - R - circle.radius) <= tolerance)
    {
      const Vec2<S> n = (c - circle.centre).normalized();
      const Vec3<S> normal(n.x(), n.y(), S(0));
      // Met with its cushion at the tangent point, rounding turns the jaw's normal by up to 1e-8
      // rad from the cushion's: held against both, a cluster wedged across the table there was
      // left moving into the cushion facing it at 3e-9 m/s.
      if (std::none_of(normals.begin(), normals.end(),
                       [&](const Vec3<S>& wall) { return wall.dot(normal) > S(1) - S(kParallelWalls); }))
        normals.push_back(normal);
    }
  return normals;
}

template <typename S>
void EventResolver<S>::holdAgainstWall(Ball<S>& ball, const Vec3<S>& normal) const
{
  const S R = params_.ball_radius;
  const S v_n = ball.v.dot(normal);
  if (!(std::abs(v_n) < S(engine_.limits().sustained_contact_speed)) || ball.motion != Motion::Sliding)
    return;
  Vec3<S> v = ball.v - v_n * normal;
  const S u_n = slipVelocity(v, ball.w, R).dot(normal);
  if (!(u_n > S(0)))
    return;  // the cloth pulls the ball off the wall, or along it: free motion
  // Cloth friction at the bottom point, balanced by the wall's reaction through the centre
  // (a normal force on a sphere has no torque), acts on the spin alone: an impulse of
  // j = (2/5) m u_n against the slip turns w about z x n until the slip has no part into the
  // wall. It opposes the slip, so it removes energy.
  //
  // The slip is left pointing out of the wall by a few ulps rather than exactly along it: a
  // slip a hair into the wall, by rounding, would be found as the same contact again at the
  // same instant. (The energy this can add is of the order of m ulp^2, below 1e-28 J.)
  const Vec3<S> axis = Vec3<S>::UnitZ().cross(normal);
  const S ulp = zeroSpeed<S>() * (v.norm() + R * ball.w.norm());
  Vec3<S> w = ball.w + ((u_n + ulp) / R) * axis;
  for (S nudge = ulp; slipVelocity(v, w, R).dot(normal) > -S(0.5) * ulp; nudge *= S(2))
    w += (nudge / R) * axis;
  ball.v = v;
  ball.w = w;
  settleMotion(ball, R);
}

template <typename S>
bool EventResolver<S>::facedAcross(const Vec3<S>& normal, const std::vector<Vec3<S>>& walls)
{
  return std::any_of(walls.begin(), walls.end(),
                     [&](const Vec3<S>& other) { return normal.dot(other) < S(kParallelWalls) - S(1); });
}

template <typename S>
void EventResolver<S>::holdAcross(Ball<S>& joined, const Vec3<S>& normal) const
{
  // A cluster spanning the table from a wall to the one facing it (two large balls wedged
  // between the long cushions) cannot move across: each wall takes what would move it into that
  // wall, and the cloth friction across that the two walls balance turns the slip across into
  // spin, whichever way it points (holdAgainstWall, both ways at once). Its velocity across and
  // its spin about the horizontal axis along the walls are taken out: the slip across,
  // v.n - R w.(z x n), is then nothing, exactly on walls along the table's axes, and the
  // cluster slides along the walls without being found against either again at once (a slip
  // left a hair into one wall, by rounding, pressed the cluster into it every nanosecond: soak
  // seed 12, shot 19678, whose cushions are also 2e-13 rad from parallel, doc/accuracy.md).
  // Taking components out removes energy.
  const Vec3<S> axis = Vec3<S>::UnitZ().cross(normal);
  joined.v -= joined.v.dot(normal) * normal;
  joined.w -= joined.w.dot(axis) * axis;
  settleMotion(joined, params_.ball_radius);
}

#define CUE_SIM_INSTANTIATE_SUSTAINED_CONTACT(S)                                                                       \
  template bool EventResolver<S>::inSustainedContact(const Ball<S>&, const Ball<S>&) const;                            \
  template bool EventResolver<S>::growCluster(S, const Vec3<S>&, std::vector<int>&);                                   \
  template void EventResolver<S>::joinPressedCluster(S, int, int);                                                     \
  template void EventResolver<S>::moveAsOne(Ball<S>&, const std::vector<int>&);                                        \
  template void EventResolver<S>::collapse(S, int, int, bool);                                                         \
  template std::vector<Vec3<S>> EventResolver<S>::touchingWalls(const Ball<S>&) const;                                 \
  template void EventResolver<S>::holdAgainstWall(Ball<S>&, const Vec3<S>&) const;                                     \
  template bool EventResolver<S>::facedAcross(const Vec3<S>&, const std::vector<Vec3<S>>&);                            \
  template void EventResolver<S>::holdAcross(Ball<S>&, const Vec3<S>&) const;
CUE_SIM_INSTANTIATE_SUSTAINED_CONTACT(double)
CUE_SIM_INSTANTIATE_SUSTAINED_CONTACT(long double)

}  // namespace physics
}  // namespace cue_sim
