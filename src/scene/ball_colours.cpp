#include "cue_sim/scene/ball_colours.hpp"

#include <array>

namespace cue_sim
{
BallSet ballSetFor(bool table_has_pockets)
{
  return table_has_pockets ? BallSet::Pool : BallSet::Carom;
}

BallSet ballSetFor(const physics::TableModel& table)
{
  BallSet set;
  if (table.balls() && ballSetNamed(table.balls()->set, set))
    return set;
  return ballSetFor(!table.pockets().empty());
}

static_assert(static_cast<std::size_t>(BallSet::Snooker) + 1 == physics::kBallSetNames.size(),
              "BallSet follows physics::kBallSetNames, one for one");

const char* ballSetName(BallSet set)
{
  return physics::kBallSetNames[static_cast<std::size_t>(set)];
}

bool ballSetNamed(const std::string& name, BallSet& set)
{
  for (std::size_t i = 0; i < physics::kBallSetNames.size(); ++i)
    if (name == physics::kBallSetNames[i])
    {
      set = static_cast<BallSet>(i);
      return true;
    }
  return false;
}

Rgb ballColour(int id, BallSet set)
{
  if (set == BallSet::Snooker)
  {
    // The cue ball, the reds (1-15), then the colours by value (16-21).
    static const std::array<Rgb, 8> snooker = {{
        {0.97f, 0.97f, 0.93f},  // cue ball
        {0.8f, 0.04f, 0.04f},   // red
        {1.0f, 0.85f, 0.05f},   // yellow
        {0.0f, 0.3f, 0.12f},    // green: darker than the cloth
        {0.42f, 0.22f, 0.08f},  // brown
        {0.05f, 0.25f, 0.85f},  // blue
        {1.0f, 0.5f, 0.65f},    // pink
        {0.05f, 0.05f, 0.05f},  // black
    }};
    const int index = id >= 1 && id <= 15 ? 1 : id >= 16 && id <= 21 ? id - 14 : 0;
    return snooker[static_cast<std::size_t>(index)];
  }
  if (set == BallSet::Carom)
  {
    // The yellow and the red of a carom set, as pool's 1 and 3.
    static const std::array<Rgb, 3> carom = {{{0.97f, 0.97f, 0.93f}, {1.0f, 0.82f, 0.0f}, {0.85f, 0.05f, 0.05f}}};
    return carom[id >= 0 && id <= 2 ? id : 0];
  }
  static const std::array<Rgb, 9> colours = {{
      {0.97f, 0.97f, 0.93f},  // cue ball: off-white
      {1.0f, 0.82f, 0.0f},    // yellow
      {0.0f, 0.2f, 0.8f},     // blue
      {0.85f, 0.05f, 0.05f},  // red
      {0.4f, 0.1f, 0.55f},    // purple
      {1.0f, 0.45f, 0.0f},    // orange
      {0.0f, 0.3f, 0.12f},    // green: darker than the cloth, as on real balls (and told apart from it by a camera)
      {0.5f, 0.08f, 0.1f},    // maroon
      {0.05f, 0.05f, 0.05f},  // black
  }};
  if (isStriped(id))
    return colours[id - 8];
  return colours[id >= 0 && id <= 8 ? id : 0];
}

bool isStriped(int id, BallSet set)
{
  return set == BallSet::Pool && id >= 9 && id <= 15;
}

bool isNumbered(int id, BallSet set)
{
  return set == BallSet::Pool && id > 0;
}

Rgb numberColour(int id)
{
  // Seen from above, a stripe's number sits on its white cap.
  const Rgb under = isStriped(id) ? ballColour(0) : ballColour(id);
  // Relative luminance (ITU-R BT.601 weights); above one half, dark text reads better.
  const float luminance = 0.299f * under.r + 0.587f * under.g + 0.114f * under.b;
  return luminance > 0.5f ? Rgb{0.0f, 0.0f, 0.0f} : Rgb{1.0f, 1.0f, 1.0f};
}

}  // namespace cue_sim
