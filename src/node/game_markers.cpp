#include "node/game_markers.hpp"

#include <cmath>
#include <sstream>

#include "cue_sim/game/referee.hpp"
#include "node/table_markers.hpp"

namespace cue_sim
{
namespace
{
using visualization_msgs::Marker;

/// Height of the markers drawn on the cloth [m]: above it, below a ball's equator.
constexpr double kOnCloth = 0.002;
/// From the cloth's edge to the middle of the text beside it [m]: its six lines clear the cushion.
constexpr double kTextGap = 0.42;
/// Radius of the ring drawn round a called pocket's centre [m], and its line's width.
constexpr double kCallRing = 0.08, kCallLine = 0.008;

/// Width of the line of a carom point's path [m].
constexpr double kPathLine = 0.006;

std::string statusText(const GameState& s)
{
  std::ostringstream text;
  const auto rules = game::makeRules(s.rules);
  text << game::rulesTitle(s.rules);
  if (s.target > 0)
    text << ", race to " << s.target;
  text << ", shot " << s.shots + 1;
  if (s.over)
    text << ": over, " << (s.winner >= 0 ? s.players[static_cast<std::size_t>(s.winner)] + " won" : "no winner");
  for (std::size_t i = 0; i < 2; ++i)
  {
    text << "\n" << (!s.over && s.turn == static_cast<int>(i) ? "> " : "   ") << s.players[i];
    if (rules->playsGroups())
      text << ", " << s.groups[i];
    if (s.target > 0)
      text << " (ball " << rules->cueBall(static_cast<int>(i)) << "): " << s.score[i]
           << (s.score[i] == 1 ? " point, " : " points, ") << s.innings[i]
           << (s.innings[i] == 1 ? " inning" : " innings");
    else if (rules->keepsScore())
      text << ": " << s.score[i] << (s.score[i] == 1 ? " point" : " points");
    else
      text << ", fouls " << s.consecutive_fouls[i];
  }
  if (!s.over)
  {
    if (s.shot_in_progress)
      text << "\nshot in play";
    else if (s.break_shot)
      text << "\nto break";
    if (!s.ball_in_hand.empty() && !s.shot_in_progress)
      text << "\nball in hand "
           << (s.ball_in_hand == "anywhere" ? "anywhere"
               : s.ball_in_hand == "in_d"   ? "in the D"
                                            : "behind the head string");
    if (s.free_ball && !s.shot_in_progress)
      text << "\nfree ball";
    else if (s.colour_next && !s.shot_in_progress)
      text << "\non: a colour";
    if (s.called_ball >= 0)
      text << "\ncalled " << s.called_ball << (s.called_pocket.empty() ? "" : " in " + s.called_pocket);
    if (s.push_out_called)
      text << ", push-out";
  }
  if (s.last_ruling.refereed)
    text << "\nlast: "
         << (s.last_ruling.foul
                 ? "foul" + (s.last_ruling.penalty > 0 ? ", " + std::to_string(s.last_ruling.penalty) + " away"
                                                       : std::string())
             : s.target > 0 && s.last_ruling.points > 0 ? std::string("point")
             : s.last_ruling.points > 0                 ? std::to_string(s.last_ruling.points) + " scored"
             : s.target > 0                             ? std::string("no point")
                                                        : std::string("legal"))
         << " (" << s.last_ruling.rule << ")";
  if (!s.before_shot.empty() && !s.shot_in_progress)
    text << "\nballs re-spotted before this shot";
  return text.str();
}
}  // namespace

visualization_msgs::MarkerArray gameMarkers(const GameState& state, const physics::TableModel& table,
                                            double cushion_height, const std::vector<Eigen::Vector2d>& point_path)
{
  visualization_msgs::MarkerArray array;
  Marker clear;
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);
  if (!state.active)
    return array;
  const std::string& frame = state.header.frame_id;

  Marker status = markerIn(frame, "game_status", 0, Marker::TEXT_VIEW_FACING);
  status.pose.position.x = table.clothCentre().x();
  status.pose.position.y = table.clothCentre().y() + table.clothWidth() / 2 + kTextGap;
  status.pose.position.z = 0.05;
  status.scale.z = 0.04;
  status.color = rgba(1.0f, 1.0f, 1.0f);
  status.text = statusText(state);
  array.markers.push_back(status);

  const bool in_hand = !state.ball_in_hand.empty() && !state.shot_in_progress && !state.over;
  if (in_hand)
  {
    Marker region = markerIn(frame, "ball_in_hand", 0, Marker::CUBE);
    region.pose.position.x = (state.place_min.x + state.place_max.x) / 2;
    region.pose.position.y = (state.place_min.y + state.place_max.y) / 2;
    region.pose.position.z = kOnCloth;
    region.scale.x = state.place_max.x - state.place_min.x;
    region.scale.y = state.place_max.y - state.place_min.y;
    region.scale.z = 0.001;
    region.color = rgba(1.0f, 1.0f, 1.0f, 0.18f);
    array.markers.push_back(region);
  }
  if (in_hand && state.ball_in_hand == "behind_head_string")
  {
    Marker line = markerIn(frame, "head_string", 0, Marker::LINE_LIST);
    line.scale.x = 0.004;
    line.color = rgba(1.0f, 1.0f, 1.0f, 0.8f);
    geometry_msgs::Point a, b;
    a.x = b.x = table.headStringX();
    a.y = table.clothCentre().y() - table.clothWidth() / 2;
    b.y = table.clothCentre().y() + table.clothWidth() / 2;
    a.z = b.z = kOnCloth;
    line.points = {a, b};
    array.markers.push_back(line);
  }
  if (point_path.size() > 1)
  {
    Marker path = markerIn(frame, "point_path", 0, Marker::LINE_STRIP);
    path.scale.x = kPathLine;
    path.color = rgba(0.2f, 0.9f, 1.0f, 0.9f);  // cyan: no ball's colour, and clear on the cloth
    for (const Eigen::Vector2d& p : point_path)
    {
      geometry_msgs::Point point;
      point.x = p.x();
      point.y = p.y();
      point.z = kOnCloth;
      path.points.push_back(point);
    }
    array.markers.push_back(path);
  }
  for (const auto& pocket : table.pockets())
    if (!state.over && pocket.name == state.called_pocket)
    {
      Marker ring = markerIn(frame, "called_pocket", 0, Marker::LINE_STRIP);
      ring.scale.x = kCallLine;
      ring.color = rgba(1.0f, 0.85f, 0.0f);
      for (int i = 0; i <= 36; ++i)
      {
        geometry_msgs::Point p;
        p.x = pocket.centre.x() + kCallRing * std::cos(i * M_PI / 18);
        p.y = pocket.centre.y() + kCallRing * std::sin(i * M_PI / 18);
        p.z = cushion_height + kOnCloth;  // over the jaws and rails round the pocket
        ring.points.push_back(p);
      }
      array.markers.push_back(ring);
    }
  return array;
}

}  // namespace cue_sim
