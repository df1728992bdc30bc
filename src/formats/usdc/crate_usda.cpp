#include "formats/usdc/crate_usda.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <new>
#include <stdexcept>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "formats/usdc/crate_usda_style.h"
#include "formats/usdc/crate_values.h"

namespace assetlint::usdc {
namespace {

class Writer {
 public:
  explicit Writer(const CrateFile& file) : file_(file), values_(file) {
    for (std::size_t i = 0; i < file.specs().size(); ++i) by_path_.emplace(file.paths()[file.specs()[i].path].text, i);
  }

  CrateText run() {
    // The text is 2 to 5 times the crate's size: reserved once instead of growing by copies.
    out_.reserve(file_.bytes().size() * 4);
    out_ = "#usda 1.0\n";
    const auto root = find("/");
    std::vector<Field> fields;
    if (root) fields = file_.fields_of(file_.specs()[*root]);
    objects_.push_back({0, ""});
    std::vector<std::string> lines;
    metadata(fields, "/", 1, true, lines);
    if (!lines.empty()) {
      out_ += "(\n";
      for (const auto& l : lines) out_ += l;
      out_ += ")\n";
    }
    for (const std::string& name : names(fields, "primChildren", "/")) {
      out_ += "\n";
      prim("/" + name, name, 0);
    }
    CrateText result;
    result.text = std::move(out_);
    result.objects = std::move(objects_);
    result.version = file_.version();
    result.skipped_fields = std::move(skipped_);
    return result;
  }

 private:
  std::optional<std::size_t> find(const std::string& path) const {
    auto it = by_path_.find(path);
    if (it == by_path_.end()) return std::nullopt;
    return it->second;
  }

  const Field* field(const std::vector<Field>& fields, std::string_view name) const {
    for (const Field& f : fields)
      if (file_.token(f.token, "FIELDS") == name) return &f;
    return nullptr;
  }

  std::vector<std::string> names(const std::vector<Field>& fields, std::string_view key, const std::string& path) {
    const Field* f = field(fields, key);
    if (!f) return {};
    const auto views = values_.tokens(f->rep, fmt::format("<{}> {}", path, key));
    return {views.begin(), views.end()};
  }

  void locate(const std::string& path) { objects_.push_back({out_.size(), path}); }

  // `key = value` lines of a spec's metadata, in file order.
  void metadata(const std::vector<Field>& fields, const std::string& path, int indent, bool layer,
                std::vector<std::string>& lines) {
    const std::string pad = indentation(indent);
    for (const Field& f : fields) {
      const std::string& key = file_.token(f.token, "FIELDS");
      if (is_structural_field(key)) continue;
      const std::string what = fmt::format("<{}> {}", path, key);
      try {
        if (key == "subLayers") {
          std::vector<std::pair<double, double>> offsets;
          if (const Field* o = field(fields, "subLayerOffsets")) offsets = values_.layer_offsets(o->rep, what);
          const std::vector<std::string_view> layers = values_.tokens(f.rep, what);
          std::string text = pad + "subLayers = [\n";
          for (std::size_t i = 0; i < layers.size(); ++i) {
            text += indentation(indent + 1) + asset_literal(layers[i]);
            if (i < offsets.size() && (offsets[i].first != 0.0 || offsets[i].second != 1.0)) {
              text += fmt::format(" (offset = {}; scale = {})", offsets[i].first, offsets[i].second);
            }
            text += i + 1 < layers.size() ? ",\n" : "\n";
          }
          lines.push_back(text + pad + "]\n");
          continue;
        }
        if (key == "variantSelection") {
          std::string text = pad + "variants = {\n";
          for (const auto& [set, selection] : values_.string_map(f.rep, what))
            text += indentation(indent + 1) + "string " + (valid_name(set, false) ? set : quoted(set)) + " = " +
                    quoted(selection) + "\n";
          lines.push_back(text + pad + "}\n");
          continue;
        }
        const std::string shown = key == "documentation" ? "doc" : key == "variantSetNames" ? "variantSets" : key;
        if (!valid_name(shown, false)) {
          skipped_.push_back(what + " (not a USDA metadata name)");
          continue;
        }
        if (values_.is_list_op(f.rep)) {
          const ListOpValue op = values_.list_op(f.rep, what);
          if (op.is_explicit && op.parts.empty()) lines.push_back(pad + shown + " = None\n");
          for (const auto& [kind, items] : op.parts) {
            std::string text = pad;
            if (kind != ItemOp::Explicit) text += std::string(item_op_keyword(kind)) + " ";
            text += shown + " = ";
            if (items.empty() && kind == ItemOp::Explicit) text += "None";
            else if (items.size() == 1 && bare_when_single(key)) text += items[0];
            else text += bracketed(items, indent);
            lines.push_back(text + "\n");
          }
          continue;
        }
        Literal value = values_.literal(f.rep, what, indent);
        if (value.type == "bool") value.text = value.text == "1" ? "true" : "false";
        if (layer && key == "comment") lines.push_back(pad + value.text + "\n");
        else lines.push_back(pad + shown + " = " + value.text + "\n");
      } catch (const UnsupportedValue&) {
        skipped_.push_back(what);
      }
    }
  }

  void metadata_block(const std::vector<Field>& fields, const std::string& path, int indent) {
    std::vector<std::string> lines;
    metadata(fields, path, indent + 1, false, lines);
    if (lines.empty()) return;
    out_ += " (\n";
    for (const auto& l : lines) out_ += l;
    out_ += indentation(indent) + ")";
  }

  void prim(const std::string& path, const std::string& name, int indent) {
    const auto index = find(path);
    if (!index) return;
    const Spec& spec = file_.specs()[*index];
    if (spec.type != SpecType::Prim) fail("SPECS", fmt::format("<{}> is listed as a prim but is not one", path));
    if (indent > 120) fail("SPECS", fmt::format("<{}>: prims nest too deep", path));
    const std::vector<Field> fields = file_.fields_of(spec);
    std::string specifier = "over";
    if (const Field* f = field(fields, "specifier")) {
      const auto v = values_.enum_value(f->rep, "<" + path + "> specifier");
      specifier = v == 0 ? "def" : v == 1 ? "over" : "class";
    }
    std::string type;
    if (const Field* f = field(fields, "typeName")) {
      type = values_.token(f->rep, "<" + path + "> typeName");
      if (!valid_name(type, false)) fail("SPECS", fmt::format("<{}> has the type name '{}'", path, type));
    }
    locate(path);
    out_ += indentation(indent) + specifier + " " + (type.empty() ? "" : type + " ") + quoted(name);
    metadata_block(fields, path, indent);
    out_ += "\n" + indentation(indent) + "{\n";
    body(fields, path, indent + 1);
    out_ += indentation(indent) + "}\n";
  }

  // Properties, children and variant sets of a prim or variant.
  void body(const std::vector<Field>& fields, const std::string& path, int indent) {
    const std::string pad = indentation(indent);
    for (const auto* order : {"primOrder", "propertyOrder"}) {
      if (const Field* f = field(fields, order)) {
        std::vector<std::string> items;
        for (const auto& n : values_.tokens(f->rep, "<" + path + "> " + order)) items.push_back(quoted(n));
        out_ += pad + "reorder " + (std::string_view(order) == "primOrder" ? "nameChildren" : "properties") + " = " +
                bracketed(items, indent) + "\n";
      }
    }
    std::vector<std::string> properties = names(fields, "properties", path);
    std::stable_sort(properties.begin(), properties.end(), [](const std::string& a, const std::string& b) { return dictionary_less(a, b); });
    for (const std::string& name : properties) property(path, name, indent);
    const std::string prefix = path.back() == '}' ? path : path + "/";
    for (const std::string& name : names(fields, "primChildren", path)) {
      prim(prefix + name, name, indent);
      locate(path);
    }
    for (const std::string& set : names(fields, "variantSetChildren", path)) {
      const auto set_index = find(path + "{" + set + "=}");
      if (!set_index) continue;
      // As OpenUSD writes a variant set: its variants by name, and nothing for a set without one.
      std::vector<std::pair<std::string, std::size_t>> variants;
      for (const std::string& variant : names(file_.fields_of(file_.specs()[*set_index]), "variantChildren", path))
        if (const auto v = find(path + "{" + set + "=" + variant + "}")) variants.emplace_back(variant, *v);
      if (variants.empty()) continue;
      std::sort(variants.begin(), variants.end());
      out_ += pad + "variantSet " + quoted(set) + " = {\n";
      for (const auto& [variant, v] : variants) {
        const std::string variant_path = path + "{" + set + "=" + variant + "}";
        const std::vector<Field> variant_fields = file_.fields_of(file_.specs()[v]);
        locate(variant_path);
        out_ += indentation(indent + 1) + quoted(variant);
        metadata_block(variant_fields, variant_path, indent + 1);
        out_ += " {\n";
        body(variant_fields, variant_path, indent + 2);
        out_ += indentation(indent + 1) + "}\n";
        locate(path);
      }
      out_ += pad + "}\n";
    }
  }

  void property(const std::string& owner, const std::string& name, int indent) {
    const std::string path = owner + "." + name;
    const auto index = find(path);
    if (!index) return;
    if (!valid_name(name, true)) fail("SPECS", fmt::format("<{}>: '{}' is not a property name", path, name));
    const Spec& spec = file_.specs()[*index];
    const std::vector<Field> fields = file_.fields_of(spec);
    const std::string pad = indentation(indent);
    bool custom = false;
    if (const Field* f = field(fields, "custom")) custom = values_.boolean(f->rep, "<" + path + "> custom");
    std::optional<std::uint32_t> variability;
    if (const Field* f = field(fields, "variability")) variability = values_.enum_value(f->rep, "<" + path + "> variability");
    locate(path);
    if (spec.type == SpecType::Relationship) {
      const std::string head = std::string(custom ? "custom " : "") + (variability == 0u ? "varying " : "") + "rel " + name;
      std::vector<std::string> declarations;
      if (const Field* f = field(fields, "targetPaths")) declarations = path_lists(f->rep, head, path + " targetPaths");
      if (declarations.empty()) declarations.push_back(head);
      for (std::size_t i = 0; i < declarations.size(); ++i) {
        out_ += pad + declarations[i];
        if (i == 0) metadata_block(fields, path, indent);
        out_ += "\n";
      }
      return;
    }
    if (spec.type != SpecType::Attribute) fail("SPECS", fmt::format("<{}> is listed as a property but is a spec of type {}", path, static_cast<unsigned>(spec.type)));
    std::string type;
    if (const Field* f = field(fields, "typeName")) {
      type = values_.token(f->rep, "<" + path + "> typeName");
    }
    if (!valid_type_name(type)) fail("SPECS", fmt::format("<{}> has the type name '{}'", path, type));
    const std::string head = std::string(custom ? "custom " : "") + (variability == 1u ? "uniform " : "") + type + " " + name;
    const Field* value = field(fields, "default");
    const Field* samples = field(fields, "timeSamples");
    const Field* connections = field(fields, "connectionPaths");
    std::optional<Literal> default_value;
    if (value) {
      try {
        default_value = values_.literal(value->rep, "<" + path + "> default", indent);
      } catch (const UnsupportedValue& u) {
        skipped_.push_back(u.what);
      }
    }
    std::vector<std::string> lines;
    metadata(fields, path, indent + 1, false, lines);
    if (default_value || !lines.empty() || (!samples && !connections)) {
      out_ += pad + head;
      if (default_value) {
        out_ += " = ";
        out_ += default_value->text;
      }
      metadata_block(fields, path, indent);
      out_ += "\n";
    }
    if (samples) {
      try {
        const auto list = values_.time_samples(samples->rep, "<" + path + "> timeSamples", indent + 1);
        out_ += pad + head + ".timeSamples = {\n";
        for (const auto& [time, v] : list) out_ += indentation(indent + 1) + time + ": " + v.text + ",\n";
        out_ += pad + "}\n";
      } catch (const UnsupportedValue& u) {
        skipped_.push_back(u.what);
      }
    }
    if (connections)
      for (const std::string& d : path_lists(connections->rep, head + ".connect", path + " connectionPaths")) out_ += pad + d + "\n";
  }

  // `prepend rel x = </a>`-style declarations of a path list op.
  std::vector<std::string> path_lists(ValueRep rep, const std::string& head, const std::string& what) {
    const ListOpValue op = values_.list_op(rep, "<" + what + ">");
    std::vector<std::string> out;
    if (op.is_explicit && op.parts.empty()) out.push_back(head + " = None");
    for (const auto& [kind, items] : op.parts) {
      std::string text = kind == ItemOp::Explicit ? "" : std::string(item_op_keyword(kind)) + " ";
      text += head + " = ";
      if (items.empty()) text += kind == ItemOp::Explicit ? "None" : "[]";
      else if (items.size() == 1) text += items[0];
      else text += bracketed(items, 0);
      out.push_back(text);
    }
    return out;
  }

  const CrateFile& file_;
  ValueReader values_;
  std::unordered_map<std::string, std::size_t> by_path_;
  std::string out_;
  std::vector<ObjectLocation> objects_;
  std::vector<std::string> skipped_;
};

}  // namespace

std::variant<CrateText, CrateError> crate_to_usda(std::string_view bytes) {
  try {
    const CrateFile file(bytes);
    return Writer(file).run();
  } catch (const CrateError& e) {
    return e;
  } catch (const UnsupportedValue& u) {
    return CrateError{"values", fmt::format("{}: a value of a type that has no USDA form here", u.what)};
  } catch (const std::bad_alloc&) {
    return CrateError{"values", "the file claims more data than fits in memory"};
  } catch (const std::length_error&) {
    return CrateError{"values", "the file claims more data than fits in memory"};
  }
}

std::shared_ptr<const SourceFile> crate_source(const std::string& path, std::string_view bytes, std::string& error) {
  auto result = crate_to_usda(bytes);
  if (auto* e = std::get_if<CrateError>(&result)) {
    error = describe(*e, path);
    return nullptr;
  }
  auto& text = std::get<CrateText>(result);
  return std::make_shared<const SourceFile>(path, std::move(text.text), std::move(text.objects));
}

std::string describe(const CrateError& error, std::string_view path) {
  return fmt::format("cannot read the binary USD layer '{}': {}: {}", path, error.section, error.message);
}

}  // namespace assetlint::usdc
