#include "node/node_parameters.hpp"

#include <fstream>
#include <sstream>

#include "cue_sim/table_description/table_catalog.hpp"
#include "cue_sim/table_description/urdf_table_loader.hpp"

namespace cue_sim
{
namespace
{
std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
    throw std::runtime_error("cannot read URDF file '" + path + "'");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

[[noreturn]] void refuse(const std::string& name, double value, const std::string& range)
{
  std::ostringstream why;
  why << "~" << name << " must be in " << range << ", got " << value;
  throw std::runtime_error(why.str());
}

/// A non-negative integer parameter (XML-RPC has no unsigned or 64-bit integers).
std::size_t readCount(ros::NodeHandle& private_node, const std::string& name, std::size_t fallback)
{
  int value = static_cast<int>(fallback);
  private_node.param(name, value, value);
  if (value < 1)
    refuse(name, value, "[1, 2147483647]");
  return static_cast<std::size_t>(value);
}

void readNoise(ros::NodeHandle& private_node, session::LiveTableOptions& options)
{
  // Off by default; the deviations default to those of the computational pool tournaments.
  physics::ExecutionNoise& noise = options.noise;
  private_node.param("noise/enabled", options.noise_enabled, false);
  private_node.param("noise/speed", noise.speed, noise.speed);
  private_node.param("noise/phi", noise.phi, noise.phi);
  private_node.param("noise/theta", noise.theta, noise.theta);
  private_node.param("noise/a", noise.a, noise.a);
  private_node.param("noise/b", noise.b, noise.b);
  int seed = 0;
  private_node.param("noise/seed", seed, 0);
  if (seed < 0)
    refuse("noise/seed", seed, "[0, 2147483647]");
  options.noise_seed = static_cast<std::uint64_t>(seed);
}

void readTable(ros::NodeHandle& node, ros::NodeHandle& private_node, NodeParameters& p)
{
  // The table comes from ~urdf_file, else the robot_description parameter, else ~table by name.
  std::string urdf_file, table_name = "7ft";
  private_node.param("urdf_file", urdf_file, urdf_file);
  private_node.param("table", table_name, table_name);
  try
  {
    if (!urdf_file.empty())
      p.urdf_xml = readFile(urdf_file);
    else if (!node.getParam("robot_description", p.urdf_xml))
      p.urdf_xml = readFile(tableUrdfPath(table_name));
    p.table_model = std::make_shared<const physics::TableModel>(tableFromUrdf(p.urdf_xml, p.table_frame));
  }
  catch (const TableDescriptionError& e)
  {
    throw std::runtime_error(std::string("table description: ") + e.what());
  }
}
}  // namespace

NodeParameters readNodeParameters(ros::NodeHandle& node, ros::NodeHandle& private_node, bool sim_time)
{
  NodeParameters p;
  session::LiveTableOptions& options = p.table;
  private_node.param("publish_rate", p.publish_rate, p.publish_rate);
  private_node.param("table_frame", p.table_frame, p.table_frame);
  private_node.param("world_frame", p.world_frame, p.world_frame);
  private_node.param("ball_frame_prefix", p.ball_frame_prefix, p.ball_frame_prefix);
  private_node.param("rack", p.rack, p.rack);
  private_node.param("real_time_factor", p.real_time_factor, p.real_time_factor);
  private_node.param("tf_timeout", p.tf_timeout, p.tf_timeout);
  private_node.param("aim_marker", p.aim_marker, p.aim_marker);
  private_node.param("allow_strike_while_moving", options.allow_strike_while_moving, false);
  private_node.param("rack_gap", options.rack_gap, options.rack_gap);
  private_node.param("paused", options.paused, false);
  options.limits.max_batch_shots = readCount(private_node, "max_batch_shots", options.limits.max_batch_shots);
  options.limits.max_samples = readCount(private_node, "max_samples", options.limits.max_samples);
  options.limits.max_reply_bytes = readCount(private_node, "max_reply_mb", options.limits.max_reply_bytes >> 20) << 20;
  readNoise(private_node, options);

  if (!(p.publish_rate > 0 && p.publish_rate <= 10000))
    refuse("publish_rate", p.publish_rate, "(0, 10000] Hz");
  if (!(p.real_time_factor >= 0 && p.real_time_factor <= session::kMaxRealTimeFactor))
    refuse("real_time_factor", p.real_time_factor, "[0, 1000] (0: as fast as possible, with use_sim_time)");
  if (p.real_time_factor == 0 && !sim_time)
    throw std::runtime_error(
        "~real_time_factor 0 (as fast as possible) needs use_sim_time: the node then drives /clock");
  if (!(p.tf_timeout > 0 && p.tf_timeout <= kMaxTfTimeout))
    refuse("tf_timeout", p.tf_timeout, "(0, 1] s");
  for (const std::string* frame : {&p.table_frame, &p.world_frame, &p.ball_frame_prefix})
    if (frame->empty() || frame->front() == '/')
      throw std::runtime_error("frame ids must be non-empty and without a leading '/', got '" + *frame + "'");
  // With sim time the node's /clock runs at the real-time factor, and physics follows /clock.
  options.real_time_factor = sim_time ? 1.0 : p.real_time_factor;
  const std::string why = options.whyInvalid();
  if (!why.empty())
    throw std::runtime_error("~" + why);

  for (const auto& field : physics::physicsParamFields())
    private_node.param(field.name, p.physics.*field.member, p.physics.*field.member);
  const std::string bad_physics = p.physics.validate();
  if (!bad_physics.empty())
    throw std::runtime_error("physics parameter ~" + bad_physics);
  private_node.param("ball_ball_model", p.models.ball_ball, p.models.ball_ball);
  private_node.param("cushion_model", p.models.cushion, p.models.cushion);
  readTable(node, private_node, p);
  return p;
}

}  // namespace cue_sim
