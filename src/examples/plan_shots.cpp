// Plans a break-off shot with ~predict_batch: every heading round the cue ball at three speeds,
// all on the node's cores in one call; keeps the shot that pockets the most object balls without
// the cue ball, and strikes it. Run it next to a table: rosrun cue_sim plan_shots
#include <cue_sim/PredictBatch.h>
#include <cue_sim/Strike.h>
#include <ros/ros.h>

#include <cmath>
#include <cstdio>

int pocketed(const cue_sim::Prediction& p)  // object balls pocketed; -1 if the cue ball drops
{
  int count = 0;
  for (const cue_sim::Event& e : p.events)
    if (e.kind == cue_sim::Event::POCKETED)
      count = (e.ball_id == 0 || count < 0) ? -1 : count + 1;
  return p.success ? count : -1;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "plan_shots");
  ros::NodeHandle node;
  ros::service::waitForService("/table/predict_batch");
  cue_sim::PredictBatch batch;
  for (double speed : {2.0, 4.0, 6.0})
    for (int k = 0; k < 72; ++k)
    {
      cue_sim::Shot shot;
      shot.ball_id = 0;
      shot.speed = speed;
      shot.phi = 2 * M_PI * k / 72;
      batch.request.shots.push_back(shot);
    }
  if (!ros::service::call("/table/predict_batch", batch) || !batch.response.success)
    return 1;
  std::size_t best = 0;
  for (std::size_t i = 1; i < batch.response.predictions.size(); ++i)
    if (pocketed(batch.response.predictions[i]) > pocketed(batch.response.predictions[best]))
      best = i;
  const cue_sim::Shot& shot = batch.request.shots[best];
  std::printf("best of %zu shots: speed %.1f m/s, phi %.3f rad, pockets %d\n", batch.request.shots.size(), shot.speed,
              shot.phi, pocketed(batch.response.predictions[best]));
  cue_sim::Strike strike;
  strike.request.ball_id = shot.ball_id;
  strike.request.speed = shot.speed;
  strike.request.phi = shot.phi;
  if (!ros::service::call("/table/strike", strike) || !strike.response.success)
    return 1;
  std::printf("%s\n", strike.response.message.c_str());
  return 0;
}
