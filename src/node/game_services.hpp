// table_node's games: services to start and end a game, place the cue ball in hand and call a
// shot, and the latched ~game_state and ~game_markers. Strikes stay TableServices'; in a game
// the live table referees them. What is checked and why a request is refused is the live
// table's (session::LiveTable, src/session/live_game.cpp).
#pragma once

#include <cue_sim/CallShot.h>
#include <cue_sim/PlaceCueBall.h>
#include <cue_sim/StartGame.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <vector>

#include "node/node_parameters.hpp"
#include "node/shared_table.hpp"

namespace cue_sim
{
class GameServices
{
public:
  GameServices(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters);

  /// Publishes ~game_state and ~game_markers stamped `stamp` if the game changed since they last
  /// went out (call it holding the lock).
  void publishIfChanged(const session::LiveTable& table, const ros::Time& stamp);

private:
  bool onStartGame(StartGame::Request& request, StartGame::Response& response);
  bool onEndGame(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onPlaceCueBall(PlaceCueBall::Request& request, PlaceCueBall::Response& response);
  bool onCallShot(CallShot::Request& request, CallShot::Response& response);

  SharedTable& shared_;
  const NodeParameters& parameters_;
  long published_ = -1;  ///< the game version last published
  ros::Publisher state_publisher_, marker_publisher_;
  std::vector<ros::ServiceServer> services_;
};

}  // namespace cue_sim
