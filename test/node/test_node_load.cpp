// The tick never waits: tf keeps its rate while a batch at ~max_batch_shots, predictions with
// samples and a stream of ~strike_cue calls in a frame tf does not know run at once, and a
// batch over the limit is refused before any work. Through a real master.
#include <cue_sim/StrikeCue.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <tf2_msgs/TFMessage.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "table_client.hpp"

namespace
{
constexpr double kPublishRate = 100.0;  // config/table_node.yaml
constexpr int kBatchLimit = 3000;       // node_load.test

class NodeLoadTest : public ::testing::Test
{
protected:
  NodeLoadTest()
  {
    tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>("/tf", 1000, [this](const tf2_msgs::TFMessageConstPtr& m) {
      for (const auto& t : m->transforms)
        if (t.child_frame_id == "ball_0")
        {
          std::lock_guard<std::mutex> lock(mutex_);
          stamps_.push_back(t.header.stamp);
        }
    });
  }

  /// Ticks stamped in [from, to).
  std::size_t ticksBetween(const ros::Time& from, const ros::Time& to)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t n = 0;
    for (const auto& s : stamps_)
      n += s >= from && s < to;
    return n;
  }

  /// The longest time between two ticks stamped in [from, to).
  double longestGap(const ros::Time& from, const ros::Time& to)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    double gap = 0;
    for (std::size_t i = 1; i < stamps_.size(); ++i)
      if (stamps_[i - 1] >= from && stamps_[i] < to)
        gap = std::max(gap, (stamps_[i] - stamps_[i - 1]).toSec());
    return gap;
  }

  ros::NodeHandle nh_;
  TableClient table_;
  std::mutex mutex_;
  std::vector<ros::Time> stamps_;
  ros::Subscriber tf_sub_;  // last: destroyed first
};

std::vector<cue_sim::Shot> breaks(std::size_t count)
{
  std::vector<cue_sim::Shot> shots;
  for (std::size_t i = 0; i < count; ++i)
    shots.push_back(TableClient::shot(0, 2.0 + 6.0 * static_cast<double>(i) / count, 0.001 * static_cast<double>(i)));
  return shots;
}

/// The load's clients stand for programs on other machines or cores: on the test's 2-core machine
/// they yield the cores to the node (their own work, deserializing 3000-shot replies, would
/// otherwise take the tf thread's turn), as the node's own heavy threads yield to its tf thread.
void yieldToTheNode()
{
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
}

TEST_F(NodeLoadTest, TfKeepsItsRateWhileHeavyRequestsRun)
{
  ASSERT_TRUE(table_.rack("eight").success);
  ros::WallDuration(1.0).sleep();

  // A batch over the limit is refused at once, saying how big it is and what the limit is.
  const ros::WallTime asked = ros::WallTime::now();
  const cue_sim::PredictBatch::Response over = table_.predictBatch(breaks(kBatchLimit + 1), {});
  EXPECT_FALSE(over.success);
  EXPECT_NE(over.message.find(std::to_string(kBatchLimit + 1) +
                              " shots, at most ~max_batch_shots = " + std::to_string(kBatchLimit)),
            std::string::npos)
      << over.message;
  EXPECT_LT((ros::WallTime::now() - asked).toSec(), 1.0) << "refused before any work";

  std::atomic<bool> stop{false};
  std::atomic<int> batches{0}, refused_cues{0}, sampled{0};
  std::vector<std::thread> load;
  load.emplace_back([&] {
    yieldToTheNode();
    while (!stop)
    {
      const cue_sim::PredictBatch::Response r = table_.predictBatch(breaks(kBatchLimit), {});
      EXPECT_TRUE(r.success) << r.message;
      EXPECT_EQ(r.predictions.size(), static_cast<std::size_t>(kBatchLimit));
      ++batches;
    }
  });
  load.emplace_back([&] {
    yieldToTheNode();
    ros::NodeHandle nh;
    ros::ServiceClient client = nh.serviceClient<cue_sim::StrikeCue>("/table/strike_cue");
    while (!stop)
    {
      cue_sim::StrikeCue srv;
      srv.request.cue.header.frame_id = "no_such_robot";
      srv.request.cue.pose.orientation.w = 1;
      srv.request.speed = 1.0;
      ASSERT_TRUE(client.call(srv));
      EXPECT_FALSE(srv.response.success);
      refused_cues += srv.response.message.find("cannot transform") != std::string::npos;
    }
  });
  load.emplace_back([&] {
    yieldToTheNode();
    while (!stop)
    {
      const cue_sim::Prediction p = table_.predict(TableClient::shot(0, 2.0, 0.0), {}, 0.001);
      EXPECT_TRUE(p.success) << p.message;
      ++sampled;
    }
  });
  ros::WallDuration(1.0).sleep();  // the load under way
  const ros::Time from = ros::Time::now();
  ros::WallDuration(6.0).sleep();
  const ros::Time to = ros::Time::now();
  stop = true;
  for (auto& t : load)
    t.join();
  ros::WallDuration(0.5).sleep();  // the last ticks arrive

  EXPECT_GT(batches, 0);
  EXPECT_GT(refused_cues, 20) << "each unknown frame waits ~tf_timeout (50 ms)";
  EXPECT_GT(sampled, 0);
  const double seconds = (to - from).toSec();
  const double rate = static_cast<double>(ticksBetween(from, to)) / seconds;
  std::printf(
      "under load for %.1f s: tf at %.1f Hz (set %.0f Hz), longest pause %.1f ms; %d batches of %d shots, "
      "%d cue poses refused, %d sampled predictions\n",
      seconds, rate, kPublishRate, 1e3 * longestGap(from, to), batches.load(), kBatchLimit, refused_cues.load(),
      sampled.load());
  EXPECT_GT(rate, 0.9 * kPublishRate) << "tf ticks per second under load";
  EXPECT_LT(rate, 1.1 * kPublishRate) << "tf ticks per second under load";
  // Second by second too.
  for (int k = 0; k + 1 <= static_cast<int>(seconds); ++k)
  {
    const ros::Time a = from + ros::Duration(k), b = a + ros::Duration(1.0);
    EXPECT_GE(ticksBetween(a, b), static_cast<std::size_t>(0.9 * kPublishRate)) << "second " << k;
  }
  EXPECT_LT(longestGap(from, to), 5.0 / kPublishRate) << "the longest pause of tf under load [s]";
}
}  // namespace
