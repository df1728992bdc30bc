#include "engine/collision.h"

#include <atomic>

namespace assetlint::collision {
namespace {
std::atomic<const Engine*> g_engine{nullptr};
}  // namespace

const Engine* installed_engine() { return g_engine.load(); }
void install_engine(const Engine* engine) { g_engine.store(engine); }

}  // namespace assetlint::collision
