#include <stdexcept>

#include "cue_sim/physics/collision_models.hpp"

namespace cue_sim
{
namespace physics
{
std::vector<std::string> ballBallModelNames()
{
  return {"frictional", "frictionless"};
}

std::vector<std::string> cushionModelNames()
{
  return {"han2005", "simple"};
}

namespace
{
std::string joined(const std::vector<std::string>& names)
{
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}
}  // namespace

template <typename S>
std::unique_ptr<BallBallModel<S>> makeBallBallModel(const std::string& name)
{
  if (name == "frictional")
    return std::make_unique<FrictionalBallBall<S>>();
  if (name == "frictionless")
    return std::make_unique<FrictionlessBallBall<S>>();
  throw std::invalid_argument("unknown ball-ball model '" + name + "' (known: " + joined(ballBallModelNames()) + ")");
}

template <typename S>
std::unique_ptr<CushionModel<S>> makeCushionModel(const std::string& name)
{
  if (name == "han2005")
    return std::make_unique<HanCushion<S>>();
  if (name == "simple")
    return std::make_unique<SimpleCushion<S>>();
  throw std::invalid_argument("unknown cushion model '" + name + "' (known: " + joined(cushionModelNames()) + ")");
}

template std::unique_ptr<BallBallModel<double>> makeBallBallModel(const std::string&);
template std::unique_ptr<BallBallModel<long double>> makeBallBallModel(const std::string&);
template std::unique_ptr<CushionModel<double>> makeCushionModel(const std::string&);
template std::unique_ptr<CushionModel<long double>> makeCushionModel(const std::string&);

}  // namespace physics
}  // namespace cue_sim
