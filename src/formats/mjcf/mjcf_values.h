#pragma once
// Reading MJCF attribute values into model quantities, with spans into whichever file
// (model, include) and element (instance, default class) wrote them.
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/mjcf/mjcf_defaults.h"
#include "formats/mjcf/mjcf_sources.h"
#include "model/asset.h"
#include "model/quantity.h"

namespace assetlint::mjcf {

// <compiler> settings that change how values read (MuJoCo's defaults).
struct Compiler {
  bool degree = true;                      // angle="degree"
  std::string eulerseq = "xyz";            // lower case: axes that move with the frame
  bool autolimits = true;                  // limited="auto" means "limited when a range is given"
  std::string inertiafromgeom = "auto";    // "true": <inertial> is ignored, geoms give mass and inertia
  int inertia_group_low = 0, inertia_group_high = 5;  // inertiagrouprange: the geom groups that carry mass
  double settotalmass = -1;                // > 0: every body's mass and inertia scaled to this total
  double boundmass = 0;                    // every body's mass raised to at least this
  double boundinertia = 0;                 // every principal moment raised to at least this
  bool balanceinertia = false;             // moments breaking A + B >= C replaced by their mean
  std::string meshdir;                     // where mesh files are (meshdir, else assetdir); relative to the model
  Span angle_span;                         // where angle= is written, for notes
};

class Values {
 public:
  Values(const MjcfSources& sources, std::vector<Diagnostic>& diagnostics) : sources_(sources), out_(diagnostics) {}

  Span element_span(const tinyxml2::XMLElement* el) const { return sources_.document_of(el).element_span(el); }
  Span value_span(const Attr& a, const char* name) const { return sources_.document_of(a.element).value_span(a.element, name); }
  Span token_span(const Attr& a, const char* name, std::size_t i) const {
    return sources_.document_of(a.element).token_span(a.element, name, i);
  }

  // All numbers of an attribute (`count` of them when count > 0); reports a parse error otherwise.
  std::optional<std::vector<double>> numbers(const Attr& a, const char* name, std::size_t count = 0);
  // Token `index` of the attribute as a quantity in `unit` (value × scale in model units).
  OptQuantity quantity(const Attr& a, const char* name, Unit unit, std::size_t index = 0, double scale = 1.0);
  // "true" / "false" / "auto" attributes; nullopt for "auto" or absent, reported when misspelt.
  std::optional<bool> flag(const Attr& a, const char* name);

  // The literals read from default classes, with how often each was used.
  std::vector<InheritedLiteral> inherited_literals() const;

  Diagnostic& error(const Span& span, std::string message);
  Diagnostic& unsupported(const Span& span, std::string message);
  // A class attribute naming no default class. MuJoCo refuses the model at the first one;
  // every later use becomes a note on that one error, so a file completed by a loader that
  // adds its classes reads as the one fact it is.
  void unknown_class(const Span& span, std::string_view attribute, std::string_view cls);

 private:
  void note_use(const Attr& a, const Span& span);

  const MjcfSources& sources_;
  std::vector<Diagnostic>& out_;
  std::map<std::pair<FileId, std::size_t>, InheritedLiteral> inherited_;
  std::optional<std::size_t> unknown_class_error_;  // index into out_
  std::vector<std::string> unknown_classes_;        // in order of first use
  std::size_t unknown_class_uses_ = 0;
};

// The rotation an element writes with quat, axisangle, euler, xyaxes or zaxis (identity when none).
Eigen::Matrix3d orientation(const tinyxml2::XMLElement* el, const std::vector<const tinyxml2::XMLElement*>& defaults,
                            const Compiler& compiler, Values& values);
// pos + orientation.
Eigen::Isometry3d pose(const tinyxml2::XMLElement* el, const Compiler& compiler, Values& values);

}  // namespace assetlint::mjcf
