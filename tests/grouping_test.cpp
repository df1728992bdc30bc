#include <catch2/catch.hpp>

#include "report/grouping.h"

namespace assetlint {
namespace {

Diagnostic finding(std::string message, std::string note, std::uint32_t line) {
  Diagnostic d;
  d.rule = "inertia-invalid";
  d.severity = Severity::Error;
  d.message = std::move(message);
  d.span.line = line;
  d.note(std::move(note));
  return d;
}

TEST_CASE("grouping: findings differing only in quoted names group, other words or numbers do not", "[report]") {
  const std::vector<Diagnostic> ds{
      finding("link 'palm' moves but has no <inertial>", "It is the child of revolute joint 'WRJ1'.", 31),
      finding("link 'thumb' moves but has no <inertial>", "It is the child of revolute joint 'THJ5'.", 64),
      finding("link 'wrist' moves but its mass is 0 kg", "It is the child of revolute joint 'WRJ2'.", 18),
      finding("link 'index' moves but has no <inertial>", "It is the child of revolute joint 'FFJ4'.", 149),
      finding("link 'ring' moves but its mass is 1 kg", "It is the child of revolute joint 'RFJ4'.", 200),
  };
  const auto groups = group_identical(ds);
  REQUIRE(groups.size() == 3);
  CHECK(groups[0].first == 0);
  CHECK(groups[0].others == std::vector<std::size_t>{1, 3});
  CHECK(groups[1].first == 2);
  CHECK(groups[1].others.empty());
  CHECK(groups[2].first == 4);
  CHECK(first_quoted(ds[1].message) == "thumb");
  CHECK(first_quoted("no quotes").empty());
}

TEST_CASE("grouping: a different rule, severity or note keeps findings apart", "[report]") {
  Diagnostic a = finding("link 'a' moves but has no <inertial>", "same", 1);
  Diagnostic b = a, c = a, d = a;
  b.severity = Severity::Warning;
  c.rule = "structure-undefined-link";
  d.notes.front().message = "other";
  CHECK(group_identical({a, b, c, d}).size() == 4);
  CHECK(group_identical({a, a}).size() == 1);
}

}  // namespace
}  // namespace assetlint

namespace assetlint {
namespace {

TEST_CASE("grouping: a xacro macro's call chain and places in notes do not keep findings apart", "[report][xacro]") {
  Diagnostic left = finding("link 'left_outer_knuckle' moves but has no <inertial>",
                            "the value is computed by '${prefix}${side}_outer_knuckle' in the xacro source", 6);
  left.note("in macro 'outer_knuckle' called at robotiq_arg2f.xacro:36:5");
  left.note("in macro 'finger_links' called at robotiq_arg2f_85_model_macro.xacro:198:5");
  left.note("the value of property 'mass', defined at robotiq_arg2f.xacro:3:5, is used here");
  Diagnostic right = left;
  right.message = "link 'right_outer_knuckle' moves but has no <inertial>";
  right.notes[2].message = "in macro 'finger_links' called at robotiq_arg2f_85_model_macro.xacro:199:5";
  right.notes[3].message = "the value of property 'mass', defined at robotiq_arg2f.xacro:9:5, is used here";
  CHECK(group_identical({left, right}).size() == 1);
  // The finding whose fix travels with the first's (one xacro literal for both) stays with it.
  Fix fix{"mirror the limits", Applicability::Unsafe, {}};
  left.fix = fix;
  right.note(left.span, "The fix of this finding rewrites the same xacro literal.");
  CHECK(group_identical({left, right}).size() == 1);
  // Other words in a note still keep them apart; numbers that are not places too.
  right.notes[1].message = "the value is computed by '${x}' in the xacro source, twice";
  CHECK(group_identical({left, right}).size() == 2);
  Diagnostic heavier = left;
  heavier.notes[3].message = "the value of property 'mass', defined at robotiq_arg2f.xacro:3:5, is 2 kg";
  CHECK(group_identical({left, heavier}).size() == 2);
}

}  // namespace
}  // namespace assetlint
