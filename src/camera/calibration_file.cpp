#include "cue_sim/camera/calibration_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cue_sim
{
namespace camera
{
std::string defaultCalibrationPath()
{
  // As table names find their URDF files: $CUE_SIM_CONFIG_DIR first, then the source tree, then
  // the install space (CUE_SIM_CONFIG_DIRS).
  std::string dirs;
  if (const char* env = std::getenv("CUE_SIM_CONFIG_DIR"))
    dirs = std::string(env) + ":";
  dirs += CUE_SIM_CONFIG_DIRS;
  std::istringstream list(dirs);
  std::string dir, tried;
  while (std::getline(list, dir, ':'))
  {
    if (dir.empty())
      continue;
    const std::string candidate = dir + "/" + kDefaultCalibrationFile;
    if (std::ifstream(candidate).good())
      return candidate;
    tried += (tried.empty() ? "" : ", ") + candidate;
  }
  throw std::invalid_argument("the default calibration is in none of " + tried +
                              " (set CUE_SIM_CONFIG_DIR to the package's config folder)");
}

Intrinsics intrinsicsFromFile(const std::string& path)
{
  try
  {
    const YAML::Node file = YAML::LoadFile(path);
    Intrinsics k;
    k.width = file["image_width"].as<int>();
    k.height = file["image_height"].as<int>();
    const auto m = file["camera_matrix"]["data"].as<std::vector<double>>();
    if (m.size() != 9)
      throw std::invalid_argument("camera_matrix has " + std::to_string(m.size()) + " numbers, not 9");
    k.fx = m[0];
    k.cx = m[2];
    k.fy = m[4];
    k.cy = m[5];
    if (file["distortion_model"] && file["distortion_model"].as<std::string>() != "plumb_bob")
      throw std::invalid_argument("distortion_model is '" + file["distortion_model"].as<std::string>() +
                                  "', only plumb_bob is drawn");
    const auto d = file["distortion_coefficients"]["data"].as<std::vector<double>>();
    for (std::size_t i = 0; i < k.distortion.size() && i < d.size(); ++i)
      k.distortion[i] = d[i];
    const std::string why = k.whyInvalid();
    if (!why.empty())
      throw std::invalid_argument(why);
    return k;
  }
  catch (const YAML::Exception& e)
  {
    throw std::invalid_argument("calibration '" + path + "': " + e.what());
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument("calibration '" + path + "': " + e.what());
  }
}

}  // namespace camera
}  // namespace cue_sim
