// dynamic_reconfigure of table_node: physics coefficients and contact models take effect
// between shots (a shot in flight finishes with the physics it started with, so that it stays
// what its prediction said); the real-time factor at once. An invalid change is refused with
// the reason, and the last valid configuration stays (and is what the server reports back).
#pragma once

#include <cue_sim/TableNodeConfig.h>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <string>

#include "node/shared_table.hpp"

namespace cue_sim
{
class PhysicsReconfigure
{
public:
  PhysicsReconfigure(ros::NodeHandle& private_node, SharedTable& shared);

private:
  void onReconfigure(TableNodeConfig& config, uint32_t level);
  /// Empty if `config` can be applied (then it is), else why not.
  std::string apply(const TableNodeConfig& config);

  SharedTable& shared_;
  TableNodeConfig applied_;  ///< the last valid configuration
  dynamic_reconfigure::Server<TableNodeConfig> server_;
};

}  // namespace cue_sim
