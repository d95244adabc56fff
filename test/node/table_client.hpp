// A test client of one table_node (by its name): service calls and the latest ~state, through
// a real master. Needs a running spinner (test/node/rostest_main.cpp starts one).
#pragma once

#include <cue_sim/Predict.h>
#include <cue_sim/PredictBatch.h>
#include <cue_sim/Rack.h>
#include <cue_sim/Strike.h>
#include <cue_sim/StrikeCue.h>
#include <cue_sim/TableState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "ros_conditions.hpp"

class TableClient
{
public:
  explicit TableClient(const std::string& node = "/table") : node_(node)
  {
    EXPECT_TRUE(ros::service::waitForService(node + "/predict_batch", ros::Duration(kGenerousWait))) << node;
    // Persistent: each is looked up at the master once, at its first call. A call on a plain
    // client looks the service up every time, in a single try (roscpp's lookupService does not
    // retry the master), so any failed exchange with the master on a loaded machine fails the
    // call at once, with nothing logged: so ~rack failed once in CI (FollowedCueTest, 2026-11-28).
    strike_ = nh_.serviceClient<cue_sim::Strike>(node + "/strike", true);
    predict_ = nh_.serviceClient<cue_sim::Predict>(node + "/predict", true);
    predict_batch_ = nh_.serviceClient<cue_sim::PredictBatch>(node + "/predict_batch", true);
    rack_ = nh_.serviceClient<cue_sim::Rack>(node + "/rack", true);
    strike_cue_ = nh_.serviceClient<cue_sim::StrikeCue>(node + "/strike_cue", true);
    state_sub_ = nh_.subscribe<cue_sim::TableState>(node + "/state", 10, [this](const cue_sim::TableStateConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      last_state_ = m;
    });
  }

  cue_sim::Rack::Response rack(const std::string& layout, const std::vector<int>& ids = {},
                               const std::vector<std::pair<double, double>>& xy = {})
  {
    cue_sim::Rack srv;
    srv.request.layout = layout;
    for (int id : ids)
      srv.request.ids.push_back(id);
    for (const auto& p : xy)
    {
      geometry_msgs::Point point;
      point.x = p.first;
      point.y = p.second;
      srv.request.positions.push_back(point);
    }
    EXPECT_TRUE(rack_.call(srv)) << node_;
    return srv.response;
  }

  /// The first ~state that shows a rack the node answered with `racked` (at rest, as a rack is).
  /// Under sim time the node's clock runs ahead of this client's: a state stamped after the
  /// client's now may still be from before the rack, so the wait is for the rack's own stamp.
  cue_sim::TableStateConstPtr afterRack(const cue_sim::Rack::Response& racked)
  {
    EXPECT_TRUE(racked.success) << racked.message;
    return stateAfter(racked.stamp);
  }

  static cue_sim::Shot shot(int ball, double speed, double phi, double theta = 0, double a = 0, double b = 0)
  {
    cue_sim::Shot s;
    s.ball_id = ball;
    s.speed = speed;
    s.phi = phi;
    s.theta = theta;
    s.a = a;
    s.b = b;
    return s;
  }

  cue_sim::Strike::Response strike(const cue_sim::Shot& s)
  {
    cue_sim::Strike srv;
    srv.request.ball_id = s.ball_id;
    srv.request.speed = s.speed;
    srv.request.phi = s.phi;
    srv.request.theta = s.theta;
    srv.request.a = s.a;
    srv.request.b = s.b;
    EXPECT_TRUE(strike_.call(srv)) << node_;
    return srv.response;
  }

  cue_sim::StrikeCue::Response strikeCue(const geometry_msgs::PoseStamped& cue, double speed)
  {
    cue_sim::StrikeCue srv;
    srv.request.cue = cue;
    srv.request.speed = speed;
    EXPECT_TRUE(strike_cue_.call(srv)) << node_;
    return srv.response;
  }

  cue_sim::Prediction predict(const cue_sim::Shot& s, const std::vector<cue_sim::BallState>& balls = {},
                              double sample_period = 0, bool noise = false, uint64_t seed = 0)
  {
    cue_sim::Predict srv;
    srv.request.shot = s;
    srv.request.balls = balls;
    srv.request.sample_period = sample_period;
    srv.request.noise = noise;
    srv.request.seed = seed;
    EXPECT_TRUE(predict_.call(srv)) << node_;
    return srv.response.prediction;
  }

  cue_sim::PredictBatch::Response predictBatch(const std::vector<cue_sim::Shot>& shots,
                                               const std::vector<cue_sim::BallState>& balls = {})
  {
    cue_sim::PredictBatch srv;
    srv.request.shots = shots;
    srv.request.balls = balls;
    EXPECT_TRUE(predict_batch_.call(srv)) << node_;
    return srv.response;
  }

  /// The first ~state message stamped after now. Waits in wall time: with sim time as fast as
  /// possible, a simulated 10 ms passes in next to no time.
  cue_sim::TableStateConstPtr freshState()
  {
    const ros::Time asked = ros::Time::now();
    cue_sim::TableStateConstPtr fresh;
    if (waitFor([&] {
          std::lock_guard<std::mutex> lock(mutex_);
          fresh = last_state_;
          return fresh && fresh->header.stamp > asked;
        }))
      return fresh;
    ADD_FAILURE() << "no " << node_ << "/state message stamped after " << asked;
    return boost::make_shared<cue_sim::TableState>();
  }

  /// The first ~state stamped at or after `stamp` (a time the node reported).
  cue_sim::TableStateConstPtr stateAfter(const ros::Time& stamp)
  {
    cue_sim::TableStateConstPtr after;
    if (waitFor([&] {
          std::lock_guard<std::mutex> lock(mutex_);
          after = last_state_;
          return after && after->header.stamp >= stamp;
        }))
      return after;
    ADD_FAILURE() << "no " << node_ << "/state message stamped at or after " << stamp;
    return boost::make_shared<cue_sim::TableState>();
  }

  /// The first ~state at rest, waiting at most `timeout` seconds of wall time (the shot's own
  /// duration, say) and kGenerousWait more for a loaded machine.
  cue_sim::TableStateConstPtr atRest(double timeout)
  {
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(timeout + kGenerousWait);
    while (ros::WallTime::now() < until)
    {
      const auto state = freshState();
      if (!state->moving)
        return state;
    }
    ADD_FAILURE() << node_ << ": balls still moving after " << timeout << " s";
    return freshState();
  }

  /// The first ~state at rest stamped after `stamp` (a strike's, which the node reported): under
  /// sim time a state at rest stamped after this client's clock may still be from before the
  /// strike. Waits at most `timeout` seconds of wall time and kGenerousWait more.
  cue_sim::TableStateConstPtr atRestAfter(const ros::Time& stamp, double timeout)
  {
    cue_sim::TableStateConstPtr rest;
    if (waitFor(
            [&] {
              std::lock_guard<std::mutex> lock(mutex_);
              rest = last_state_;
              return rest && rest->header.stamp > stamp && !rest->moving;
            },
            timeout + kGenerousWait))
      return rest;
    ADD_FAILURE() << node_ << ": no ~state at rest after " << stamp << " within " << timeout << " s";
    return boost::make_shared<cue_sim::TableState>();
  }

  static std::map<int, cue_sim::BallState> byId(const std::vector<cue_sim::BallState>& balls)
  {
    std::map<int, cue_sim::BallState> out;
    for (const auto& b : balls)
      out[b.id] = b;
    return out;
  }

private:
  std::string node_;
  ros::NodeHandle nh_;
  ros::ServiceClient strike_, predict_, predict_batch_, rack_, strike_cue_;
  std::mutex mutex_;
  cue_sim::TableStateConstPtr last_state_;
  // Last, so that it is destroyed first: no callback can then reach the members above.
  ros::Subscriber state_sub_;
};
