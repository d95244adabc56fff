// The coefficients' ranges (issue 15): every value out of its range is refused naming the field,
// the value and the range, and cushion_height lies strictly between R and 2R.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cue_sim/physics/engine.hpp"

using namespace cue_sim::physics;

namespace
{
std::string text(double x)
{
  std::ostringstream out;
  out << x;
  return out.str();
}
}  // namespace

TEST(PhysicsParams, TheDefaultsAreValid)
{
  EXPECT_EQ(PhysicsParams<double>().validate(), "");
  EXPECT_EQ(PhysicsParams<long double>().validate(), "");
}

TEST(PhysicsParams, EveryRefusalNamesTheFieldTheValueAndTheRange)
{
  for (const ParamField& field : physicsParamFields())
  {
    if (std::isnan(field.min))
      continue;  // cushion_height: below
    for (const double bad : {field.min - 1 - std::abs(field.min), field.max * 2 + 1, double(NAN), double(INFINITY)})
    {
      PhysicsParams<double> p;
      p.*field.member = bad;
      const std::string why = p.validate();
      EXPECT_EQ(why.rfind(field.name, 0), 0u) << why;
      EXPECT_NE(why.find(text(bad)), std::string::npos) << why;
      EXPECT_NE(why.find("[" + text(field.min) + ", " + text(field.max) + "]"), std::string::npos) << why;
    }
    for (const double good : {field.min, field.max})
    {
      PhysicsParams<double> p;
      p.*field.member = good;
      if (field.member == &PhysicsParams<double>::ball_radius)
        p.cushion_height = 1.28 * good;  // stays between R and 2R
      EXPECT_EQ(p.validate(), "") << field.name << " = " << good;
    }
  }
}

TEST(PhysicsParams, TheCushionNoseLiesStrictlyBetweenTheBallsEquatorAndItsTop)
{
  PhysicsParams<double> p;
  const double R = p.ball_radius;
  for (const double bad : {0.0, R, 2 * R, 3 * R, -R, double(NAN)})
  {
    p.cushion_height = bad;
    const std::string why = p.validate();
    EXPECT_EQ(why.rfind("cushion_height", 0), 0u) << why;
    EXPECT_NE(why.find(text(bad)), std::string::npos) << why;
    EXPECT_NE(why.find("(R, 2R) = (" + text(R) + ", " + text(2 * R) + ")"), std::string::npos) << why;
    EXPECT_NE(why.find("equator"), std::string::npos) << why;  // the reason
    EXPECT_THROW(Engine<double>(std::make_shared<const TableModel>(TableModel::carom("carom", 2.84, 1.42)), p),
                 std::invalid_argument);
  }
  for (const double good : {R * (1 + 1e-9), 1.28 * R, 2 * R * (1 - 1e-9)})
  {
    p.cushion_height = good;
    EXPECT_EQ(p.validate(), "") << good;
  }
}
