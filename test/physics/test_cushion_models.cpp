// Cushion models: limits with a closed form, the invariants every model keeps, and the
// integration of Mathavan, Jackson and Parkin 2010 against its own long-double limit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/motion.hpp"

using namespace cue_sim::physics;

namespace
{
/// The paper's ball and cushion (Mathavan 2010, section 2 and Table 1: a snooker ball, the nose
/// at 7R/5, e = 0.98, mu_w = 0.14 at the cushion, mu_s = 0.212 on the cloth).
template <typename S = double>
PhysicsParams<S> papersBall()
{
  PhysicsParams<S> p;
  p.ball_mass = 0.1406;
  p.ball_radius = 0.02625;
  p.cushion_height = 0.02625 * 7 / 5;
  p.e_cushion_work = 0.98;
  p.mu_cushion = 0.14;
  p.mu_slide = 0.212;
  return p;
}

/// The paper's frame: the cushion along x at +y, so its normal into play is -y; the ball comes
/// in at `alpha` to the cushion with speed V, topspin k_t V/R about its travel and side spin
/// k_s V/R (the paper's omega_0T and omega_0S).
template <typename S>
Ball<S> incoming(S speed, S alpha, S k_top, S k_side, const PhysicsParams<S>& p)
{
  Ball<S> b;
  b.r = Vec3<S>(0, 0, p.ball_radius);
  b.v = speed * Vec3<S>(std::cos(alpha), std::sin(alpha), 0);
  const S top = k_top * speed / p.ball_radius;
  b.w = Vec3<S>(-top * std::sin(alpha), top * std::cos(alpha), k_side * speed / p.ball_radius);
  return b;
}

const Vec3<double> kIntoPlay(0, -1, 0);
const double kDeg = M_PI / 180;
}  // namespace

TEST(MathavanCushion, WithoutFrictionTheNormalVelocityComesBackTimesE)
{
  // With no friction the normal impulse is the only force: the closing speed falls linearly in
  // it, and giving back e^2 of the compression's work is Newton's restitution. Spin and the
  // velocity along the cushion are untouched, whatever the tolerance and the nose's height.
  for (const double height : {1.05, 1.4, 1.95})
    for (const double tolerance : {1e-2, 1e-6, 1e-12})
      for (const double alpha : {5.0, 45.0, 90.0})
      {
        PhysicsParams<double> p = papersBall();
        p.mu_cushion = 0;
        p.mu_slide = 0;
        p.cushion_height = height * p.ball_radius;
        p.cushion_impact_tolerance = tolerance;
        p.e_cushion_work = 0.7;
        Ball<double> b = incoming(1.3, alpha * kDeg, 1.0, -2.0, p);
        const Ball<double> before = b;
        makeCushionModel<double>("mathavan2010")->resolve(b, kIntoPlay, p);
        SCOPED_TRACE(std::to_string(height) + " R, tolerance " + std::to_string(tolerance) + ", " +
                     std::to_string(alpha));
        EXPECT_NEAR(b.v.y(), -0.7 * before.v.y(), 1e-12);
        EXPECT_NEAR(b.v.x(), before.v.x(), 1e-12);
        EXPECT_NEAR((b.w - before.w).norm(), 0, 1e-9);
        EXPECT_EQ(b.v.z(), 0.0);
      }
}

TEST(MathavanCushion, SlidingThroughoutFollowsThePapersEquationsInClosedForm)
{
  // Head on with heavy topspin (20 V/R) and no cloth friction, the nose slips one way through
  // the whole impact (phi = -90 degrees in the paper's Eq. 13-17). The equations are then linear
  // in the impulse: v_y falls at (cos(t) + mu_w sin(t)) / M, so v_y' = -e V, the impulse is
  // (1 + e) M V / (cos(t) + mu_w sin(t)), and w_x grows by 5 mu_w / (2 M R) times it.
  PhysicsParams<double> p = papersBall();
  p.mu_slide = 0;
  const double V = 1.2, sin_t = 0.4, cos_t = std::sqrt(21.0) / 5;
  for (const double tolerance : {1e-2, 1e-8})
  {
    p.cushion_impact_tolerance = tolerance;
    Ball<double> b = incoming(V, 90 * kDeg, 20.0, 0.0, p);
    const Ball<double> before = b;
    makeCushionModel<double>("mathavan2010")->resolve(b, kIntoPlay, p);
    const double impulse = (1 + p.e_cushion_work) * p.ball_mass * V / (cos_t + p.mu_cushion * sin_t);
    EXPECT_NEAR(b.v.y(), -p.e_cushion_work * V, 1e-12);
    EXPECT_NEAR(b.v.x(), 0, 1e-12);
    EXPECT_NEAR(b.w.x(), before.w.x() + 5 * p.mu_cushion / (2 * p.ball_mass * p.ball_radius) * impulse, 1e-9);
    EXPECT_NEAR(b.w.y(), 0, 1e-9);
    EXPECT_NEAR(b.w.z(), 0, 1e-9);
  }
}

TEST(MathavanCushion, TheReboundConvergesAsTheToleranceFalls)
{
  // The paper's rebounds at V = 1 m/s (its figures' speed), each against the same impact in
  // long double with a tolerance of 1e-10. Per-step control of a second-order method makes the
  // error fall as the tolerance to the 2/3 (a hundred times for a thousand); where a slip stops
  // or turns in two dimensions it is first order there (tol^1/2, thirty times). Head-on shots,
  // whose slips all lie in one line, are exact: each stop or turn ends a step.
  struct Case
  {
    double alpha_deg, k_top, k_side;
  };
  for (const Case c : {Case{30, -1, 0}, Case{11.5, 2, -1}, Case{45, 1, 0}, Case{60, 1, 2}, Case{90, 1, 1},
                       Case{90, 0, 0}, Case{75, 0, 0}, Case{60, 1, -2}, Case{90, -1, 0}})
  {
    SCOPED_TRACE(std::to_string(c.alpha_deg) + " deg, topspin " + std::to_string(c.k_top) + ", side " +
                 std::to_string(c.k_side));
    PhysicsParams<long double> pl = papersBall<long double>();
    pl.cushion_impact_tolerance = 1e-10;
    Ball<long double> reference = incoming<long double>(1, c.alpha_deg * kDeg, c.k_top, c.k_side, pl);
    makeCushionModel<long double>("mathavan2010")->resolve(reference, kIntoPlay.cast<long double>(), pl);
    const auto errorWith = [&](double tolerance) {
      PhysicsParams<double> p = papersBall();
      p.cushion_impact_tolerance = tolerance;
      Ball<double> b = incoming(1.0, c.alpha_deg * kDeg, c.k_top, c.k_side, p);
      makeCushionModel<double>("mathavan2010")->resolve(b, kIntoPlay, p);
      return (b.v - reference.v.cast<double>()).norm();
    };
    const double coarse = errorWith(1e-6), fine = errorWith(1e-9);
    EXPECT_LT(fine, coarse / 30 + 1e-12);
    EXPECT_LT(fine, 5e-7);
  }
}

TEST(MathavanCushion, HeadOnEveryToleranceGivesTheSameRebound)
{
  // Head on, every slip lies along the cushion's normal plane: each contact slides one way,
  // stops, sticks or turns, and the integration ends a step at each such change, between which
  // the motion is linear in the impulse and the midpoint step exact. Draw, stun and follow.
  for (const double k_top : {-1.0, 0.0, 1.0, 3.0})
  {
    Ball<double> loose, tight;
    for (const double tolerance : {1e-2, 1e-9})
    {
      PhysicsParams<double> p = papersBall();
      p.cushion_impact_tolerance = tolerance;
      Ball<double>& b = tolerance > 1e-3 ? loose : tight;
      b = incoming(1.0, 90 * kDeg, k_top, 0.0, p);
      makeCushionModel<double>("mathavan2010")->resolve(b, kIntoPlay, p);
    }
    EXPECT_NEAR((loose.v - tight.v).norm(), 0, 1e-13) << k_top;
    EXPECT_NEAR(papersBall().ball_radius * (loose.w - tight.w).norm(), 0, 1e-13) << k_top;
    EXPECT_LT(tight.v.y(), -0.5) << k_top;  // it came back
  }
}

TEST(StrongeCushion, WithoutFrictionItIsNewtonsRestitutionAtTheNose)
{
  // With no friction the tangential spring never pulls: the normal velocity at the nose comes
  // back times e_cushion, the spin is untouched, and the rebound is han2005's without friction.
  for (const double alpha : {10.0, 45.0, 90.0})
  {
    PhysicsParams<double> p = papersBall();
    p.f_cushion = 0;
    Ball<double> stronge = incoming(1.3, alpha * kDeg, 1.0, -2.0, p), han = stronge;
    const Ball<double> before = stronge;
    makeCushionModel<double>("stronge2018")->resolve(stronge, kIntoPlay, p);
    makeCushionModel<double>("han2005")->resolve(han, kIntoPlay, p);
    EXPECT_NEAR((stronge.v - han.v).norm(), 0, 1e-15) << alpha;
    EXPECT_NEAR((stronge.w - before.w).norm(), 0, 1e-12) << alpha;
  }
}

TEST(StrongeCushion, ARigidTangentIsHan2005)
{
  // The book's rigid limit: a tangential spring far stiffer than the normal one stops the slip
  // as rigid Coulomb friction with stick does, which is han2005 with the same e_cushion and
  // f_cushion. At eta = 1e4 the vibration left is 1e-4 of mu beta_t v_n.
  struct Case
  {
    double alpha_deg, k_top, k_side;
  };
  for (const Case c : {Case{90, 0, 0}, Case{90, 2, 0}, Case{30, 0, 1}, Case{60, -1, -2}, Case{10, 0, 0}})
  {
    PhysicsParams<double> p = papersBall();
    p.cushion_frequency_ratio = 1e4;
    Ball<double> stronge = incoming(1.0, c.alpha_deg * kDeg, c.k_top, c.k_side, p), han = stronge;
    makeCushionModel<double>("stronge2018")->resolve(stronge, kIntoPlay, p);
    makeCushionModel<double>("han2005")->resolve(han, kIntoPlay, p);
    EXPECT_NEAR((stronge.v - han.v).norm(), 0, 2e-4) << c.alpha_deg;
    EXPECT_NEAR(p.ball_radius * (stronge.w - han.w).norm(), 0, 5e-4) << c.alpha_deg;
  }
}

TEST(StrongeCushion, AComplianceTangentChangesGlancingReboundsOnly)
{
  // At the default ratio (1.7) a fast slip slides throughout and the rebound is the rigid one;
  // a slow slip is caught by the spring and given back, so the two models differ there. Head on
  // with topspin k V/R the nose slips at V (sin(alpha) + k) up its face: a touch of draw
  // (k = -0.3) leaves 0.1 V, under mu beta_t v_n / eta^2 = 0.22 V.
  const PhysicsParams<double> p = papersBall();
  Ball<double> fast_s = incoming(1.0, 20 * kDeg, 0.0, 3.0, p), fast_h = fast_s;
  makeCushionModel<double>("stronge2018")->resolve(fast_s, kIntoPlay, p);
  makeCushionModel<double>("han2005")->resolve(fast_h, kIntoPlay, p);
  EXPECT_NEAR((fast_s.v - fast_h.v).norm(), 0, 1e-12);
  Ball<double> slow_s = incoming(1.0, 90 * kDeg, -0.3, 0.0, p), slow_h = slow_s;
  makeCushionModel<double>("stronge2018")->resolve(slow_s, kIntoPlay, p);
  makeCushionModel<double>("han2005")->resolve(slow_h, kIntoPlay, p);
  EXPECT_GT(p.ball_radius * (slow_s.w - slow_h.w).norm(), 1e-3);
}

TEST(CushionModels, NeverGainEnergyLeaveTheCushionAndStayOnTheCloth)
{
  // Every registered cushion model, random balls and coefficients: the ball leaves level, with
  // no more kinetic energy (translation and spin) than it came with. The integrated impact and
  // the reflection also leave it moving off the cushion (v.n >= 0); the models with one impulse
  // at the nose (han2005, stronge2018) may not (with a nose near the ball's top or little
  // restitution, its push is mostly down), and the engine repeats it, then stops what is left
  // (EventResolver::wallImpact).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1), symmetric(-1, 1);
  for (const std::string& name : cushionModelNames())
  {
    const auto model = makeCushionModel<double>(name);
    for (int i = 0; i < 3000; ++i)
    {
      PhysicsParams<double> p;
      p.e_cushion = unit(rng);
      p.e_cushion_work = unit(rng);
      p.f_cushion = 2 * unit(rng);
      p.mu_cushion = 2 * unit(rng);
      p.mu_slide = 2 * unit(rng);
      p.cushion_height = p.ball_radius * (1.01 + 0.98 * unit(rng));
      p.cushion_impact_tolerance = std::pow(10.0, -9 + 7 * unit(rng));
      p.cushion_frequency_ratio = 0.1 * std::pow(1000.0, unit(rng));
      const Vec3<double> n = Vec3<double>(symmetric(rng), symmetric(rng), 0).normalized();
      Ball<double> b;
      b.r = Vec3<double>(0, 0, p.ball_radius);
      b.v = 3 * Vec3<double>(symmetric(rng), symmetric(rng), 0);
      b.v -= std::max(0.0, b.v.dot(n)) * n * 1.5;  // into the cushion
      b.w = 200 * Vec3<double>(symmetric(rng), symmetric(rng), symmetric(rng));
      const double energy = kineticEnergy(b, p);
      model->resolve(b, n, p);
      SCOPED_TRACE(name + " #" + std::to_string(i));
      ASSERT_LE(kineticEnergy(b, p), energy * (1 + 1e-12));
      if (name != "han2005" && name != "stronge2018")
      {
        ASSERT_GE(b.v.dot(n), -1e-12 * b.v.norm());
      }
      ASSERT_EQ(b.v.z(), 0.0);
      ASSERT_TRUE(b.v.allFinite() && b.w.allFinite());
    }
  }
}

TEST(CushionModels, ARigidCushionsReboundScalesWithTheSpeed)
{
  // None of the rigid models has a speed or time scale: three times the velocity and spin in
  // gives three times out (the paper's reason to check its rigid cushion only below 2.5 m/s).
  for (const std::string& name : cushionModelNames())
  {
    const PhysicsParams<double> p = papersBall();
    const auto model = makeCushionModel<double>(name);
    Ball<double> slow = incoming(0.8, 35 * kDeg, 1.5, -0.7, p), fast = incoming(2.4, 35 * kDeg, 1.5, -0.7, p);
    model->resolve(slow, kIntoPlay, p);
    model->resolve(fast, kIntoPlay, p);
    EXPECT_NEAR((fast.v - 3 * slow.v).norm(), 0, 1e-12) << name;
    EXPECT_NEAR((fast.w - 3 * slow.w).norm(), 0, 1e-9) << name;
  }
}

TEST(CushionModels, ARigidCushionsReboundScalesDownToSpeedsNearRounding)
{
  // The same down to a ball pressed on a cushion at a picometre a second, which a held ball's
  // rounding makes: no threshold of the models may stand in for the impact's own scale.
  for (const std::string& name : cushionModelNames())
    for (const double scale : {1e-6, 1e-9, 1e-12})
    {
      const PhysicsParams<double> p = papersBall();
      const auto model = makeCushionModel<double>(name);
      Ball<double> unit = incoming(1.0, 35 * kDeg, 1.5, -0.7, p), small = incoming(scale, 35 * kDeg, 1.5, -0.7, p);
      model->resolve(unit, kIntoPlay, p);
      model->resolve(small, kIntoPlay, p);
      EXPECT_NEAR((small.v / scale - unit.v).norm(), 0, 1e-6) << name << " at " << scale;
      EXPECT_NEAR(p.ball_radius * (small.w / scale - unit.w).norm(), 0, 1e-6) << name << " at " << scale;
    }
}

TEST(MathavanCushion, FrictionsCoupledTooStronglyToSweepAreStillCoulombs)
{
  // A big ball (R = 0.24 m) with a nose at 1.36 R, mu = 2.15 at the nose and 0.99 on the cloth,
  // from the soak (seed 8): the nose's sticking friction loads the cloth's sliding one so hard
  // that sweeping the two in turn never settles. The impact must still be Coulomb's: within
  // its tolerance of the long-double impact at 1e-10, and the same at every speed scale.
  PhysicsParams<double> p = papersBall();
  p.ball_radius = 0.24142832520196955;
  p.ball_mass = 0.170097;
  p.cushion_height = 0.32821915014929853;
  p.e_cushion_work = 0.00025078668085709485;
  p.mu_cushion = 2.1540814331818101;
  p.mu_slide = 0.99199058548346786;
  p.cushion_impact_tolerance = 1e-5;
  PhysicsParams<long double> pl = p.cast<long double>();
  pl.cushion_impact_tolerance = 1e-10;
  const Vec3<double> v(0.2014, -0.4331, 0), w(1.79, 0.834, 0.25), into_play(0, 1, 0);
  Ball<long double> reference;
  reference.r = Vec3<long double>(0, 0, pl.ball_radius);
  reference.v = v.cast<long double>();
  reference.w = w.cast<long double>();
  makeCushionModel<long double>("mathavan2010")->resolve(reference, into_play.cast<long double>(), pl);
  const double speed_scale = v.norm() + p.ball_radius * w.norm();
  for (const double scale : {1.0, 1e-12})
  {
    Ball<double> b;
    b.r = Vec3<double>(0, 0, p.ball_radius);
    b.v = scale * v;
    b.w = scale * w;
    makeCushionModel<double>("mathavan2010")->resolve(b, into_play, p);
    EXPECT_LT((b.v / scale - reference.v.cast<double>()).norm(), 2 * p.cushion_impact_tolerance * speed_scale);
    EXPECT_LT(p.ball_radius * (b.w / scale - reference.w.cast<double>()).norm(),
              2 * p.cushion_impact_tolerance * speed_scale);
    EXPECT_GE(b.v.dot(into_play) / scale, -1e-15);  // it does not close on the cushion beyond rounding
  }
}

TEST(MathavanCushion, StronglyCoupledFrictionsScaleDownToRounding)
{
  // Frictions coupled too strongly to sweep (mu_cushion 2.2 at a nose at 1.28 R, mu_slide 4.1 on
  // the cloth; soak seed 8, shot 5521) are solved contact by contact, which must judge a slip's
  // direction against the impact's own speed scale as the sweeps do: a ball pressed on a cushion
  // at a few zeroSpeed() (a held ball's rounding) rebounds as it does at 1 m/s, scaled. While the
  // solve measured slips against zeroSpeed() itself, the two disagreed at every step and such an
  // impact took 16384 steps (0.3 s) to a different rebound.
  PhysicsParams<double> p;
  p.ball_radius = 0.0593495;
  p.cushion_height = 0.0759674;
  p.mu_cushion = 2.15701;
  p.mu_slide = 4.09287;
  p.e_cushion_work = 0.98;
  const Vec3<double> v(0.127, -0.999, 0), w(-3.43, 5.82, -1.23), into_play(0.45883612734398488, 0.88852091041459147, 0);
  const auto reboundAt = [&](double scale) {
    Ball<double> b;
    b.r = Vec3<double>(0, 0, p.ball_radius);
    b.v = scale * v;
    b.w = scale * w;
    makeCushionModel<double>("mathavan2010")->resolve(b, into_play, p);
    return std::make_pair(Vec3<double>(b.v / scale), Vec3<double>(b.w / scale));
  };
  const auto unit = reboundAt(1);
  const double speed_scale = v.norm() + p.ball_radius * w.norm();
  for (const double scale : {1e-12, 3e-14})
  {
    const auto small = reboundAt(scale);
    EXPECT_LT((small.first - unit.first).norm(), p.cushion_impact_tolerance * speed_scale) << scale;
    EXPECT_LT(p.ball_radius * (small.second - unit.second).norm(), p.cushion_impact_tolerance * speed_scale) << scale;
  }
}

TEST(CushionModels, AMirroredShotReboundsMirrored)
{
  // Reflecting the shot in the plane through the cushion's normal (x -> -x) reflects the
  // rebound; spin is a pseudovector, so w_x keeps its sign and w_y, w_z change theirs.
  const auto mirrored = [](Vec3<double> v) { return Vec3<double>(-v.x(), v.y(), v.z()); };
  const auto mirroredSpin = [](Vec3<double> w) { return Vec3<double>(w.x(), -w.y(), -w.z()); };
  for (const std::string& name : cushionModelNames())
  {
    const PhysicsParams<double> p = papersBall();
    const auto model = makeCushionModel<double>(name);
    Ball<double> a = incoming(1.1, 50 * kDeg, 0.6, 1.3, p), b = a;
    b.v = mirrored(a.v);
    b.w = mirroredSpin(a.w);
    model->resolve(a, kIntoPlay, p);
    model->resolve(b, kIntoPlay, p);
    EXPECT_NEAR((b.v - mirrored(a.v)).norm(), 0, 1e-12) << name;
    EXPECT_NEAR((b.w - mirroredSpin(a.w)).norm(), 0, 1e-9) << name;
  }
}
