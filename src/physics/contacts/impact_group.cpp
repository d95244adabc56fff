// A ball-ball impact resolved with every ball touching the pair and the walls those balls touch,
// as one impact (doc/physics.md, "Simultaneous impacts").
#include <algorithm>
#include <cmath>

#include "cue_sim/physics/motion.hpp"
#include "physics/contacts/event_resolver.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A cushion or jaw that a member of an impact group touches.
template <typename S>
struct GroupWall
{
  int member;
  Vec3<S> normal;  // into play
};

/// What the models' sweeps leave closing in a group, taken out by perfectly inelastic,
/// frictionless impulses swept until nothing closes (or kInelasticSweeps). Each is the
/// projection of the velocities, in the kinetic-energy metric, onto those that do not close
/// that contact, a half-space holding rest: it cannot add energy, and the sweeps converge
/// (alternating projections onto convex sets that meet). A ball-ball step keeps momentum.
template <typename S>
void stopGroupClosing(std::vector<Ball<S>>& balls, const std::vector<std::pair<int, int>>& contacts,
                      const std::vector<GroupWall<S>>& walls)
{
  for (int sweep = 0; sweep < kInelasticSweeps; ++sweep)
  {
    bool any = false;
    for (const std::pair<int, int>& c : contacts)
      any = stopClosing(balls[c.first], balls[c.second]) || any;
    for (const GroupWall<S>& wall : walls)
      any = stopClosing(balls[wall.member], wall.normal) || any;
    if (!any)
      return;
  }
}
}  // namespace

template <typename S>
std::vector<int> EventResolver<S>::touchingGroup(S time, int first, int second)
{
  const S touching = S(2) * params_.ball_radius + S(kTouchingSlack);
  std::vector<int> group;
  group.reserve(8);
  group.push_back(first);
  if (second >= 0)
    group.push_back(second);
  std::vector<int> own_nearby;
  std::vector<int>& nearby = context_.scratch ? *context_.scratch : own_nearby;
  for (std::size_t k = 0; k < group.size(); ++k)
  {
    nearBalls(state_.balls[group[k]].r.template head<2>(), touching, nearby);
    for (int j : nearby)
    {
      if (std::find(group.begin(), group.end(), j) != group.end() ||
          cannotReach(state_.balls[j], state_.balls[group[k]].r, touching, time))
        continue;
      const Ball<S> at_time = evolve(state_.balls[j], time, params_);
      // A ball in the air is no part of a group on the cloth (it meets balls pair by pair).
      if (!at_time.airborne() && (at_time.r - state_.balls[group[k]].r).template head<2>().norm() <= touching)
      {
        state_.balls[j] = at_time;
        group.push_back(j);
      }
    }
  }
  return group;
}

template <typename S>
bool EventResolver<S>::resolveLonePair(int first, int second)
{
  // What the sweep of resolveImpactGroup does for a lone pair, without its machinery.
  Ball<S>& a = state_.balls[first];
  Ball<S>& b = state_.balls[second];
  const Vec3<S> a_before = a.v, b_before = b.v;
  for (int sweep = 0; sweep < kImpactSweeps && closingSpeed(a, b) > zeroSpeed<S>(); ++sweep)
    engine_.ballBallModel().resolve(a, b, params_);
  stopClosing(a, b);
  settleMotion(a, params_.ball_radius);
  settleMotion(b, params_.ball_radius);
  changed(first);
  changed(second);
  return a.v != a_before || b.v != b_before;
}

template <typename S>
bool EventResolver<S>::resolveImpactGroup(S time, int first, int second)
{
  const Vec3<S> first_before = state_.balls[first].v, second_before = state_.balls[second].v;
  const S touching = S(2) * params_.ball_radius + S(kTouchingSlack);
  const std::vector<int> group = touchingGroup(time, first, second);
  if (group.size() == 2 && (state_.balls[first].r - state_.balls[second].r).template head<2>().norm() <= touching &&
      touchingWalls(state_.balls[first]).empty() && touchingWalls(state_.balls[second]).empty())
    return resolveLonePair(first, second);
  // The impact works on copies of the group's balls alone; contacts and walls name balls by
  // their place in the group.
  std::vector<Ball<S>> members;
  members.reserve(group.size());
  for (int g : group)
    members.push_back(state_.balls[g]);
  std::vector<std::pair<int, int>> contacts;
  for (std::size_t a = 0; a < group.size(); ++a)
    for (std::size_t b = a + 1; b < group.size(); ++b)
      if ((members[a].r - members[b].r).template head<2>().norm() <= touching)
        contacts.emplace_back(static_cast<int>(a), static_cast<int>(b));
  // Cushions and jaws a group ball touches take part too: a ball pinned against a cushion.
  std::vector<GroupWall<S>> walls;
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
    for (int sweep = 0; sweep < kImpactSweeps; ++sweep)
    {
      bool any = false;
      for (std::size_t c : order)
        if (closing(balls, contacts[c]) > zeroSpeed<S>())
        {
          engine_.ballBallModel().resolve(balls[contacts[c].first], balls[contacts[c].second], params_);
          any = true;
        }
      for (const GroupWall<S>& wall : walls)
        if (balls[wall.member].v.dot(wall.normal) < -zeroSpeed<S>())
        {
          wallImpact(balls[wall.member], wall.normal);
          any = true;
        }
      if (!any)
        return balls;
    }
    stopGroupClosing(balls, contacts, walls);
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
    Ball<S>& b = state_.balls[group[g]];
    b.v = v[g] / S(orders.size());
    b.w = w[g] / S(orders.size());
    settleMotion(b, params_.ball_radius);
    changed(group[g]);
  }
  return state_.balls[first].v != first_before || state_.balls[second].v != second_before;
}

template <typename S>
void EventResolver<S>::passImpactOnThroughCloth(S time, int flying, int support)
{
  // A ball dropped onto a ball pinned against a cushion would otherwise push it on in events at
  // one instant, each passing a share of the push down the pinned row and back (soak seed 8,
  // shot 1794: hundreds of thousands of events). As in an impact group, the push goes on at
  // once; the flying ball is no part of the group, so the two impacts take turns.
  const S touching = S(2) * params_.ball_radius + S(kTouchingSlack);
  // The balls on the cloth touching the support: the impulses move none of them, nor lift any.
  const std::vector<int> group = touchingGroup(time, support, -1);
  for (int j : group)
    changed(j);  // brought to `time`: its record is renewed, as a full scan sees it
  for (int sweep = 0; sweep < kImpactSweeps; ++sweep)
  {
    bool pushed_on = false;
    for (int j : group)
    {
      const Ball<S>& on = state_.balls[support];
      if (j != support && (state_.balls[j].r - on.r).template head<2>().norm() <= touching &&
          closingSpeed(on, state_.balls[j]) > zeroSpeed<S>())
      {
        pushed_on = resolveImpactGroup(time, support, j) || pushed_on;
        break;
      }
    }
    // A ball driven only into walls is left to the wall's own events, as before: held there, a
    // ball in the air on it and a nose comes to rest (soak seed 7, shot 2510: 29 387 events
    // that way, 978 153 without an end when the walls took part here).
    for (const Vec3<S>& normal : touchingWalls(state_.balls[support]))
      if (pushed_on && state_.balls[support].v.dot(normal) < -zeroSpeed<S>())
      {
        wallImpact(state_.balls[support], normal);
        settleMotion(state_.balls[support], params_.ball_radius);
        pushed_on = true;
      }
    Ball<S>& a = state_.balls[flying];
    Ball<S>& b = state_.balls[support];
    const Vec3<S> n = (b.r - a.r).normalized();
    if (!pushed_on || !((a.v - b.v).dot(n) > zeroSpeed<S>()))
      return;
    impactInAir(a, b, n);
  }
  Ball<S>& a = state_.balls[flying];
  const Vec3<S> n = (state_.balls[support].r - a.r).normalized();
  const S closing = (a.v - state_.balls[support].v).dot(n);
  if (closing > zeroSpeed<S>())
    a.v -= closing * n;
}

#define CUE_SIM_INSTANTIATE_IMPACT_GROUP(S)                                                                            \
  template std::vector<int> EventResolver<S>::touchingGroup(S, int, int);                                              \
  template bool EventResolver<S>::resolveLonePair(int, int);                                                           \
  template bool EventResolver<S>::resolveImpactGroup(S, int, int);                                                     \
  template void EventResolver<S>::passImpactOnThroughCloth(S, int, int);
CUE_SIM_INSTANTIATE_IMPACT_GROUP(double)
CUE_SIM_INSTANTIATE_IMPACT_GROUP(long double)

}  // namespace physics
}  // namespace cue_sim
