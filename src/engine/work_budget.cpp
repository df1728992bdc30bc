#include "engine/work_budget.h"

#include <atomic>

namespace assetlint {
namespace {

std::atomic<double> per_file_seconds{kDefaultTimeBudgetSeconds};

}  // namespace

Deadline Deadline::after(double seconds) {
  Deadline deadline;
  if (seconds <= 0) return deadline;
  deadline.seconds_ = seconds;
  deadline.end_ = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  return deadline;
}

Deadline Deadline::for_one_file() { return after(per_file_seconds.load()); }

void set_time_budget(double seconds) { per_file_seconds.store(seconds); }
double time_budget() { return per_file_seconds.load(); }

}  // namespace assetlint
