// The `simulate` program, run as a user would, its JSON read back.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

namespace
{
struct ProgramRun
{
  int status;
  std::string out;
};

ProgramRun simulate(const std::string& scene_text, const std::string& args = "")
{
  const std::string path = ::testing::TempDir() + "/scene.yaml";
  std::ofstream(path) << scene_text;
  const std::string command = std::string(CUE_SIM_SIMULATE) + " " + path + " " + args + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe.get()))
    out += buffer.data();
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), out};
}
}  // namespace

TEST(SimulateProgram, BreakShotPrintsEventsAndAFinalStateAtRest)
{
  const ProgramRun run = simulate("table: 7ft\nrack: eight\nshot: {ball: 0, speed: 8.0, phi: 0.0}\n");
  ASSERT_EQ(run.status, 0) << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_TRUE(report["at_rest"].get<bool>());
  EXPECT_GT(report["events"].size(), 30u);
  ASSERT_EQ(report["final_state"]["balls"].size(), 16u);
  double last_t = 0;
  bool first_is_ball_ball = false;
  for (const auto& e : report["events"])
  {
    EXPECT_GE(e["t"].get<double>(), last_t);  // in time order
    last_t = e["t"].get<double>();
    if (e["kind"] == "ball_ball" && !first_is_ball_ball)
      first_is_ball_ball = e["ball"] == 0 && e["other"] == 1;  // the cue ball meets the apex first
  }
  EXPECT_TRUE(first_is_ball_ball);
  for (const auto& b : report["final_state"]["balls"])
  {
    const std::string motion = b["motion"];
    EXPECT_TRUE(motion == "stationary" || motion == "pocketed") << b.dump();
    EXPECT_TRUE(std::isfinite(b["position"][0].get<double>()));
  }
}

TEST(SimulateProgram, DurationStopsMidShot)
{
  const ProgramRun run = simulate("rack: empty\nshot: {speed: 2.0, phi: 0.5}\nduration: 0.25\n");
  ASSERT_EQ(run.status, 0) << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_FALSE(report["at_rest"].get<bool>());
  const auto& ball = report["final_state"]["balls"][0];
  EXPECT_NEAR(std::atan2(ball["velocity"][1].get<double>(), ball["velocity"][0].get<double>()), 0.5, 1e-12);
}

TEST(SimulateProgram, BadSceneExitsNonZeroWithTheReason)
{
  const ProgramRun run = simulate("rack: empty\nballs: [{id: 1, position: [-0.4954, 0.0]}]\n");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.out.find("overlap"), std::string::npos) << run.out;
}

TEST(SimulateProgram, TheDurationOptionStopsWhereTheSceneFileWould)
{
  const std::string scene = "rack: eight\nshot: {speed: 7.0, phi: 0.003}\n";
  const ProgramRun option = simulate(scene, "--duration 0.8 --indent -1");
  const ProgramRun in_file = simulate(scene + "duration: 0.8\n", "--indent -1");
  ASSERT_EQ(option.status, 0) << option.out;
  EXPECT_EQ(option.out, in_file.out);  // the same events and final state, to the last digit
  const auto report = nlohmann::json::parse(option.out);
  EXPECT_FALSE(report["at_rest"].get<bool>());
  for (const auto& e : report["events"])
    EXPECT_LE(e["t"].get<double>(), 0.8);
  EXPECT_NE(simulate(scene, "--duration -1").status, 0);
}

TEST(SimulateProgram, ABallBehindAPocketsMouthIsRefused)
{
  // Past the cushion line, beside the side pocket's capture circle: off the playing area.
  const ProgramRun run = simulate("rack: empty\nballs: [{id: 1, position: [0.12, 0.51]}]\n");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.out.find("off the cloth"), std::string::npos) << run.out;
}

TEST(SimulateProgram, ExitCodesSayWhatWentWrong)
{
  EXPECT_EQ(simulate("rack: eight\n", "--help").status, 0);
  const ProgramRun option = simulate("rack: eight\n", "--no-such-option");
  EXPECT_EQ(option.status, 2) << option.out;
  EXPECT_EQ(simulate("rack: eight\n", "--indent 99").status, 2);
  // A ball far faster than any shot gives: refused by name, not printed as a null position.
  const ProgramRun fast = simulate("rack: empty\nballs: [{id: 0, position: [0, 0], velocity: [1e308, 0]}]\n");
  EXPECT_EQ(fast.status, 1);
  EXPECT_NE(fast.out.find("speed"), std::string::npos) << fast.out;
  EXPECT_EQ(fast.out.find("null"), std::string::npos) << fast.out;
  const ProgramRun nan = simulate("rack: empty\nballs: [{id: 0, position: [0, 0], velocity: [.nan, 0]}]\n");
  EXPECT_EQ(nan.status, 1);
  EXPECT_NE(nan.out.find("finite"), std::string::npos) << nan.out;
  // The engine giving up is a code of its own.
  const ProgramRun limited = simulate("rack: eight\nshot: {speed: 8}\n", "--max-events 5");
  EXPECT_EQ(limited.status, 3) << limited.out;
}

TEST(SimulateProgram, AGameSceneIsRuledOn)
{
  // A scratch: the cue ball alone rolled into a corner pocket, solids to shoot in 8-ball.
  const ProgramRun run = simulate(
      "table: 7ft\nballs: [{id: 0, position: [0.5, 0.2]}, {id: 3, position: [-0.5, -0.3]}, {id: 8, position: [0, 0]}]\n"
      "shot: {speed: 1.5, phi: 0.5418}\n"
      "game: {rules: eight_ball, break: false, groups: [solids, stripes]}\n");
  ASSERT_EQ(run.status, 0) << run.out;
  const auto report = nlohmann::json::parse(run.out);
  const auto& ruling = report["ruling"];
  ASSERT_TRUE(ruling.is_object()) << run.out;
  EXPECT_TRUE(ruling["foul"].get<bool>()) << ruling.dump();
  EXPECT_EQ(ruling["rule"], "WPA 6.1");
  EXPECT_EQ(ruling["ball_in_hand"], "anywhere");
  EXPECT_EQ(ruling["next_player"], 1);
  EXPECT_FALSE(ruling["game_over"].get<bool>());
  EXPECT_EQ(report["game"]["turn"], 1);
  EXPECT_EQ(report["game"]["fouls"][0], 1);
  // A called ball must be on the table.
  const ProgramRun missing = simulate("rack: nine\nshot: {speed: 8}\ngame: {rules: nine_ball, called_ball: 12}\n");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("game.called_ball: ball 12 is not on the table"), std::string::npos) << missing.out;
  // A game's shot is ruled on at rest: a duration is refused.
  EXPECT_EQ(simulate("rack: eight\nshot: {speed: 8}\ngame: {rules: eight_ball}\n", "--duration 0.1").status, 1);
}

TEST(SimulateProgram, ASelfPlayRecordReplaysShotByShot)
{
  // Each shot of a recorded game, written as a scene, gives the same ruling through `simulate`.
  const std::string dir = ::testing::TempDir() + "/self_play_record";
  const std::string command =
      std::string(CUE_SIM_SELF_PLAY) + " --rules nine_ball --games 1 --seed 5 --out " + dir + " 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream summary_file(dir + "/nine_ball_0/game.json");
  ASSERT_TRUE(summary_file) << dir;
  const auto summary = nlohmann::json::parse(summary_file);
  ASSERT_GT(summary["shots"].size(), 1u);
  for (const auto& shot : summary["shots"])
  {
    std::ifstream scene(dir + "/nine_ball_0/" + shot["file"].get<std::string>());
    const std::string text((std::istreambuf_iterator<char>(scene)), std::istreambuf_iterator<char>());
    const ProgramRun run = simulate(text);
    ASSERT_EQ(run.status, 0) << run.out;
    EXPECT_EQ(nlohmann::json::parse(run.out)["ruling"], shot["ruling"]) << shot["file"];
  }
}
