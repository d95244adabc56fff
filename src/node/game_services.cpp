#include "node/game_services.hpp"

#include <visualization_msgs/MarkerArray.h>

#include "node/game_markers.hpp"
#include "node/game_messages.hpp"
#include "node/ros_conversions.hpp"

namespace cue_sim
{
GameServices::GameServices(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters)
  : shared_(shared), parameters_(parameters)
{
  state_publisher_ = private_node.advertise<GameState>("game_state", 10, true);
  marker_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("game_markers", 1, true);
  services_ = {
      private_node.advertiseService("start_game", &GameServices::onStartGame, this),
      private_node.advertiseService("end_game", &GameServices::onEndGame, this),
      private_node.advertiseService("place_cue_ball", &GameServices::onPlaceCueBall, this),
      private_node.advertiseService("call_shot", &GameServices::onCallShot, this),
  };
}

void GameServices::publishIfChanged(const session::LiveTable& table, const ros::Time& stamp)
{
  if (table.game().version() == published_)
    return;
  published_ = table.game().version();
  const GameState state = toGameStateMsg(table, stamp, parameters_.table_frame);
  state_publisher_.publish(state);
  // A carom game's last point, drawn until the next shot: the cue ball's path from the strike to
  // rest, kept from the strike's own run.
  const std::optional<game::Turn>& last = table.game().lastTurn();
  const bool point = last && !table.game().pendingTurn() && last->ruling.points > 0;
  marker_publisher_.publish(gameMarkers(state, table.table(), table.engine().params().cushion_height,
                                        point ? table.game().lastPath() : std::vector<Eigen::Vector2d>{}));
}

bool GameServices::onStartGame(StartGame::Request& request, StartGame::Response& response)
{
  session::GameRequest game;
  game.rules = request.rules;
  if (request.players.size() == 2)
    game.players = {request.players[0], request.players[1]};
  else if (!request.players.empty())
  {
    response.message = "players: give two names or none, got " + std::to_string(request.players.size());
    return true;
  }
  game.breaker = request.first_player;
  game.seed = request.seed;
  game.target = request.target;
  game.balls = toBallInputs(request.balls);
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  const ros::Time now = shared_.now();
  const session::Outcome outcome = shared_.live->startGame(game, toStamp(now));
  response.success = outcome.success;
  response.message = outcome.message;
  response.state = toGameStateMsg(*shared_.live, now, parameters_.table_frame);
  return true;
}

bool GameServices::onEndGame(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  const session::Outcome outcome = shared_.live->endGame(toStamp(shared_.now()));
  response.success = outcome.success;
  response.message = outcome.message;
  return true;
}

bool GameServices::onPlaceCueBall(PlaceCueBall::Request& request, PlaceCueBall::Response& response)
{
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  const ros::Time now = shared_.now();
  const session::Outcome outcome =
      shared_.live->placeCueBall(Eigen::Vector2d(request.position.x, request.position.y), toStamp(now));
  response.success = outcome.success;
  response.message = outcome.message;
  if (outcome.success)
    response.stamp = now;
  return true;
}

bool GameServices::onCallShot(CallShot::Request& request, CallShot::Response& response)
{
  session::GameCall call;
  call.ball = request.ball;
  call.pocket = request.pocket;
  call.push_out = request.push_out;
  std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
  const session::Outcome outcome = shared_.live->callShot(call, toStamp(shared_.now()));
  response.success = outcome.success;
  response.message = outcome.message;
  return true;
}

}  // namespace cue_sim
