// Ball colours: the standard set, and numbers that can be read on every ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cue_sim/scene/ball_colours.hpp"

namespace
{
using cue_sim::Rgb;

/// WCAG 2 relative luminance of an sRGB colour.
double luminance(const Rgb& c)
{
  const auto linear = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

/// WCAG 2 contrast ratio, from 1 (none) to 21 (black on white).
double contrast(const Rgb& a, const Rgb& b)
{
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}
}  // namespace

TEST(BallColours, StripesShareTheirSolidsColoursOnAWhiteBall)
{
  for (int id = 9; id <= 15; ++id)
  {
    EXPECT_TRUE(cue_sim::isStriped(id));
    const Rgb stripe = cue_sim::ballColour(id), solid = cue_sim::ballColour(id - 8);
    EXPECT_EQ(stripe.r, solid.r);
    EXPECT_EQ(stripe.g, solid.g);
    EXPECT_EQ(stripe.b, solid.b);
  }
  for (int id = 0; id <= 8; ++id)
    EXPECT_FALSE(cue_sim::isStriped(id));
  EXPECT_GT(luminance(cue_sim::ballColour(0)), 0.8) << "the cue ball is white";
  EXPECT_LT(luminance(cue_sim::ballColour(8)), 0.01) << "the 8 is black";
}

TEST(BallColours, EveryNumberReadsOnItsBall)
{
  // A number sits on the ball's colour, or on a stripe's white cap; WCAG asks 3:1 of large text.
  for (int id = 0; id <= 15; ++id)
  {
    const Rgb under = cue_sim::isStriped(id) ? cue_sim::ballColour(0) : cue_sim::ballColour(id);
    EXPECT_GE(contrast(cue_sim::numberColour(id), under), 3.0) << "ball " << id;
  }
}

// Snooker's balls (issue 34): every red alike, six colours each of its own, nothing numbered or
// striped, and each told apart from the cloth and from every other colour.
TEST(BallColours, SnookersRedsAreAlikeAndItsColoursAllDiffer)
{
  using cue_sim::BallSet;
  const auto same = [](const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; };
  for (int red = 2; red <= 15; ++red)
    EXPECT_TRUE(same(cue_sim::ballColour(red, BallSet::Snooker), cue_sim::ballColour(1, BallSet::Snooker)));
  const Rgb cloth{0.05f, 0.45f, 0.2f};  // urdf/'s cloth
  for (int a = 0; a <= 21; ++a)
  {
    EXPECT_FALSE(cue_sim::isNumbered(a, BallSet::Snooker)) << a;
    EXPECT_FALSE(cue_sim::isStriped(a, BallSet::Snooker)) << a;
    // Told apart from the cloth by colour (red and green are near in luminance): as far in RGB
    // as pool's green ball, the nearest of pool's, is.
    const Rgb c = cue_sim::ballColour(a, BallSet::Snooker);
    EXPECT_GT(std::hypot(c.r - cloth.r, c.g - cloth.g, c.b - cloth.b), 0.17) << a << " against the cloth";
    if (a != 0 && a != 1 && a < 16)
      continue;  // the other reds are the 1's
    for (int b = std::max(a + 1, 16); b <= 21; ++b)
    {
      EXPECT_FALSE(same(cue_sim::ballColour(a, BallSet::Snooker), cue_sim::ballColour(b, BallSet::Snooker)))
          << a << " and " << b;
    }
  }
  EXPECT_LT(luminance(cue_sim::ballColour(21, BallSet::Snooker)), 0.01) << "the black";
  EXPECT_GT(luminance(cue_sim::ballColour(0, BallSet::Snooker)), 0.8) << "the cue ball is white";
  BallSet set;
  ASSERT_TRUE(cue_sim::ballSetNamed("snooker", set));
  EXPECT_EQ(set, BallSet::Snooker);
  EXPECT_FALSE(cue_sim::ballSetNamed("bagatelle", set));
}
