// What each ball looks like, declared once for every picture of the table (rviz markers, the
// Python module's drawings): standard pool colours and which balls are striped.
#pragma once

namespace cue_sim
{
struct Rgb
{
  float r = 0, g = 0, b = 0;  ///< each in [0, 1]
};

/// Standard pool colours: 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green, 7 maroon,
/// 8 black; 9-15 are the stripes of 1-7; 0 (and any other id) is the white cue ball.
Rgb ballColour(int id);
/// Balls 9-15: a coloured band on a white ball.
bool isStriped(int id);
/// The colour a ball's number is written in to be read on it: black on light balls (the cue ball,
/// yellow, orange, and the white caps of the stripes), white on dark ones.
Rgb numberColour(int id);

}  // namespace cue_sim
