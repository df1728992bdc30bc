#pragma once
// The wall-clock time the work on one file may take (--time-budget). The size limits bound what
// a file can make asset-lint build; this bounds what no size limit catches, so a hostile file
// ends with an error instead of holding a CI runner until the job's own timeout.
#include <chrono>
#include <optional>
#include <stdexcept>

namespace assetlint {

inline constexpr double kDefaultTimeBudgetSeconds = 60;

class Deadline {
 public:
  Deadline() = default;  // never passes
  static Deadline after(double seconds);
  // The process's budget per file (set_time_budget), counted from now.
  static Deadline for_one_file();

  bool passed() const { return end_ && std::chrono::steady_clock::now() >= *end_; }
  double budget_seconds() const { return seconds_; }

 private:
  std::optional<std::chrono::steady_clock::time_point> end_;
  double seconds_ = 0;
};

// Thrown where work on a file stops because its deadline passed; the file is reported as not
// checked, with this message.
struct TimeBudgetExceeded : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Set by the CLI before any file is read; 0 or less means no budget.
void set_time_budget(double seconds);
double time_budget();

}  // namespace assetlint
