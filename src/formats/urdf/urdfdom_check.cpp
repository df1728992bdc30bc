#include "formats/urdf/urdfdom_check.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <atomic>
#include <mutex>
#include <string>

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

// urdfdom hands some of its messages, with the document's text in them, to console_bridge as
// the format string ("Unable to parse component [x%n] to a double"): a '%' of the document
// would be read as a conversion (and %n writes through a stray pointer). Doubled, every '%'
// prints as itself, and the document keeps its verdict (a '%' is the same kind of character
// as two, and distinct names stay distinct).
std::string percent_doubled(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 16);
  for (char c : text) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

// The messages that passed the document's text as an argument show the doubled '%' as is.
void undo_doubling(std::string& message) {
  for (std::size_t at = 0; (at = message.find("%%", at)) != std::string::npos; ++at) message.erase(at, 1);
}

}  // namespace

std::vector<std::string> urdfdom_errors(std::string_view document) {
  std::lock_guard lock(urdfdom_mutex);
  ++runs;
  CollectingHandler handler;
  console_bridge::useOutputHandler(&handler);
  bool accepted = false;
  const bool has_percent = document.find('%') != std::string_view::npos;
  try {
    const ::urdf::ModelInterfaceSharedPtr model = ::urdf::parseURDF(has_percent ? percent_doubled(document) : std::string(document));
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
  if (has_percent)
    for (std::string& m : handler.messages) undo_doubling(m);
  if (handler.messages.empty()) handler.messages.push_back("urdfdom rejected the model");
  return std::move(handler.messages);
}

std::size_t urdfdom_runs() { return runs.load(); }

}  // namespace assetlint::urdf
