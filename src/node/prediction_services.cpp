#include "node/prediction_services.hpp"

#include <malloc.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <thread>

#include "node/game_messages.hpp"
#include "node/ros_conversions.hpp"
#include "node/shot_markers.hpp"
#include "node/thread_priority.hpp"

namespace cue_sim
{
namespace
{
/// How often the node looks whether heavy requests have stopped, to give the memory their replies
/// took back to the system.
const ros::WallDuration kTrimPeriod(2.0);

/// The queue's thread: lowered once, on its first request.
void lowerPriorityOnce()
{
  thread_local bool lowered = false;
  if (!lowered)
    lowerThisThreadsPriority();
  lowered = true;
}
}  // namespace

PredictionServices::PredictionServices(ros::NodeHandle& private_node, SharedTable& shared,
                                       const NodeParameters& parameters)
  : shared_(shared), parameters_(parameters)
{
  // Batches on one thread fewer than the cores: the publishing thread keeps a core.
  pool_ = std::make_unique<physics::ThreadPool>(std::max(1u, std::thread::hardware_concurrency()) - 1,
                                                lowerThisThreadsPriority);
  preview_publisher_ = private_node.advertise<visualization_msgs::MarkerArray>("preview", 1, true);
  ros::AdvertiseServiceOptions predict, batch;
  predict.init<Predict::Request, Predict::Response>(private_node.resolveName("predict"),
                                                    [this](Predict::Request& q, Predict::Response& r) {
                                                      lowerPriorityOnce();
                                                      return onPredict(q, r);
                                                    });
  batch.init<PredictBatch::Request, PredictBatch::Response>(
      private_node.resolveName("predict_batch"), [this](PredictBatch::Request& q, PredictBatch::Response& r) {
        lowerPriorityOnce();
        return onPredictBatch(q, r);
      });
  predict.callback_queue = batch.callback_queue = &queue_;
  services_ = {private_node.advertiseService(predict), private_node.advertiseService(batch)};
  ros::WallTimerOptions trim(
      kTrimPeriod, [this](const ros::WallTimerEvent&) { trimMemory(); }, &queue_);
  trim_timer_ = private_node.createWallTimer(trim);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
}

PredictionServices::~PredictionServices()
{
  spinner_->stop();
}

void PredictionServices::clearPreview()
{
  preview_publisher_.publish(clearedPreview());
}

void PredictionServices::trimMemory()
{
  // glibc keeps freed memory in its arenas: a batch's reply would stay with the node for good.
  // Trim once the requests stop, not while they run: malloc_trim holds the arenas' locks while it
  // returns memory (30 to 80 ms after batches of 3000 shots), and the publishing thread's own
  // allocations wait on them, pausing tf.
  if (recent_.exchange(false))
    return;
  if (ran_.exchange(false))
    malloc_trim(0);
}

bool PredictionServices::onPredict(Predict::Request& request, Predict::Response& response)
{
  ran_ = recent_ = true;
  session::PredictionStart start;
  std::string why = session::whyBadSamplePeriod(request.sample_period);
  long layout = 0, strikes = 0;  // the table the preview is of
  if (why.empty())
  {
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    why = shared_.live->predictionStart(toBallInputs(request.balls), toStamp(shared_.now()), start);
    layout = shared_.live->motion().layoutVersion();
    strikes = shared_.live->motion().strikeCount();
  }
  if (!why.empty())
  {
    response.prediction.executed = request.shot;
    response.prediction.message = why;
    return true;
  }
  // The shot runs once: its trajectories draw the preview.
  const session::PredictionOptions options{request.sample_period, request.noise ? &parameters_.table.noise : nullptr,
                                           request.seed, true};
  const session::ShotPrediction prediction =
      session::predictShot(*start.engine, start.table, toSessionShot(request.shot), options, parameters_.table.limits);
  response.prediction =
      toPredictionMsg(prediction, start.engine->table(), request.sample_period, parameters_.table_frame);
  game::Ruling ruling;
  const bool refereed = session::predictedRuling(start, prediction, ruling);
  response.prediction.ruling = toRulingMsg(ruling, refereed);
  if (prediction.success)
  {
    const visualization_msgs::MarkerArray preview =
        previewMarkers(session::previewPaths(prediction, start.engine->params()), parameters_.table_frame,
                       ballSetFor(start.engine->table()));
    // Drawn only if the table has not moved on meanwhile (the publishing thread clears a preview
    // when it does, under the same lock).
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    if (shared_.live->motion().layoutVersion() == layout && shared_.live->motion().strikeCount() == strikes)
      preview_publisher_.publish(preview);
  }
  return true;
}

bool PredictionServices::onPredictBatch(PredictBatch::Request& request, PredictBatch::Response& response)
{
  ran_ = recent_ = true;
  const session::PredictionLimits& limits = parameters_.table.limits;
  session::PredictionStart start;
  std::string why = session::whyBadSamplePeriod(request.sample_period);
  if (why.empty() && request.shots.size() > limits.max_batch_shots)
    why = "shots: " + std::to_string(request.shots.size()) +
          " shots, at most ~max_batch_shots = " + std::to_string(limits.max_batch_shots);
  if (why.empty())
  {
    std::lock_guard<PriorityInheritingMutex> lock(shared_.mutex);
    why = shared_.live->predictionStart(toBallInputs(request.balls), toStamp(shared_.now()), start);
  }
  std::vector<session::ShotPrediction> predictions;
  if (why.empty())
  {
    std::vector<session::Shot> shots;
    shots.reserve(request.shots.size());
    for (const auto& s : request.shots)
      shots.push_back(toSessionShot(s));
    const session::PredictionOptions options{request.sample_period, request.noise ? &parameters_.table.noise : nullptr,
                                             request.seed};
    predictions = session::predictBatch(*start.engine, start.table, shots, options, limits, *pool_, why);
  }
  response.success = why.empty();
  response.message = why;
  if (!why.empty())
    return true;
  std::size_t succeeded = 0;
  response.predictions.reserve(predictions.size());
  for (auto& p : predictions)
  {
    succeeded += p.success;
    response.predictions.push_back(
        toPredictionMsg(p, start.engine->table(), request.sample_period, parameters_.table_frame));
    game::Ruling ruling;
    const bool refereed = session::predictedRuling(start, p, ruling);
    response.predictions.back().ruling = toRulingMsg(ruling, refereed);
    p = session::ShotPrediction();  // the message holds it now
  }
  response.message = std::to_string(succeeded) + " of " + std::to_string(request.shots.size()) +
                     " shots predicted on " + std::to_string(pool_->size()) + " threads";
  return true;
}

}  // namespace cue_sim
