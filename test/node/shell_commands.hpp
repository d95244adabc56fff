// What the node's tests run in a shell: a program (its exit code and output), and a bag recorded
// with record.launch, as a user would run them.
#pragma once

#include <gtest/gtest.h>
#include <ros/master.h>
#include <ros/ros.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <utility>

/// Runs a command; its exit code and what it printed (stdout and stderr).
inline std::pair<int, std::string> runCommand(const std::string& command)
{
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe))
    output += buffer;
  const int status = pipe ? pclose(pipe) : -1;
  return {WEXITSTATUS(status), output};
}

/// Whether `node` subscribes to `topic`, as the master says, asking for at most `timeout` s.
inline bool subscribedBy(const std::string& topic, const std::string& node, double timeout)
{
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::WallTime::now() < until)
  {
    XmlRpc::XmlRpcValue request, response, payload;
    request[0] = ros::this_node::getName();
    if (ros::master::execute("getSystemState", request, response, payload, false))
    {
      XmlRpc::XmlRpcValue& subscribers = payload[1];
      for (int i = 0; i < subscribers.size(); ++i)
        if (static_cast<std::string>(subscribers[i][0]) == topic)
          for (int j = 0; j < subscribers[i][1].size(); ++j)
            if (static_cast<std::string>(subscribers[i][1][j]) == node)
              return true;
    }
    ros::WallDuration(0.1).sleep();
  }
  return false;
}

/// `roslaunch cue_sim record.launch` into `bag`, from construction until stop() (its node is
/// /record; its output goes to `log`).
class BagRecording
{
public:
  BagRecording(const std::string& bag, const std::string& log)
  {
    std::remove(bag.c_str());
    launch_ = std::thread([bag, log] {
      const std::string command = "roslaunch cue_sim record.launch bag:=" + bag + " > " + log + " 2>&1";
      EXPECT_EQ(std::system(command.c_str()), 0) << command;
    });
  }
  ~BagRecording() { stop(); }

  /// Ends the recording (the bag is closed once this returns).
  void stop()
  {
    if (!launch_.joinable())
      return;
    EXPECT_EQ(std::system("rosnode kill /record > /dev/null 2>&1"), 0);
    launch_.join();
  }

private:
  std::thread launch_;
};
