// Ball-ball models: the integrated impact on the cloth (Mathavan, Jackson and Parkin 2014)
// against the models it reduces to, bounds on what the cloth can do, its convergence and the
// invariants every ball-ball model keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

#include "cue_sim/physics/collision_models.hpp"
#include "cue_sim/physics/motion.hpp"

using namespace cue_sim::physics;

namespace
{
const double kDeg = M_PI / 180;

/// A cue ball at the origin moving along +x at `speed` with spin `w`, meeting an object ball at
/// rest at cut angle `cut` (the line of centres `cut` off the cue ball's travel).
template <typename S = double>
std::pair<Ball<S>, Ball<S>> cutShot(S cut, S speed, const std::common_type_t<Vec3<S>>& w, const PhysicsParams<S>& p)
{
  Ball<S> cue, object;
  cue.r = Vec3<S>(0, 0, p.ball_radius);
  object.r = cue.r + 2 * p.ball_radius * Vec3<S>(std::cos(cut), std::sin(cut), 0);
  cue.v = Vec3<S>(speed, 0, 0);
  cue.w = w;
  return {cue, object};
}

/// The rolling spin of a ball moving along +x at `speed`: w = z x v / R.
Vec3<double> rolling(double speed, const PhysicsParams<double>& p)
{
  return Vec3<double>(0, speed / p.ball_radius, 0);
}

double gap(const Ball<double>& a, const Ball<double>& b, const PhysicsParams<double>& p)
{
  return (a.v - b.v).norm() + p.ball_radius * (a.w - b.w).norm();
}

void resolveWith(const std::string& model, Ball<double>& a, Ball<double>& b, const PhysicsParams<double>& p)
{
  makeBallBallModel<double>(model)->resolve(a, b, p);
}
}  // namespace

TEST(MathavanBallBall, WithoutFrictionBetweenTheBallsItIsTheFrictionlessModel)
{
  // No friction between the balls presses neither into the cloth, so the cloth's friction has no
  // load: the normal impulse alone, with work-done restitution that is Newton's.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  PhysicsParams<double> p;
  p.mu_ball_a = p.mu_ball_b = 0;
  p.mu_slide = 0.3;
  for (int i = 0; i < 200; ++i)
  {
    auto [a, b] =
        cutShot(80 * kDeg * unit(rng), 3 + 2 * unit(rng), 100 * Vec3<double>(unit(rng), unit(rng), unit(rng)), p);
    b.v = Vec3<double>(unit(rng), unit(rng), 0);
    b.w = 100 * Vec3<double>(unit(rng), unit(rng), unit(rng));
    Ball<double> fa = a, fb = b;
    resolveWith("mathavan2014", a, b, p);
    resolveWith("frictionless", fa, fb, p);
    ASSERT_LT(gap(a, fa, p) + gap(b, fb, p), 1e-12) << i;
  }
}

TEST(MathavanBallBall, AHorizontalSlipIsTheFrictionalModelWhateverTheCloth)
{
  // Stun and side spin leave the balls' contact slipping horizontally: the friction between them
  // presses neither into the cloth, and the slip keeps its direction. That is the frictional
  // model's impulse, sliding throughout or stopped and held (fast and slow, full and thin), with
  // or without cloth friction.
  for (const double mu_slide : {0.0, 0.2})
    for (const double cut_deg : {0.0, 5.0, 20.0, 30.0, 45.0, 70.0, 85.0})
      for (const double speed : {0.3, 2.0, 8.0})
        for (const double side : {-40.0, 0.0, 25.0})
        {
          PhysicsParams<double> p;
          p.mu_slide = mu_slide;
          auto [a, b] = cutShot(cut_deg * kDeg, speed, Vec3<double>(0, 0, side), p);
          Ball<double> fa = a, fb = b;
          resolveWith("mathavan2014", a, b, p);
          resolveWith("frictional", fa, fb, p);
          EXPECT_LT(gap(a, fa, p) + gap(b, fb, p), 1e-12 * speed)
              << mu_slide << " " << cut_deg << " " << speed << " " << side;
        }
}

TEST(MathavanBallBall, WithoutClothFrictionAVerticalSlipSlidingThroughoutIsTheFrictionalModel)
{
  // Straight in with follow or draw the balls' contact slips vertically only, and fast enough
  // that mu_b (1 + e) m v / 2 cannot stop it: friction slides straight up or down throughout,
  // as in the frictional model's single impulse. The cloth then takes the vertical part.
  PhysicsParams<double> p;
  p.mu_slide = 0;
  for (const double top : {-2.0, -1.0, 1.0, 2.0})
  {
    auto [a, b] = cutShot(0.0, 2.0, top * rolling(2.0, p), p);
    Ball<double> fa = a, fb = b;
    resolveWith("mathavan2014", a, b, p);
    resolveWith("frictional", fa, fb, p);
    EXPECT_LT(gap(a, fa, p) + gap(b, fb, p), 1e-12) << top;
  }
}

TEST(MathavanBallBall, TheClothUnderThePressedBallTakesAtMostMuSlideOfItsLoad)
{
  // A rolling cue ball straight into an object ball: the balls' contact slips down on the cue
  // ball's side, so friction lifts the cue ball and presses the object ball into the cloth with
  // up to mu_b times the normal impulse P. The object ball slides off along the line, and the
  // cloth's friction under it, at most mu_slide times that load, is the only outside impulse:
  // the pair's momentum falls by it, backwards along the line, and it turns the object ball
  // forwards (more topspin than without cloth friction, the frictional model's impact).
  const PhysicsParams<double> p;
  for (const double speed : {0.5, 2.0, 6.0})
  {
    auto [a, b] = cutShot(0.0, speed, rolling(speed, p), p);
    Ball<double> fa = a, fb = b;
    const Vec3<double> momentum = p.ball_mass * (a.v + b.v);
    resolveWith("mathavan2014", a, b, p);
    resolveWith("frictional", fa, fb, p);
    const double mu_b = p.mu_ball_a + p.mu_ball_b * std::exp(-p.mu_ball_c * speed);
    // P: what the object ball's forward momentum took, the cloth's share added back, within 10 %.
    const double P = 1.1 * (1 + p.e_ball) * p.ball_mass / 2 * speed;
    const Vec3<double> cloth = p.ball_mass * (a.v + b.v) - momentum;
    EXPECT_LT(cloth.x(), 0) << speed;
    EXPECT_NEAR(cloth.y(), 0, 1e-15) << speed;
    EXPECT_LE(-cloth.x(), p.mu_slide * mu_b * P) << speed;
    EXPECT_GT(-cloth.x(), 0.1 * p.mu_slide * mu_b * P) << speed;
    EXPECT_GT(b.w.y(), fb.w.y()) << speed;
    EXPECT_LT(b.v.x(), fb.v.x()) << speed;
  }
}

TEST(MathavanBallBall, TheImpactConvergesAsTheToleranceFalls)
{
  // Spin shots whose slips turn in two dimensions, with the cloth loaded: each against the same
  // impact in long double at 1e-10.
  struct Case
  {
    double cut_deg, top, side;
  };
  for (const Case c : {Case{30, 1, 0}, Case{15, 1, 20}, Case{45, -1, -30}, Case{60, 2, 10}, Case{5, 0.3, 0}})
  {
    SCOPED_TRACE(std::to_string(c.cut_deg) + " deg, top " + std::to_string(c.top) + ", side " + std::to_string(c.side));
    PhysicsParams<long double> pl;
    pl.ball_impact_tolerance = 1e-10;
    const Vec3<long double> wl(0, c.top * 1.5 / pl.ball_radius, c.side);
    auto [ra, rb] = cutShot<long double>(c.cut_deg * kDeg, 1.5, wl, pl);
    makeBallBallModel<long double>("mathavan2014")->resolve(ra, rb, pl);
    const auto errorWith = [&](double tolerance) {
      PhysicsParams<double> p;
      p.ball_impact_tolerance = tolerance;
      auto [a, b] = cutShot(c.cut_deg * kDeg, 1.5, Vec3<double>(0, c.top * 1.5 / p.ball_radius, c.side), p);
      resolveWith("mathavan2014", a, b, p);
      return (a.v - ra.v.cast<double>()).norm() + (b.v - rb.v.cast<double>()).norm();
    };
    const double coarse = errorWith(1e-5), fine = errorWith(1e-9);
    EXPECT_LT(fine, coarse / 10 + 1e-12);
    EXPECT_LT(fine, 1e-6);
  }
}

TEST(MathavanBallBall, RollingThrowsLessThanStun)
{
  // Alciatore TP A-14: follow or draw leaves the balls' contact slipping fast in the vertical,
  // so friction slides there and the sideways throw of a cut shot falls well below a stun
  // shot's at the same cut and speed.
  const PhysicsParams<double> p;
  for (const double cut_deg : {15.0, 30.0, 45.0})
  {
    const double cut = cut_deg * kDeg;
    auto [sa, sb] = cutShot(cut, 1.0, Vec3<double>::Zero(), p);
    auto [ra, rb] = cutShot(cut, 1.0, rolling(1.0, p), p);
    resolveWith("mathavan2014", sa, sb, p);
    resolveWith("mathavan2014", ra, rb, p);
    const double stun = cut - std::atan2(sb.v.y(), sb.v.x()), roll = cut - std::atan2(rb.v.y(), rb.v.x());
    EXPECT_GT(stun, 1.0 * kDeg) << cut_deg;
    EXPECT_GT(roll, 0.0) << cut_deg;
    EXPECT_LT(roll, 0.7 * stun) << cut_deg;
  }
}

TEST(BallBallModels, KeepMomentumNeverGainEnergyPartAndStayOnTheCloth)
{
  // Every registered ball-ball model, random balls and coefficients: the balls leave level and
  // parting, with no more kinetic energy than they came with. Momentum along the cloth is kept
  // but for what the cloth's friction takes: at most mu_slide times the balls' vertical friction.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0, 1), symmetric(-1, 1);
  for (const std::string& name : ballBallModelNames())
  {
    const auto model = makeBallBallModel<double>(name);
    for (int i = 0; i < 3000; ++i)
    {
      PhysicsParams<double> p;
      p.e_ball = unit(rng);
      p.mu_ball_a = 0.5 * unit(rng);
      p.mu_ball_b = 0.5 * unit(rng);
      p.mu_slide = 2 * unit(rng);
      p.ball_impact_tolerance = std::pow(10.0, -9 + 7 * unit(rng));
      auto [a, b] = cutShot(std::asin(symmetric(rng)), 4 * unit(rng),
                            200 * Vec3<double>(symmetric(rng), symmetric(rng), symmetric(rng)), p);
      b.v = 2 * Vec3<double>(symmetric(rng), symmetric(rng), 0);
      b.w = 200 * Vec3<double>(symmetric(rng), symmetric(rng), symmetric(rng));
      const Vec3<double> n = (b.r - a.r).normalized();
      const double closing = (a.v - b.v).dot(n);
      const double energy = kineticEnergy(a, p) + kineticEnergy(b, p);
      const Vec3<double> momentum = a.v + b.v;
      model->resolve(a, b, p);
      SCOPED_TRACE(name + " #" + std::to_string(i));
      ASSERT_TRUE(a.v.allFinite() && a.w.allFinite() && b.v.allFinite() && b.w.allFinite());
      ASSERT_LE(kineticEnergy(a, p) + kineticEnergy(b, p), energy * (1 + 1e-12) + 1e-15);
      ASSERT_EQ(a.v.z(), 0.0);
      ASSERT_EQ(b.v.z(), 0.0);
      if (closing > 0)
      {
        ASSERT_GE((b.v - a.v).dot(n), -1e-9 * closing);
        // P is at most (1 + e) m closing / 2 times 16 when jammed; the balls' friction mu_b P.
        const double mu_b = p.mu_ball_a + p.mu_ball_b;
        ASSERT_LE((a.v + b.v - momentum).norm(), p.mu_slide * mu_b * 16 * (1 + p.e_ball) * closing + 1e-12);
      }
    }
  }
}
