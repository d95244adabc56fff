// The contact models by name, from their one declaration (contact_models.def).
#include <stdexcept>
#include <type_traits>

#include "cue_sim/physics/collision_models.hpp"
#include "physics/models/model_factories.hpp"

namespace cue_sim
{
namespace physics
{
const std::vector<ModelInfo>& contactModels()
{
  static const std::vector<ModelInfo> models = {
#define CUE_SIM_MODEL(kind, name, summary, coefficients, reference) {#kind, #name, summary, coefficients, reference},
#include "cue_sim/physics/contact_models.def"
#undef CUE_SIM_MODEL
  };
  return models;
}

namespace
{
std::vector<std::string> namesOf(const std::string& kind)
{
  std::vector<std::string> names;
  for (const ModelInfo& model : contactModels())
    if (model.kind == kind)
      names.push_back(model.name);
  return names;
}

std::string joined(const std::vector<std::string>& names)
{
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}
}  // namespace

std::vector<std::string> ballBallModelNames()
{
  return namesOf("ball_ball");
}

std::vector<std::string> cushionModelNames()
{
  return namesOf("cushion");
}

std::vector<std::string> ballTableModelNames()
{
  return namesOf("ball_table");
}

std::vector<std::string> cueModelNames()
{
  return namesOf("cue");
}

namespace
{
std::string orDefault(std::string name, const std::vector<std::string>& names)
{
  return name.empty() ? names.front() : name;
}
}  // namespace

ModelChoice::ModelChoice() : ModelChoice("", "") {}

ModelChoice::ModelChoice(std::string ball_ball_model, std::string cushion_model, std::string ball_table_model,
                         std::string cue_model)
  : ball_ball(orDefault(std::move(ball_ball_model), ballBallModelNames())),
    cushion(orDefault(std::move(cushion_model), cushionModelNames())),
    ball_table(orDefault(std::move(ball_table_model), ballTableModelNames())),
    cue(orDefault(std::move(cue_model), cueModelNames()))
{
}

namespace
{
/// Keeps a made model when it is of the kind asked for: the declarations' loop below makes only
/// the one whose kind and name match, and this picks it up with its type.
template <typename Base, typename Made>
void keep(std::unique_ptr<Base>& out, std::unique_ptr<Made> made)
{
  if constexpr (std::is_same_v<Base, Made>)
    out = std::move(made);
}

template <typename Base>
std::unique_ptr<Base> madeByName(const std::string& kind, const std::string& name)
{
  using S = typename Base::Scalar;
  std::unique_ptr<Base> out;
#define CUE_SIM_MODEL(model_kind, model_name, ...)                                                                     \
  if (kind == #model_kind && name == #model_name)                                                                      \
    keep(out, make_##model_kind##_##model_name<S>());
#include "cue_sim/physics/contact_models.def"
#undef CUE_SIM_MODEL
  return out;
}
}  // namespace

template <typename S>
std::unique_ptr<BallBallModel<S>> makeBallBallModel(const std::string& name)
{
  if (auto model = madeByName<BallBallModel<S>>("ball_ball", name))
    return model;
  throw std::invalid_argument("unknown ball-ball model '" + name + "' (known: " + joined(ballBallModelNames()) + ")");
}

template <typename S>
std::unique_ptr<CushionModel<S>> makeCushionModel(const std::string& name)
{
  if (auto model = madeByName<CushionModel<S>>("cushion", name))
    return model;
  throw std::invalid_argument("unknown cushion model '" + name + "' (known: " + joined(cushionModelNames()) + ")");
}

template <typename S>
std::unique_ptr<BallTableModel<S>> makeBallTableModel(const std::string& name)
{
  if (auto model = madeByName<BallTableModel<S>>("ball_table", name))
    return model;
  throw std::invalid_argument("unknown ball-table model '" + name + "' (known: " + joined(ballTableModelNames()) + ")");
}

template <typename S>
std::unique_ptr<CueModel<S>> makeCueModel(const std::string& name)
{
  if (auto model = madeByName<CueModel<S>>("cue", name))
    return model;
  throw std::invalid_argument("unknown cue model '" + name + "' (known: " + joined(cueModelNames()) + ")");
}

template std::unique_ptr<BallBallModel<double>> makeBallBallModel(const std::string&);
template std::unique_ptr<BallBallModel<long double>> makeBallBallModel(const std::string&);
template std::unique_ptr<CushionModel<double>> makeCushionModel(const std::string&);
template std::unique_ptr<CushionModel<long double>> makeCushionModel(const std::string&);
template std::unique_ptr<BallTableModel<double>> makeBallTableModel(const std::string&);
template std::unique_ptr<BallTableModel<long double>> makeBallTableModel(const std::string&);
template std::unique_ptr<CueModel<double>> makeCueModel(const std::string&);
template std::unique_ptr<CueModel<long double>> makeCueModel(const std::string&);

}  // namespace physics
}  // namespace cue_sim
