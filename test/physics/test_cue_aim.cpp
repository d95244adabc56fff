// From a cue's pose to the strike: the ball it meets, phi, theta, a and b with the README's
// signs, and refusals that say what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cue_sim/physics/cue_aim.hpp"
#include "resting_ball.hpp"

using namespace cue_sim::physics;

namespace
{
const PhysicsParams<double> kParams;
const double R = kParams.ball_radius;

CueStrike<double> strikeOf(double phi, double theta, double a, double b)
{
  CueStrike<double> s;
  s.speed = 2;
  s.phi = phi;
  s.theta = theta;
  s.a = a;
  s.b = b;
  return s;
}
}  // namespace

TEST(CueAim, ALevelCueThroughTheCentreIsACentreHitAlongItsAxis)
{
  const std::vector<Ball<double>> balls = {restingBall(0, 0.1, 0.2)};
  CueStick cue;
  cue.tip = Vec3<double>(0.1 - R - 0.05, 0.2, R);
  cue.axis = Vec3<double>(3, 0, 0);
  CueAim aim;
  ASSERT_EQ(aimCue(balls, kParams, cue, 2.5, aim), "");
  EXPECT_EQ(aim.ball_id, 0);
  EXPECT_EQ(aim.strike.speed, 2.5);
  EXPECT_EQ(aim.strike.phi, 0);
  EXPECT_EQ(aim.strike.theta, 0);
  EXPECT_NEAR(aim.strike.a, 0, 1e-15);
  EXPECT_NEAR(aim.strike.b, 0, 1e-15);
  EXPECT_NEAR(aim.travel, 0.05, 1e-15);
}

TEST(CueAim, AnAxisRightOfCentreIsRightEnglishAndAboveIsFollow)
{
  // Shooting along +x, the shooter's right is -y.
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0)};
  CueStick cue;
  cue.axis = Vec3<double>(1, 0, 0);
  cue.tip = Vec3<double>(-0.1, -0.01, R);
  CueAim aim;
  ASSERT_EQ(aimCue(balls, kParams, cue, 2, aim), "");
  EXPECT_NEAR(aim.strike.a, contactOffset(0.01 / R, kParams), 1e-12);
  EXPECT_GT(aim.strike.a, 0);
  EXPECT_NEAR(aim.strike.b, 0, 1e-15);
  cue.tip = Vec3<double>(-0.1, 0, R + 0.008);
  ASSERT_EQ(aimCue(balls, kParams, cue, 2, aim), "");
  EXPECT_NEAR(aim.strike.b, contactOffset(0.008 / R, kParams), 1e-12);
  EXPECT_GT(aim.strike.b, 0);
  EXPECT_NEAR(aim.strike.a, 0, 1e-15);
}

// aimCue and cueStickFor invert each other.
TEST(CueAim, RecoversEveryStrikeFromTheCueThatMakesIt)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  const Ball<double> ball = restingBall(4, 0.3, -0.1);
  for (int i = 0; i < 500; ++i)
  {
    const double radius = 0.49 * std::sqrt(unit(random)), angle = 2 * M_PI * unit(random);
    const CueStrike<double> want =
        strikeOf(M_PI * (2 * unit(random) - 1), 1.5 * unit(random), radius * std::cos(angle), radius * std::sin(angle));
    CueAim aim;
    ASSERT_EQ(aimCue({ball}, kParams, cueStickFor(ball, want, kParams, 0.02), 2, aim), "") << "strike " << i;
    EXPECT_EQ(aim.ball_id, 4);
    EXPECT_NEAR(aim.strike.phi, want.phi, 1e-12) << "strike " << i;
    EXPECT_NEAR(aim.strike.theta, want.theta, 1e-12) << "strike " << i;
    EXPECT_NEAR(aim.strike.a, want.a, 1e-12) << "strike " << i;
    EXPECT_NEAR(aim.strike.b, want.b, 1e-12) << "strike " << i;
    EXPECT_NEAR(aim.travel, 0.02, 1e-12) << "strike " << i;
  }
}

TEST(CueAim, TheFirstBallAlongTheStrokeIsTheOneStruck)
{
  const std::vector<Ball<double>> balls = {restingBall(0, 0.3, 0), restingBall(1, 0.0, 0)};
  CueStick cue;
  cue.tip = Vec3<double>(-0.2, 0, R);
  cue.axis = Vec3<double>(1, 0, 0);
  CueAim aim;
  ASSERT_EQ(aimCue(balls, kParams, cue, 2, aim), "");
  EXPECT_EQ(aim.ball_id, 1);
  EXPECT_NEAR(aim.travel, 0.2 - R, 1e-15);
}

TEST(CueAim, RefusalsSayWhatIsWrong)
{
  Ball<double> pocketed = restingBall(9, 0, 0);
  pocketed.motion = Motion::Pocketed;
  const std::vector<Ball<double>> balls = {restingBall(0, 0, 0), restingBall(2, -0.3, 0.0), pocketed};
  CueAim aim;
  const auto refusal = [&](Vec3<double> tip, Vec3<double> axis) {
    CueStick cue;
    cue.tip = tip;
    cue.axis = axis;
    return aimCue(balls, kParams, cue, 2, aim);
  };
  // Beside the ball.
  EXPECT_NE(refusal({-0.1, 0.1, R}, {1, 0, 0}).find("meets no ball"), std::string::npos);
  // The axis inside the ball, but too far out for the tip: a miscue.
  EXPECT_NE(refusal({0.1, 0.8 * R, R}, {-1, 0, 0}).find("miscue"), std::string::npos);
  // Only the rim of the shaft reaches the ball.
  EXPECT_NE(refusal({0.1, R + 0.003, R}, {-1, 0, 0}).find("side of the cue's tip"), std::string::npos);
  // Ball 2 sits on the shaft behind the tip.
  EXPECT_NE(refusal({-0.1, 0, R}, {1, 0, 0}).find("shaft passes through ball 2"), std::string::npos);
  EXPECT_NE(refusal({0.2, 0, R}, {-1, 0, 0.1}).find("points upwards"), std::string::npos);
  EXPECT_NE(refusal({0.005, 0, R}, {1, 0, 0}).find("inside ball 0"), std::string::npos);
  EXPECT_NE(refusal({0.2, 0, R}, {0, 0, 0}).find("non-zero axis"), std::string::npos);
  // From the other side, ball 0 is met first and ball 2 is not in the way; the pocketed ball
  // at the same place as ball 0 is not there at all.
  EXPECT_EQ(refusal({0.2, 0, R}, {-1, 0, 0}), "");
  EXPECT_EQ(aim.ball_id, 0);
  EXPECT_NEAR(aim.strike.phi, M_PI, 1e-15);
  CueStick fast;
  fast.tip = Vec3<double>(0.2, 0, R);
  fast.axis = Vec3<double>(-1, 0, 0);
  EXPECT_NE(aimCue(balls, kParams, fast, 13, aim).find("speed"), std::string::npos);
}

TEST(CueAim, AnElevatedCueSpinsTheBallAboutThePointItMeets)
{
  // The cue's pose gives the contact point: its axis passes o from the centre (o perpendicular to
  // the axis u), and the curved tip meets the ball o / (1 + r_tip / R) from the centre on the face
  // seen along u. The strike aimCue answers must spin the ball as a push along u at that point
  // does: w parallel to (P - C) x u. A cue aimed at the centre, however steep, spins nothing.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 200; ++k)
  {
    const double theta = 1.4 * unit(random), phi = 6.28 * unit(random);
    const Vec3<double> u(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), -std::sin(theta));
    Vec3<double> o = Vec3<double>(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5) * R;
    o -= o.dot(u) * u;  // perpendicular to the axis
    if (k % 10 == 0)
      o.setZero();
    const Ball<double> ball = restingBall(0, 0, 0);
    CueStick cue;
    cue.axis = u;
    cue.tip = ball.r + o - u * (2 * R);
    CueAim aim;
    if (!aimCue({ball}, kParams, cue, 2.0, aim).empty())
      continue;  // a miscue
    const Vec3<double> face = o / (1 + kParams.cue_tip_radius / R);
    const Vec3<double> contact = face - std::sqrt(R * R - face.squaredNorm()) * u;
    Ball<double> struck = ball;
    applyCueStrike(struck, aim.strike, kParams);
    const Vec3<double> lever = contact.cross(u);
    if (lever.norm() < 1e-15)
    {
      // A centre hit: what spin is left comes from the rounding of the pose's offset (1e-16 R).
      EXPECT_LT(struck.w.norm(), 1e-12) << "a centre hit at theta " << theta;
      continue;
    }
    EXPECT_NEAR(struck.w.normalized().dot(lever.normalized()), 1, 1e-9) << "strike " << k;
  }
}
