#pragma once
// An MJCF model file and the files its <include>s bring in, parsed with positions.
// `<include file>` is resolved relative to the model file's directory (as MuJoCo does,
// also for includes inside included files); files outside the checked tree are skipped
// like USD layers (`layer-unresolved`), unless outside files are allowed.
#include <tinyxml2.h>

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/diagnostic.h"
#include "engine/file_system.h"
#include "formats/xml/xml_document.h"
#include "model/source.h"
#include "engine/settings.h"

namespace assetlint::mjcf {

struct ReadOptions {
  // Included files outside this directory tree are not read. Empty: the model's directory.
  std::string root_dir;
  bool allow_outside_root = false;
  // The MuJoCo release the model is judged for ([mujoco] version): how dampratio derives kv,
  // which attributes it still accepts.
  MujocoVersion mujoco;
};

class MjcfSources {
 public:
  MjcfSources(std::shared_ptr<const SourceFile> model, const FileSystem& files, const ReadOptions& options);

  // The <mujoco> element of the model file; null when the file is not MJCF (reported).
  const tinyxml2::XMLElement* root() const { return root_; }
  // Element children in document order, each <include> replaced by the included file's children.
  std::vector<const tinyxml2::XMLElement*> children(const tinyxml2::XMLElement* parent) const;
  const xml::XmlDocument& document_of(const tinyxml2::XMLElement* el) const;

  std::vector<std::shared_ptr<const SourceFile>> sources;  // by FileId; [0] the model file
  std::vector<Diagnostic> diagnostics;                     // parse-error, layer-unresolved
  bool usable = true;                                      // false: a file does not parse

 private:
  void expand(const tinyxml2::XMLElement* parent, std::vector<std::string>& chain, int depth);
  const tinyxml2::XMLElement* include(const tinyxml2::XMLElement* el, const std::vector<std::string>& chain);
  const xml::XmlDocument* load(const std::string& key);
  Diagnostic& report(std::string_view rule, Severity severity, const Span& span, std::string message);

  const FileSystem& files_;
  ReadOptions options_;
  std::string model_dir_;
  std::vector<std::unique_ptr<xml::XmlDocument>> documents_;  // by FileId
  std::unordered_map<const tinyxml2::XMLDocument*, const xml::XmlDocument*> owner_;
  std::unordered_map<std::string, const xml::XmlDocument*> by_path_;
  std::unordered_map<const tinyxml2::XMLElement*, const tinyxml2::XMLElement*> included_;  // <include> → its root
  const tinyxml2::XMLElement* root_ = nullptr;
};

}  // namespace assetlint::mjcf
