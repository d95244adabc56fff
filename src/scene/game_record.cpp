#include "cue_sim/scene/game_record.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "cue_sim/scene/shot_report.hpp"

namespace cue_sim
{
Scene shotScene(const game::GameRecord& record, std::size_t k, const std::string& table_name,
                const physics::Engine<double>& engine)
{
  Scene scene;
  scene.table_name = table_name;
  scene.table = engine.tableShared();
  scene.params = engine.params();
  scene.models = engine.models();
  // The balls on the table: a scene has no pocketed balls (those are out of the game).
  for (physics::Ball<double> b : record.before.at(k).balls)
    if (b.inPlay())
    {
      b.time = 0;
      scene.state.balls.push_back(b);
    }
  Shot shot;
  shot.ball = record.turns.at(k).ball;
  shot.strike = record.turns.at(k).strike;
  shot.push_out = record.turns.at(k).push_out;
  scene.shot = shot;
  scene.game = record.state_before.at(k);
  return scene;
}

namespace
{
/// Shot k as a player makes it (where the cue ball stood, the call, the strike as executed) and
/// its ruling: what a replay on the node needs (scripts/play_game.py --replay). Doubles round-trip.
nlohmann::json turnJson(const game::GameRecord& record, std::size_t k, const physics::TableModel& table)
{
  const game::Turn& turn = record.turns[k];
  const physics::TableState<double>& before = record.before[k];
  const physics::Ball<double>& cue = before.balls[static_cast<std::size_t>(before.indexOf(turn.ball))];
  const std::string pocket =
      turn.called_pocket >= 0 ? table.pockets()[static_cast<std::size_t>(turn.called_pocket)].name : "";
  return {{"player", turn.player},
          {"ball", turn.ball},
          {"cue_ball", {cue.r.x(), cue.r.y()}},
          {"called_ball", turn.called_ball},
          {"called_pocket", pocket},
          {"push_out", turn.push_out},
          {"strike",
           {{"speed", turn.strike.speed},
            {"phi", turn.strike.phi},
            {"theta", turn.strike.theta},
            {"a", turn.strike.a},
            {"b", turn.strike.b}}},
          {"ruling", rulingJson(turn.ruling)}};
}
}  // namespace

int writeGameRecord(const game::GameRecord& record, const std::string& dir, const std::string& table_name,
                    const physics::Engine<double>& engine)
{
  std::filesystem::create_directories(dir);
  nlohmann::json summary = {{"rules", record.rules},         {"game", record.index},
                            {"table", table_name},           {"players", record.players},
                            {"rack_seed", record.rack_seed}, {"first_player", record.first_player},
                            {"target", record.end.target},   {"shots", nlohmann::json::array()}};
  int written = 0;
  for (std::size_t k = 0; k < record.turns.size(); ++k)
  {
    char name[32];
    std::snprintf(name, sizeof name, "shot_%03zu.yaml", k);
    const std::filesystem::path path = std::filesystem::path(dir) / name;
    std::ofstream out(path);
    out << sceneYaml(shotScene(record, k, table_name, engine),
                     record.rules + " game " + std::to_string(record.index) + ", shot " + std::to_string(k) +
                         " by player " + std::to_string(record.turns[k].player) +
                         ": `rosrun cue_sim simulate` on this file plays it again and rules on it");
    if (!out)
      throw std::runtime_error("cannot write " + path.string());
    ++written;
    summary["shots"].push_back(turnJson(record, k, engine.table()));
    summary["shots"].back()["file"] = name;
  }
  summary["end"] = gameStateJson(record.end, engine.table());
  std::ofstream out(std::filesystem::path(dir) / "game.json");
  out << summary.dump(1) << "\n";
  if (!out)
    throw std::runtime_error("cannot write " + (std::filesystem::path(dir) / "game.json").string());
  return written + 1;
}

}  // namespace cue_sim
