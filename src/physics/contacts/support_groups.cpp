// Balls in sustained contact in the air (doc/physics.md, "Resting contact"). A ball that comes to a
// support (another ball, a cushion's nose, a post's rim) slower than kSettleSpeed stays on it: the
// contact lasts longer than a bounce would (Luding and McNamara's TC model). From then on it, and the
// balls it presses on, move by the contact equations (src/physics/supports/), a step at a time: each
// step gathers the balls touching the group, stops what still closes, chooses every contact's modes
// (pressed or free, sticking or sliding, rolling or stuck), and either freezes the group (at rest
// and held there: Held in the air, Stationary on the cloth), lets its balls go back to their own
// closed-form motion (nothing presses a ball in the air any more), or integrates the next step and
// gives each ball the quadratic piece it follows until then.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "cue_sim/physics/motion.hpp"
#include "physics/contacts/event_resolver.hpp"
#include "physics/supports/contact_system.hpp"
#include "physics/supports/support_step.hpp"

namespace cue_sim
{
namespace physics
{
namespace
{
/// A group is at rest when none of its balls moves or turns (at its surface) faster than a sustained
/// contact begins (kSettleSpeed) and none accelerates by more than this share of g. A pile that can
/// stand finds its forces by creeping in the band where friction is regularized (a statically
/// indeterminate pile: its stuck forces of least norm, what the complementarity problem gives, may
/// exceed their bounds where another share of its weight does not), and a marginal one creeps slower
/// still: static friction, above the sliding friction on a real table, holds both. A ball this far
/// from a balance (1e-4 rad off a frictionless support's top) is held there.
constexpr double kRestShare = 1e-4;
/// The first step of a group, as a share of its natural time sqrt(R / g) (54 us for a pool ball); the
/// next is tried at twice the last.
constexpr double kFirstStep = 1e-3;
/// The longest step, in natural times: a ball creeping on its supports, whose piece is exact for long.
constexpr double kLongestStep = 10;
/// A step that ends on a mode change within this share of the natural time sqrt(R / g) (54 ns for a
/// pool ball) ends at once: that mode is turned before the step is taken again ...
constexpr double kAtOnce = 1e-6;
/// ... up to this many modes a step.
constexpr int kFlips = 8;
/// Sweeps of the impulses that stop what closes in a group before its step: frictionless and
/// perfectly inelastic, each an orthogonal projection, so they converge and cannot add energy.
constexpr int kStopSweeps = 1000;

/// Union-find over a group's bodies.
int rootOf(std::vector<int>& parent, int k)
{
  while (parent[static_cast<std::size_t>(k)] != k)
    k = parent[static_cast<std::size_t>(k)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(k)])];
  return k;
}
}  // namespace

namespace
{
/// The factor on the bodies' velocities and spins that leaves them no more energy than `allowed`
/// (1 if they have no more; 0 if their height alone has more).
template <typename S>
S energyScaleFor(S allowed, const std::vector<ContactBody<S>>& bodies, const PhysicsParams<S>& p)
{
  const S energy = groupEnergy(bodies, p);
  if (!(energy > allowed))
    return S(1);
  S kinetic = S(0);
  for (const ContactBody<S>& b : bodies)
    kinetic += S(0.5) * p.ball_mass * (b.v.squaredNorm() + S(0.4) * p.ball_radius * p.ball_radius * b.w.squaredNorm());
  return kinetic > S(0) ? std::sqrt(std::max(kinetic - (energy - allowed), S(0)) / kinetic) : S(0);
}

/// Off the cloth, or leaving it (the slate throwing it up).
template <typename S>
bool inTheAir(const ContactBody<S>& body, S radius)
{
  return body.r.z() - radius > onClothHeight(radius) || body.v.z() > S(0);
}

// The cloth's resistances as couples at a contact: rolling, 7/5 mu_roll R lambda, which slows a ball
// rolling on the slate under its weight at mu_roll g as the closed form does; drilling, the slate's spin
// decay turned into a couple likewise. Rolling against the couple takes a friction of mu_roll lambda at
// the contact.

/// The slate's contact. Its stuck slip holds twice the rolling's friction whatever mu_slide is, so that
/// a ball on the cloth that the group lets go of rolls on as its closed form does (the registry allows
/// mu_roll above mu_slide, which the closed form follows though a cloth could not bear it); a sliding
/// slip takes mu_slide, as the closed form's slide does.
template <typename S>
ContactLink<S> slateLink(int body, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  return {body,
          -1,
          -1,
          Surface::Slate,
          p.mu_slide,
          S(1.4) * p.mu_roll * R,
          S(0.4) * R * R * p.spinDecel() / p.gravity,
          std::max(p.mu_slide, S(2) * p.mu_roll)};
}

/// A contact with a ball or a wall: friction mu, and the cloth's couples, the rolling one at most what
/// half that friction bears (as it always is for a real table's coefficients, mu_roll 0.005-0.015 against
/// 0.1-0.4), leaving room for the other loads on the ball.
template <typename S>
ContactLink<S> surfaceLink(int body, int other, int obstacle, Surface surface, S mu, const PhysicsParams<S>& p)
{
  const S R = p.ball_radius;
  return {body,
          other,
          obstacle,
          surface,
          mu,
          S(1.4) * std::min(p.mu_roll, S(0.5) * mu) * R,
          S(0.4) * R * R * p.spinDecel() / p.gravity,
          mu};
}

/// A ball on the cloth slower than the slide speed is stopped: below it the contact equations'
/// friction is regularized and its closed form's is not, so the two would disagree on where it goes,
/// and it stops within v / (mu_roll g) < 6 ms anyway (less than 2e-7 m further on).
template <typename S>
void stopIfCreeping(Ball<S>& b, S radius, S slide_speed)
{
  if (!b.airborne() && !b.supported() && b.v.norm() < slide_speed && radius * b.w.norm() < slide_speed &&
      (b.v != Vec3<S>::Zero() || b.w != Vec3<S>::Zero()))
  {
    b.v.setZero();
    b.w.setZero();
    b.motion = Motion::Stationary;
  }
}

/// The closed-form motion a ball of a group goes on with when nothing presses it: in the air, or on
/// the cloth, where a slip inside the band where the group's friction is regularized was stuck: it
/// leaves rolling, that slip taken out as the cloth takes it at the end of a slide (applyTransition),
/// or its closed form would slide on for a few microseconds the group did not. The mode decision
/// judges a free ball on the cloth by this same motion, so that the event search, which follows it,
/// finds no contact the group let go of.
template <typename S>
void goFree(Ball<S>& b, const PhysicsParams<S>& p, S slide_speed)
{
  b.motion = Motion::Airborne;
  b.piece = SupportPiece<S>();
  settleMotion(b, p.ball_radius);
  if (b.motion == Motion::Sliding && slipVelocity(b.v, b.w, p.ball_radius).norm() < slide_speed)
    applyTransition(b, p);
  stopIfCreeping(b, p.ball_radius, slide_speed);
}

/// A group left with nothing pressed may hold contacts that the event search finds pressing (grazes:
/// a gap whose acceleration is within rounding of zero, where the contact equations, by their
/// tolerance, leave it free). Each ball in the air is sent off them all together by a few ulps of its
/// speed, so that none is found again at this instant (parting one pair at a time closed another).
template <typename S>
void partGrazes(const ContactSystem<S>& system, std::vector<ContactBody<S>>& bodies,
                const std::vector<ContactLink<S>>& links, S radius)
{
  for (int sweep = 0; sweep < 8; ++sweep)
  {
    bool any = false;
    for (std::size_t l = 0; l < links.size(); ++l)
    {
      const ContactLink<S>& link = links[l];
      ContactBody<S>& b = bodies[static_cast<std::size_t>(link.body)];
      ContactBody<S>* o = link.other >= 0 ? &bodies[static_cast<std::size_t>(link.other)] : nullptr;
      const bool b_air = inTheAir(b, radius), o_air = o && inTheAir(*o, radius);
      if (!b_air && !o_air)
        continue;  // on the cloth both: the planar search's own rules part them
      const ContactGeometry<S> c = system.geometryOf(link, bodies);
      const S parting = system.relativeVelocity(link, bodies).dot(c.n);
      const S wanted = roundingSpeed(b.v.norm() + (o ? o->v.norm() : S(0)));
      if (!(parting < wanted))
        continue;
      any = true;
      const S push = wanted - parting;
      if (b_air && o_air)
      {
        b.v += S(0.5) * push * c.n;
        o->v -= S(0.5) * push * c.n;
      }
      else if (b_air)
        b.v += push * c.n;
      else
        o->v -= push * c.n;
    }
    if (!any)
      return;
  }
}
}  // namespace

template <typename S>
Ball<S> EventResolver<S>::stateAt(int index, S time) const
{
  const Ball<S>& ball = state_.balls[static_cast<std::size_t>(index)];
  Ball<S> out = evolve(ball, time, params_);
  if (ball.supported() && !(time < ball.piece.until))
    out.v = ball.piece.v_end;  // the contact equations' velocity at the piece's end
  return out;
}

template <typename S>
std::vector<int> EventResolver<S>::supportedGroupOf(int index, S time)
{
  std::vector<int> group;
  if (index < 0 || !state_.balls[static_cast<std::size_t>(index)].supported())
    return group;
  const S reach = S(2) * params_.ball_radius + supportTouch(params_);
  group.push_back(index);
  std::vector<int> near;
  for (std::size_t k = 0; k < group.size(); ++k)
  {
    const Vec3<S> r = stateAt(group[k], time).r;
    nearBalls(r.template head<2>(), reach, near);
    for (int j : near)
    {
      if (!state_.balls[static_cast<std::size_t>(j)].supported() ||
          std::find(group.begin(), group.end(), j) != group.end())
        continue;
      if ((stateAt(j, time).r - r).norm() <= reach)
        group.push_back(j);
    }
  }
  return group;
}

template <typename S>
void EventResolver<S>::cutGroup(int index, S time)
{
  // Between its steps a group follows its pieces, whose energy is the integrated one only to the
  // contact tolerance: brought to an instant within them, it is given no more than it had at their
  // start (what it would gain, its speed pays).
  const std::vector<int> group = supportedGroupOf(index, time);
  std::vector<ContactBody<S>> start, cut;
  for (int j : group)
  {
    const Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    if (!(time < ball.piece.until))
      continue;
    start.push_back({ball.r, ball.v, ball.w, true});
    const Ball<S> then = evolve(ball, time, params_);
    cut.push_back({then.r, then.v, then.w, true});
  }
  const S scale = energyScaleFor(groupEnergy(start, params_), cut, params_);
  for (int j : group)
  {
    Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    if (!(time < ball.piece.until))
      continue;
    ball = evolve(ball, time, params_);
    ball.v *= scale;
    ball.w *= scale;
    ball.piece.v_end = ball.v;
    ball.piece.until = time;
    changed(j);
  }
}

template <typename S>
void EventResolver<S>::dissolveGroup(int index, S time)
{
  for (int j : supportedGroupOf(index, time))
  {
    Ball<S>& ball = state_.balls[static_cast<std::size_t>(j)];
    ball = stateAt(j, time);
    ball.motion = Motion::Airborne;  // settled below: in the air, or on the cloth
    settleMotion(ball, params_.ball_radius);
    changed(j);
  }
}

/// A group as one step sees it: its balls (indices into the table's state), their states at the step's
/// start, the bodies the contact equations move, and the contacts among them and with the table.
template <typename S>
struct SupportGroup
{
  std::vector<int> balls;
  std::vector<Ball<S>> now;       ///< each ball at the step's start, along its path
  std::vector<Ball<S>> original;  ///< as gathered, before this step changed anything
  std::vector<char> gone;         ///< left the table over a wall's top
  std::vector<ContactLink<S>> links;
  std::vector<ContactBody<S>> bodies;
  std::vector<LinkMode<S>> modes;
  std::vector<BodyRates<S>> rates;
};

/// Who the step moves by the contact equations: a ball with a pressed contact whose balls, linked by
/// pressed contacts, include one held up off the slate; and whether all of them are at rest.
struct Membership
{
  std::vector<char> member, on_slate;
  bool any = false, at_rest = true;
};

template <typename S>
Membership membershipOf(const SupportGroup<S>& g, const PhysicsParams<S>& p)
{
  const std::size_t n = g.balls.size();
  Membership out;
  out.member.assign(n, 0);
  out.on_slate.assign(n, 0);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> pressed(n, 0);
  for (std::size_t l = 0; l < g.links.size(); ++l)
  {
    const ContactLink<S>& link = g.links[l];
    if (!g.modes[l].pressed)
      continue;
    pressed[static_cast<std::size_t>(link.body)] = 1;
    if (link.surface == Surface::Slate)
      out.on_slate[static_cast<std::size_t>(link.body)] = 1;
    if (link.other >= 0)
    {
      pressed[static_cast<std::size_t>(link.other)] = 1;
      parent[static_cast<std::size_t>(rootOf(parent, link.body))] = rootOf(parent, link.other);
    }
  }
  std::vector<char> held_up(n, 0);  // by root
  for (std::size_t k = 0; k < n; ++k)
    if (pressed[k] && !out.on_slate[k])  // (one just leaving the slate, at its height, counts)
      held_up[static_cast<std::size_t>(rootOf(parent, static_cast<int>(k)))] = 1;
  const S R = p.ball_radius, rest_speed = S(kSettleSpeed), rest_acceleration = S(kRestShare) * p.gravity;
  for (std::size_t k = 0; k < n; ++k)
  {
    out.member[k] = pressed[k] && held_up[static_cast<std::size_t>(rootOf(parent, static_cast<int>(k)))];
    if (!out.member[k])
      continue;
    out.any = true;
    const ContactBody<S>& b = g.bodies[k];
    out.at_rest = out.at_rest && b.v.norm() <= rest_speed && R * b.w.norm() <= rest_speed &&
                  g.rates[k].a.norm() <= rest_acceleration && R * g.rates[k].alpha.norm() <= rest_acceleration;
  }
  return out;
}

template <typename S>
SupportGroup<S> EventResolver<S>::gatherGroup(S time, int seed)
{
  // The balls touching the seed, and what touches them in turn through balls in the air or in a group
  // (a ball on the cloth touching them is taken, but not looked around: a rack beside a ball that bears
  // one stays out until it is pushed). A group taken within its pieces (by an event of a ball it
  // touches) is brought to `time` first, with no more energy than its pieces started with.
  const S R = params_.ball_radius, touch = supportTouch(params_), reach = S(2) * R + touch;
  cutGroup(seed, time);
  SupportGroup<S> g;
  g.balls.push_back(seed);
  g.now.push_back(stateAt(seed, time));
  std::vector<int> near;
  for (std::size_t k = 0; k < g.balls.size(); ++k)
  {
    const Ball<S> b = g.now[k];
    if (k > 0 && !b.airborne() && !b.supported())
      continue;
    nearBalls(b.r.template head<2>(), reach, near);
    for (int j : near)
    {
      const Ball<S>& other = state_.balls[static_cast<std::size_t>(j)];
      if (j == g.balls[k] || !other.inPlay() || std::find(g.balls.begin(), g.balls.end(), j) != g.balls.end() ||
          cannotReach(other, b.r, reach, time))
        continue;
      Ball<S> o = stateAt(j, time);
      if (ballContact(b.r, o.r, R).gap > touch)
        continue;
      if (o.supported() && time < other.piece.until)
      {
        cutGroup(j, time);  // another group's ball, within its pieces
        o = stateAt(j, time);
      }
      g.balls.push_back(j);
      g.now.push_back(o);
    }
  }
  g.original = g.now;
  const S slide_speed = ContactSystem<S>(geometry_, params_).slideSpeed();
  for (Ball<S>& b : g.now)
    stopIfCreeping(b, R, slide_speed);
  // A ball in the air that has passed over a wall's top has left the playing surface: it leaves the
  // table, as a flight over the cushions does, and the group goes on without it.
  g.gone.assign(g.balls.size(), 0);
  for (std::size_t k = 0; k < g.balls.size(); ++k)
    if (g.now[k].airborne() && overTheTop(geometry_, g.now[k].r))
    {
      g.gone[k] = 1;
      Ball<S>& ball = state_.balls[static_cast<std::size_t>(g.balls[k])];
      ball = g.now[k];
      ball.motion = Motion::Airborne;
      ball.piece = SupportPiece<S>();
      leaveTable(ball);
      changed(g.balls[k]);
    }
  // Every contact among them, and with the slate and the walls they touch.
  const S mu_ball = engine_.ballBallModel().sustainedFriction(params_);
  const S mu_wall = engine_.cushionModel().sustainedFriction(params_);
  for (std::size_t k = 0; k < g.balls.size(); ++k)
    for (std::size_t j = k + 1; j < g.balls.size(); ++j)
      if (!g.gone[k] && !g.gone[j] && ballContact(g.now[k].r, g.now[j].r, R).gap <= touch)
        g.links.push_back(surfaceLink(static_cast<int>(k), static_cast<int>(j), -1, Surface::Ball, mu_ball, params_));
  std::vector<WallTouch> walls;
  for (std::size_t k = 0; k < g.balls.size(); ++k)
  {
    if (g.gone[k])
      continue;
    const Vec3<S>& r = g.now[k].r;
    const int body = static_cast<int>(k);
    if (r.z() - R <= touch)
      g.links.push_back(slateLink(body, params_));
    wallsTouching(geometry_, r, R, touch, walls);
    for (const WallTouch& wall : walls)
      g.links.push_back(surfaceLink(body, -1, wall.index, wall.surface, mu_wall, params_));
  }
  g.bodies.resize(g.balls.size());
  for (std::size_t k = 0; k < g.balls.size(); ++k)
    g.bodies[k] = {g.now[k].r, g.now[k].v, g.now[k].w, true, Vec3<S>::Zero(), false};
  return g;
}

template <typename S>
void EventResolver<S>::meetWithinGroup(const ContactSystem<S>& system, SupportGroup<S>& g)
{
  // What meets faster than a sustained contact is an impact (the models' impulses, swept over the
  // group until nothing closes that fast: an arrival at the very end of a step); what closes slower is
  // stopped, frictionless and perfectly inelastic.
  const auto closingOf = [&](const ContactLink<S>& l) {
    return -system.relativeVelocity(l, g.bodies).dot(system.geometryOf(l, g.bodies).n);
  };
  for (int sweep = 0; sweep < kImpactSweeps; ++sweep)
  {
    bool any = false;
    for (const ContactLink<S>& l : g.links)
    {
      if (meetSlowly(closingOf(l)))
        continue;
      any = true;
      Ball<S>& b = g.now[static_cast<std::size_t>(l.body)];
      const Vec3<S> n = system.geometryOf(l, g.bodies).n;
      if (l.surface == Surface::Ball)
        impactInAir(g.now[static_cast<std::size_t>(l.other)], b, n);
      else if (l.surface == Surface::Slate)
        landOnSlate(b, engine_.ballTableModel(), params_);
      else if (l.surface == Surface::Face || l.surface == Surface::PostSide)
      {
        const S vz = b.v.z();
        b.v.z() = S(0);
        wallImpact(b, n);
        b.v.z() = vz;
      }
      else
        b.v -= (S(1) + params_.e_cushion) * b.v.dot(n) * n;  // a nose's edge or a rim, frictionless
      for (std::size_t k = 0; k < g.balls.size(); ++k)
      {
        g.bodies[k].v = g.now[k].v;
        g.bodies[k].w = g.now[k].w;
      }
    }
    if (!any)
      break;
  }
  for (int sweep = 0; sweep < kStopSweeps; ++sweep)
  {
    bool any = false;
    for (const ContactLink<S>& l : g.links)
    {
      // (What closes slower than zeroSpeed is no closing, for the event search too: stopped, it would
      // only stir the balls' rounding. What closes faster the search finds again at once, so it is
      // stopped however slow.)
      const S closing = closingOf(l);
      if (!(closing > zeroSpeed<S>()))
        continue;
      const Vec3<S> n = system.geometryOf(l, g.bodies).n;
      ContactBody<S>& b = g.bodies[static_cast<std::size_t>(l.body)];
      if (l.other >= 0)
      {
        b.v += S(0.5) * closing * n;
        g.bodies[static_cast<std::size_t>(l.other)].v -= S(0.5) * closing * n;
      }
      else
        b.v += closing * n;
      any = true;
    }
    if (!any)
      break;
  }
}

template <typename S>
void EventResolver<S>::decideGroupModes(const ContactSystem<S>& system, SupportGroup<S>& g)
{
  // A ball on the cloth that nothing but the slate will press follows its own closed-form path: the
  // mode decision judges its contacts against that path. (One that follows it already is put in that
  // motion now: a slip or a creep the motion takes out is taken out before the contacts are judged,
  // not after. One the equations moved goes on as they say if they still press it.)
  const S R = params_.ball_radius;
  for (std::size_t k = 0; k < g.balls.size(); ++k)
    if (!inTheAir(g.bodies[k], R))
    {
      Ball<S> free = g.now[k];
      free.r = g.bodies[k].r;
      free.v = g.bodies[k].v;
      free.w = g.bodies[k].w;
      goFree(free, params_, system.slideSpeed());
      if (!g.now[k].supported())
      {
        g.bodies[k].v = free.v;
        g.bodies[k].w = free.w;
      }
      const Trajectory<S> path = trajectoryFrom(free, free.time, params_);
      g.bodies[k].free_on_cloth = true;
      g.bodies[k].a_free = Vec3<S>(S(2) * path.c2.x(), S(2) * path.c2.y(), S(0));
    }
  if (!system.decideModes(g.bodies, g.links, g.modes, g.rates))
  {
    system.jam(g.bodies, g.links);
    if (!system.decideModes(g.bodies, g.links, g.modes, g.rates))
      system.holdTogether(g.bodies, g.links, g.modes, g.rates);
  }
  // Drift off the pressed contacts taken out, positions and normal velocities. (A stuck slip or turning
  // keeps what is left of it, below the slide speed: taking that out too would take out the friction
  // of the regularized band that let it stick, and stall a pile that is moving.)
  const S energy_before = groupEnergy(g.bodies, params_);
  system.projectPositions(g.bodies, g.links, g.modes);
  system.projectVelocities(g.bodies, g.links, g.modes, true);
  const S scale = energyScaleFor(energy_before, g.bodies, params_);
  for (ContactBody<S>& b : g.bodies)
  {
    b.v *= scale;
    b.w *= scale;
  }
  system.accelerations(g.bodies, g.links, g.modes, g.rates);
}

template <typename S>
void EventResolver<S>::writeFree(const SupportGroup<S>& g, std::size_t k, S time)
{
  if (g.gone[k])
    return;
  Ball<S> b = g.now[k];
  b.r = g.bodies[k].r;
  b.v = g.bodies[k].v;
  b.w = g.bodies[k].w;
  b.time = time;
  if (b.held() && (b.v != Vec3<S>::Zero() || b.w != Vec3<S>::Zero()))
    b.motion = Motion::Airborne;
  if (!b.held())
    goFree(b, params_, ContactSystem<S>(geometry_, params_).slideSpeed());
  const Ball<S>& before = g.original[k];
  Ball<S>& ball = state_.balls[static_cast<std::size_t>(g.balls[k])];
  if (b.motion != before.motion || b.v != before.v || b.w != before.w || b.r != before.r || ball.supported())
  {
    ball = b;
    changed(g.balls[k]);
  }
}

template <typename S>
void EventResolver<S>::holdAtRest(const SupportGroup<S>& g, std::size_t k, bool on_slate, S time)
{
  Ball<S>& b = state_.balls[static_cast<std::size_t>(g.balls[k])];
  b = g.now[k];
  b.time = time;
  b.r = g.bodies[k].r;
  b.v.setZero();
  b.w.setZero();
  b.piece = SupportPiece<S>();
  b.motion = on_slate ? Motion::Stationary : Motion::Held;
  if (on_slate)
    b.r.z() = params_.ball_radius;
  else
    held_here_.push_back(g.balls[k]);
  changed(g.balls[k]);
}

template <typename S>
void EventResolver<S>::stepGroup(S time, int seed)
{
  SupportGroup<S> g = gatherGroup(time, seed);
  const ContactSystem<S> system(geometry_, params_);
  meetWithinGroup(system, g);
  decideGroupModes(system, g);
  const S T = supportTime(params_);
  const Ball<S>& first = state_.balls[static_cast<std::size_t>(seed)];
  const S last = first.supported() ? first.piece.until - first.time : S(0);
  const S trial = std::max(S(2) * last, S(kFirstStep) * T);
  for (int flip = 0;; ++flip)
  {
    const Membership who = membershipOf(g, params_);
    if (!who.any)
      partGrazes(system, g.bodies, g.links, params_.ball_radius);
    if (!who.any || who.at_rest)
    {
      for (std::size_t k = 0; k < g.balls.size(); ++k)
        if (who.member[k])
          holdAtRest(g, k, who.on_slate[k] != 0, time);
        else
          writeFree(g, k, time);
      return;
    }
    for (std::size_t k = 0; k < g.balls.size(); ++k)
      if (!who.member[k])
        writeFree(g, k, time);
    // The step: the group's balls move by the equations; the others touching them follow their own
    // paths, which hold until their next transition: the step ends there at the latest.
    std::vector<ContactLink<S>> step_links;
    std::vector<LinkMode<S>> step_modes;
    std::vector<std::size_t> link_of;  // each step link's index in g.links
    bool held_both_ways = false;
    for (std::size_t l = 0; l < g.links.size(); ++l)
      if (who.member[static_cast<std::size_t>(g.links[l].body)] ||
          (g.links[l].other >= 0 && who.member[static_cast<std::size_t>(g.links[l].other)]))
      {
        step_links.push_back(g.links[l]);
        step_modes.push_back(g.modes[l]);
        link_of.push_back(l);
        held_both_ways = held_both_ways || g.modes[l].bilateral;
      }
    // (A contact held both ways, where no modes are consistent, is held a first step's length only.)
    S longest = S(held_both_ways ? kFirstStep : kLongestStep) * T;
    std::vector<ContactBody<S>> bodies = g.bodies;
    for (std::size_t k = 0; k < g.balls.size(); ++k)
    {
      bodies[k].dynamic = who.member[k] != 0;
      const Ball<S>& own = state_.balls[static_cast<std::size_t>(g.balls[k])];
      if (!who.member[k] && own.moving())
        longest = std::min(longest, std::max(own.time + timeToTransition(own, params_) - time, S(0)));
    }
    if (!(longest > S(0)))
      longest = S(kFirstStep) * T;
    const KinematicPaths<S> paths = [&](S tau, std::vector<ContactBody<S>>& y) {
      for (std::size_t k = 0; k < g.balls.size(); ++k)
        if (!who.member[k])
        {
          const Ball<S> b = evolve(state_.balls[static_cast<std::size_t>(g.balls[k])], time + tau, params_);
          y[k].r = b.r;
          y[k].v = b.v;
          y[k].w = b.w;
        }
    };
    const SupportStep<S> step =
        stepSupported(system, bodies, step_links, step_modes, paths, trial, longest, params_.contact_tolerance);
    // A mode that stops holding at once (its margin at its bound and leaving it: a friction at its
    // limit whose load grows, a force falling through zero) is turned the way its margin says, and the
    // group judged again, or each step would end there and the decision start it the same way again.
    if (flip < kFlips && step.mode_changed && step.h < S(kAtOnce) * T && step.crossed.link >= 0)
    {
      const std::size_t l = link_of[static_cast<std::size_t>(step.crossed.link)];
      MarginTag tag = step.crossed;
      tag.link = static_cast<int>(l);
      if (flipMode(tag, g.modes, system.grazeForce()))
      {
        system.accelerations(g.bodies, g.links, g.modes, g.rates);
        continue;
      }
    }
    writePieces(g, who, step, time);
    return;
  }
}

template <typename S>
void EventResolver<S>::writePieces(const SupportGroup<S>& g, const Membership& who, const SupportStep<S>& step, S time)
{
  // Energy is never gained: what the integration's error would add, the group's speed pays.
  std::vector<ContactBody<S>> start_members, end_members;
  for (std::size_t k = 0; k < g.balls.size(); ++k)
    if (who.member[k])
    {
      start_members.push_back(g.bodies[k]);
      end_members.push_back(step.end[k]);
    }
  const S scale = energyScaleFor(groupEnergy(start_members, params_), end_members, params_);
  std::size_t d = 0;
  for (std::size_t k = 0; k < g.balls.size(); ++k)
  {
    if (!who.member[k])
      continue;
    Ball<S>& b = state_.balls[static_cast<std::size_t>(g.balls[k])];
    b = g.now[k];
    b.time = time;
    b.r = g.bodies[k].r;
    b.v = g.bodies[k].v;
    b.w = g.bodies[k].w;
    b.pocket = -1;
    b.motion = who.on_slate[k] ? Motion::Bearing : Motion::Supported;
    b.piece.a = step.a[d];
    b.piece.v_end = scale * step.end[k].v;
    b.piece.alpha = (scale * step.end[k].w - g.bodies[k].w) / step.h;
    b.piece.until = time + step.h;
    if (who.on_slate[k])
    {
      // On the cloth, exactly: the slate's contact keeps z = R and v_z = 0.
      b.r.z() = params_.ball_radius;
      b.v.z() = b.piece.a.z() = b.piece.v_end.z() = S(0);
    }
    ++d;
    changed(g.balls[k]);
  }
}

#define CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(S)                                                                          \
  template Ball<S> EventResolver<S>::stateAt(int, S) const;                                                            \
  template std::vector<int> EventResolver<S>::supportedGroupOf(int, S);                                                \
  template void EventResolver<S>::cutGroup(int, S);                                                                    \
  template void EventResolver<S>::dissolveGroup(int, S);                                                               \
  template void EventResolver<S>::stepGroup(S, int);                                                                   \
  template SupportGroup<S> EventResolver<S>::gatherGroup(S, int);                                                      \
  template void EventResolver<S>::meetWithinGroup(const ContactSystem<S>&, SupportGroup<S>&);                          \
  template void EventResolver<S>::decideGroupModes(const ContactSystem<S>&, SupportGroup<S>&);                         \
  template void EventResolver<S>::writeFree(const SupportGroup<S>&, std::size_t, S);                                   \
  template void EventResolver<S>::holdAtRest(const SupportGroup<S>&, std::size_t, bool, S);                            \
  template void EventResolver<S>::writePieces(const SupportGroup<S>&, const Membership&, const SupportStep<S>&, S);
CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(double)
CUE_SIM_INSTANTIATE_SUPPORT_GROUPS(long double)

}  // namespace physics
}  // namespace cue_sim
