// cue_sim/TableNodelet: the table node in a nodelet manager, beside consumers of its camera, which
// then get each image as a shared pointer instead of a copy over TCP (README, "The camera"). The
// same TableNode as table_node runs; its publishing loop runs on a thread of the nodelet's own.
#include <nodelet/nodelet.h>

#include <memory>
#include <pluginlib/class_list_macros.hpp>
#include <thread>

#include "node/table_node.hpp"
#include "node/thread_priority.hpp"

namespace cue_sim
{
class TableNodelet : public nodelet::Nodelet
{
public:
  ~TableNodelet() override
  {
    if (node_)
      node_->stop();
    if (publishing_.joinable())
      publishing_.join();
  }

private:
  void onInit() override
  {
    try
    {
      node_ = std::make_unique<TableNode>(getNodeHandle(), getPrivateNodeHandle());
    }
    catch (const std::exception& e)
    {
      // The manager stays up for its other nodelets; this one says why it has no table.
      NODELET_FATAL("cue_sim: the table cannot start: %s", e.what());
      throw;
    }
    publishing_ = std::thread([this] { node_->run(); });
  }

  std::unique_ptr<TableNode> node_;
  std::thread publishing_;
};

}  // namespace cue_sim

PLUGINLIB_EXPORT_CLASS(cue_sim::TableNodelet, nodelet::Nodelet)
