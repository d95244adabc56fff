// The main of every rostest of the node: gtest, a ROS node (roslaunch names it after the test),
// and a spinner for TableClient's subscriptions and the tests' own callbacks.
#include <gtest/gtest.h>
#include <ros/ros.h>

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "cue_sim_node_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int result = RUN_ALL_TESTS();
  ros::shutdown();
  return result;
}
