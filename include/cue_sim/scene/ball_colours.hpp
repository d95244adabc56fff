// What each ball looks like, declared once for every picture of the table (rviz markers, the
// camera, the Python module's drawings): standard pool colours and which balls are striped and
// numbered, carom's three balls, or snooker's reds and colours.
#pragma once

#include <string>

#include "cue_sim/physics/table_model.hpp"

namespace cue_sim
{
struct Rgb
{
  float r = 0, g = 0, b = 0;  ///< each in [0, 1]
};

/// The balls a table is played with: pool's numbered set; carom's three (0 the white, 1 the
/// yellow, 2 the red); snooker's (0 the cue ball, 1-15 the reds, 16 yellow, 17 green, 18 brown,
/// 19 blue, 20 pink, 21 black). Carom and snooker balls carry no numbers or stripes.
/// In the order of physics::kBallSetNames, which names them.
enum class BallSet
{
  Pool,
  Carom,
  Snooker,
};
/// Pool's set on a table with pockets, carom's on one without.
BallSet ballSetFor(bool table_has_pockets);
/// The set the table's description names (its `balls` link, TableBalls::set), else by its pockets.
BallSet ballSetFor(const physics::TableModel& table);
/// Its name in physics::kBallSetNames: "pool", "carom", "snooker".
const char* ballSetName(BallSet set);
/// The set of that name; false for none.
bool ballSetNamed(const std::string& name, BallSet& set);

/// Standard pool colours: 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon,
/// 8 black; 9-15 are the stripes of 1-7; 0 (and any other id) is the white cue ball. Carom: 0
/// white, 1 yellow, 2 red, any other white. Snooker: as the set says; any other id white.
Rgb ballColour(int id, BallSet set = BallSet::Pool);
/// Pool's balls 9-15: a coloured band on a white ball.
bool isStriped(int id, BallSet set = BallSet::Pool);
/// Whether the ball carries its number: pool's object balls.
bool isNumbered(int id, BallSet set = BallSet::Pool);
/// The colour a ball's number is written in to be read on it: black on light balls (the cue ball,
/// yellow, orange, and the white caps of the stripes), white on dark ones.
Rgb numberColour(int id);

}  // namespace cue_sim
