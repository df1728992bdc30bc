#pragma once
// A source text (one file, one layer) and positions inside it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace assetlint {

using FileId = std::uint32_t;
inline constexpr FileId kNoFile = static_cast<FileId>(-1);

// A byte range of a source text, with its 1-based line and column.
// Columns count Unicode code points (a UTF-8 BOM is not counted).
struct Span {
  FileId file = kNoFile;
  std::size_t offset = 0;
  std::size_t length = 0;
  std::uint32_t line = 0;    // 0 = unknown
  std::uint32_t column = 0;  // 0 = unknown

  bool valid() const { return file != kNoFile && line != 0; }
  std::size_t end() const { return offset + length; }
};

struct LineColumn {
  std::uint32_t line = 1;
  std::uint32_t column = 1;
};

// Where an object of a binary layer starts in the text it is shown as: a prim or property
// path ("/robot/LF_HAA.drive:angular:physics:stiffness"), "" for the layer itself.
struct ObjectLocation {
  std::size_t offset = 0;
  std::string path;
};

// The text of a file as read from disk, with a line index built once.
class SourceFile {
 public:
  SourceFile(std::string path, std::string text);
  // A binary layer (USD crate), held as the USDA text it reads as. Its lines are not the
  // file's: locations in it name the object at an offset instead (object_at).
  SourceFile(std::string path, std::string text, std::vector<ObjectLocation> objects);

  bool binary() const { return binary_; }
  // The object whose text holds `offset` ("" for layer metadata, or in a text file).
  std::string_view object_at(std::size_t offset) const;

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  std::string_view view() const { return text_; }

  // Line and column of a byte offset (offset may equal text size).
  LineColumn position(std::size_t offset) const;
  // A span for [offset, offset + length) in this file, with line and column filled.
  Span span(FileId id, std::size_t offset, std::size_t length) const;
  // Byte offset where a 1-based line starts.
  std::size_t line_start(std::uint32_t line) const;
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(line_starts_.size()); }

 private:
  std::string path_;
  std::string text_;
  std::vector<std::size_t> line_starts_;
  bool ascii_ = true;  // no byte >= 0x80: a column is a byte count
  std::size_t bom_length_ = 0;
  bool binary_ = false;
  std::vector<ObjectLocation> objects_;  // by offset
};

}  // namespace assetlint
