#include "cue_sim/scene/shot_report.hpp"

namespace cue_sim
{
using nlohmann::json;
using namespace physics;

namespace
{
json vec(const Vec3<double>& v)
{
  return json::array({v.x(), v.y(), v.z()});
}

json eventJson(const TableModel& table, const Event<double>& e)
{
  json j = {{"t", e.time}, {"kind", eventKindName(e.kind)}, {"ball", e.ball}};
  if (e.other >= 0)
    j["other"] = e.other;
  if (e.kind == EventKind::BallCushion)
    j["cushion"] = table.segments()[e.obstacle].name;
  if (e.kind == EventKind::BallCircle)
    j["cushion"] = table.circles()[e.obstacle].name;
  if (e.kind == EventKind::Pocketed)
    j["pocket"] = table.pockets()[e.obstacle].name;
  return j;
}
}  // namespace

json shotReport(const Engine<double>& engine, const TableState<double>& final_state,
                const std::vector<Event<double>>& events, bool at_rest)
{
  json report;
  report["table"] = engine.table().name();
  report["models"] = {{"ball_ball", engine.models().ball_ball}, {"cushion", engine.models().cushion}};
  report["events"] = json::array();
  for (const auto& e : events)
    report["events"].push_back(eventJson(engine.table(), e));
  json balls = json::array();
  for (const auto& b : engine.snapshot(final_state))
  {
    json jb = {{"id", b.id},
               {"position", vec(b.r)},
               {"velocity", vec(b.v)},
               {"angular_velocity", vec(b.w)},
               {"motion", motionName(b.motion)}};
    if (b.pocket >= 0)
      jb["pocket"] = engine.table().pockets()[b.pocket].name;
    balls.push_back(jb);
  }
  report["final_state"] = {{"time", final_state.time}, {"balls", balls}};
  report["at_rest"] = at_rest;
  return report;
}

json rulingJson(const game::Ruling& r)
{
  return {{"foul", r.foul},
          {"rule", r.rule},
          {"reason", r.reason},
          {"ball_in_hand", game::ballInHandName(r.ball_in_hand)},
          {"next_player", r.next_player},
          {"continues", r.continues},
          {"respot", r.respot},
          {"rerack", r.rerack},
          {"game_over", r.game_over},
          {"winner", r.winner},
          {"points", r.points},
          {"penalty", r.penalty},
          {"colour_next", r.colour_next},
          {"groups", {game::groupName(r.groups[0]), game::groupName(r.groups[1])}}};
}

json gameStateJson(const game::GameState& g, const physics::TableModel& table)
{
  const json called_pocket =
      g.called_pocket >= 0 ? json(table.pockets()[static_cast<std::size_t>(g.called_pocket)].name) : json(-1);
  const std::string in_hand = game::ballInHandName(g.ball_in_hand);
  return {{"rules", g.rules},
          {"players", g.players},
          {"turn", g.turn},
          {"break", g.break_shot},
          {"groups", {game::groupName(g.groups[0]), game::groupName(g.groups[1])}},
          {"called_ball", g.called_ball},
          {"called_pocket", called_pocket},
          {"ball_in_hand", in_hand.empty() ? "none" : in_hand},
          {"fouls", g.consecutive_fouls},
          {"push_out_allowed", g.push_out_allowed},
          {"shots", g.shots},
          {"score", g.score},
          {"target", g.target},
          {"innings", g.innings},
          {"before_shot", g.before_shot},
          {"colour_next", g.colour_next},
          {"free_ball", g.free_ball},
          {"over", g.over},
          {"winner", g.winner}};
}

}  // namespace cue_sim
