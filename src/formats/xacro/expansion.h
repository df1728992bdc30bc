#pragma once
// What expanding a .xacro file produces: the URDF element tree, every element and attribute
// with where it came from (the literal in a .xacro file, the property it was substituted
// from, the expression or argument that computed it, the macro calls it was expanded in).
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "formats/xacro/source_tree.h"
#include "model/source.h"

namespace assetlint::xacro {

struct CallFrame {
  std::string macro;
  Span call;  // the call's start tag
};
using CallChain = std::shared_ptr<const std::vector<CallFrame>>;  // outermost call first

struct Origin {
  enum class Kind {
    Literal,     // written as is at `span`
    Property,    // the value of property `name`, written at `span` (its definition), used at `use`
    Expression,  // computed by the expressions `name` in the attribute at `span`
    Argument,    // depends on the xacro arguments `name`
  };
  Kind kind = Kind::Literal;
  Span span;
  Span use;
  std::string name;
  CallChain chain;  // the macro calls the attribute was expanded in
};

struct OutAttribute {
  std::string name;
  std::string value;
  Origin origin;
};

struct OutNode {
  XNode::Kind kind = XNode::Kind::Element;
  std::string name;  // element name; text or comment
  std::vector<OutAttribute> attributes;
  std::vector<OutNode> children;
  Span span;  // the element's start tag in its .xacro file
  CallChain chain;
  // While expanding: nonzero on the empty text node that marks where xacro stops dropping
  // comments (see Expander::drop_previous_comments); none is left in a finished expansion.
  std::uint64_t comment_stop = 0;

  OutAttribute* attribute(std::string_view attr);
};

// A value given to `$(arg name)`: from the command line or configuration, or a xacro:arg default.
struct ArgumentValue {
  std::string value;
  std::string origin;  // "--xacro-arg", "asset-lint.toml:4"; empty for a xacro:arg default
  Span span;           // the xacro:arg's default, when it came from there
};

struct Expansion {
  // The files read, in the order first read; file i's spans carry FileId first_id + i.
  std::vector<std::shared_ptr<const SourceFile>> files;
  OutNode root;
  std::map<std::string, ArgumentValue> arguments;
};

}  // namespace assetlint::xacro
