// A camera calibration file as camera_info_manager writes and reads it (image_width,
// image_height, camera_matrix, distortion_model plumb_bob, distortion_coefficients), read without
// ROS, for the programs that draw camera pictures outside the node.
#pragma once

#include <string>

#include "cue_sim/camera/pinhole_camera.hpp"

namespace cue_sim
{
namespace camera
{
/// The calibration the node uses by default, relative to the package's config folder.
constexpr const char* kDefaultCalibrationFile = "camera/overhead_1920x1200.yaml";
/// Where that file is: in $CUE_SIM_CONFIG_DIR if set and there, else in the source tree, else in
/// the install space. Throws std::invalid_argument naming the places it looked.
std::string defaultCalibrationPath();
/// The intrinsics in a calibration file. Throws std::invalid_argument naming the file and what
/// is missing or wrong in it.
Intrinsics intrinsicsFromFile(const std::string& path);

}  // namespace camera
}  // namespace cue_sim
