#include "node/node_parameters.hpp"

#include <algorithm>
#include <fstream>
#include <set>
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

template <typename T>
const char* kindOf();
template <>
const char* kindOf<double>()
{
  return "a number";
}
template <>
const char* kindOf<int>()
{
  return "an integer";
}
template <>
const char* kindOf<bool>()
{
  return "true or false";
}
template <>
const char* kindOf<std::string>()
{
  return "a string";
}

/// Reads private parameters, each of its kind (a wrong kind is refused, not replaced by the
/// default), and knows which it read: any other private parameter is a misspelling.
class ParameterReader
{
public:
  explicit ParameterReader(ros::NodeHandle& private_node) : node_(private_node) {}

  template <typename T>
  void read(const std::string& name, T& value)
  {
    known_.insert(name);
    if (node_.hasParam(name) && !node_.getParam(name, value))
      throw std::runtime_error("~" + name + " must be " + kindOf<T>());
  }

  /// A non-negative integer (XML-RPC has no unsigned or 64-bit integers).
  std::size_t count(const std::string& name, std::size_t fallback)
  {
    int value = static_cast<int>(fallback);
    read(name, value);
    if (value < 1)
      refuse(name, value, "[1, 2147483647]");
    return static_cast<std::size_t>(value);
  }

  /// A seed: a non-negative integer (XML-RPC has no unsigned integers).
  std::uint32_t seed(const std::string& name)
  {
    int value = 0;
    read(name, value);
    if (value < 0)
      refuse(name, value, "[0, 2147483647]");
    return static_cast<std::uint32_t>(value);
  }

  /// Throws naming the first private parameter nothing read, and the known ones.
  void refuseUnknown() const
  {
    std::vector<std::string> names;
    node_.getParamNames(names);
    const std::string prefix = node_.getNamespace() + "/";
    for (const std::string& name : names)
    {
      if (name.compare(0, prefix.size(), prefix) != 0)
        continue;
      const std::string key = name.substr(prefix.size());
      if (known_.count(key) || belowAGroup(key))
        continue;
      std::string list;
      for (const auto& k : known_)
        list += (list.empty() ? "" : ", ") + k;
      throw std::runtime_error("unknown parameter ~" + key + " (known: " + list + ")");
    }
  }

private:
  /// Whether `key` lies a level below one of the table's groups (camera/rectify/interpolation):
  /// the space of another node in the table's namespace, not a parameter of the table's. image_proc's
  /// rectify in ~camera keeps its parameters there, set whenever its nodelet loads, before or after
  /// the table; image_transport's plugins keep theirs under ~camera/image_raw. A misspelling within a
  /// group (~camera/widht) is still one level down, and refused.
  bool belowAGroup(const std::string& key) const
  {
    const std::size_t slash = key.find('/');
    if (slash == std::string::npos || key.find('/', slash + 1) == std::string::npos)
      return false;
    const std::string group = key.substr(0, slash + 1);
    return std::any_of(known_.begin(), known_.end(),
                       [&](const std::string& k) { return k.compare(0, group.size(), group) == 0; });
  }

  ros::NodeHandle& node_;
  std::set<std::string> known_;
};

void readCamera(ParameterReader& reader, CameraParameters& camera)
{
  reader.read("camera/enabled", camera.enabled);
  reader.read("camera/frame", camera.frame);
  reader.read("camera/rate", camera.rate);
  reader.read("camera/exposure", camera.exposure);
  reader.read("camera/noise", camera.noise);
  reader.read("camera/queue_size", camera.queue_size);
  reader.read("camera/info_url", camera.info_url);
  reader.read("camera/width", camera.width);
  reader.read("camera/height", camera.height);
  reader.read("camera/publish_frame", camera.publish_frame);
  const char* axes[6] = {"x", "y", "z", "roll", "pitch", "yaw"};
  for (int i = 0; i < 6; ++i)
  {
    reader.read(std::string("camera/") + axes[i], camera.pose[i]);
    if (!std::isfinite(camera.pose[i]) || std::abs(camera.pose[i]) > 100)
      refuse(std::string("camera/") + axes[i], camera.pose[i], "[-100, 100]");
  }
  if (!(camera.rate > 0 && camera.rate <= 120))
    refuse("camera/rate", camera.rate, "(0, 120] Hz");
  if (!(camera.exposure >= 0 && camera.exposure <= 0.1))
    refuse("camera/exposure", camera.exposure, "[0, 0.1] s");
  if (!(camera.noise >= 0 && camera.noise <= 50))
    refuse("camera/noise", camera.noise, "[0, 50] levels");
  if (camera.queue_size < 1 || camera.queue_size > kMaxCameraQueue)
    refuse("camera/queue_size", camera.queue_size, "[1, " + std::to_string(kMaxCameraQueue) + "] images");
  for (const auto& [name, value] :
       {std::pair<const char*, int>{"camera/width", camera.width}, {"camera/height", camera.height}})
    if (value != 0 && (value < 16 || value > 8192))
      refuse(name, value, "{0} or [16, 8192] px");
  if ((camera.width == 0) != (camera.height == 0))
    throw std::runtime_error("~camera/width and ~camera/height: set both or neither");
  if (camera.frame.empty() || camera.frame.front() == '/')
    throw std::runtime_error("~camera/frame must be non-empty and without a leading '/', got '" + camera.frame + "'");
}

void readCue(ParameterReader& reader, CueParameters& cue)
{
  reader.read("cue/frame", cue.frame);
  if (!cue.frame.empty() && cue.frame.front() == '/')
    throw std::runtime_error("~cue/frame must be without a leading '/', got '" + cue.frame + "'");
  for (const session::CueFollowerField& field : session::cueFollowerFields())
    reader.read(std::string("cue/") + field.name, cue.follower.*field.member);
  if (const std::string why = cue.follower.whyInvalid(); !why.empty())
    throw std::runtime_error("~cue/" + why);  // names the setting, its value and its range
}

void readNoise(ParameterReader& reader, session::LiveTableOptions& options)
{
  // Off by default; the deviations default to those of the computational pool tournaments.
  physics::ExecutionNoise& noise = options.noise;
  reader.read("noise/enabled", options.noise_enabled);
  reader.read("noise/speed", noise.speed);
  reader.read("noise/phi", noise.phi);
  reader.read("noise/theta", noise.theta);
  reader.read("noise/a", noise.a);
  reader.read("noise/b", noise.b);
  options.noise_seed = reader.seed("noise/seed");
}

void readTable(ros::NodeHandle& node, ParameterReader& reader, NodeParameters& p)
{
  // The table comes from ~urdf_file, else the robot_description parameter, else ~table by name.
  std::string urdf_file, table_name = "7ft";
  reader.read("urdf_file", urdf_file);
  reader.read("table", table_name);
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
  ParameterReader reader(private_node);
  reader.read("publish_rate", p.publish_rate);
  reader.read("table_frame", p.table_frame);
  reader.read("world_frame", p.world_frame);
  reader.read("ball_frame_prefix", p.ball_frame_prefix);
  reader.read("rack", p.rack);
  reader.read("real_time_factor", p.real_time_factor);
  reader.read("tf_timeout", p.tf_timeout);
  reader.read("aim_marker", p.aim_marker);
  reader.read("allow_strike_while_moving", options.allow_strike_while_moving);
  reader.read("rack_gap", options.rack_gap);
  reader.read("rack_jitter", options.rack_jitter);
  options.rack_seed = reader.seed("rack_seed");
  reader.read("paused", options.paused);
  options.limits.max_batch_shots = reader.count("max_batch_shots", options.limits.max_batch_shots);
  options.limits.max_samples = reader.count("max_samples", options.limits.max_samples);
  options.limits.max_reply_bytes = reader.count("max_reply_mb", options.limits.max_reply_bytes >> 20) << 20;
  readNoise(reader, options);
  readCamera(reader, p.camera);
  readCue(reader, p.cue);

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

  readTable(node, reader, p);
  // The table's own balls (a snooker or carom table names them) unless ~ball_radius or
  // ~ball_mass say otherwise; the values used go on the parameter server, where
  // dynamic_reconfigure takes its first configuration from.
  p.physics = physics::tableDefaults(*p.table_model);
  for (const auto& field : physics::physicsParamFields())
    reader.read(field.name, p.physics.*field.member);
  for (const char* name : {"ball_radius", "ball_mass"})
    if (!private_node.hasParam(name))
      for (const auto& field : physics::physicsParamFields())
        if (std::string(field.name) == name)
          private_node.setParam(name, p.physics.*field.member);
  const std::string bad_physics = p.physics.validate();
  if (!bad_physics.empty())
    throw std::runtime_error("physics parameter ~" + bad_physics);
  reader.read("ball_ball_model", p.models.ball_ball);
  reader.read("cushion_model", p.models.cushion);
  reader.read("ball_table_model", p.models.ball_table);
  reader.read("cue_model", p.models.cue);
  reader.refuseUnknown();
  return p;
}

}  // namespace cue_sim
