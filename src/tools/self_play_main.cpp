// self_play: whole games between two shot planners, with execution noise (README, "Playing a game"; doc/tools.md,
// "Games and the referee").
//   rosrun cue_sim self_play --rules nine_ball --games 100 --seed 7 --out self_play_records
// Prints progress, then games finished, who won, shots and fouls per game; with --out, each game
// as scene files that `simulate` replays shot by shot.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "cue_sim/game/referee.hpp"
#include "cue_sim/game/self_play.hpp"
#include "cue_sim/scene/game_record.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

int main(int argc, char** argv)
{
  CLI::App app{"Self-play: whole games of every ruleset between two shot planners, refereed."};
  std::vector<std::string> rules = cue_sim::game::rulesNames();
  int games = 10, max_shots = 500, target = 0;
  std::uint64_t seed = 0;
  bool no_noise = false;
  std::string table_name, out_dir;
  app.add_option("--rules", rules, "rulesets to play, each N games")->check(CLI::IsMember(cue_sim::game::rulesNames()));
  app.add_option("--games", games, "games of each ruleset")->check(CLI::Range(1, 1000000));
  app.add_option("--seed", seed, "seed of the racks and the execution noise");
  app.add_option("--max-shots", max_shots, "the shot cap: a game not over by then ends without a winner")
      ->check(CLI::Range(1, 100000));
  app.add_option("--table", table_name,
                 "a bundled table (7ft, 9ft, carom, snooker) or a URDF file; by default each ruleset's own (7ft, carom, snooker)");
  app.add_option("--target", target, "the points that win where the game keeps a score (3-cushion: 40)")
      ->check(CLI::Range(1, cue_sim::game::GamePlay::kMaxTarget));
  app.add_flag("--no-noise", no_noise, "strike exactly as planned");
  app.add_option("--out", out_dir, "write each game's shots as scene files here (<rules>_<game>/shot_NNN.yaml)");
  CLI11_PARSE(app, argc, argv);
  try
  {
    for (const std::string& ruleset : rules)
    {
      const std::string played_on = table_name.empty() ? cue_sim::game::rulesTable(ruleset) : table_name;
      const auto table = std::make_shared<const cue_sim::physics::TableModel>(
          cue_sim::tableFromUrdfFile(cue_sim::tableUrdfPath(played_on)));
      const cue_sim::physics::Engine<double> engine(table, cue_sim::physics::tableDefaults(*table));
      cue_sim::game::SelfPlayOptions options;
      options.rules = ruleset;
      options.games = games;
      options.seed = seed;
      options.max_shots = max_shots;
      options.target = cue_sim::game::makeRules(ruleset)->defaultTarget() > 0 ? target : 0;
      if (no_noise)
        options.noise = cue_sim::physics::ExecutionNoise::none();
      int done = 0;
      const auto summary = cue_sim::game::selfPlay(engine, options, [&](const cue_sim::game::GameRecord& record) {
        ++done;
        std::fprintf(stderr, "\rself_play: %s %d/%d games   ", ruleset.c_str(), done, games);
        if (!out_dir.empty())
          cue_sim::writeGameRecord(record, out_dir + "/" + ruleset + "_" + std::to_string(record.index), played_on,
                                   engine);
      });
      std::fprintf(stderr, "\n");
      std::printf(
          "%s: %d games, %d finished, %d stopped at the cap of %d shots; planner A won %d, planner B %d; "
          "%.1f shots and %.1f fouls per game\n",
          ruleset.c_str(), summary.games, summary.finished, summary.capped, max_shots, summary.wins[0], summary.wins[1],
          static_cast<double>(summary.shots) / summary.games, static_cast<double>(summary.fouls) / summary.games);
      const auto rules = cue_sim::game::makeRules(ruleset);
      if (summary.innings > 0 && rules->defaultTarget() > 0)
        std::printf("%s: %.3f points per inning (%d points in %d innings)\n", ruleset.c_str(),
                    static_cast<double>(summary.points) / summary.innings, summary.points, summary.innings);
      else if (rules->keepsScore())
        std::printf("%s: %.1f points per frame, %.1f of them from fouls; %.2f points per visit to the table; "
                    "highest break %d\n",
                    ruleset.c_str(), static_cast<double>(summary.points) / summary.games,
                    static_cast<double>(summary.penalty_points) / summary.games,
                    static_cast<double>(summary.points - summary.penalty_points) / summary.innings,
                    summary.highest_break);
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "self_play: " << e.what() << std::endl;
    return 1;
  }
}
