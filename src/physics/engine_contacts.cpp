// Resolving events: impacts of touching groups, pressed clusters joined, balls held on walls,
// pocketing (see README, "Simultaneous impacts" and "Sustained contact").
#include <algorithm>
#include <cmath>

#include "cue_sim/physics/engine.hpp"
#include "cue_sim/physics/motion.hpp"
#include "physics/engine_geometry.hpp"

namespace cue_sim
{
namespace physics
{
using namespace engine_detail;

template <typename S>
void Engine<S>::pocketBall(TableState<S>& state, Ball<S>& ball, int pocket) const
{
  // Pocketed balls rest below the cloth at their pocket's centre, stacked in arrival order.
  int already = 0;
  for (const auto& b : state.balls)
    if (b.motion == Motion::Pocketed && b.pocket == pocket)
      ++already;
  const auto& p = obstacles_->pockets[pocket];
  const S R = params_.ball_radius;
  ball.motion = Motion::Pocketed;
  ball.pocket = pocket;
  ball.r = Vec3<S>(p.centre.x(), p.centre.y(), -R - S(2) * R * S(already));
  ball.v.setZero();
  ball.w.setZero();
}

template <typename S>
bool Engine<S>::inSustainedContact(const Ball<S>& a, const Ball<S>& b) const
{
  const Trajectory<S> pa = trajectoryFrom(a, a.time, params_), pb = trajectoryFrom(b, b.time, params_);
  const Vec2<S> d = pa.c0 - pb.c0;
  const Vec2<S> n = d.normalized();
  const Vec2<S> v_rel = pa.c1 - pb.c1;
  const S closing = closingSpeed(a, b);
  if (!(closing < S(limits_.sustained_contact_speed)))
    return false;
  // After a bounce that removes the closing speed, the squared distance grows as
  // (|v_t|^2 + d.a_rel) tau^2: negative means the accelerations press the balls back together.
  const Vec2<S> v_t = v_rel + closing * n;
  return v_t.squaredNorm() + d.dot(S(2) * (pa.c2 - pb.c2)) < S(0);
}

template <typename S>
void Engine<S>::nearBalls(const TableState<S>& state, const EventContext& context, const Vec2<S>& point, S distance,
                          std::vector<int>& out) const
{
  if (context.neighbours)
  {
    context.neighbours->near(point, distance, out);
    return;
  }
  out.clear();
  for (std::size_t j = 0; j < state.balls.size(); ++j)
    if (state.balls[j].inPlay())
      out.push_back(static_cast<int>(j));
}

template <typename S>
bool Engine<S>::cannotReach(const Ball<S>& ball, const Vec3<S>& point, S distance, S time) const
{
  // No ball speeds up by more than the sliding deceleration, so by `time` it has moved at most
  // |v| dt + a dt^2 / 2 (with a nanometre for rounding): a bound that spares evolving it.
  const S dt = time - ball.time;
  const S travel = ball.moving() ? dt * (ball.v.norm() + S(0.5) * params_.slideDecel() * dt) : S(0);
  const S reach = distance + travel + S(1e-9);
  return (ball.r - point).template head<2>().squaredNorm() > reach * reach;
}

template <typename S>
void Engine<S>::joinPressedCluster(TableState<S>& state, S time, int first, int second,
                                   const EventContext& context) const
{
  std::vector<int>* changed = context.changed;
  // Joining only the pair would slow it against a third ball it touches, which would then
  // close on it and be joined, then the pair again, converging without end (a line of balls
  // rolling together). So every ball touching the cluster that the joined motion leaves
  // closing on it, slower than the sustained-contact speed, joins too, until none does.
  const S touching = S(2) * params_.ball_radius + S(1e-12);
  std::vector<int> cluster = {first, second};
  std::vector<int> candidates, nearby;
  Vec3<S> v = Vec3<S>::Zero(), w = Vec3<S>::Zero();
  for (bool grown = true; grown;)
  {
    v.setZero();
    w.setZero();
    for (int c : cluster)
    {
      v += state.balls[c].v;
      w += state.balls[c].w;
    }
    v /= S(cluster.size());
    w /= S(cluster.size());
    grown = false;
    candidates.clear();
    for (int c : cluster)
    {
      nearBalls(state, context, state.balls[c].r.template head<2>(), touching, nearby);
      candidates.insert(candidates.end(), nearby.begin(), nearby.end());
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (std::size_t m = 0; m < candidates.size() && !grown; ++m)
    {
      const std::size_t j = static_cast<std::size_t>(candidates[m]);
      if (std::find(cluster.begin(), cluster.end(), static_cast<int>(j)) != cluster.end())
        continue;
      bool near = false;
      for (int c : cluster)
        near = near || !cannotReach(state.balls[j], state.balls[c].r, touching, time);
      if (!near)
        continue;
      const Ball<S> at_time = evolve(state.balls[j], time, params_);
      for (std::size_t k = 0; k < cluster.size() && !grown; ++k)
      {
        Ball<S> joined = state.balls[cluster[k]];
        joined.v = v;
        const S closing = closingSpeed(at_time, joined);
        if ((at_time.r - joined.r).template head<2>().norm() <= touching && closing > -zeroSpeed<S>() &&
            closing < S(limits_.sustained_contact_speed))
        {
          state.balls[j] = at_time;
          cluster.push_back(static_cast<int>(j));
          grown = true;
        }
      }
    }
  }
  // A wall a cluster ball touches holds the whole cluster as it would hold the ball alone: it
  // stops the joined motion into it (the wall takes momentum), and the cloth friction it
  // balances turns the slip into it into spin (holdAgainstWall). Done once for the joined
  // motion, so the cluster's balls keep moving as one.
  Ball<S> joined = state.balls[first];
  joined.v = v;
  joined.w = w;
  settleMotion(joined, params_.ball_radius);
  for (int c : cluster)
    for (const Vec3<S>& normal : touchingWalls(state.balls[c]))
    {
      joined.v -= std::min(joined.v.dot(normal), S(0)) * normal;
      settleMotion(joined, params_.ball_radius);
      holdAgainstWall(joined, normal);
    }
  for (int c : cluster)
  {
    state.balls[c].v = joined.v;
    state.balls[c].w = joined.w;
    state.balls[c].motion = joined.motion;
    if (changed)
      changed->push_back(c);
  }
}

template <typename S>
std::vector<Vec3<S>> Engine<S>::touchingWalls(const Ball<S>& ball) const
{
  const S R = params_.ball_radius;
  const S tolerance = S(1e-12);
  std::vector<Vec3<S>> normals;
  const Vec2<S> c = ball.r.template head<2>();
  // Only a wall whose box holds the centre can touch the ball.
  const auto outside = [&](const auto& wall) {
    return (c.array() < wall.low.array()).any() || (c.array() > wall.high.array()).any();
  };
  for (const auto& seg : obstacles_->segments)
  {
    if (outside(seg))
      continue;
    const S along = seg.direction.dot(c - seg.start);
    if (along >= S(0) && along <= seg.length && std::abs(seg.normal.dot(c - seg.start) - R) <= tolerance)
      normals.emplace_back(seg.normal.x(), seg.normal.y(), S(0));
  }
  for (const auto& circle : obstacles_->circles)
    if (!outside(circle) && std::abs((c - circle.centre).norm() - R - circle.radius) <= tolerance)
    {
      const Vec2<S> n = (c - circle.centre).normalized();
      normals.emplace_back(n.x(), n.y(), S(0));
    }
  return normals;
}

template <typename S>
bool Engine<S>::resolveImpactGroup(TableState<S>& state, S time, int first, int second,
                                   const EventContext& context) const
{
  std::vector<int>* changed = context.changed;
  const Vec3<S> first_before = state.balls[first].v, second_before = state.balls[second].v;
  const S R = params_.ball_radius;
  // Balls that touch, transitively, the colliding pair take part in one impact.
  const S touching = S(2) * R + S(1e-12);
  std::vector<int> group;
  group.reserve(8);
  group.push_back(first);
  group.push_back(second);
  std::vector<int> own_nearby;
  std::vector<int>& nearby = context.scratch ? *context.scratch : own_nearby;
  for (std::size_t k = 0; k < group.size(); ++k)
  {
    nearBalls(state, context, state.balls[group[k]].r.template head<2>(), touching, nearby);
    for (int j : nearby)
    {
      if (std::find(group.begin(), group.end(), j) != group.end() ||
          cannotReach(state.balls[j], state.balls[group[k]].r, touching, time))
        continue;
      const Ball<S> at_time = evolve(state.balls[j], time, params_);
      if ((at_time.r - state.balls[group[k]].r).template head<2>().norm() <= touching)
      {
        state.balls[j] = at_time;
        group.push_back(j);
      }
    }
  }
  if (group.size() == 2 && (state.balls[first].r - state.balls[second].r).template head<2>().norm() <= touching &&
      touchingWalls(state.balls[first]).empty() && touchingWalls(state.balls[second]).empty())
  {
    // The common case, a lone pair: what the sweep below does for it, without its machinery.
    Ball<S>& a = state.balls[first];
    Ball<S>& b = state.balls[second];
    for (int sweep = 0; sweep < 100000 && closingSpeed(a, b) > zeroSpeed<S>(); ++sweep)
      ball_ball_->resolve(a, b, params_);
    settleMotion(a, R);
    settleMotion(b, R);
    if (changed)
    {
      changed->push_back(first);
      changed->push_back(second);
    }
    return a.v != first_before || b.v != second_before;
  }
  // The impact works on copies of the group's balls alone; contacts and walls name balls by
  // their place in the group.
  std::vector<Ball<S>> members;
  members.reserve(group.size());
  for (int g : group)
    members.push_back(state.balls[g]);
  std::vector<std::pair<int, int>> contacts;
  for (std::size_t a = 0; a < group.size(); ++a)
    for (std::size_t b = a + 1; b < group.size(); ++b)
      if ((members[a].r - members[b].r).template head<2>().norm() <= touching)
        contacts.emplace_back(static_cast<int>(a), static_cast<int>(b));
  // Cushions and jaws a group ball touches take part too: a ball pinned against a cushion.
  struct Wall
  {
    int member;
    Vec3<S> normal;  // into play
  };
  std::vector<Wall> walls;
  for (std::size_t g = 0; g < group.size(); ++g)
    for (const Vec3<S>& normal : touchingWalls(members[g]))
      walls.push_back({static_cast<int>(g), normal});
  const auto closing = [&](const std::vector<Ball<S>>& balls, const std::pair<int, int>& c) {
    return closingSpeed(balls[c.first], balls[c.second]);
  };
  std::vector<std::size_t> closing_now, resting;
  for (std::size_t c = 0; c < contacts.size(); ++c)
    (closing(members, contacts[c]) > zeroSpeed<S>() ? closing_now : resting).push_back(c);

  // Pairwise impulses, swept over the group until nothing closes (projected Gauss-Seidel).
  const auto sweepToRest = [&](std::vector<std::size_t> order) {
    order.insert(order.end(), resting.begin(), resting.end());
    std::vector<Ball<S>> balls = members;
    for (int sweep = 0; sweep < 100000; ++sweep)
    {
      bool any = false;
      for (std::size_t c : order)
        if (closing(balls, contacts[c]) > zeroSpeed<S>())
        {
          ball_ball_->resolve(balls[contacts[c].first], balls[contacts[c].second], params_);
          any = true;
        }
      for (const Wall& wall : walls)
        if (balls[wall.member].v.dot(wall.normal) < -zeroSpeed<S>())
        {
          cushion_->resolve(balls[wall.member], wall.normal, params_);
          any = true;
        }
      if (!any)
        break;
    }
    return balls;
  };
  // Contacts closing at the same instant have no first: every order is resolved and the
  // outcomes averaged, which keeps momentum, cannot add energy (kinetic energy is convex) and
  // keeps symmetric scenes symmetric.
  std::vector<std::vector<std::size_t>> orders;
  std::vector<std::size_t> order = closing_now;
  if (order.size() <= 4)
    do
      orders.push_back(order);
    while (std::next_permutation(order.begin(), order.end()));
  else
  {
    orders.push_back(order);
    orders.emplace_back(order.rbegin(), order.rend());
  }
  std::vector<Vec3<S>> v(group.size(), Vec3<S>::Zero()), w(group.size(), Vec3<S>::Zero());
  for (const auto& o : orders)
  {
    const std::vector<Ball<S>> outcome = sweepToRest(o);
    for (std::size_t g = 0; g < group.size(); ++g)
    {
      v[g] += outcome[g].v;
      w[g] += outcome[g].w;
    }
  }
  for (std::size_t g = 0; g < group.size(); ++g)
  {
    Ball<S>& b = state.balls[group[g]];
    b.v = v[g] / S(orders.size());
    b.w = w[g] / S(orders.size());
    settleMotion(b, R);
    if (changed)
      changed->push_back(group[g]);
  }
  return state.balls[first].v != first_before || state.balls[second].v != second_before;
}

template <typename S>
void Engine<S>::holdAgainstWall(Ball<S>& ball, const Vec3<S>& normal) const
{
  const S R = params_.ball_radius;
  const S v_n = ball.v.dot(normal);
  if (!(std::abs(v_n) < S(limits_.sustained_contact_speed)) || ball.motion != Motion::Sliding)
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
void Engine<S>::processEvent(TableState<S>& state, const Event<S>& event, const EventContext& context) const
{
  state.event_time = std::max(state.event_time, event.time);
  std::vector<int>* changed = context.changed;
  const int index = context.index;
  Ball<S>& ball = state.balls[index];
  ball = evolve(ball, event.time, params_);
  if (changed)
    changed->push_back(index);
  const S R = params_.ball_radius;
  switch (event.kind)
  {
    case EventKind::BallBall: {
      const int other_index = context.other_index;
      Ball<S>& other = state.balls[other_index];
      other = evolve(other, event.time, params_);
      if (changed)
        changed->push_back(other_index);
      // A pressed pair is joined (with its cluster, held by any wall it touches); any other
      // contact is an impact of the touching group. An event must change something, or it is
      // found again at the same instant forever.
      const Vec3<S> ball_before = ball.v, other_before = other.v;
      if (inSustainedContact(ball, other))
        joinPressedCluster(state, event.time, index, other_index, context);
      else if (!resolveImpactGroup(state, event.time, index, other_index, context))
      {
        // Found closing by the gap polynomial but not by the impact's own arithmetic: a closing
        // speed within rounding of zero. The model resolves it alone, or, if even it sees no
        // approach, the pair is parted by a few ulps of their speed.
        ball_ball_->resolve(ball, other, params_);
        if (ball.v == ball_before && other.v == other_before)
        {
          const Vec3<S> n = Vec3<S>(other.r.x() - ball.r.x(), other.r.y() - ball.r.y(), S(0)).normalized();
          const S part = roundingSpeed((ball.v - other.v).norm());
          ball.v -= S(0.5) * part * n;
          other.v += S(0.5) * part * n;
        }
      }
      settleMotion(ball, R);
      settleMotion(other, R);
      break;
    }
    case EventKind::BallCushion:
    case EventKind::BallCircle: {
      const Vec2<S> n = event.kind == EventKind::BallCushion
                            ? obstacles_->segments[event.obstacle].normal
                            : (ball.r.template head<2>() - obstacles_->circles[event.obstacle].centre).normalized();
      const Vec3<S> normal(n.x(), n.y(), S(0));
      const Vec3<S> v_before = ball.v, w_before = ball.w;
      cushion_->resolve(ball, normal, params_);
      settleMotion(ball, R);
      holdAgainstWall(ball, normal);
      if (ball.v == v_before && ball.w == w_before)
      {
        // Found approaching or pressing by the gap polynomial but by neither the model nor the
        // hold: within rounding of zero. Moved off by a few ulps of its speed, the ball is not
        // found at this wall again at this instant.
        ball.v += roundingSpeed(ball.v.norm()) * normal;
        settleMotion(ball, R);
      }
      break;
    }
    case EventKind::Pocketed:
      pocketBall(state, ball, event.obstacle);
      break;
    default:
      applyTransition(ball, params_);
      break;
  }
}

template void Engine<double>::processEvent(TableState<double>&, const Event<double>&, const EventContext&) const;
template void Engine<long double>::processEvent(TableState<long double>&, const Event<long double>&,
                                                const EventContext&) const;

}  // namespace physics
}  // namespace cue_sim
