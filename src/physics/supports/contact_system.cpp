#include "physics/supports/contact_system.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cue_sim
{
namespace physics
{
namespace
{
/// Slips below this share of sqrt(g R) [m/s] (5.3e-5 m/s for a pool ball) may stick, and a sliding
/// friction below it is scaled down in proportion: Coulomb's law regularized, which makes its force
/// smooth where the slip turns or stops. Its time constant, m v / (7/2 mu lambda), 1.3e-5 s for a pool
/// ball on another, is a few of the integrator's steps; what it leaves of a slip when the contact
/// sticks is taken out by an impulse of at most m (5.3e-5)^2 / 2 = 2.4e-10 J.
constexpr double kSlideShare = 1e-4;
/// A resistance of coefficient mu (a couple's over R) is regularized over at least this many times
/// mu sqrt(g R), so that its time constant, about the band over (7/2) mu g, is no shorter than
/// kBandPerMu / 3.5 of the natural time sqrt(R / g) (7.7 us for a pool ball): the registry allows a
/// ball-ball friction of 110 and a rolling resistance of 10, whose bands of kSlideShare alone would make
/// the equations as stiff as a microsecond a step. Up to mu = 0.2 the band is kSlideShare's.
constexpr double kBandPerMu = 5e-4;

/// Pivots of the complementarity problem before the last modes are taken: each contact changes its
/// normal mode and its three frictions at most a few times.
constexpr int kPivotsPerLink = 12;
/// Forces within this share of the weight of what they act on, and accelerations within this share
/// of g, are zero: the rounding of a solve of a few dozen terms of that size.
constexpr double kForceRounding = 1e-11;
/// A free contact may close by this share of the contact tolerance within a step before it is a new
/// event.
constexpr double kGrazeShare = 0.1;
/// A free contact is pressed only if the bodies would press into it by more than this share of their
/// weight: below it, the solve's rounding makes it press and let go in turn.
constexpr double kGrazeForce = 1e-8;
/// Normal forces beyond this many times the weight and the fastest ball's centripetal load m v^2 / R
/// are no sustained contact's: the modes found are next to Painleve's paradox, where a friction that
/// grows with the normal force drives the normal force on (a sliding ball on the cloth of mu_slide 45
/// pressed by a ball landing on it: forces of ten thousand weights, slips stopped in nanoseconds). The
/// contacts jam instead, as where no modes are consistent: the impulse the forces tend to.
constexpr double kJamLoad = 1e3;
/// A sliding resistance whose regularization settles faster than this share of the natural time
/// sqrt(R / g) is too stiff to integrate (on the slate, whose band is the closed forms' narrow one,
/// mu_slide above 2.9 or a rolling resistance above 2): where the modes would fall back on sliding,
/// the contacts jam instead.
constexpr double kStiffShare = 1e-5;

/// The link as its mode makes it act: a contact held both ways has no friction and no couples.
template <typename S>
ContactLink<S> asActing(const ContactLink<S>& link, const LinkMode<S>& mode)
{
  ContactLink<S> acting = link;
  if (mode.bilateral)
    acting.mu = acting.grip = acting.rolling = acting.drilling = S(0);
  return acting;
}

/// Two unit tangents at a contact, chosen the same way from the normal wherever it is.
template <typename S>
void tangents(const Vec3<S>& n, Vec3<S>& t1, Vec3<S>& t2)
{
  const Vec3<S> a = std::abs(n.x()) < S(0.6) ? Vec3<S>::UnitX() : Vec3<S>::UnitY();
  t1 = n.cross(a).normalized();
  t2 = n.cross(t1);
}

/// The unit vector of v, or `fallback` where v is shorter than `small`.
template <typename S>
Vec3<S> directionOr(const Vec3<S>& v, S small, const Vec3<S>& fallback)
{
  const S length = v.norm();
  return length > small ? Vec3<S>(v / length) : fallback;
}
}  // namespace

template <typename S>
ContactSystem<S>::ContactSystem(const TableGeometry<S>& geometry, const PhysicsParams<S>& params)
  : geometry_(geometry),
    params_(params),
    inertia_(S(0.4) * params.ball_mass * params.ball_radius * params.ball_radius),
    slide_speed_(S(kSlideShare) * std::sqrt(params.gravity * params.ball_radius))
{
}

template <typename S>
S ContactSystem<S>::bandFor(const ContactLink<S>& link, S mu) const
{
  // The slate's are the closed forms' own: a ball the slate alone presses is handed back to them,
  // which slide at full friction down to the slide speed.
  if (link.surface == Surface::Slate)
    return slide_speed_;
  return std::max(slide_speed_, S(kBandPerMu) * mu * std::sqrt(params_.gravity * params_.ball_radius));
}

template <typename S>
S ContactSystem<S>::grazeForce() const
{
  return S(kGrazeForce) * params_.ball_mass * params_.gravity;
}

template <typename S>
ContactGeometry<S> ContactSystem<S>::geometryOf(const ContactLink<S>& link,
                                                const std::vector<ContactBody<S>>& bodies) const
{
  const Vec3<S>& r = bodies[static_cast<std::size_t>(link.body)].r;
  const S R = params_.ball_radius;
  switch (link.surface)
  {
    case Surface::Ball:
      return ballContact(r, bodies[static_cast<std::size_t>(link.other)].r, R);
    case Surface::Slate:
      return slateContact(r, R);
    case Surface::Face:
    case Surface::Edge:
      return cushionContact(geometry_, link.obstacle, r, R);
    case Surface::PostSide:
    case Surface::Rim:
      return postContact(geometry_, link.obstacle, r, R);
  }
  return slateContact(r, R);
}

template <typename S>
Vec3<S> ContactSystem<S>::relativeVelocity(const ContactLink<S>& link, const std::vector<ContactBody<S>>& bodies) const
{
  const Vec3<S>& v = bodies[static_cast<std::size_t>(link.body)].v;
  return link.other >= 0 ? Vec3<S>(v - bodies[static_cast<std::size_t>(link.other)].v) : v;
}

template <typename S>
Vec3<S> ContactSystem<S>::slip(const ContactLink<S>& link, const ContactGeometry<S>& c,
                               const std::vector<ContactBody<S>>& bodies) const
{
  // The contact point moves with each surface: v + w x (point - centre), the point R from each
  // centre along -n (the body's side) and +n (the other ball's).
  const S R = params_.ball_radius;
  const ContactBody<S>& b = bodies[static_cast<std::size_t>(link.body)];
  Vec3<S> u = b.v + b.w.cross(Vec3<S>(-R * c.n));
  if (link.other >= 0)
  {
    const ContactBody<S>& o = bodies[static_cast<std::size_t>(link.other)];
    u -= o.v + o.w.cross(Vec3<S>(R * c.n));
  }
  return u - u.dot(c.n) * c.n;
}

template <typename S>
Vec3<S> ContactSystem<S>::turning(const ContactLink<S>& link, const std::vector<ContactBody<S>>& bodies) const
{
  const Vec3<S>& w = bodies[static_cast<std::size_t>(link.body)].w;
  return link.other >= 0 ? Vec3<S>(w - bodies[static_cast<std::size_t>(link.other)].w) : w;
}

/// The contact equations at one state, assembled: an unknown for each normal force (of the pressed
/// contacts, or of every contact) and each stuck resistance, each a generalized force on one or two
/// bodies per unit of it, with the relative acceleration it keeps at zero (a normal force: at zero
/// while it acts, non-negative while it does not). acc = A x + c.
template <typename S>
struct ContactSystem<S>::Assembly
{
  struct Unknown
  {
    int link;
    bool normal;                                       ///< the normal force (with the opposing resistances)
    Vec3<S> f, tau_body, tau_other;                    ///< force on the body (the other: -f), torques
    Vec3<S> friction, couple;                          ///< its tangential force and its couple on the body
    Vec3<S> a_body, alpha_body, a_other, alpha_other;  ///< its row's coefficients on the accelerations
  };
  std::vector<Unknown> unknowns;
  Matrix A;
  Vector c;
};

template <typename S>
void ContactSystem<S>::assemble(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                const std::vector<LinkMode<S>>& modes, bool every_normal, Assembly& out) const
{
  const S R = params_.ball_radius, m = params_.ball_mass, I = inertia_;
  const Vec3<S> gravity(S(0), S(0), -params_.gravity);
  out.unknowns.clear();
  std::vector<S> kappa;
  const auto dynamic = [&](int b) { return b >= 0 && bodies[static_cast<std::size_t>(b)].dynamic; };
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    const LinkMode<S>& mode = modes[l];
    const ContactLink<S> link = asActing(links[l], mode);
    if ((!every_normal && !mode.pressed) || (!dynamic(link.body) && !dynamic(link.other)))
      continue;
    const ContactGeometry<S> c = geometryOf(link, bodies);
    Vec3<S> t1, t2;
    tangents(c.n, t1, t2);
    const Vec3<S> v_rel = relativeVelocity(link, bodies), n_dot = c.H * v_rel;
    const Vec3<S> u = slip(link, c, bodies), turn = turning(link, bodies);
    const ContactBody<S>& b = bodies[static_cast<std::size_t>(link.body)];
    const Vec3<S> w_sum = link.other >= 0 ? Vec3<S>(b.w + bodies[static_cast<std::size_t>(link.other)].w) : b.w;
    const Vec3<S> lever = -R * c.n;  // from the body's centre to the contact point
    const S turn_n = turn.dot(c.n);
    const Vec3<S> turn_t = turn - turn_n * c.n;
    const bool slip_stuck = link.grip > S(0) && mode.slip == Resist::Stuck;
    const bool roll_stuck = slip_stuck && link.rolling > S(0) && mode.roll == Resist::Stuck;
    const bool drill_stuck = link.drilling > S(0) && mode.drill == Resist::Stuck;
    // The normal force, with the opposing resistances, which scale with it.
    typename Assembly::Unknown normal{static_cast<int>(l),
                                      true,
                                      c.n,
                                      Vec3<S>::Zero(),
                                      Vec3<S>::Zero(),
                                      Vec3<S>::Zero(),
                                      Vec3<S>::Zero(),
                                      c.n,
                                      Vec3<S>::Zero(),
                                      -c.n,
                                      Vec3<S>::Zero()};
    // Sliding: against the motion, in proportion below its band.
    if (link.mu > S(0) && mode.slip == Resist::Sliding)
    {
      normal.friction = -link.mu * u / std::max(u.norm(), bandFor(link, link.mu));
      normal.f += normal.friction;
      normal.tau_body = normal.tau_other = lever.cross(normal.friction);
    }
    if (slip_stuck && link.rolling > S(0) && mode.roll == Resist::Sliding)
      normal.couple -= link.rolling * turn_t / std::max(turn_t.norm(), bandFor(link, link.rolling / R) / R);
    if (link.drilling > S(0) && mode.drill == Resist::Sliding)
      normal.couple -= link.drilling * turn_n / std::max(std::abs(turn_n), bandFor(link, link.drilling / R) / R) * c.n;
    normal.tau_body += normal.couple;
    normal.tau_other -= normal.couple;
    out.unknowns.push_back(normal);
    kappa.push_back(v_rel.dot(n_dot));
    if (slip_stuck)
      for (const Vec3<S>& t : {t1, t2})
      {
        const Vec3<S> tau = lever.cross(t), arm = -R * c.n.cross(t);
        out.unknowns.push_back({static_cast<int>(l), false, t, tau, tau, t, Vec3<S>::Zero(), t, arm, -t, arm});
        kappa.push_back(-R * t.dot(w_sum.cross(n_dot)));
      }
    if (roll_stuck)
      for (const Vec3<S>& t : {t1, t2})
      {
        out.unknowns.push_back({static_cast<int>(l), false, Vec3<S>::Zero(), t, -t, Vec3<S>::Zero(), t, Vec3<S>::Zero(),
                                t, Vec3<S>::Zero(), -t});
        kappa.push_back(-turn_n * t.dot(n_dot));
      }
    if (drill_stuck)
    {
      out.unknowns.push_back({static_cast<int>(l), false, Vec3<S>::Zero(), c.n, -c.n, Vec3<S>::Zero(), c.n,
                              Vec3<S>::Zero(), c.n, Vec3<S>::Zero(), -c.n});
      kappa.push_back(turn.dot(n_dot));
    }
  }
  const int n = static_cast<int>(out.unknowns.size());
  out.A.resize(n, n);
  out.c.resize(n);
  for (int r = 0; r < n; ++r)
  {
    const typename Assembly::Unknown& row = out.unknowns[static_cast<std::size_t>(r)];
    const ContactLink<S>& lr = links[static_cast<std::size_t>(row.link)];
    const auto apply = [&](const Vec3<S>& a_b, const Vec3<S>& al_b, const Vec3<S>& a_o, const Vec3<S>& al_o) {
      return row.a_body.dot(a_b) + row.alpha_body.dot(al_b) + row.a_other.dot(a_o) + row.alpha_other.dot(al_o);
    };
    for (int k = 0; k < n; ++k)
    {
      const typename Assembly::Unknown& col = out.unknowns[static_cast<std::size_t>(k)];
      const ContactLink<S>& lc = links[static_cast<std::size_t>(col.link)];
      // The column's accelerations of the row's two bodies.
      Vec3<S> a_b = Vec3<S>::Zero(), al_b = Vec3<S>::Zero(), a_o = Vec3<S>::Zero(), al_o = Vec3<S>::Zero();
      const auto add = [&](int body, const Vec3<S>& force, const Vec3<S>& torque) {
        if (!dynamic(body))
          return;
        if (body == lr.body)
        {
          a_b += force / m;
          al_b += torque / I;
        }
        if (body == lr.other)
        {
          a_o += force / m;
          al_o += torque / I;
        }
      };
      add(lc.body, col.f, col.tau_body);
      add(lc.other, Vec3<S>(-col.f), col.tau_other);
      out.A(r, k) = apply(a_b, al_b, a_o, al_o);
    }
    const auto freeOf = [&](int b) {
      return b < 0 ? Vec3<S>(Vec3<S>::Zero()) : dynamic(b) ? gravity : bodies[static_cast<std::size_t>(b)].a_free;
    };
    out.c(r) =
        apply(freeOf(lr.body), Vec3<S>::Zero(), freeOf(lr.other), Vec3<S>::Zero()) + kappa[static_cast<std::size_t>(r)];
  }
}

template <typename S>
void ContactSystem<S>::applyForces(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                   const Assembly& assembly, const Vector& x, std::vector<LinkMode<S>>& modes,
                                   std::vector<BodyRates<S>>& rates) const
{
  const S m = params_.ball_mass, I = inertia_;
  rates.assign(bodies.size(), BodyRates<S>{Vec3<S>(S(0), S(0), -params_.gravity), Vec3<S>::Zero()});
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (!bodies[b].dynamic)
      rates[b].a = bodies[b].a_free;
  for (LinkMode<S>& mode : modes)
  {
    mode.lambda = S(0);
    mode.friction.setZero();
    mode.couple.setZero();
  }
  for (std::size_t k = 0; k < assembly.unknowns.size(); ++k)
  {
    const typename Assembly::Unknown& col = assembly.unknowns[k];
    const ContactLink<S>& link = links[static_cast<std::size_t>(col.link)];
    const S value = x(static_cast<int>(k));
    if (bodies[static_cast<std::size_t>(link.body)].dynamic)
    {
      rates[static_cast<std::size_t>(link.body)].a += value * col.f / m;
      rates[static_cast<std::size_t>(link.body)].alpha += value * col.tau_body / I;
    }
    if (link.other >= 0 && bodies[static_cast<std::size_t>(link.other)].dynamic)
    {
      rates[static_cast<std::size_t>(link.other)].a -= value * col.f / m;
      rates[static_cast<std::size_t>(link.other)].alpha += value * col.tau_other / I;
    }
    LinkMode<S>& mode = modes[static_cast<std::size_t>(col.link)];
    if (col.normal)
      mode.lambda = value;
    mode.friction += value * col.friction;
    mode.couple += value * col.couple;
  }
}

template <typename S>
void ContactSystem<S>::accelerations(const std::vector<ContactBody<S>>& bodies,
                                     const std::vector<ContactLink<S>>& links, std::vector<LinkMode<S>>& modes,
                                     std::vector<BodyRates<S>>& rates) const
{
  Assembly assembly;
  assemble(bodies, links, modes, false, assembly);
  Vector x = Vector::Zero(static_cast<int>(assembly.unknowns.size()));
  if (x.size() > 0)
  {
    // Minimum norm where the contacts are more than the bodies' freedoms (a ball on four supports
    // shares its weight in the least-squares way: statically indeterminate, any share would do).
    x = Eigen::CompleteOrthogonalDecomposition<Matrix>(assembly.A).solve(Vector(-assembly.c));
    if (!x.allFinite())
      x.setZero();
  }
  applyForces(bodies, links, assembly, x, modes, rates);
}

template <typename S>
bool ContactSystem<S>::pressNormals(const Assembly& assembly, Vector& x) const
{
  // Baraff's incremental algorithm (after Dantzig): the stuck resistances are equalities, always
  // clamped (acc = 0); each normal force whose acceleration is negative is driven up from zero,
  // keeping every clamped acceleration at zero, until its own acceleration reaches zero; on the way
  // a clamped normal force that falls to zero is let go, and a free one whose acceleration falls to
  // zero is clamped. For symmetric positive semidefinite A (no opposing friction) it cannot cycle.
  const int n = static_cast<int>(assembly.unknowns.size());
  const S tolerance = S(kForceRounding) * params_.gravity;
  std::vector<char> clamped(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k)
    clamped[static_cast<std::size_t>(k)] = !assembly.unknowns[static_cast<std::size_t>(k)].normal;
  const auto solveClamped = [&](int driven, Vector& dx) {
    // dx: 1 on `driven` (or nothing), and on the clamped set what keeps their accelerations where
    // they are (driven >= 0) or makes them zero (driven < 0, from acc).
    std::vector<int> set;
    for (int k = 0; k < n; ++k)
      if (clamped[static_cast<std::size_t>(k)] && k != driven)
        set.push_back(k);
    dx = Vector::Zero(n);
    if (driven >= 0)
      dx(driven) = S(1);
    if (set.empty())
      return;
    Matrix sub(static_cast<int>(set.size()), static_cast<int>(set.size()));
    Vector rhs(static_cast<int>(set.size()));
    for (std::size_t i = 0; i < set.size(); ++i)
    {
      for (std::size_t j = 0; j < set.size(); ++j)
        sub(static_cast<int>(i), static_cast<int>(j)) = assembly.A(set[i], set[j]);
      rhs(static_cast<int>(i)) = driven >= 0 ? -assembly.A(set[i], driven) : S(0);
    }
    if (driven < 0)
      for (std::size_t i = 0; i < set.size(); ++i)
        rhs(static_cast<int>(i)) = -(assembly.A.row(set[i]).dot(x) + assembly.c(set[i]));
    const Vector part = Eigen::CompleteOrthogonalDecomposition<Matrix>(sub).solve(rhs);
    for (std::size_t i = 0; i < set.size(); ++i)
      dx(set[i]) += part(static_cast<int>(i));
  };
  x = Vector::Zero(n);
  Vector dx;
  solveClamped(-1, dx);  // the equalities alone
  x += dx;
  Vector acc = assembly.A * x + assembly.c;
  int budget = 16 * (n + 1);
  for (int d = 0; d < n; ++d)
  {
    if (!assembly.unknowns[static_cast<std::size_t>(d)].normal || clamped[static_cast<std::size_t>(d)] ||
        !(acc(d) < -tolerance))
      continue;
    while (budget-- > 0)
    {
      solveClamped(d, dx);
      const Vector dacc = assembly.A * dx;
      S step = infinity<S>();
      int blocking = -1;
      if (dacc(d) > S(0))
      {
        step = -acc(d) / dacc(d);
        blocking = d;
      }
      for (int k = 0; k < n; ++k)
      {
        if (k == d || !assembly.unknowns[static_cast<std::size_t>(k)].normal)
          continue;
        if (clamped[static_cast<std::size_t>(k)] && dx(k) < S(0))
        {
          const S s = -x(k) / dx(k);
          if (s < step)
          {
            step = s;
            blocking = k;
          }
        }
        else if (!clamped[static_cast<std::size_t>(k)] && dacc(k) < S(0) && acc(k) >= -tolerance)
        {
          const S s = -acc(k) / dacc(k);
          if (s < step)
          {
            step = s;
            blocking = k;
          }
        }
      }
      if (blocking < 0)
        return false;  // nothing stops the drive: the system cannot be made consistent
      step = std::max(step, S(0));
      x += step * dx;
      acc = assembly.A * x + assembly.c;
      if (blocking == d)
      {
        clamped[static_cast<std::size_t>(d)] = 1;
        break;
      }
      clamped[static_cast<std::size_t>(blocking)] = !clamped[static_cast<std::size_t>(blocking)];
      if (!clamped[static_cast<std::size_t>(blocking)])
        x(blocking) = S(0);
    }
    if (budget <= 0)
      return false;
    d = -1;  // look again from the first: a clamp or a release may have made another negative
  }
  return true;
}

template <typename S>
bool ContactSystem<S>::decideModes(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                   std::vector<LinkMode<S>>& modes, std::vector<BodyRates<S>>& rates) const
{
  const S R = params_.ball_radius, m = params_.ball_mass;
  const S weight = m * params_.gravity, small = slide_speed_, small_turn = small / R;
  const S force_rounding = S(kForceRounding) * weight;
  modes.assign(links.size(), LinkMode<S>());
  // What the velocities say: slips and turnings slower than the slide speed stuck, the others sliding;
  // contacts parting faster than it are not pressed.
  std::vector<char> parting(links.size(), 0);
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    const ContactLink<S>& link = links[l];
    LinkMode<S>& mode = modes[l];
    const ContactGeometry<S> c = geometryOf(link, bodies);
    const Vec3<S> u = slip(link, c, bodies), turn = turning(link, bodies);
    const S turn_n = turn.dot(c.n);
    const Vec3<S> turn_t = turn - turn_n * c.n;
    parting[l] = relativeVelocity(link, bodies).dot(c.n) > slide_speed_;
    mode.slip = u.norm() < small ? Resist::Stuck : Resist::Sliding;
    mode.roll = turn_t.norm() < small_turn ? Resist::Stuck : Resist::Sliding;
    mode.drill = std::abs(turn_n) < small_turn ? Resist::Stuck : Resist::Sliding;
  }
  // 1. Which contacts press, as if no resistance held anything stuck: the frictionless problem's
  // matrix is symmetric positive semidefinite, which the pivoting solves without cycling.
  std::vector<LinkMode<S>> loose = modes;
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    LinkMode<S>& mode = loose[l];
    mode.pressed = !parting[l];
    for (Resist* r : {&mode.slip, &mode.roll, &mode.drill})
      *r = Resist::Sliding;
  }
  Assembly assembly;
  assemble(bodies, links, loose, false, assembly);
  Vector x;
  bool settled = pressNormals(assembly, x);
  for (std::size_t l = 0; l < links.size(); ++l)
    modes[l].pressed = false;
  for (std::size_t k = 0; k < assembly.unknowns.size(); ++k)
    if (assembly.unknowns[k].normal && x(static_cast<int>(k)) > S(0))
      modes[static_cast<std::size_t>(assembly.unknowns[k].link)].pressed = true;
  // 2. With the resistances back: a normal force that turns negative lets go, a free contact pressed
  // into presses (once each), and the resistance furthest beyond its bound starts, until none is.
  // A ball on the cloth that no contact but the slate presses follows its own closed-form path from
  // here on: whether a free contact is pressed into is judged against that path.
  std::vector<ContactBody<S>> used = followed(bodies, links, modes);
  std::vector<int> pressed_again(links.size(), 0);
  for (std::size_t round = 0; round <= 8 * links.size() + 8; ++round)
  {
    accelerations(used, links, modes, rates);
    int worst = -1, kind = 0;
    S worst_value = S(0);
    const auto consider = [&](int l, int k, S value) {
      if (value > worst_value)
      {
        worst = l;
        kind = k;
        worst_value = value;
      }
    };
    for (std::size_t l = 0; l < links.size(); ++l)
    {
      const ContactLink<S>& link = links[l];
      const LinkMode<S>& mode = modes[l];
      if (mode.pressed)
      {
        if (!mode.bilateral)
          consider(static_cast<int>(l), 0, -mode.lambda - force_rounding);
        continue;
      }
      if (parting[l] || pressed_again[l] > 2)
        continue;
      consider(static_cast<int>(l), 1, pressingInto(link, used, rates));
    }
    if (worst < 0)
      for (std::size_t l = 0; l < links.size(); ++l)
      {
        const ContactLink<S>& link = links[l];
        const LinkMode<S>& mode = modes[l];
        if (!mode.pressed)
          continue;
        const ContactGeometry<S> c = geometryOf(link, used);
        const Vec3<S> couple_t = mode.couple - mode.couple.dot(c.n) * c.n;
        const bool slip_stuck = link.grip > S(0) && mode.slip == Resist::Stuck;
        if (slip_stuck)
          consider(static_cast<int>(l), 2, mode.friction.norm() - link.grip * mode.lambda - force_rounding);
        if (slip_stuck && link.rolling > S(0) && mode.roll == Resist::Stuck)
          consider(static_cast<int>(l), 3, (couple_t.norm() - link.rolling * mode.lambda) / R - force_rounding);
        if (link.drilling > S(0) && mode.drill == Resist::Stuck)
          consider(static_cast<int>(l), 4,
                   (std::abs(mode.couple.dot(c.n)) - link.drilling * mode.lambda) / R - force_rounding);
      }
    if (worst < 0)
    {
      // A contact pressed and let go twice over: no consistent modes here (Painleve's paradox).
      for (std::size_t l = 0; l < links.size(); ++l)
        settled = settled && pressed_again[l] <= 2;
      return settled && !nearPainleve(bodies, links, modes);
    }
    LinkMode<S>& mode = modes[static_cast<std::size_t>(worst)];
    switch (kind)
    {
      case 0:
        mode.pressed = false;
        used = followed(bodies, links, modes);  // a ball on the cloth it let go of follows its own path again
        break;
      case 1: {
        mode.pressed = true;
        const ContactLink<S>& pressed = links[static_cast<std::size_t>(worst)];
        for (const int b : {pressed.body, pressed.other})
          if (b >= 0)
            used[static_cast<std::size_t>(b)].dynamic = bodies[static_cast<std::size_t>(b)].dynamic;  // pressed on now
        // Pressed, it pulls; free, it is pressed into: what the stuck resistances about its bodies hold
        // makes the normal forces inconsistent. They slide instead (friction that can neither hold nor
        // let go is taken as sliding). If even then (a friction or a couple that grows with the normal
        // force faster than the normal force parts the bodies: Painleve's paradox), no modes are
        // consistent: the contacts jam (jam(), then holdTogether()). Resistances too stiff to slide
        // (kStiffShare) jam at once.
        const int again = ++pressed_again[static_cast<std::size_t>(worst)];
        if (again == 2 && stiffAbout(links, pressed))
        {
          accelerations(used, links, modes, rates);
          return false;
        }
        if (again == 2)
          for (std::size_t k = 0; k < links.size(); ++k)
            for (const int b : {pressed.body, pressed.other})
              if (b >= 0 && (links[k].body == b || links[k].other == b))
                modes[k].slip = modes[k].roll = modes[k].drill = Resist::Sliding;
        if (again == 3)
        {
          accelerations(used, links, modes, rates);
          return false;
        }
        break;
      }
      case 2:
        mode.slip = mode.roll = Resist::Sliding;  // rolling resistance acts while the slip sticks
        break;
      case 3:
        mode.roll = Resist::Sliding;
        break;
      case 4:
        mode.drill = Resist::Sliding;
        break;
    }
  }
  accelerations(used, links, modes, rates);
  return false;  // did not settle: the last modes stand
}

template <typename S>
bool ContactSystem<S>::stiffAbout(const std::vector<ContactLink<S>>& links, const ContactLink<S>& pressed) const
{
  const S R = params_.ball_radius, natural_speed = std::sqrt(params_.gravity * R);
  const auto stiff = [&](const ContactLink<S>& link, S mu) {
    return mu > S(0) && bandFor(link, mu) < S(kStiffShare) * S(3.5) * mu * natural_speed;
  };
  for (const ContactLink<S>& link : links)
    for (const int b : {pressed.body, pressed.other})
      if (b >= 0 && (link.body == b || link.other == b) &&
          (stiff(link, link.mu) || stiff(link, link.rolling / R) || stiff(link, link.drilling / R)))
        return true;
  return false;
}

template <typename S>
bool ContactSystem<S>::nearPainleve(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                    const std::vector<LinkMode<S>>& modes) const
{
  S fastest = S(0);
  for (const ContactBody<S>& b : bodies)
    fastest = std::max(fastest, b.v.squaredNorm());
  const S load = S(kJamLoad) * params_.ball_mass * (params_.gravity + fastest / params_.ball_radius);
  for (std::size_t l = 0; l < links.size(); ++l)
    if (modes[l].pressed && modes[l].lambda > load)
      return true;
  return false;
}

template <typename S>
void ContactSystem<S>::margins(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                               const std::vector<LinkMode<S>>& modes, const std::vector<BodyRates<S>>& rates,
                               const std::vector<S>& start_gaps, std::vector<S>& out,
                               std::vector<MarginTag>* tags) const
{
  (void)rates;
  const S R = params_.ball_radius, weight = params_.ball_mass * params_.gravity;
  out.clear();
  if (tags)
    tags->clear();
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    const auto add = [&](MarginKind kind, S value) {
      out.push_back(value);
      if (tags)
        tags->push_back({static_cast<int>(l), kind});
    };
    const LinkMode<S>& mode = modes[l];
    const ContactLink<S> link = asActing(links[l], mode);
    const ContactGeometry<S> c = geometryOf(link, bodies);
    // The surface is still the one met: a cushion's face below the nose, its edge above it, beside
    // the cushion and in front of its line; a post's side or rim.
    if (link.surface == Surface::Face || link.surface == Surface::Edge || link.surface == Surface::PostSide ||
        link.surface == Surface::Rim)
    {
      const S above = (bodies[static_cast<std::size_t>(link.body)].r.z() - geometry_.nose_height) / R;
      add(MarginKind::Surface, link.surface == Surface::Face || link.surface == Surface::PostSide ? -above : above);
      if (link.surface == Surface::Face || link.surface == Surface::Edge)
      {
        const S length = geometry_.segments[static_cast<std::size_t>(link.obstacle)].length;
        add(MarginKind::Surface, c.along / R);
        add(MarginKind::Surface, (length - c.along) / R);
        if (link.surface == Surface::Edge)
          add(MarginKind::Surface, c.across / R);
      }
    }
    if (!mode.pressed)
    {
      // Free to part: it must not close again within the step (an impact, or a new contact) by more
      // than a tenth of the contact tolerance, the accuracy the pieces are kept to anyway (a free
      // contact grazing along, its gap's acceleration near zero, is not a new event each time its
      // gap dips by rounding).
      add(MarginKind::Gap, (c.gap - std::min(start_gaps[l], -S(kGrazeShare) * params_.contact_tolerance)) / R);
      continue;
    }
    if (!mode.bilateral)  // (one held both ways holds for its step, which is short: see stepGroup)
      add(MarginKind::Press, mode.lambda / weight);
    // A stuck resistance holds within its bound; a sliding one is smooth, and may stick again at the
    // next step.
    const Vec3<S> couple_t = mode.couple - mode.couple.dot(c.n) * c.n;
    const bool slip_stuck = link.grip > S(0) && mode.slip == Resist::Stuck;
    if (slip_stuck)
      add(MarginKind::Slip, (link.grip * mode.lambda - mode.friction.norm()) / weight);
    if (slip_stuck && link.rolling > S(0) && mode.roll == Resist::Stuck)
      add(MarginKind::Roll, (link.rolling * mode.lambda - couple_t.norm()) / (weight * R));
    if (link.drilling > S(0) && mode.drill == Resist::Stuck)
      add(MarginKind::Drill, (link.drilling * mode.lambda - std::abs(mode.couple.dot(c.n))) / (weight * R));
  }
}

template <typename S>
bool flipMode(const MarginTag& tag, std::vector<LinkMode<S>>& modes, S graze_force)
{
  if (tag.link < 0 || tag.link >= static_cast<int>(modes.size()))
    return false;
  LinkMode<S>& mode = modes[static_cast<std::size_t>(tag.link)];
  switch (tag.kind)
  {
    case MarginKind::Gap:
      mode.pressed = true;
      return true;
    case MarginKind::Press:
      if (mode.lambda > graze_force)
        return false;
      mode.pressed = false;
      return true;
    case MarginKind::Slip:
      mode.slip = mode.roll = Resist::Sliding;  // rolling resistance acts while the slip sticks
      return true;
    case MarginKind::Roll:
      mode.roll = Resist::Sliding;
      return true;
    case MarginKind::Drill:
      mode.drill = Resist::Sliding;
      return true;
    default:
      return false;
  }
}

template <typename S>
void ContactSystem<S>::projectVelocities(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                         const std::vector<LinkMode<S>>& modes, bool normals_only) const
{
  using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  const S R = params_.ball_radius, m = params_.ball_mass, I = inertia_;
  // Each constraint: its row on (v_body, w_body, v_other, w_other); its impulse acts along the same
  // row in the mass metric, so the correction is an orthogonal projection.
  struct Constraint
  {
    int body, other;
    Vec3<S> v_b, w_b, v_o, w_o;
  };
  std::vector<Constraint> rows;
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    const LinkMode<S>& mode = modes[l];
    const ContactLink<S> link = asActing(links[l], mode);
    if (!mode.pressed)
      continue;
    const ContactGeometry<S> c = geometryOf(link, bodies);
    Vec3<S> t1, t2;
    tangents(c.n, t1, t2);
    rows.push_back({link.body, link.other, c.n, Vec3<S>::Zero(), -c.n, Vec3<S>::Zero()});
    if (normals_only)
      continue;
    const bool slip_stuck = link.grip > S(0) && mode.slip == Resist::Stuck;
    if (slip_stuck)
      for (const Vec3<S>& t : {t1, t2})
      {
        // The slip along t: t . (v_b + w_b x (-R n) - v_o - w_o x (R n)).
        const Vec3<S> arm = -R * c.n.cross(t);
        rows.push_back({link.body, link.other, t, arm, -t, arm});
      }
    if (slip_stuck && link.rolling > S(0) && mode.roll == Resist::Stuck)
      for (const Vec3<S>& t : {t1, t2})
        rows.push_back({link.body, link.other, Vec3<S>::Zero(), t, Vec3<S>::Zero(), -t});
    if (link.drilling > S(0) && mode.drill == Resist::Stuck)
      rows.push_back({link.body, link.other, Vec3<S>::Zero(), c.n, Vec3<S>::Zero(), -c.n});
  }
  const int n = static_cast<int>(rows.size());
  if (n == 0)
    return;
  const auto dynamic = [&](int b) { return b >= 0 && bodies[static_cast<std::size_t>(b)].dynamic; };
  const auto value = [&](const Constraint& c) {
    S x = S(0);
    if (c.body >= 0)
      x +=
          c.v_b.dot(bodies[static_cast<std::size_t>(c.body)].v) + c.w_b.dot(bodies[static_cast<std::size_t>(c.body)].w);
    if (c.other >= 0)
      x += c.v_o.dot(bodies[static_cast<std::size_t>(c.other)].v) +
           c.w_o.dot(bodies[static_cast<std::size_t>(c.other)].w);
    return x;
  };
  Matrix A = Matrix::Zero(n, n);
  Vector rhs(n);
  for (int r = 0; r < n; ++r)
  {
    const Constraint& a = rows[static_cast<std::size_t>(r)];
    rhs(r) = value(a);
    for (int c = 0; c < n; ++c)
    {
      const Constraint& b = rows[static_cast<std::size_t>(c)];
      S entry = S(0);
      // The impulse of constraint b moves body x by (v_b / m, w_b / I) per unit; row a reads it.
      const auto term = [&](int body_a, const Vec3<S>& va, const Vec3<S>& wa, int body_b, const Vec3<S>& vb,
                            const Vec3<S>& wb) {
        if (body_a >= 0 && body_a == body_b && dynamic(body_a))
          entry += va.dot(vb) / m + wa.dot(wb) / I;
      };
      term(a.body, a.v_b, a.w_b, b.body, b.v_b, b.w_b);
      term(a.body, a.v_b, a.w_b, b.other, b.v_o, b.w_o);
      term(a.other, a.v_o, a.w_o, b.body, b.v_b, b.w_b);
      term(a.other, a.v_o, a.w_o, b.other, b.v_o, b.w_o);
      A(r, c) = entry;
    }
  }
  const Vector impulse = Eigen::CompleteOrthogonalDecomposition<Matrix>(A).solve(rhs);
  if (!impulse.allFinite())
    return;
  for (int r = 0; r < n; ++r)
  {
    const Constraint& c = rows[static_cast<std::size_t>(r)];
    const S p = impulse(r);
    if (dynamic(c.body))
    {
      bodies[static_cast<std::size_t>(c.body)].v -= p * c.v_b / m;
      bodies[static_cast<std::size_t>(c.body)].w -= p * c.w_b / I;
    }
    if (dynamic(c.other))
    {
      bodies[static_cast<std::size_t>(c.other)].v -= p * c.v_o / m;
      bodies[static_cast<std::size_t>(c.other)].w -= p * c.w_o / I;
    }
  }
}

template <typename S>
std::vector<ContactBody<S>> ContactSystem<S>::followed(const std::vector<ContactBody<S>>& bodies,
                                                       const std::vector<ContactLink<S>>& links,
                                                       const std::vector<LinkMode<S>>& modes) const
{
  std::vector<ContactBody<S>> used = bodies;
  for (std::size_t b = 0; b < used.size(); ++b)
  {
    if (!used[b].free_on_cloth)
      continue;
    bool pressed_by_other = false;
    for (std::size_t l = 0; l < links.size(); ++l)
      pressed_by_other =
          pressed_by_other || (modes[l].pressed && links[l].surface != Surface::Slate &&
                               (links[l].body == static_cast<int>(b) || links[l].other == static_cast<int>(b)));
    used[b].dynamic = pressed_by_other;
  }
  return used;
}

template <typename S>
S ContactSystem<S>::pressingInto(const ContactLink<S>& link, const std::vector<ContactBody<S>>& used,
                                 const std::vector<BodyRates<S>>& rates) const
{
  const bool body_dynamic = used[static_cast<std::size_t>(link.body)].dynamic;
  const bool other_dynamic = link.other >= 0 && used[static_cast<std::size_t>(link.other)].dynamic;
  if (!body_dynamic && !other_dynamic)
    return S(0);
  const ContactGeometry<S> c = geometryOf(link, used);
  const Vec3<S> v_rel = relativeVelocity(link, used);
  Vec3<S> a_rel = rates[static_cast<std::size_t>(link.body)].a;
  if (link.other >= 0)
    a_rel -= rates[static_cast<std::size_t>(link.other)].a;
  // (A free contact grazing along, its gap's acceleration within rounding of zero, stays free.)
  const S weight = params_.ball_mass * params_.gravity;
  return (-(c.n.dot(a_rel) + v_rel.dot(c.H * v_rel)) * params_.ball_mass - S(kGrazeForce) * weight) / S(2);
}

template <typename S>
void ContactSystem<S>::holdTogether(const std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                    std::vector<LinkMode<S>>& modes, std::vector<BodyRates<S>>& rates) const
{
  const S force_rounding = S(kForceRounding) * params_.ball_mass * params_.gravity;
  std::vector<ContactBody<S>> used = followed(bodies, links, modes);
  accelerations(used, links, modes, rates);
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    LinkMode<S>& mode = modes[l];
    const bool parting = relativeVelocity(links[l], bodies).dot(geometryOf(links[l], bodies).n) > slide_speed_;
    const bool inconsistent =
        mode.pressed ? mode.lambda < -force_rounding : !parting && pressingInto(links[l], used, rates) > S(0);
    if (!inconsistent)
      continue;
    mode.pressed = mode.bilateral = true;
  }
  used = followed(bodies, links, modes);
  accelerations(used, links, modes, rates);
}

template <typename S>
void ContactSystem<S>::jam(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links) const
{
  std::vector<LinkMode<S>> stuck(links.size());
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    const ContactGeometry<S> c = geometryOf(links[l], bodies);
    stuck[l].pressed = relativeVelocity(links[l], bodies).dot(c.n) <= slide_speed_;
    stuck[l].slip = links[l].grip > S(0) ? Resist::Stuck : Resist::Sliding;
    stuck[l].roll = links[l].rolling > S(0) ? Resist::Stuck : Resist::Sliding;
    stuck[l].drill = links[l].drilling > S(0) ? Resist::Stuck : Resist::Sliding;
  }
  projectVelocities(bodies, links, stuck);
}

template <typename S>
void ContactSystem<S>::projectPositions(std::vector<ContactBody<S>>& bodies, const std::vector<ContactLink<S>>& links,
                                        const std::vector<LinkMode<S>>& modes) const
{
  // Gauss-Seidel sweeps of the gaps: a few, since each is a few ulps.
  for (int sweep = 0; sweep < 4; ++sweep)
    for (std::size_t l = 0; l < links.size(); ++l)
    {
      const ContactLink<S>& link = links[l];
      if (!modes[l].pressed)
        continue;
      const ContactGeometry<S> c = geometryOf(link, bodies);
      ContactBody<S>& b = bodies[static_cast<std::size_t>(link.body)];
      const bool other_moves = link.other >= 0 && bodies[static_cast<std::size_t>(link.other)].dynamic;
      if (link.surface == Surface::Slate)
      {
        if (b.dynamic)
          b.r.z() = params_.ball_radius;
        continue;
      }
      const S share = b.dynamic && other_moves ? S(0.5) : S(1);
      if (b.dynamic)
        b.r -= share * c.gap * c.n;
      if (other_moves)
        bodies[static_cast<std::size_t>(link.other)].r += share * c.gap * c.n;
    }
}

template <typename S>
S groupEnergy(const std::vector<ContactBody<S>>& bodies, const PhysicsParams<S>& p)
{
  const S inertia = S(0.4) * p.ball_mass * p.ball_radius * p.ball_radius;
  S energy = S(0);
  for (const ContactBody<S>& b : bodies)
    energy += S(0.5) * p.ball_mass * b.v.squaredNorm() + S(0.5) * inertia * b.w.squaredNorm() +
              p.ball_mass * p.gravity * (b.r.z() - p.ball_radius);
  return energy;
}

template class ContactSystem<double>;
template class ContactSystem<long double>;
template double groupEnergy(const std::vector<ContactBody<double>>&, const PhysicsParams<double>&);
template long double groupEnergy(const std::vector<ContactBody<long double>>&, const PhysicsParams<long double>&);
template bool flipMode(const MarginTag&, std::vector<LinkMode<double>>&, double);
template bool flipMode(const MarginTag&, std::vector<LinkMode<long double>>&, long double);

}  // namespace physics
}  // namespace cue_sim
