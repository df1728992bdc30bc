#include "formats/urdf/urdfdom_check.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <atomic>
#include <mutex>

namespace assetlint::urdf {
namespace {

class CollectingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) messages.push_back(text);
  }
  std::vector<std::string> messages;
};

// console_bridge's output handler is process-wide, so urdfdom runs one file at a time.
std::mutex urdfdom_mutex;
std::atomic<std::size_t> runs{0};

}  // namespace

std::vector<std::string> urdfdom_errors(std::string_view document) {
  std::lock_guard lock(urdfdom_mutex);
  ++runs;
  CollectingHandler handler;
  console_bridge::useOutputHandler(&handler);
  bool accepted = false;
  try {
    const ::urdf::ModelInterfaceSharedPtr model = ::urdf::parseURDF(std::string(document));
    accepted = model != nullptr;
    // A model urdfdom accepts can still hold a joint cycle beside its tree; links then own
    // each other through child_links and would never be freed.
    if (model)
      for (auto& [name, link] : model->links_) {
        link->child_links.clear();
        link->child_joints.clear();
      }
  } catch (const std::exception& error) {
    handler.messages.push_back(error.what());
  }
  console_bridge::restorePreviousOutputHandler();
  if (accepted) return {};
  if (handler.messages.empty()) handler.messages.push_back("urdfdom rejected the model");
  return std::move(handler.messages);
}

std::size_t urdfdom_runs() { return runs.load(); }

}  // namespace assetlint::urdf
