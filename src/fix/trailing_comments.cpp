#include "fix/trailing_comments.h"

#include <cctype>
#include <cmath>
#include <numbers>
#include <set>

#include "formats/file_kind.h"
#include "util/numbers.h"

namespace assetlint::fix {
namespace {

// A number as written in prose: digits with an optional sign, fraction and exponent.
struct WrittenNumber {
  std::size_t offset = 0, length = 0;
  double value = 0;
};

std::vector<WrittenNumber> numbers_in(std::string_view text) {
  std::vector<WrittenNumber> found;
  for (std::size_t i = 0; i < text.size();) {
    const bool sign = (text[i] == '-' || text[i] == '+') && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]));
    if (!sign && !std::isdigit(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    // "2F-85", "v1.2", "x86": a number glued to a word is a name, not a value.
    const bool glued = i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.' ||
                                 text[i - 1] == '_' || text[i - 1] == '-');
    std::size_t end = i + (sign ? 1 : 0);
    while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '.')) ++end;
    if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
      std::size_t exponent = end + 1;
      if (exponent < text.size() && (text[exponent] == '-' || text[exponent] == '+')) ++exponent;
      if (exponent < text.size() && std::isdigit(static_cast<unsigned char>(text[exponent]))) {
        end = exponent;
        while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      }
    }
    const auto value = parse_double(text.substr(i, end - i));
    if (!glued && value) found.push_back({i, end - i, *value});
    i = end;
  }
  return found;
}

// How far from the true value a number written as `text` may be: half a unit in its last
// significant digit, trailing zeros of a whole number not counted ("5700" ± 50), and never
// less than 0.5 % (a comment rounds as its writer liked).
double tolerance(std::string_view text, double value) {
  double half = half_unit_in_last_digit(value);
  if (text.find_first_of(".eE") == std::string_view::npos)
    for (std::size_t i = text.size(); i > 1 && text[i - 1] == '0'; --i) half *= 10;
  return std::max(half, 0.005 * std::abs(value));
}

// The comment at the end of the line that holds `offset`: its offset and text.
std::optional<std::pair<std::size_t, std::string_view>> trailing_comment(const SourceFile& source, std::size_t offset) {
  const std::string_view text = source.view();
  std::size_t line_end = text.find('\n', offset);
  if (line_end == std::string_view::npos) line_end = text.size();
  const std::string_view rest = text.substr(offset, line_end - offset);
  const FileKind kind = file_kind(source.path());
  const bool usd = kind == FileKind::Usda || kind == FileKind::Usd || kind == FileKind::BinaryUsd;
  const std::size_t open = rest.find(usd ? "#" : "<!--");
  if (open == std::string_view::npos) return std::nullopt;
  std::size_t close = usd ? rest.size() : rest.find("-->", open);
  if (close == std::string_view::npos) close = rest.size();
  return std::pair{offset + open, rest.substr(open, close - open)};
}

constexpr double kFactors[] = {1, 180 / std::numbers::pi, std::numbers::pi / 180, 1000, 0.001};

// The factor that turns `value` into the comment's `number`, when one does.
std::optional<double> restating_factor(double value, const WrittenNumber& number, std::string_view written) {
  for (const double factor : kFactors)
    if (std::abs(value * factor - number.value) <= tolerance(written, number.value)) return factor;
  return std::nullopt;
}

// A fix that moves a value (swapping two limits) leaves a comment restating it true.
bool still_written(const Fix& fix, const SourceFile& source, std::size_t comment_offset, const WrittenNumber& number,
                   std::string_view written) {
  for (const Edit& edit : fix.edits) {
    if (edit.offset > comment_offset || source.view().find('\n', edit.offset) < comment_offset) continue;
    if (const auto value = parse_double(trim(edit.replacement)); value && restating_factor(*value, number, written))
      return true;
  }
  return false;
}

}  // namespace

void restate_trailing_comments(const std::vector<std::shared_ptr<const SourceFile>>& sources, Fix& fix) {
  std::set<std::pair<FileId, std::size_t>> rewritten;
  std::vector<Edit> added;
  for (const Edit& edit : fix.edits) {
    if (edit.file >= sources.size() || sources[edit.file]->binary()) continue;
    const SourceFile& source = *sources[edit.file];
    if (edit.offset + edit.length > source.view().size()) continue;
    const auto old_value = parse_double(trim(source.view().substr(edit.offset, edit.length)));
    const auto new_value = parse_double(trim(edit.replacement));
    if (!old_value || !new_value || *old_value == 0) continue;
    const auto comment = trailing_comment(source, edit.offset + edit.length);
    if (!comment) continue;
    for (const WrittenNumber& number : numbers_in(comment->second)) {
      const std::size_t at = comment->first + number.offset;
      if (rewritten.count({edit.file, at})) continue;
      const std::string_view written = comment->second.substr(number.offset, number.length);
      const auto factor = restating_factor(*old_value, number, written);
      if (!factor || still_written(fix, source, comment->first, number, written)) continue;
      added.push_back({edit.file, at, number.length, format_number(*new_value * *factor, 4)});
      rewritten.insert({edit.file, at});
    }
  }
  fix.edits.insert(fix.edits.end(), added.begin(), added.end());
}

}  // namespace assetlint::fix
