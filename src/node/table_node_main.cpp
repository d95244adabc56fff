#include <ros/ros.h>

#include "node/table_node.hpp"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "table");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try
  {
    cue_sim::TableNode table(node, private_node);
    table.run();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL("table_node cannot start: %s", e.what());
    return 1;
  }
  return 0;
}
