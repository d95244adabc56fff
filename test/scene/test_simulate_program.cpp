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

TEST(SimulateProgram, AThreeCushionSceneCountsItsCushionsAndKeepsTheScore)
{
  // The yellow's player (turn 1) drives the yellow straight up the table (+y) off the side
  // cushion and back down onto the white, without the red: no point, the inning passes, and the
  // score stands. The same shot with the white struck is the wrong ball (UMB Art. 41).
  const std::string balls =
      "table: carom\nballs: [{id: 0, position: [0.5, -0.3]}, {id: 1, position: [0.5, 0.2]}, {id: 2, position: "
      "[-0.9, 0.4]}]\n";
  const std::string game = "game: {rules: three_cushion, break: false, turn: 1, target: 10, score: [4, 7]}\n";
  const ProgramRun run = simulate(balls + "shot: {ball: 1, speed: 2, phi: 1.5707963267948966}\n" + game);
  ASSERT_EQ(run.status, 0) << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["ruling"]["rule"], "UMB Art. 83") << report["ruling"].dump();
  EXPECT_FALSE(report["ruling"]["foul"].get<bool>());
  EXPECT_EQ(report["ruling"]["points"], 0);
  EXPECT_NE(report["ruling"]["reason"].get<std::string>().find("met the white (0) but not the other"),
            std::string::npos)
      << report["ruling"].dump();
  EXPECT_EQ(report["game"]["turn"], 0);
  EXPECT_EQ(report["game"]["score"], (nlohmann::json{4, 7}));
  EXPECT_EQ(report["game"]["target"], 10);
  const ProgramRun wrong = simulate(balls + "shot: {ball: 0, speed: 2, phi: 1.5707963267948966}\n" + game);
  ASSERT_EQ(wrong.status, 0) << wrong.out;
  EXPECT_EQ(nlohmann::json::parse(wrong.out)["ruling"]["rule"], "UMB Art. 41");
  // The red is never struck; three-cushion is not played on a table with pockets, nor with a ball
  // in hand; a score must be below the target.
  EXPECT_NE(simulate(balls + "shot: {ball: 2, speed: 2}\n" + game).out.find("shot.ball: ball 2 is not struck"),
            std::string::npos);
  EXPECT_NE(simulate("table: 7ft\nrack: carom\nshot: {speed: 2}\ngame: {rules: three_cushion}\n")
                .out.find("is played on a table without pockets"),
            std::string::npos);
  EXPECT_NE(simulate(balls + "shot: {speed: 2}\ngame: {rules: three_cushion, ball_in_hand: anywhere}\n")
                .out.find("game.ball_in_hand"),
            std::string::npos);
  EXPECT_NE(simulate(balls + "shot: {speed: 2}\ngame: {rules: three_cushion, target: 5, score: [5, 0]}\n")
                .out.find("game.score[0] must be in [0, 4]"),
            std::string::npos);
  EXPECT_NE(simulate("rack: nine\nshot: {speed: 8}\ngame: {rules: nine_ball, target: 5}\n").out.find("game.target"),
            std::string::npos);
}

TEST(SimulateProgram, ASelfPlayRecordReplaysShotByShot)
{
  // Each shot of a recorded game, written as a scene, gives the same ruling through `simulate`:
  // a 9-ball game, a three-cushion race to 3, and a frame of snooker (whose scenes carry the
  // colour on and the free ball, its scores are the points and penalties ruled, and it ends).
  for (const std::string rules : {"nine_ball", "three_cushion", "snooker"})
  {
    const std::string dir = ::testing::TempDir() + "/self_play_record";
    const std::string command = std::string(CUE_SIM_SELF_PLAY) + " --rules " + rules +
                                " --games 1 --seed 5 --target 3 --out " + dir + " 2>/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::ifstream summary_file(dir + "/" + rules + "_0/game.json");
    ASSERT_TRUE(summary_file) << dir;
    const auto summary = nlohmann::json::parse(summary_file);
    ASSERT_GT(summary["shots"].size(), 1u);
    int points = 0;
    std::array<int, 2> scores{0, 0};
    bool over = false;
    for (const auto& shot : summary["shots"])
    {
      std::ifstream scene(dir + "/" + rules + "_0/" + shot["file"].get<std::string>());
      const std::string text((std::istreambuf_iterator<char>(scene)), std::istreambuf_iterator<char>());
      const ProgramRun run = simulate(text);
      ASSERT_EQ(run.status, 0) << run.out;
      EXPECT_EQ(nlohmann::json::parse(run.out)["ruling"], shot["ruling"]) << shot["file"];
      points += shot["ruling"]["points"].get<int>();
      const int player = shot["player"].get<int>();
      scores[static_cast<std::size_t>(player)] += shot["ruling"]["points"].get<int>();
      scores[static_cast<std::size_t>(1 - player)] += shot["ruling"]["penalty"].get<int>();
      over = shot["ruling"]["game_over"].get<bool>();
    }
    EXPECT_TRUE(over) << rules;
    if (rules == "snooker")
    {
      EXPECT_NE(scores[0], scores[1]) << "a frame is not drawn";
      EXPECT_GE(scores[0] + scores[1], 15 + 27) << "every red and every colour went down once at least";
    }
    if (rules == "three_cushion")
    {
      EXPECT_GE(points, 3) << "the race is won";
    }
  }
}
