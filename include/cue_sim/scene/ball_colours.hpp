// What each ball looks like, declared once for every picture of the table (rviz markers, the
// camera, the Python module's drawings): standard pool colours and which balls are striped and
// numbered, or carom's three balls.
#pragma once

namespace cue_sim
{
struct Rgb
{
  float r = 0, g = 0, b = 0;  ///< each in [0, 1]
};

/// The balls a table is played with: pool's numbered set on a table with pockets, carom's three
/// on one without (0 the white, 1 the yellow, 2 the red; no numbers, no stripes).
enum class BallSet
{
  Pool,
  Carom,
};
BallSet ballSetFor(bool table_has_pockets);

/// Standard pool colours: 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon,
/// 8 black; 9-15 are the stripes of 1-7; 0 (and any other id) is the white cue ball. Carom: 0
/// white, 1 yellow, 2 red, any other white.
Rgb ballColour(int id, BallSet set = BallSet::Pool);
/// Pool's balls 9-15: a coloured band on a white ball.
bool isStriped(int id, BallSet set = BallSet::Pool);
/// Whether the ball carries its number: pool's object balls.
bool isNumbered(int id, BallSet set = BallSet::Pool);
/// The colour a ball's number is written in to be read on it: black on light balls (the cue ball,
/// yellow, orange, and the white caps of the stripes), white on dark ones.
Rgb numberColour(int id);

}  // namespace cue_sim
