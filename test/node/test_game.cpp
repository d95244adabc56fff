// Games on table_node through its services, with a real master: starting a game, refereed
// strikes whose rulings reach the response, ~shots and the latched ~game_state, ball in hand and
// calls checked by the rules, and whole games between two planners that choose each shot from
// the node's own ~predict_batch (each prediction carrying the referee's ruling), struck with the
// node's execution noise on.
#include <cue_sim/CallShot.h>
#include <cue_sim/ExecutedShot.h>
#include <cue_sim/GameState.h>
#include <cue_sim/PlaceCueBall.h>
#include <cue_sim/StartGame.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "cue_sim/physics/physics_params.hpp"
#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"
#include "shell_commands.hpp"
#include "table_client.hpp"

namespace
{
/// Shots a game of the planners may take here before the test calls it stuck.
constexpr int kShotCap = 150;
/// Longest a shot may take to rest, in wall time with sim time as fast as possible [s].
constexpr double kRestTimeout = kGenerousWait;

const double kR = cue_sim::physics::PhysicsParams<double>().ball_radius;

class GameClient : public TableClient
{
public:
  GameClient() : table_(cue_sim::tableFromUrdfFile(cue_sim::tableUrdfPath("7ft")))
  {
    EXPECT_TRUE(ros::service::waitForService("/table/start_game", ros::Duration(20)));
    start_ = nh_.serviceClient<cue_sim::StartGame>("/table/start_game");
    end_ = nh_.serviceClient<std_srvs::Trigger>("/table/end_game");
    place_ = nh_.serviceClient<cue_sim::PlaceCueBall>("/table/place_cue_ball");
    call_ = nh_.serviceClient<cue_sim::CallShot>("/table/call_shot");
    game_sub_ = nh_.subscribe<cue_sim::GameState>("/table/game_state", 10, [this](const cue_sim::GameStateConstPtr& m) {
      std::lock_guard<std::mutex> lock(game_mutex_);
      game_ = m;
      ++game_states_;
    });
    shots_sub_ =
        nh_.subscribe<cue_sim::ExecutedShot>("/table/shots", 100, [this](const cue_sim::ExecutedShotConstPtr& m) {
          std::lock_guard<std::mutex> lock(game_mutex_);
          shots_.push_back(*m);
        });
  }

  cue_sim::StartGame::Response start(const std::string& rules, int first = 0, uint32_t seed = 0,
                                     const std::vector<cue_sim::BallState>& balls = {})
  {
    cue_sim::StartGame srv;
    srv.request.rules = rules;
    srv.request.players = {"ann", "bob"};
    srv.request.first_player = first;
    srv.request.seed = seed;
    srv.request.balls = balls;
    EXPECT_TRUE(start_.call(srv));
    return srv.response;
  }

  std_srvs::Trigger::Response end()
  {
    std_srvs::Trigger srv;
    EXPECT_TRUE(end_.call(srv));
    return srv.response;
  }

  cue_sim::PlaceCueBall::Response place(double x, double y)
  {
    cue_sim::PlaceCueBall srv;
    srv.request.position.x = x;
    srv.request.position.y = y;
    EXPECT_TRUE(place_.call(srv));
    return srv.response;
  }

  cue_sim::CallShot::Response call(int ball, const std::string& pocket, bool push_out = false)
  {
    cue_sim::CallShot srv;
    srv.request.ball = ball;
    srv.request.pocket = pocket;
    srv.request.push_out = push_out;
    EXPECT_TRUE(call_.call(srv));
    return srv.response;
  }

  /// The latest ~game_state that satisfies `ready`, waiting at most `timeout` s of wall time.
  template <typename Ready>
  cue_sim::GameStateConstPtr gameWhen(Ready ready, double timeout = kRestTimeout)
  {
    cue_sim::GameStateConstPtr seen;
    if (waitFor(
            [&] {
              std::lock_guard<std::mutex> lock(game_mutex_);
              seen = game_;
              return seen && ready(*seen);
            },
            timeout))
      return seen;
    ADD_FAILURE() << "no ~game_state as awaited within " << timeout << " s";
    return seen ? seen : boost::make_shared<cue_sim::GameState>();
  }

  /// The game once shot `shots` has come to rest (the ruling applied).
  cue_sim::GameStateConstPtr afterShot(int shots)
  {
    return gameWhen([shots](const cue_sim::GameState& g) { return !g.shot_in_progress && g.shots >= shots; });
  }

  /// The ~shots messages received, once there are at least `count` (the node publishes a shot
  /// as it strikes; it reaches this subscriber on its own connection, in its own time).
  std::vector<cue_sim::ExecutedShot> shotsSeen(std::size_t count)
  {
    std::vector<cue_sim::ExecutedShot> seen;
    if (!waitFor([&] {
          std::lock_guard<std::mutex> lock(game_mutex_);
          seen = shots_;
          return seen.size() >= count;
        }))
      ADD_FAILURE() << "fewer than " << count << " ~shots messages within " << kGenerousWait << " s";
    return seen;
  }

  /// How many ~game_state messages this client has received.
  long gameStatesSeen()
  {
    std::lock_guard<std::mutex> lock(game_mutex_);
    return game_states_;
  }

  const cue_sim::physics::TableModel& model() const { return table_; }

private:
  cue_sim::physics::TableModel table_;
  ros::NodeHandle nh_;
  ros::ServiceClient start_, end_, place_, call_;
  std::mutex game_mutex_;
  long game_states_ = 0;
  cue_sim::GameStateConstPtr game_;
  std::vector<cue_sim::ExecutedShot> shots_;
  ros::Subscriber game_sub_, shots_sub_;
};

cue_sim::BallState ballAt(int id, double x, double y)
{
  cue_sim::BallState b;
  b.id = id;
  b.position.x = x;
  b.position.y = y;
  return b;
}

Eigen::Vector2d positionOf(const cue_sim::TableState& state, int id)
{
  for (const auto& b : state.balls)
    if (b.id == id && !b.pocketed)
      return {b.position.x, b.position.y};
  return {NAN, NAN};
}

/// A planner over the node's batch: for every ball it may hit first and every pocket, the
/// ghost-ball aim at two speeds, and on a break the apex at 8 m/s; the best ruling wins (a won
/// game, a legal pot, a shot without a foul; among equals the slower).
struct BatchPlanner
{
  static double score(const cue_sim::Ruling& r, int shooter, double speed)
  {
    double s = 0;
    if (r.game_over)
      s = r.winner == shooter ? 1000 : -1000;
    else if (!r.foul && r.continues)
      s = 100;
    else if (!r.foul)
      s = 10;
    return s - speed;  // the slower among equals
  }

  static std::vector<cue_sim::Shot> candidates(const cue_sim::physics::TableModel& table,
                                               const cue_sim::TableState& balls, const cue_sim::GameState& game)
  {
    const Eigen::Vector2d cue = positionOf(balls, 0);
    std::vector<cue_sim::Shot> shots;
    for (const int id : game.legal_first)
    {
      const Eigen::Vector2d ball = positionOf(balls, id);
      if (!std::isfinite(ball.x()))
        continue;
      const Eigen::Vector2d full = ball - cue;
      shots.push_back(TableClient::shot(0, 2.0, std::atan2(full.y(), full.x())));
      for (const auto& pocket : table.pockets())
      {
        const Eigen::Vector2d ghost = ball - 2 * kR * (pocket.centre - ball).normalized();
        const Eigen::Vector2d aim = ghost - cue;
        for (const double speed : {1.5, 3.0})
          shots.push_back(TableClient::shot(0, speed, std::atan2(aim.y(), aim.x())));
      }
    }
    if (game.break_shot)
      shots.push_back(
          TableClient::shot(0, 8.0, std::atan2(table.footSpot().y() - cue.y(), table.footSpot().x() - cue.x())));
    return shots;
  }
};

TEST(Game, AStartedGameRefereesStrikesPublishesItsStateAndRefusesFreeEdits)
{
  GameClient client;
  const auto started = client.start("eight_ball", 1, 7);
  ASSERT_TRUE(started.success) << started.message;
  EXPECT_TRUE(started.state.active);
  EXPECT_EQ(started.state.turn, 1);
  EXPECT_EQ(started.state.players[1], "bob");
  EXPECT_EQ(started.state.ball_in_hand, "behind_head_string");
  EXPECT_DOUBLE_EQ(started.state.place_max.x, client.model().headStringX());
  auto game = client.gameWhen([](const cue_sim::GameState& g) { return g.active && g.break_shot && g.turn == 1; });
  EXPECT_EQ(game->shots, 0);

  const auto racked = client.rack("nine");
  EXPECT_FALSE(racked.success);
  EXPECT_NE(racked.message.find("a game of eight_ball is on"), std::string::npos) << racked.message;
  const auto object = client.strike(TableClient::shot(3, 1.0, 0));
  EXPECT_FALSE(object.success);
  EXPECT_NE(object.message.find("is not struck in a game of"), std::string::npos) << object.message;
  const auto far = client.place(client.model().headStringX() + 0.3, 0);
  EXPECT_FALSE(far.success);
  EXPECT_NE(far.message.find("behind the head string"), std::string::npos) << far.message;
  const auto placed = client.place(client.model().headStringX() - 0.1, 0.05);
  ASSERT_TRUE(placed.success) << placed.message;

  const Eigen::Vector2d cue(client.model().headStringX() - 0.1, 0.05);
  const Eigen::Vector2d apex = client.model().footSpot();
  const cue_sim::Shot brk = TableClient::shot(0, 8.0, std::atan2(apex.y() - cue.y(), apex.x() - cue.x()));
  const cue_sim::Prediction predicted = client.predict(brk);  // with noise on, the strike differs from it
  ASSERT_TRUE(predicted.success) << predicted.message;
  ASSERT_TRUE(predicted.ruling.refereed);
  EXPECT_NE(predicted.ruling.rule.find("WPA 3.3"), std::string::npos) << predicted.ruling.reason;
  const auto struck = client.strike(brk);
  ASSERT_TRUE(struck.success) << struck.message;
  ASSERT_TRUE(struck.ruling.refereed);
  EXPECT_NE(struck.ruling.rule.find("WPA"), std::string::npos) << struck.ruling.rule;

  game = client.afterShot(1);
  EXPECT_EQ(game->last_ruling.reason, struck.ruling.reason);
  EXPECT_EQ(game->turn, struck.ruling.next_player);
  EXPECT_EQ(game->ball_in_hand, struck.ruling.ball_in_hand);
  const auto shots = client.shotsSeen(1);
  ASSERT_FALSE(shots.empty());
  EXPECT_TRUE(shots.back().ruling.refereed);
  EXPECT_EQ(shots.back().ruling.reason, struck.ruling.reason);

  const auto ended = client.end();
  ASSERT_TRUE(ended.success) << ended.message;
  client.gameWhen([](const cue_sim::GameState& g) { return !g.active; });
  EXPECT_TRUE(client.rack("eight").success);
  const auto free_play = client.strike(TableClient::shot(0, 1.0, 0));
  EXPECT_TRUE(free_play.success) << free_play.message;
  EXPECT_FALSE(free_play.ruling.refereed);
  client.atRestAfter(free_play.stamp, kRestTimeout);
}

TEST(Game, AScratchGivesBallInHandAnywhereWhichPlaceCueBallChecks)
{
  GameClient client;
  const auto& model = client.model();
  Eigen::Vector2d pocket;
  for (const auto& p : model.pockets())
    if (p.name == "pocket_side_ypos")
      pocket = p.centre;
  const Eigen::Vector2d cue(pocket.x(), model.clothCentre().y() + 0.1);
  const auto started =
      client.start("nine_ball", 0, 0, {ballAt(0, cue.x(), cue.y()), ballAt(1, 0.3, -0.3), ballAt(9, 0.6, -0.3)});
  ASSERT_TRUE(started.success) << started.message;
  EXPECT_FALSE(started.state.break_shot);
  EXPECT_EQ(started.state.ball_in_hand, "");
  EXPECT_EQ(std::vector<int>(started.state.legal_first.begin(), started.state.legal_first.end()), std::vector<int>{1});
  const auto push = client.call(1, "", true);
  EXPECT_FALSE(push.success);
  EXPECT_NE(push.message.find("2.4"), std::string::npos) << push.message;

  // Struck from a cue pose (~strike_cue, refereed like ~strike): level, its tip 1 cm short of the
  // cue ball's centre height, along the line to the side pocket.
  const double phi = std::atan2(pocket.y() - cue.y(), pocket.x() - cue.x());
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "table";
  pose.pose.position.x = cue.x() - (kR + 0.01) * std::cos(phi);
  pose.pose.position.y = cue.y() - (kR + 0.01) * std::sin(phi);
  pose.pose.position.z = kR;
  pose.pose.orientation.z = std::sin(phi / 2);
  pose.pose.orientation.w = std::cos(phi / 2);
  const auto struck = client.strikeCue(pose, 2.0);
  ASSERT_TRUE(struck.success) << struck.message;
  EXPECT_EQ(struck.shot.ball_id, 0);
  ASSERT_TRUE(struck.ruling.refereed);
  EXPECT_TRUE(struck.ruling.foul);
  EXPECT_NE(struck.ruling.rule.find("6.1"), std::string::npos) << struck.ruling.reason;
  EXPECT_EQ(struck.ruling.next_player, 1);
  EXPECT_EQ(struck.ruling.ball_in_hand, "anywhere");
  const auto game = client.afterShot(1);
  EXPECT_EQ(game->turn, 1);
  EXPECT_EQ(game->consecutive_fouls[0], 1);
  EXPECT_EQ(game->ball_in_hand, "anywhere");
  EXPECT_GT(game->place_max.x, model.headStringX());  // anywhere: past the head string too

  const auto on_ball = client.place(0.3, -0.3 + kR);
  EXPECT_FALSE(on_ball.success);
  EXPECT_NE(on_ball.message.find("overlap"), std::string::npos) << on_ball.message;
  const auto placed = client.place(0.5, 0.2);
  ASSERT_TRUE(placed.success) << placed.message;
  // From the placement's stamp on (under sim time the node's clock runs ahead of this client's,
  // so "a state stamped after now" may still be from before the placement).
  const auto state = client.stateAfter(placed.stamp);
  const Eigen::Vector2d at = positionOf(*state, 0);
  EXPECT_NEAR(at.x(), 0.5, 1e-12);
  EXPECT_NEAR(at.y(), 0.2, 1e-12);
  ASSERT_TRUE(client.end().success);
}

// A bag of a game (record.launch) holds its states and each strike with its ruling.
TEST(Game, ABagRecordsTheGameStatesAndTheRulings)
{
  GameClient client;
  const std::string bag_path = std::string(CUE_SIM_TEST_DIR) + "/game_test.bag";
  BagRecording recording(bag_path, std::string(CUE_SIM_TEST_DIR) + "/game_record_test.log");
  // Every game state must reach the bag: wait until rosbag has subscribed to all three topics.
  for (const std::string topic : {"/table/game_state", "/table/shots", "/table/game_markers"})
    ASSERT_TRUE(connectedTo("/record", topic)) << topic;
  // From here on rosbag and this client receive the same messages; the game is idle, so none is
  // on its way to either.
  const long states_before = messagesReceivedBy("/record", "/table/game_state");
  const long shots_before = messagesReceivedBy("/record", "/table/shots");
  const long seen_before = client.gameStatesSeen();
  const auto started =
      client.start("nine_ball", 1, 0, {ballAt(0, -0.5, 0.0), ballAt(1, 0.0, 0.0), ballAt(9, 0.5, 0.3)});
  ASSERT_TRUE(started.success) << started.message;
  client.gameWhen(
      [](const cue_sim::GameState& g) { return g.active && g.rules == "nine_ball" && !g.over && g.shots == 0; });
  const auto struck = client.strike(TableClient::shot(0, 1.0, 0.0));
  ASSERT_TRUE(struck.success) << struck.message;
  client.afterShot(1);
  ASSERT_TRUE(client.end().success);
  client.gameWhen([](const cue_sim::GameState& g) { return !g.active; });
  // The bag holds every game state and the shot once rosbag has received as many as this client.
  ASSERT_TRUE(receivedBy("/record", "/table/game_state", states_before + (client.gameStatesSeen() - seen_before)));
  ASSERT_TRUE(receivedBy("/record", "/table/shots", shots_before + 1));
  ASSERT_TRUE(receivedBy("/record", "/table/game_markers", 1));
  recording.stop();

  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  bool started_seen = false, in_play_seen = false, ruled_seen = false;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/table/game_state"))))
  {
    const auto game = m.instantiate<cue_sim::GameState>();
    ASSERT_TRUE(game);
    if (!game->active || game->rules != "nine_ball")
      continue;
    started_seen |= game->shots == 0 && !game->shot_in_progress && game->turn == 1;
    in_play_seen |= game->shot_in_progress && game->last_ruling.reason == struck.ruling.reason;
    ruled_seen |= game->shots == 1 && !game->shot_in_progress && game->last_ruling.reason == struck.ruling.reason;
  }
  EXPECT_TRUE(started_seen);
  EXPECT_TRUE(in_play_seen);
  EXPECT_TRUE(ruled_seen);
  std::size_t shots = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/table/shots"))))
  {
    const auto played = m.instantiate<cue_sim::ExecutedShot>();
    ASSERT_TRUE(played);
    if (played->header.stamp != struck.stamp)
      continue;
    ++shots;
    EXPECT_TRUE(played->ruling.refereed);
    EXPECT_EQ(played->ruling.reason, struck.ruling.reason);
    EXPECT_EQ(played->ruling.foul, struck.ruling.foul);
  }
  EXPECT_EQ(shots, 1u);
  EXPECT_GT(bag.getSize(), 0u);
  std::size_t markers = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(std::string("/table/game_markers"))))
    markers += m.instantiate<visualization_msgs::MarkerArray>() != nullptr;
  EXPECT_GT(markers, 0u);
  bag.close();
}

// Whole games through the services: each shot chosen from ~predict_batch by the rulings it
// predicts, struck with execution noise on (the cue ball played where the referee leaves it:
// with ball in hand that is a legal place too), each strike's ruling the one ~game_state applies.
// Every game ends (a win, a loss, or three fouls in a row) within the cap.
TEST(Game, PlannersPlayWholeGamesThroughTheServices)
{
  GameClient client;
  for (const std::string rules : {"eight_ball", "nine_ball"})
    for (int g = 0; g < 2; ++g)
    {
      const auto started = client.start(rules, g % 2, static_cast<uint32_t>(g));
      ASSERT_TRUE(started.success) << started.message;
      cue_sim::GameStateConstPtr game = client.gameWhen(
          [&](const cue_sim::GameState& g) { return g.active && g.rules == rules && !g.over && g.shots == 0; });
      int shots = 0, fouls = 0;
      while (!game->over && shots < kShotCap)
      {
        const auto balls = client.stateAfter(game->header.stamp);  // the table as the game left it
        const std::vector<cue_sim::Shot> candidates = BatchPlanner::candidates(client.model(), *balls, *game);
        ASSERT_FALSE(candidates.empty());
        const auto batch = client.predictBatch(candidates);
        ASSERT_TRUE(batch.success) << batch.message;
        double best = -1e9;
        cue_sim::Shot chosen = candidates.front();
        for (std::size_t i = 0; i < candidates.size(); ++i)
        {
          const auto& p = batch.predictions[i];
          if (!p.success)
            continue;
          ASSERT_TRUE(p.ruling.refereed);
          const double s = BatchPlanner::score(p.ruling, game->turn, candidates[i].speed);
          if (s > best)
          {
            best = s;
            chosen = candidates[i];
          }
        }
        const auto struck = client.strike(chosen);
        ASSERT_TRUE(struck.success) << struck.message;
        ASSERT_TRUE(struck.ruling.refereed);
        ++shots;
        fouls += struck.ruling.foul;
        const auto game_before = game;
        game = client.afterShot(game_before->shots + 1);
        ASSERT_EQ(game->shots, game_before->shots + 1);
        EXPECT_EQ(game->last_ruling.reason, struck.ruling.reason);
        EXPECT_EQ(game->over, struck.ruling.game_over);
        if (!game->over)
        {
          EXPECT_EQ(game->turn, struck.ruling.next_player);
        }
      }
      EXPECT_TRUE(game->over) << rules << " game " << g << " not over after " << shots << " shots";
      std::printf(
          "%s game %d: %d shots, %d fouls, %s\n", rules.c_str(), g, shots, fouls,
          game->winner >= 0 ? (game->players[static_cast<std::size_t>(game->winner)] + " won").c_str() : "no winner");
      const auto after = client.strike(TableClient::shot(0, 1.0, 0));
      EXPECT_FALSE(after.success);
      EXPECT_NE(after.message.find("the game is over"), std::string::npos) << after.message;
    }
  ASSERT_TRUE(client.end().success);
}

/// scripts/play_game.py's output for a whole game of `rules` (seed 5), checked to have started
/// and ended.
std::string playedGame(const std::string& rules)
{
  const auto [code, output] = runCommand("rosrun cue_sim play_game.py --rules " + rules + " --seed 5");
  EXPECT_EQ(code, 0) << output;
  EXPECT_NE(output.find("started " + rules + ": ann against bob"), std::string::npos) << output;
  EXPECT_NE(output.find("shot 1: ann"), std::string::npos) << output;
  EXPECT_NE(output.find("game over after"), std::string::npos) << output;
  std::printf("%s", output.c_str());
  return output;
}

// scripts/play_game.py, as the README runs it: a whole game to its end through the services.
TEST(Game, ThePythonPlayerFinishesAGame)
{
  playedGame("nine_ball");
}

// The same in 10-ball, where only a called ball counts: the player calls each aim before asking
// for its prediction (~game_state's must_call), and pots called balls.
TEST(Game, ThePythonPlayerCallsItsShotsInTenBall)
{
  const std::string output = playedGame("ten_ball");
  EXPECT_NE(output.find("(WPA 9.5): the shooter continues"), std::string::npos) << output;
}

// Self-play's records (the self_play program, execution noise on) replayed on the node with
// scripts/play_game.py --replay: the node's referee rules on every shot as the record says, and every
// cue ball the physics leaves is where the record has it, bit for bit.
TEST(GameReplay, SelfPlayRecordsReplayOnTheNodeWithTheSameRulings)
{
  const std::string dir = std::string(CUE_SIM_TEST_DIR) + "/game_replay_records";
  std::system(("rm -rf '" + dir + "'").c_str());
  const auto [played, output] = runCommand(
      "rosrun cue_sim self_play --rules eight_ball nine_ball ten_ball --games 2 --seed 4 --out '" + dir + "'");
  ASSERT_EQ(played, 0) << output;
  for (const std::string game :
       {"eight_ball_0", "eight_ball_1", "nine_ball_0", "nine_ball_1", "ten_ball_0", "ten_ball_1"})
  {
    const auto [code, replay] = runCommand("rosrun cue_sim play_game.py --replay '" + dir + "/" + game + "'");
    EXPECT_EQ(code, 0) << game << ":\n" << replay;
    EXPECT_NE(replay.find("every ruling as recorded"), std::string::npos) << replay;
    const std::size_t summary = replay.rfind("replayed");
    std::printf("%s: %s", game.c_str(), summary == std::string::npos ? "" : replay.substr(summary).c_str());
  }
}

TEST(GameReplay, ThreeCushionRecordsReplayOnTheCaromTableWithTheSameRulingsAndScores)
{
  // On a node running the carom table: each player's own cue ball struck, the race's target sent
  // with the start, every ruling and every ball where the record has it.
  const std::string dir = std::string(CUE_SIM_TEST_DIR) + "/game_replay_carom_records";
  std::system(("rm -rf '" + dir + "'").c_str());
  const auto [played, output] =
      runCommand("rosrun cue_sim self_play --rules three_cushion --games 2 --seed 4 --target 4 --out '" + dir + "'");
  ASSERT_EQ(played, 0) << output;
  for (const std::string game : {"three_cushion_0", "three_cushion_1"})
  {
    const auto [code, replay] = runCommand("rosrun cue_sim play_game.py --replay '" + dir + "/" + game + "'");
    EXPECT_EQ(code, 0) << game << ":\n" << replay;
    EXPECT_NE(replay.find("every ruling as recorded"), std::string::npos) << replay;
    EXPECT_NE(replay.find("a point (UMB Art. 83)"), std::string::npos) << "a race to 4 has points: " << replay;
    const std::size_t summary = replay.rfind("replayed");
    std::printf("%s: %s", game.c_str(), summary == std::string::npos ? "" : replay.substr(summary).c_str());
  }
}

TEST(GameReplay, SnookerRecordsReplayOnTheSnookerTableWithTheSameRulingsAndScores)
{
  // On a node running the snooker table: the cue ball in hand in the D, the colours re-spotted,
  // every ruling (points and penalties with it) and every ball where the record has it.
  const std::string dir = std::string(CUE_SIM_TEST_DIR) + "/game_replay_snooker_records";
  std::system(("rm -rf '" + dir + "'").c_str());
  const auto [played, output] =
      runCommand("rosrun cue_sim self_play --rules snooker --games 1 --seed 4 --out '" + dir + "'");
  ASSERT_EQ(played, 0) << output;
  const auto [code, replay] = runCommand("rosrun cue_sim play_game.py --replay '" + dir + "/snooker_0'");
  EXPECT_EQ(code, 0) << replay;
  EXPECT_NE(replay.find("every ruling as recorded"), std::string::npos) << replay;
  EXPECT_NE(replay.find("the frame ends on the black"), std::string::npos) << "the frame is played out: " << replay;
  const std::size_t summary = replay.rfind("replayed");
  std::printf("snooker_0: %s", summary == std::string::npos ? "" : replay.substr(summary).c_str());
}

}  // namespace
