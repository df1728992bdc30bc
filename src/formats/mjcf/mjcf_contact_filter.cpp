#include "formats/mjcf/mjcf_contact_filter.h"

#include <string_view>

#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_values.h"
#include "util/numbers.h"

namespace assetlint::mjcf {
namespace {

using tinyxml2::XMLElement;

class FilterReader {
 public:
  FilterReader(std::shared_ptr<const SourceFile> file, const FileSystem& files, const ReadOptions& options)
      : sources_(std::move(file), files, options), values_(sources_, ignored_) {}

  ContactFilter run() {
    const XMLElement* root = sources_.root();
    if (!root || !sources_.usable) return std::move(filter_);
    const auto sections = sources_.children(root);
    for (const XMLElement* el : sections)
      if (std::string_view(el->Name()) == "default") defaults_.read(sources_, el, ignored_);
    for (const XMLElement* el : sections) {
      const std::string_view tag = el->Name();
      if (tag == "option") read_flags(el);
      else if (tag == "contact") read_excludes(el);
      else if (tag == "worldbody") read_geoms(el, "main");
    }
    return std::move(filter_);
  }

 private:
  void read_flags(const XMLElement* option) {
    for (const XMLElement* el : sources_.children(option)) {
      if (std::string_view(el->Name()) != "flag") continue;
      const auto enabled = [&](const char* name, bool& out) {
        if (const char* v = el->Attribute(name)) {
          out = trim(v) != "disable";
          filter_.flag_span = values_.element_span(el);
        }
      };
      enabled("filterparent", filter_.filter_parent);
      enabled("contact", filter_.contacts);
    }
  }

  void read_excludes(const XMLElement* contact) {
    for (const XMLElement* el : sources_.children(contact)) {
      if (std::string_view(el->Name()) != "exclude") continue;
      const char* a = el->Attribute("body1");
      const char* b = el->Attribute("body2");
      if (a && b) filter_.excluded.push_back({std::string(trim(a)), std::string(trim(b)), values_.element_span(el)});
    }
  }

  // Bodies, frames and geoms below `parent`, each geom with the class it defaults to.
  void read_geoms(const XMLElement* parent, const std::string& cls) {
    for (const XMLElement* el : sources_.children(parent)) {
      const std::string_view tag = el->Name();
      if (tag == "body" || tag == "frame") {
        const char* child = el->Attribute("childclass");
        read_geoms(el, child && defaults_.has_class(child) ? std::string(child) : cls);
      } else if (tag == "geom") {
        const char* own = el->Attribute("class");
        const auto& defs = defaults_.elements(own && defaults_.has_class(own) ? std::string(own) : cls, "geom");
        const Span span = values_.element_span(el);
        filter_.bits[{span.file, span.offset}] = {bits(el, defs, "contype"), bits(el, defs, "conaffinity")};
      }
    }
  }

  std::uint32_t bits(const XMLElement* geom, const std::vector<const XMLElement*>& defs, const char* name) {
    const auto v = values_.numbers(Defaults::lookup(geom, defs, name), name, 1);
    if (!v) return 1;  // MuJoCo's default contype and conaffinity
    return (*v)[0] > 0 ? static_cast<std::uint32_t>((*v)[0]) : 0;
  }

  std::vector<Diagnostic> ignored_;  // the reader reported the model's problems already
  MjcfSources sources_;
  Values values_;
  Defaults defaults_;
  ContactFilter filter_;
};

}  // namespace

std::array<std::uint32_t, 2> ContactFilter::bits_of(const Span& geom) const {
  const auto it = bits.find({geom.file, geom.offset});
  return it == bits.end() ? std::array<std::uint32_t, 2>{1, 1} : it->second;
}

const ContactFilter::Excluded* ContactFilter::find_excluded(const std::string& a, const std::string& b) const {
  for (const Excluded& pair : excluded)
    if ((pair.body1 == a && pair.body2 == b) || (pair.body1 == b && pair.body2 == a)) return &pair;
  return nullptr;
}

ContactFilter read_contact_filter(std::shared_ptr<const SourceFile> file, const FileSystem& files,
                                  const ReadOptions& options) {
  return FilterReader(std::move(file), files, options).run();
}

}  // namespace assetlint::mjcf
