#include "fix/diff.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace assetlint::fix {
namespace {

// Lines with their terminators; the last line may have none.
std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl + 1;
    lines.push_back(text.substr(start, end - start));
    start = end;
  }
  return lines;
}

enum class Op { Keep, Delete, Insert };
struct Step {
  Op op;
  std::size_t a;  // index in the old lines (Keep, Delete)
  std::size_t b;  // index in the new lines (Keep, Insert)
};

// Myers' O((N+M)·D) shortest edit script on the lines between the common prefix and
// suffix (fixes change few lines, so D is small).
std::vector<Step> edit_script(const std::vector<std::string_view>& a, const std::vector<std::string_view>& b) {
  std::size_t prefix = 0;
  while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix]) ++prefix;
  std::size_t suffix = 0;
  while (suffix < a.size() - prefix && suffix < b.size() - prefix &&
         a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix])
    ++suffix;
  const long n = static_cast<long>(a.size() - prefix - suffix);
  const long m = static_cast<long>(b.size() - prefix - suffix);
  auto A = [&](long i) { return a[prefix + static_cast<std::size_t>(i)]; };
  auto B = [&](long j) { return b[prefix + static_cast<std::size_t>(j)]; };

  std::vector<Step> middle;
  if (n > 0 || m > 0) {
    const long max = n + m;
    std::vector<long> v(2 * static_cast<std::size_t>(max) + 2, 0);
    std::vector<std::vector<long>> trace;  // v[k] for k in [-d, d] after step d
    const auto at = [&](long k) -> long& { return v[static_cast<std::size_t>(k + max + 1)]; };
    long found = -1;
    for (long d = 0; d <= max && found < 0; ++d) {
      for (long k = -d; k <= d; k += 2) {
        long x = (k == -d || (k != d && at(k - 1) < at(k + 1))) ? at(k + 1) : at(k - 1) + 1;
        long y = x - k;
        while (x < n && y < m && A(x) == B(y)) ++x, ++y;
        at(k) = x;
        if (x >= n && y >= m) {
          found = d;
          break;
        }
      }
      std::vector<long> snapshot(static_cast<std::size_t>(2 * d + 1));
      for (long k = -d; k <= d; ++k) snapshot[static_cast<std::size_t>(k + d)] = at(k);
      trace.push_back(std::move(snapshot));
    }
    // Walk back from (n, m).
    long x = n, y = m;
    for (long d = found; d > 0; --d) {
      const auto& prev = trace[static_cast<std::size_t>(d - 1)];
      const auto prev_at = [&](long k) { return prev[static_cast<std::size_t>(k + d - 1)]; };
      const long k = x - y;
      const bool down = k == -d || (k != d && prev_at(k - 1) < prev_at(k + 1));
      const long prev_k = down ? k + 1 : k - 1;
      const long prev_x = prev_at(prev_k);
      const long prev_y = prev_x - prev_k;
      while (x > prev_x + (down ? 0 : 1) && y > prev_y + (down ? 1 : 0)) {
        --x, --y;
        middle.push_back({Op::Keep, static_cast<std::size_t>(x), static_cast<std::size_t>(y)});
      }
      if (down) {
        --y;
        middle.push_back({Op::Insert, 0, static_cast<std::size_t>(y)});
      } else {
        --x;
        middle.push_back({Op::Delete, static_cast<std::size_t>(x), 0});
      }
    }
    while (x > 0 && y > 0) {
      --x, --y;
      middle.push_back({Op::Keep, static_cast<std::size_t>(x), static_cast<std::size_t>(y)});
    }
    std::reverse(middle.begin(), middle.end());
  }

  std::vector<Step> script;
  script.reserve(prefix + middle.size() + suffix);
  for (std::size_t i = 0; i < prefix; ++i) script.push_back({Op::Keep, i, i});
  for (Step s : middle) {
    s.a += prefix;
    s.b += prefix;
    script.push_back(s);
  }
  for (std::size_t i = 0; i < suffix; ++i)
    script.push_back({Op::Keep, a.size() - suffix + i, b.size() - suffix + i});
  return script;
}

std::string range(std::size_t first, std::size_t count) {
  if (count == 0) return fmt::format("{},0", first);  // the line before the (empty) range
  if (count == 1) return fmt::format("{}", first + 1);
  return fmt::format("{},{}", first + 1, count);
}

void append_line(std::string& out, char marker, std::string_view line) {
  out += marker;
  out.append(line);
  if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

}  // namespace

std::string unified_diff(std::string_view before, std::string_view after, std::string_view a_label,
                         std::string_view b_label, int context) {
  if (before == after) return {};
  const auto a = split_lines(before), b = split_lines(after);
  const std::vector<Step> script = edit_script(a, b);
  const std::size_t ctx = static_cast<std::size_t>(std::max(0, context));

  std::string out = fmt::format("--- {}\n+++ {}\n", a_label, b_label);
  std::size_t i = 0;
  while (i < script.size()) {
    while (i < script.size() && script[i].op == Op::Keep) ++i;
    if (i == script.size()) break;
    // A hunk: from `ctx` lines before this change to `ctx` lines after the last change
    // that is followed by at most 2·ctx unchanged lines before the next one.
    const std::size_t start = i >= ctx ? i - ctx : 0;
    std::size_t end = i;  // one past the last change of the hunk
    std::size_t j = i;
    while (j < script.size()) {
      if (script[j].op != Op::Keep) {
        end = ++j;
        continue;
      }
      std::size_t k = j;
      while (k < script.size() && script[k].op == Op::Keep) ++k;
      if (k == script.size() || k - j > 2 * ctx) break;
      j = k;
    }
    const std::size_t stop = std::min(script.size(), end + ctx);

    std::size_t a_first = 0, b_first = 0, a_count = 0, b_count = 0;
    // Where the hunk starts in each file: the first step's line, or (for a side with
    // no lines in the hunk) the number of lines before it.
    std::size_t a_before = 0, b_before = 0;
    for (std::size_t s = 0; s < start; ++s) {
      if (script[s].op != Op::Insert) ++a_before;
      if (script[s].op != Op::Delete) ++b_before;
    }
    a_first = a_before;
    b_first = b_before;
    std::string body;
    for (std::size_t s = start; s < stop; ++s) {
      const Step& step = script[s];
      switch (step.op) {
        case Op::Keep: append_line(body, ' ', a[step.a]); ++a_count; ++b_count; break;
        case Op::Delete: append_line(body, '-', a[step.a]); ++a_count; break;
        case Op::Insert: append_line(body, '+', b[step.b]); ++b_count; break;
      }
    }
    out += fmt::format("@@ -{} +{} @@\n", range(a_first, a_count), range(b_first, b_count));
    out += body;
    i = stop;
  }
  return out;
}

}  // namespace assetlint::fix
