// A ball on the slate: flight under gravity, one impact, and the closed-form bounce sequence
// (PHYSICS.md, balls off the cloth) against the textbook drop, the impact's invariants, and the
// same sequence followed one bounce at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cue_sim/physics/motion.hpp"
#include "physics/models/ball_table/slate_bounce.hpp"
#include "physics/models/flight.hpp"

using namespace cue_sim::physics;

namespace
{
const PhysicsParams<double> p;
const double kR = p.ball_radius, kG = p.gravity;

/// Angular momentum about the contact point under the ball, per unit mass: I w / m + (R z) x v.
Vec3<double> momentAboutContact(const Ball<double>& b)
{
  return 0.4 * kR * kR * b.w + kR * Vec3<double>::UnitZ().cross(b.v);
}

double slip(const Ball<double>& b)
{
  return slipVelocity(b.v, b.w, kR).norm();
}

/// The bounces one at a time: impact, flight up and down again, until the rebound is nothing.
struct Followed
{
  Ball<double> end;
  int impacts = 0;
  int slip_stopped_at = -1;
};

Followed followBounces(Ball<double> b, const SlateContact<double>& contact)
{
  Followed f;
  for (; f.impacts < 5000 && b.v.z() < 0; ++f.impacts)
  {
    const bool slipping = slip(b) > 0;
    b = slateImpact(b, contact, kR);
    if (slipping && f.slip_stopped_at < 0 && slip(b) < 1e-12 * (1 + b.v.norm()))
      f.slip_stopped_at = f.impacts;
    // Up and back down to the slate: the flight's own root, from the slate's height.
    const double flight = timeToHeight(b.r.z(), b.v.z(), kR, kG);
    b.r = flightPosition(b.r, b.v, flight, kG);
    b.r.z() = kR;
    b.time += flight;
    b.v = flightVelocity(b.v, flight, kG);
    if (!(b.v.z() < -1e-300))
      break;
  }
  b.v.z() = 0;
  f.end = b;
  return f;
}

/// A ball reaching the slate with velocity v and spin w.
Ball<double> landing(const Vec3<double>& v, const Vec3<double>& w)
{
  Ball<double> b;
  b.r = Vec3<double>(0.1, -0.2, kR);
  b.v = v;
  b.w = w;
  return b;
}
}  // namespace

TEST(Flight, ParabolaApexAndLanding)
{
  const Vec3<double> r0(0.1, -0.2, kR), v0(1.5, 0.5, 2.0);
  const double apex = apexHeight(r0.z(), v0.z(), kG);
  EXPECT_NEAR(apex, kR + 4.0 / (2 * kG), 1e-15);
  // Back to the slate after 2 vz / g, at the horizontal velocity times it.
  const double t = timeToHeight(r0.z(), v0.z(), kR, kG);
  EXPECT_NEAR(t, 2 * 2.0 / kG, 1e-15);
  const Vec3<double> r = flightPosition(r0, v0, t, kG);
  EXPECT_NEAR(r.z(), kR, 1e-15);
  EXPECT_NEAR(r.x(), 0.1 + 1.5 * t, 1e-15);
  EXPECT_NEAR(flightVelocity(v0, t, kG).z(), -2.0, 1e-14);
  // At the apex's time the centre is at the apex and still.
  EXPECT_NEAR(flightPosition(r0, v0, 2.0 / kG, kG).z(), apex, 1e-15);
  // Above the apex never; below the slate and falling, never again.
  EXPECT_TRUE(std::isinf(timeToHeight(r0.z(), v0.z(), apex + 1e-6, kG)));
  EXPECT_TRUE(std::isinf(timeToHeight(0.01, -1.0, 0.02, kG)));
  EXPECT_EQ(timeToHeight(kR, -1.0, kR, kG), 0.0);
  EXPECT_EQ(timeToHeight(kR, 0.0, kR, kG), 0.0);
}

TEST(Flight, ShortDropsWithoutCancellation)
{
  // A centre a nanometre over the height, falling at 3 m/s: the time is drop / speed to first order.
  // The textbook root (vz + sqrt(vz^2 + 2 g d)) / g loses every digit here.
  for (const double drop : {1e-9, 1e-12, 1e-15})
  {
    const double t = timeToHeight(kR + drop, -3.0, kR, kG);
    const long double exact = 2.0L * static_cast<long double>((kR + drop) - kR) /
                              (std::sqrt(9.0L + 2.0L * kG * static_cast<long double>((kR + drop) - kR)) + 3.0L);
    EXPECT_NEAR(t, static_cast<double>(exact), 1e-15 * static_cast<double>(exact)) << drop;
    EXPECT_GT(t, 0.0);
  }
}

TEST(SlateBounce, DroppedBallBouncesAsTheGeometricSeries)
{
  // Dropped from H over the cloth, no spin, any friction: heights fall by e^2 a bounce, and the
  // bounces take 2 e t1 / (1 - e) after a first fall of t1 = sqrt(2 H / g) (PHYSICS.md).
  const double H = 0.2, t1 = std::sqrt(2 * H / kG);
  for (const double e : {0.0, 0.3, 0.5, 0.8})
  {
    const SlateContact<double> contact{e, 0.2};
    Ball<double> m = landing(Vec3<double>(0, 0, -kG * t1), Vec3<double>::Zero());
    const BounceSeries<double> series = bounceSeries(m, contact, kR, kG);
    EXPECT_NEAR(series.end.time - m.time, 2 * e * t1 / (1 - e), 1e-15) << e;
    EXPECT_NEAR(series.first_rebound, e * e * H, 1e-15) << e;
    EXPECT_EQ((series.end.r - m.r).norm(), 0.0);
    EXPECT_EQ(series.end.v.norm(), 0.0);
    // Each rebound's height is e^2 of the last.
    double height = H;
    for (int k = 0; k < 6 && e > 0; ++k)
    {
      m = slateImpact(m, contact, kR);
      const double rise = apexHeight(0.0, m.v.z(), kG);
      EXPECT_NEAR(rise, e * e * height, 1e-15) << e << " bounce " << k;
      height = rise;
      m.v.z() = -m.v.z();
    }
  }
}

TEST(SlateBounce, OneImpactKeepsMomentAboutTheContactAndGainsNoEnergy)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> speed(-4, 4), spin(-200, 200), e(0, 0.95), mu(0, 0.6);
  for (int i = 0; i < 2000; ++i)
  {
    const Ball<double> in = landing(Vec3<double>(speed(random), speed(random), -std::fabs(speed(random)) - 1e-3),
                                    Vec3<double>(spin(random), spin(random), spin(random)));
    const SlateContact<double> contact{e(random), mu(random)};
    const Ball<double> out = slateImpact(in, contact, kR);
    // Normal restitution, and the normal part's energy down by e^2 exactly.
    EXPECT_NEAR(out.v.z(), -contact.restitution * in.v.z(), 1e-15);
    // Both impulses act at the contact point: the horizontal moment about it is kept.
    const Vec3<double> before = momentAboutContact(in), after = momentAboutContact(out);
    EXPECT_NEAR(after.x(), before.x(), 1e-13);
    EXPECT_NEAR(after.y(), before.y(), 1e-13);
    EXPECT_EQ(out.w.z(), in.w.z());
    EXPECT_LE(kineticEnergy(out, p), kineticEnergy(in, p) * (1 + 1e-14));
    // Friction never reverses the slip: it keeps its direction, shrunk, or stops.
    EXPECT_LE(slip(out), slip(in) * (1 + 1e-14) + 1e-14);
    // No more friction than Coulomb's bound on what the normal impulse allows.
    const double tangential = (Vec3<double>(out.v.x(), out.v.y(), 0) - Vec3<double>(in.v.x(), in.v.y(), 0)).norm();
    EXPECT_LE(tangential, contact.friction * (1 + contact.restitution) * -in.v.z() * (1 + 1e-14) + 1e-15);
  }
}

TEST(SlateBounce, FrictionThatCanStopTheSlipLeavesTheBallRolling)
{
  // A draw shot landing: forward at 3 m/s, backspin, coming down at 2 m/s onto a grippy slate.
  const Ball<double> in = landing(Vec3<double>(3, 0, -2), Vec3<double>(0, -80, 0));
  const Ball<double> out = slateImpact(in, SlateContact<double>{0.5, 0.9}, kR);
  EXPECT_NEAR(slip(out), 0.0, 1e-13);
  // Rolling, with the moment about the contact it came with: (7/5) R v_x = (2/5) R^2 w_y + R v_x0.
  EXPECT_NEAR(out.v.x(), (5 * 3.0 + 2 * kR * -80.0) / 7, 1e-14);
  EXPECT_NEAR(out.v.y(), 0.0, 1e-15);
}

TEST(SlateBounce, TheSeriesIsTheBouncesFollowedOneByOne)
{
  struct Case
  {
    const char* what;
    Ball<double> in;
    SlateContact<double> contact;
    // The impact that stops the slip, by hand from (7/2) mu (1 + e) U_0 (1 - e^(k+1)) / (1 - e) >= |u|;
    // -1: still slipping at the end; -2: not checked.
    int stopped_at;
  };
  const Case cases[] = {
      {"stun landing, grippy: stops at the first impact", landing({3, 0, -2}, {0, 0, 0}), {0.5, 0.9}, 0},
      {"heavy backspin, some grip: stops later", landing({2, 1, -1.5}, {60, -150, 30}), {0.6, 0.4}, 3},
      {"heavy backspin, little grip: slides on", landing({2, 1, -1.5}, {60, -150, 30}), {0.5, 0.01}, -1},
      {"frictionless", landing({2, 1, -1.5}, {60, -150, 30}), {0.5, 0.0}, -1},
      {"no bounce", landing({2, 1, -1.5}, {60, -150, 30}), {0.0, 0.2}, -2},
      {"lively slate", landing({-1, 0.5, -3}, {10, 20, -5}), {0.9, 0.05}, -2},
  };
  for (const Case& c : cases)
  {
    const BounceSeries<double> series = bounceSeries(c.in, c.contact, kR, kG);
    const Followed followed = followBounces(c.in, c.contact);
    const double scale = c.in.v.norm();
    EXPECT_NEAR(series.end.time, followed.end.time, 1e-13 * (1 + followed.end.time)) << c.what;
    EXPECT_NEAR((series.end.r - followed.end.r).norm(), 0.0, 1e-13 * (1 + (followed.end.r - c.in.r).norm())) << c.what;
    EXPECT_NEAR((series.end.v - followed.end.v).norm(), 0.0, 1e-13 * scale) << c.what;
    EXPECT_NEAR(kR * (series.end.w - followed.end.w).norm(), 0.0, 1e-13 * scale) << c.what;
    EXPECT_EQ(series.end.v.z(), 0.0);
    if (c.contact.friction > 0)
    {
      EXPECT_EQ(series.slip_stopped_at, followed.slip_stopped_at) << c.what;
    }
    if (c.stopped_at != -2)
    {
      EXPECT_EQ(series.slip_stopped_at, c.stopped_at) << c.what;
    }
    EXPECT_LE(kineticEnergy(series.end, p), kineticEnergy(c.in, p)) << c.what;
  }
}

TEST(SlateBounce, LongDoubleAgrees)
{
  Ball<long double> in;
  in.r = Vec3<long double>(0.1L, -0.2L, static_cast<long double>(kR));
  in.v = Vec3<long double>(2, 1, -1.5);
  in.w = Vec3<long double>(60, -150, 30);
  const BounceSeries<long double> wide =
      bounceSeries(in, SlateContact<long double>{0.6L, 0.4L}, (long double)kR, (long double)kG);
  const BounceSeries<double> narrow = bounceSeries(landing({2, 1, -1.5}, {60, -150, 30}), {0.6, 0.4}, kR, kG);
  EXPECT_EQ(wide.slip_stopped_at, narrow.slip_stopped_at);
  EXPECT_NEAR(static_cast<double>(wide.end.r.x()), narrow.end.r.x(), 1e-15);
  EXPECT_NEAR(static_cast<double>(wide.end.v.y()), narrow.end.v.y(), 1e-15);
}
