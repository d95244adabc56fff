#include "cue_sim/physics/rack.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "cue_sim/physics/snooker_markings.hpp"

namespace cue_sim
{
namespace physics
{
std::vector<std::string> rackNames()
{
  return {"eight", "nine", "ten", "carom", "snooker", "empty"};
}

std::string rackNamesText()
{
  std::string text;
  for (const std::string& name : rackNames())
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

namespace
{
/// [m] From the head spot to either starting spot along the head string, on a match carom table
/// (UMB World Rules, Art. 13: 18.2 cm on the 2.84 m table).
constexpr double kCaromStartingSpotOffset = 0.182;

template <typename S>
Ball<S> restingBall(int id, double x, double y, S radius)
{
  Ball<S> b;
  b.id = id;
  b.r = Vec3<S>(S(x), S(y), radius);
  return b;
}
}  // namespace

template <typename S>
TableState<S> rackLayout(const std::string& name, const TableModel& table, S ball_radius, const RackOptions& options)
{
  // Rows of ball numbers from the apex back. Eight-ball: the 8 in the middle of the third row,
  // a solid (6) and a stripe (12) in the back corners. Nine-ball: a diamond, 1 at the apex.
  // Ten-ball (WPA 9.2): a triangle of four rows, 1 at the apex, the 10 in the middle of the third
  // row, and the 2 and 3 in the back corners, as tournaments that fix them ask.
  static const std::vector<std::vector<int>> eight_rows = {{1}, {11, 5}, {2, 8, 10}, {9, 7, 14, 4}, {6, 15, 13, 3, 12}};
  static const std::vector<std::vector<int>> nine_rows = {{1}, {2, 3}, {4, 9, 5}, {6, 7}, {8}};
  static const std::vector<std::vector<int>> ten_rows = {{1}, {6, 4}, {7, 10, 5}, {2, 8, 9, 3}};
  // Snooker (WPBSA Section 3, 2): the 15 reds (1-15) in a triangle of five rows.
  static const std::vector<std::vector<int>> snooker_rows = {
      {1}, {2, 3}, {4, 5, 6}, {7, 8, 9, 10}, {11, 12, 13, 14, 15}};
  const std::vector<std::vector<int>>* rows = nullptr;
  if (name == "eight")
    rows = &eight_rows;
  else if (name == "nine")
    rows = &nine_rows;
  else if (name == "ten")
    rows = &ten_rows;
  else if (name == "snooker")
    rows = &snooker_rows;
  else if (name != "empty" && name != "carom")
    throw std::invalid_argument("unknown rack '" + name + "' (known: " + rackNamesText() + ")");

  Eigen::Vector2d head = table.headSpot(), foot = table.footSpot();
  TableState<S> state;
  if (name == "carom")
  {
    // The starting position (UMB Art. 23): the red (2) on the top spot, the other cue ball (1)
    // on the bottom spot, and the breaker's (0) on a starting spot beside it.
    state.balls.push_back(restingBall<S>(0, head.x(), head.y() + kCaromStartingSpotOffset, ball_radius));
    state.balls.push_back(restingBall<S>(1, head.x(), head.y(), ball_radius));
    state.balls.push_back(restingBall<S>(2, foot.x(), foot.y(), ball_radius));
    return state;
  }
  const double spacing = 2 * static_cast<double>(ball_radius) + options.gap;
  if (name == "snooker")
  {
    // The colours (16 yellow to 21 black) on their spots, the cue ball in the D on the baulk line
    // midway between the yellow and brown spots, and the reds' apex as near the pink as the gap
    // allows, on the long string behind it (WPBSA Section 3, 2).
    const SnookerMarkings m = snookerMarkings(table);
    head = (m.spotOf(SnookerColour::Yellow) + m.spotOf(SnookerColour::Brown)) / 2;
    foot = m.spotOf(SnookerColour::Pink) + Eigen::Vector2d(spacing, 0);
    for (int k = 0; k < 6; ++k)
      state.balls.push_back(restingBall<S>(16 + k, m.spots[static_cast<std::size_t>(k)].x(),
                                           m.spots[static_cast<std::size_t>(k)].y(), ball_radius));
  }
  state.balls.insert(state.balls.begin(), restingBall<S>(0, head.x(), head.y(), ball_radius));
  if (!rows)
    return state;
  if (!(options.jitter >= 0 && options.jitter <= options.gap / 2))
    throw std::invalid_argument("rack jitter must be in [0, gap / 2] so that no balls overlap");
  const double row_step = spacing * std::sqrt(3.0) / 2;
  // std::mt19937 and the arithmetic below are fully specified, so a seed gives the same rack
  // everywhere (std:: distributions are not, and are not used).
  std::mt19937 random(options.seed);
  const auto unit = [&] { return static_cast<double>(random()) / 4294967296.0; };
  for (std::size_t k = 0; k < rows->size(); ++k)
  {
    const auto& row = (*rows)[k];
    for (std::size_t j = 0; j < row.size(); ++j)
    {
      double x = foot.x() + k * row_step;
      double y = foot.y() + (static_cast<double>(j) - (row.size() - 1) / 2.0) * spacing;
      if (options.jitter > 0 && !(k == 0 && j == 0))  // the apex stays on the foot spot
      {
        double dx, dy;  // uniform in the disc of radius jitter, by rejection (no libm)
        do
        {
          dx = (2 * unit() - 1) * options.jitter;
          dy = (2 * unit() - 1) * options.jitter;
        } while (dx * dx + dy * dy > options.jitter * options.jitter);
        x += dx;
        y += dy;
      }
      state.balls.push_back(restingBall<S>(row[j], x, y, ball_radius));
    }
  }
  if (name == "snooker")  // by id, as the colours came first
    std::sort(state.balls.begin(), state.balls.end(), [](const Ball<S>& a, const Ball<S>& b) { return a.id < b.id; });
  return state;
}

template TableState<double> rackLayout(const std::string&, const TableModel&, double, const RackOptions&);
template TableState<long double> rackLayout(const std::string&, const TableModel&, long double, const RackOptions&);

}  // namespace physics
}  // namespace cue_sim
