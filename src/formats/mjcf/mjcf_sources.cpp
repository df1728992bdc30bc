#include "formats/mjcf/mjcf_sources.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "rules/reader_rules.h"

namespace assetlint::mjcf {
namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

// Deeper nesting than any real model; a guard against include chains built to exhaust the stack.
constexpr int kMaxIncludeDepth = 32;

std::string normalize(const fs::path& path) {
  std::string s = path.lexically_normal().generic_string();
  return s.empty() ? std::string(".") : s;
}

}  // namespace

MjcfSources::MjcfSources(std::shared_ptr<const SourceFile> model, const FileSystem& files, const ReadOptions& options)
    : files_(files), options_(options) {
  model_dir_ = fs::path(model->path()).parent_path().string();
  sources.push_back(std::move(model));
  documents_.push_back(std::make_unique<xml::XmlDocument>(*sources[0], 0));
  const xml::XmlDocument& doc = *documents_[0];
  for (const auto& error : doc.errors()) report(rules::kParseError.id, rules::kParseError.default_severity, error.span, error.message);
  const XMLElement* root = doc.root();
  if (!root) {
    usable = false;
    return;
  }
  if (std::string_view(root->Name()) != "mujoco") {
    report(rules::kParseError.id, rules::kParseError.default_severity, doc.element_span(root),
           fmt::format("not MJCF: the root element is <{}>, expected <mujoco>", root->Name()));
    usable = false;
    return;
  }
  owner_[root->GetDocument()] = &doc;
  by_path_[normalize(fs::absolute(sources[0]->path()))] = &doc;
  root_ = root;
  std::vector<std::string> chain{normalize(fs::absolute(sources[0]->path()))};
  expand(root_, chain, 0);
}

Diagnostic& MjcfSources::report(std::string_view rule, Severity severity, const Span& span, std::string message) {
  diagnostics.push_back({std::string(rule), severity, span, std::move(message), std::nullopt, {}, {}, {}});
  return diagnostics.back();
}

const xml::XmlDocument& MjcfSources::document_of(const XMLElement* el) const {
  return *owner_.at(el->GetDocument());
}

std::vector<const XMLElement*> MjcfSources::children(const XMLElement* parent) const {
  std::vector<const XMLElement*> out;
  for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "include") {
      out.push_back(c);
      continue;
    }
    if (auto it = included_.find(c); it != included_.end()) {
      auto more = children(it->second);
      out.insert(out.end(), more.begin(), more.end());
    }
  }
  return out;
}

// Loads every <include> below `parent` (depth first, so an include inside an included file
// is resolved in its place).
void MjcfSources::expand(const XMLElement* parent, std::vector<std::string>& chain, int depth) {
  for (const XMLElement* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "include") {
      expand(c, chain, depth);
      continue;
    }
    if (depth >= kMaxIncludeDepth) {
      report(rules::kLayerUnresolved.id, Severity::Error, document_of(c).element_span(c),
             fmt::format("<include> nested more than {} deep; not read", kMaxIncludeDepth));
      continue;
    }
    const XMLElement* root = include(c, chain);
    if (!root) continue;
    chain.push_back(normalize(fs::absolute(document_of(root).file().path())));
    included_[c] = root;
    expand(root, chain, depth + 1);
    chain.pop_back();
  }
}

const XMLElement* MjcfSources::include(const XMLElement* el, const std::vector<std::string>& chain) {
  const xml::XmlDocument& from = document_of(el);
  const char* file = el->Attribute("file");
  if (!file || !*file) {
    report(rules::kParseError.id, rules::kParseError.default_severity, from.element_span(el),
           "<include> without a file attribute");
    usable = false;
    return nullptr;
  }
  const Span span = from.value_span(el, "file");
  fs::path path(file);
  if (path.is_relative()) path = fs::path(model_dir_) / path;
  const std::string key = normalize(path);
  const std::string absolute = normalize(fs::absolute(key));
  if (std::find(chain.begin(), chain.end(), absolute) != chain.end()) {
    report(rules::kLayerUnresolved.id, Severity::Warning, span,
           fmt::format("include cycle: '{}' already includes this file; the include is ignored", file));
    return nullptr;
  }
  if (!options_.allow_outside_root) {
    const std::string root = options_.root_dir.empty() ? model_dir_ : options_.root_dir;
    const fs::path relative = fs::path(absolute).lexically_relative(normalize(fs::absolute(root.empty() ? "." : root)));
    if (relative.empty() || *relative.begin() == "..") {
      report(rules::kLayerUnresolved.id, rules::kLayerUnresolved.default_severity, span,
             fmt::format("include '{}' is outside the checked directory tree; skipped", file))
          .note(fmt::format("The checked tree is '{}'; --allow-outside-root reads files outside it.",
                            root.empty() ? std::string(".") : root));
      return nullptr;
    }
  }
  const xml::XmlDocument* doc = load(key);
  if (!doc) {
    std::string error;
    files_.read(key, error);
    // MuJoCo refuses a model whose include it cannot open; what the include holds (a <compiler>
    // angle, the default classes) changes how everything else reads, so nothing is judged.
    report(rules::kLayerUnresolved.id, Severity::Error, span, fmt::format("include '{}' cannot be read: {}", file, error))
        .note("MuJoCo does not load a model with a missing include, and its elements (a <compiler> setting, default "
              "classes) would change how the rest reads: nothing else in the model is checked.");
    usable = false;
    return nullptr;
  }
  const XMLElement* root = doc->root();
  if (!root) {
    usable = false;
    return nullptr;
  }
  // MuJoCo inserts the children of an included file's root whatever the root is called
  // (<mujoco>, <mujocoinclude>, or the section it holds, such as <worldbody>).
  return root;
}

const xml::XmlDocument* MjcfSources::load(const std::string& key) {
  const std::string absolute = normalize(fs::absolute(key));
  if (auto it = by_path_.find(absolute); it != by_path_.end()) return it->second;
  std::string error;
  std::optional<std::string> text = files_.read(key, error);
  if (!text) return nullptr;
  const auto id = static_cast<FileId>(sources.size());
  sources.push_back(std::make_shared<const SourceFile>(key, std::move(*text)));
  documents_.push_back(std::make_unique<xml::XmlDocument>(*sources.back(), id));
  const xml::XmlDocument* doc = documents_.back().get();
  for (const auto& e : doc->errors()) report(rules::kParseError.id, rules::kParseError.default_severity, e.span, e.message);
  if (doc->root()) owner_[doc->root()->GetDocument()] = doc;
  by_path_[absolute] = doc;
  return doc;
}

}  // namespace assetlint::mjcf
