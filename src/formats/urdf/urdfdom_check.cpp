#include "formats/urdf/urdfdom_check.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

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

}  // namespace

std::vector<std::string> urdfdom_errors(std::string_view document) {
  std::lock_guard lock(urdfdom_mutex);
  CollectingHandler handler;
  console_bridge::useOutputHandler(&handler);
  bool accepted = false;
  try {
    accepted = ::urdf::parseURDF(std::string(document)) != nullptr;
  } catch (const std::exception& error) {
    handler.messages.push_back(error.what());
  }
  console_bridge::restorePreviousOutputHandler();
  if (accepted) return {};
  if (handler.messages.empty()) handler.messages.push_back("urdfdom rejected the model");
  return std::move(handler.messages);
}

}  // namespace assetlint::urdf
