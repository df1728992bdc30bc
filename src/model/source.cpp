#include "model/source.h"

#include <algorithm>
#include <cstring>
#include <iterator>

namespace assetlint {
namespace {

// Eight bytes at a time: the line index of a 200 MB stage must stay a few milliseconds.
bool all_ascii(std::string_view text) {
  std::uint64_t high = 0;
  std::size_t i = 0;
  for (; i + 8 <= text.size(); i += 8) {
    std::uint64_t word;
    std::memcpy(&word, text.data() + i, 8);
    high |= word;
  }
  for (; i < text.size(); ++i) high |= static_cast<unsigned char>(text[i]);
  return (high & 0x8080808080808080ULL) == 0;
}

}  // namespace

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  if (text_.size() >= 3 && static_cast<unsigned char>(text_[0]) == 0xEF &&
      static_cast<unsigned char>(text_[1]) == 0xBB && static_cast<unsigned char>(text_[2]) == 0xBF) {
    bom_length_ = 3;
  }
  line_starts_.push_back(0);
  ascii_ = all_ascii(text_);
  const char* const begin = text_.data();
  const char* const end = begin + text_.size();
  if (std::memchr(begin, '\r', text_.size()) == nullptr) {
    // The common case, searched with memchr: a 200 MB stage is indexed in a few milliseconds.
    for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p))));)
      line_starts_.push_back(static_cast<std::size_t>(++p - begin));
    return;
  }
  for (std::size_t i = 0; i < text_.size(); ++i) {
    // "\r\n" and "\n" end a line; a lone "\r" does too (old Mac files).
    if (text_[i] == '\n') {
      line_starts_.push_back(i + 1);
    } else if (text_[i] == '\r' && (i + 1 == text_.size() || text_[i + 1] != '\n')) {
      line_starts_.push_back(i + 1);
    }
  }
}

SourceFile::SourceFile(std::string path, std::string text, std::vector<ObjectLocation> objects)
    : SourceFile(std::move(path), std::move(text)) {
  binary_ = true;
  objects_ = std::move(objects);
}

std::string_view SourceFile::object_at(std::size_t offset) const {
  auto it = std::upper_bound(objects_.begin(), objects_.end(), offset,
                             [](std::size_t o, const ObjectLocation& l) { return o < l.offset; });
  if (it == objects_.begin()) return {};
  return std::prev(it)->path;
}

LineColumn SourceFile::position(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  // Readers ask in file order: the line of the previous question, or the next one, is
  // usually the answer, where a search of a 100 000-joint file's index misses the cache.
  thread_local std::size_t previous = 0;
  const auto on_line = [&](std::size_t line) {
    return line < line_starts_.size() && line_starts_[line] <= offset &&
           (line + 1 == line_starts_.size() || offset < line_starts_[line + 1]);
  };
  std::size_t line_index = previous;
  if (!on_line(line_index) && !on_line(++line_index)) {
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    line_index = static_cast<std::size_t>(it - line_starts_.begin()) - 1;
  }
  previous = line_index;
  std::size_t start = line_starts_[line_index];
  if (line_index == 0) start = std::max(start, std::min(bom_length_, offset));
  if (ascii_) return {static_cast<std::uint32_t>(line_index + 1), static_cast<std::uint32_t>(offset - start + 1)};
  std::uint32_t column = 1;
  for (std::size_t i = start; i < offset; ++i) {
    // Count code points: skip UTF-8 continuation bytes.
    if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;
  }
  return {static_cast<std::uint32_t>(line_index + 1), column};
}

Span SourceFile::span(FileId id, std::size_t offset, std::size_t length) const {
  const LineColumn lc = position(offset);
  return Span{id, offset, length, lc.line, lc.column};
}

std::size_t SourceFile::line_start(std::uint32_t line) const {
  if (line == 0) return 0;
  if (line > line_starts_.size()) return text_.size();
  return line_starts_[line - 1];
}

}  // namespace assetlint
