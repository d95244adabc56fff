// The table as a nodelet: the same services, tf and camera as table_node, an image consumer in the
// same manager (image_proc's rectify) fed from it, and an unload that ends the table cleanly while
// the manager and its other nodelets go on.
#include <gtest/gtest.h>
#include <nodelet/NodeletList.h>
#include <nodelet/NodeletUnload.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <atomic>

#include "table_client.hpp"

namespace
{
std::vector<std::string> loadedNodelets()
{
  nodelet::NodeletList list;
  EXPECT_TRUE(ros::service::call("/table_manager/list", list));
  return list.response.nodelets;
}

TEST(Nodelet, ServesTheTableAndFeedsAConsumerInItsManager)
{
  TableClient table;
  ASSERT_TRUE(table.atRest(30));
  // A strike moves the cue ball in tf, as table_node's does.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(buffer.canTransform("table", "ball_0", ros::Time(0), ros::Duration(20)));
  const double x_before = buffer.lookupTransform("table", "ball_0", ros::Time(0)).transform.translation.x;
  const cue_sim::Strike::Response struck = table.strike(TableClient::shot(0, 1.0, 0.0));
  ASSERT_TRUE(struck.success) << struck.message;
  const auto at_rest = table.atRest(30);
  const double x_after = buffer.lookupTransform("table", "ball_0", ros::Time(0)).transform.translation.x;
  EXPECT_GT(x_after - x_before, 0.1) << "the cue ball rolled along +x";

  // image_proc's rectify, in the same manager, rectifies the table's camera.
  ros::NodeHandle nh;
  std::atomic<int> rectified{0};
  sensor_msgs::ImageConstPtr last;
  std::mutex mutex;
  ros::Subscriber sub =
      nh.subscribe<sensor_msgs::Image>("/table/camera/image_rect", 2, [&](const sensor_msgs::ImageConstPtr& image) {
        std::lock_guard<std::mutex> lock(mutex);
        last = image;
        ++rectified;
      });
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(60);
  while (rectified < 3 && ros::WallTime::now() < until)
    ros::WallDuration(0.05).sleep();
  ASSERT_GE(rectified, 3) << "no rectified images from the manager";
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(last->width, 640u);
  EXPECT_EQ(last->height, 400u);
  EXPECT_EQ(last->encoding, "bgr8");
}

TEST(Nodelet, UnloadingTheTableLeavesTheManagerAndItsOtherNodelets)
{
  const std::vector<std::string> before = loadedNodelets();
  ASSERT_NE(std::find(before.begin(), before.end(), "/table"), before.end());
  nodelet::NodeletUnload unload;
  unload.request.name = "/table";
  ASSERT_TRUE(ros::service::call("/table_manager/unload_nodelet", unload));
  EXPECT_TRUE(unload.response.success);
  // The table's services go; the manager answers and keeps rectify.
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(30);
  while (ros::service::exists("/table/strike", false) && ros::WallTime::now() < until)
    ros::WallDuration(0.05).sleep();
  EXPECT_FALSE(ros::service::exists("/table/strike", false)) << "the table's services outlived it";
  const std::vector<std::string> after = loadedNodelets();
  EXPECT_EQ(std::find(after.begin(), after.end(), "/table"), after.end());
  EXPECT_NE(std::find(after.begin(), after.end(), "/table/camera/rectify"), after.end());
}

}  // namespace
