#include "formats/urdf/mujoco_singletons.h"

#include <fmt/format.h>

#include <array>
#include <string_view>

#include "rules/reader_rules.h"

namespace assetlint::urdf {
namespace {

using xml::Element;

// Parent element name → the children MuJoCo's importer (xml_urdf.cc, mjXURDF) fetches with
// FindSubElem, which refuses a second one. Visual <geometry> and <origin> are left out: the
// importer discards visual geoms unless <compiler discardvisual="false">, and reads them only then.
struct Singletons {
  std::string_view parent;
  std::array<std::string_view, 6> children;
};
constexpr std::array<Singletons, 9> kSingletons{{
    {"robot", {"mujoco"}},
    {"mujoco", {"compiler", "option", "size"}},
    {"material", {"color"}},
    {"link", {"inertial"}},
    {"inertial", {"mass", "inertia", "origin"}},
    {"visual", {"material"}},
    {"collision", {"geometry", "origin"}},
    {"geometry", {"box", "cylinder", "sphere", "capsule", "mesh"}},
    {"joint", {"parent", "child", "axis", "dynamics", "limit", "origin"}},
}};

const Singletons* singletons_of(std::string_view parent) {
  for (const Singletons& s : kSingletons)
    if (s.parent == parent) return &s;
  return nullptr;
}

// One parent with a repeated child MuJoCo reads once.
struct Repeat {
  Span second;        // the first repetition, where MuJoCo stops
  Span first;         // the one urdfdom keeps
  std::string where;  // "a <visual> of 'base_link'"
  std::string child;
  std::string parent;
  int count = 2;
};

void visit(const xml::ScannedDocument& doc, const Element* el, std::string_view owner, std::vector<Repeat>& out) {
  const Singletons* rule = singletons_of(el->name);
  // A link's or joint's name, so the message says whose element repeats.
  std::string_view name = owner;
  const bool named = el->name == "link" || el->name == "joint";
  if (named)
    if (auto n = doc.value(el, "name")) name = *n;
  if (rule) {
    for (std::string_view child : rule->children) {
      if (child.empty()) break;
      const Element* first = doc.first_child(el, child);
      if (!first) continue;
      const Element* second = doc.next_sibling(first, child);
      if (!second) continue;
      int count = 2;
      for (const Element* more = doc.next_sibling(second, child); more; more = doc.next_sibling(more, child)) ++count;
      const std::string where = named || name.empty()
                                    ? fmt::format("<{}{}>", el->name, name.empty() ? "" : fmt::format(" '{}'", name))
                                    : fmt::format("a <{}> of '{}'", el->name, name);
      out.push_back({doc.element_span(second), doc.element_span(first), where, std::string(child),
                     std::string(el->name), count});
      break;  // MuJoCo stops at the first child it finds repeated
    }
  }
  for (const Element* c = doc.first_child(el); c; c = doc.next_sibling(c)) visit(doc, c, name, out);
}

}  // namespace

std::vector<Diagnostic> repeated_singletons(const xml::ScannedDocument& doc) {
  std::vector<Repeat> repeats;
  if (const Element* robot = doc.root()) visit(doc, robot, {}, repeats);
  if (repeats.empty()) return {};
  // One finding: MuJoCo stops at the first repetition, and the others are the same defect.
  const Repeat& r = repeats.front();
  Diagnostic d{std::string(rules::kUrdfRepeatedElement.id), rules::kUrdfRepeatedElement.default_severity, r.second,
               fmt::format("{} has {} <{}> elements: MuJoCo's URDF importer refuses the file", r.where, r.count, r.child),
               std::nullopt,
               {}, {}, {}};
  d.note(r.first, fmt::format("The first <{}>: urdfdom, ROS and the importers built on it read this one and ignore {}.",
                              r.child, r.count == 2 ? "the second" : fmt::format("the other {}", r.count - 1)));
  d.note(fmt::format("MuJoCo reads the <{}> of a <{}> at most once and stops with \"repeated element: '{}'\" "
                     "(mjXUtil::FindSubElem, called by mjXURDF).",
                     r.child, r.parent, r.child));
  constexpr std::size_t kListed = 5;
  if (repeats.size() > 1)
    d.note(fmt::format("{} more element{} repeat{} a child MuJoCo reads once:", repeats.size() - 1,
                       repeats.size() == 2 ? "" : "s", repeats.size() == 2 ? "s" : ""));
  for (std::size_t i = 1; i < repeats.size() && i <= kListed; ++i)
    d.note(repeats[i].second, fmt::format("{} has {} <{}> elements.", repeats[i].where, repeats[i].count, repeats[i].child));
  if (repeats.size() > kListed + 1) d.note(fmt::format("… and {} more.", repeats.size() - kListed - 1));
  d.note("Keep one of each; merge what the others say into it if it matters.");
  return {std::move(d)};
}

}  // namespace assetlint::urdf
