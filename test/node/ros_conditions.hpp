// Conditions the node's tests wait on, each with a generous deadline: never a fixed sleep. A wait
// ends as soon as its condition holds, so a generous deadline costs nothing when all is well and
// spares a false failure on a loaded machine.
#pragma once

#include <gtest/gtest.h>
#include <ros/master.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <string>

/// The deadline [s] of waits on the node in the tests: far above anything an idle machine needs
/// (a few hundred milliseconds at most), for a machine whose cores other work keeps busy.
constexpr double kGenerousWait = 60.0;

/// Polls `condition` every `poll` seconds of wall time until it holds (true) or `timeout` passes (false).
template <typename Condition>
bool waitFor(Condition condition, double timeout = kGenerousWait, double poll = 0.01)
{
  const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(timeout);
  while (!condition())
  {
    if (ros::WallTime::now() > until)
      return condition();
    ros::WallDuration(poll).sleep();
  }
  return true;
}

/// How many messages of `topic` the roscpp node `node` (rosbag's /record, say) has received on
/// all its connections to publishers of it, by the node's own bus statistics (getBusStats, ROS's
/// slave API); -1 if it has no connection for the topic (not subscribed, or not connected yet).
inline long messagesReceivedBy(const std::string& node, const std::string& topic)
{
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = node;
  if (!ros::master::execute("lookupNode", request, response, payload, false) ||
      payload.getType() != XmlRpc::XmlRpcValue::TypeString)
    return -1;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port))
    return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue ask, stats;
  ask[0] = ros::this_node::getName();
  if (!client.execute("getBusStats", ask, stats) || client.isFault())
    return -1;
  // [publications, subscriptions] (some versions wrap it as [code, message, it]); a subscription
  // is [topic, [[connection id, bytes, messages, drops, ...], ...]].
  XmlRpc::XmlRpcValue& both =
      stats.size() == 3 && stats[0].getType() == XmlRpc::XmlRpcValue::TypeInt ? stats[2] : stats;
  if (both.getType() != XmlRpc::XmlRpcValue::TypeArray || both.size() < 2)
    return -1;
  XmlRpc::XmlRpcValue& subscriptions = both[1];
  for (int i = 0; i < subscriptions.size(); ++i)
    if (static_cast<std::string>(subscriptions[i][0]) == topic)
    {
      XmlRpc::XmlRpcValue& connections = subscriptions[i][1];
      if (connections.size() == 0)
        return -1;
      long received = 0;
      for (int c = 0; c < connections.size(); ++c)
        received += static_cast<int>(connections[c][2]);
      return received;
    }
  return -1;
}

/// Waits until `node` is connected to a publisher of `topic` (latched messages then reach it at once).
inline bool connectedTo(const std::string& node, const std::string& topic, double timeout = kGenerousWait)
{
  return waitFor([&] { return messagesReceivedBy(node, topic) >= 0; }, timeout, 0.05);
}

/// Waits until `node` has received at least `count` messages of `topic`.
inline bool receivedBy(const std::string& node, const std::string& topic, long count, double timeout = kGenerousWait)
{
  return waitFor([&] { return messagesReceivedBy(node, topic) >= count; }, timeout, 0.05);
}
