// ~predict and ~predict_batch: heavy requests, on a queue and a thread of their own below the
// publishing thread's priority. Each takes its starting point from the live table under the
// lock and runs outside it; the memory its reply took goes back to the system soon after.
#pragma once

#include <cue_sim/Predict.h>
#include <cue_sim/PredictBatch.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <atomic>
#include <memory>

#include "cue_sim/physics/thread_pool.hpp"
#include "node/node_parameters.hpp"
#include "node/shared_table.hpp"

namespace cue_sim
{
class PredictionServices
{
public:
  PredictionServices(ros::NodeHandle& private_node, SharedTable& shared, const NodeParameters& parameters);
  ~PredictionServices();

  /// ~predict (also what the aim marker's "Predict" asks): draws the paths on ~preview.
  bool onPredict(Predict::Request& request, Predict::Response& response);
  bool onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response);
  /// Takes the preview off ~preview (the table was struck, racked, reset or edited). Call with
  /// shared_.mutex held.
  void clearPreview();

private:
  /// Gives the memory heavy requests freed back to the system.
  void trimMemory();

  SharedTable& shared_;
  const NodeParameters& parameters_;
  ros::CallbackQueue queue_;
  std::unique_ptr<physics::ThreadPool> pool_;  ///< batches' threads
  std::atomic<bool> ran_{false};               ///< a request ran since the last trim
  std::atomic<bool> recent_{false};            ///< a request ran since the trim timer last fired
  ros::Publisher preview_publisher_;
  ros::WallTimer trim_timer_;
  std::vector<ros::ServiceServer> services_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;  // last: stopped first
};

}  // namespace cue_sim
