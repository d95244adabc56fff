#include <malloc.h>
#include <ros/ros.h>

#include "node/table_node.hpp"

namespace
{
/// Blocks from this size [bytes] up are mapped on their own and go back to the system when
/// freed. glibc otherwise raises the threshold after each large block it frees, and the next
/// replies of heavy requests land in its heaps, where they leave memory the node keeps for good.
constexpr int kMmapThreshold = 128 * 1024;
/// Heaps glibc keeps for the node's threads: a few, not one per thread and core.
constexpr int kMallocArenas = 2;
}  // namespace

int main(int argc, char** argv)
{
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_ARENA_MAX, kMallocArenas);
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
