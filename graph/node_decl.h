// node_decl.h -- what a node type is: ports, parameters, docs, declared once.
//
// The declaration is the single source of truth: the evaluator reads inputs and
// parameters by it, the cache hashes parameters in its order, the .pxg format
// reads and writes parameters by its names, the CLI prints docs from it and the
// studio draws the node from it.
//
//   static void declare(NodeDecl& d) {
//     d.doc("Grows or shrinks a footprint by a distance.").category("Footprint");
//     d.input<Footprint>("footprint").doc("Closed plan loops");
//     d.param<double>("distance").default_value(1.0).range(-50, 50).unit("m");
//     d.param_enum("join", {"miter", "round"}, "miter");
//     d.output<Footprint>("result");
//   }
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/file_version_memo.h"
#include "graph/status.h"
#include "graph/value.h"

namespace procex {

class NodeDecl;

struct PortDecl {
  std::string name;  // identifier: [a-z0-9_], unique among the node's inputs (or outputs)
  const ValueType* type = nullptr;
  std::string doc;
  bool optional = false;  // inputs only: may stay unconnected
};

struct ParamDecl {
  std::string name;  // identifier, unique among the node's parameters
  const ValueType* type = nullptr;
  Value default_value;
  std::optional<double> min, max;  // numbers (float, int) only; inclusive
  std::string unit;                // "m", "deg", ... for docs and the editor
  std::string doc;
  std::vector<std::string> choices;  // enum parameters only
  bool sets_port_count = false;      // ParamBuilder::sets_port_count

  // Ok, or why `v` is not acceptable (wrong type, out of range, unknown choice).
  Status check(const Value& v) const;
};

// Most ports a parameter that sets a port count may ask for.
inline constexpr std::size_t kMaxPortCount = 64;

// The port count a value of a port-count parameter asks for: an int's value,
// a list<string>'s length.
std::size_t port_count_of(const Value& v);

// Chained setters for the port just declared.
class PortBuilder {
 public:
  PortBuilder& doc(std::string text);
  PortBuilder& optional(bool yes = true);
  std::size_t index() const { return index_; }

 private:
  friend class NodeDecl;
  PortBuilder(std::vector<PortDecl>& ports, std::size_t i) : ports_(&ports), index_(i) {}
  std::vector<PortDecl>* ports_;
  std::size_t index_;
};

// Chained setters for the parameter just declared.
class ParamBuilder {
 public:
  template <class T>
  ParamBuilder& default_value(T v) {
    return default_value_of(Value::make<T>(std::move(v)));
  }
  ParamBuilder& default_value_of(Value v);
  ParamBuilder& range(double min, double max);
  ParamBuilder& min(double v);
  ParamBuilder& max(double v);
  ParamBuilder& unit(std::string u);
  ParamBuilder& doc(std::string text);
  // Variadic ports: this parameter (an int with a range within 0..kMaxPortCount,
  // or a list<string>, by its length) decides how many ports the node has. The
  // declare function reads it with NodeDecl::count_of and declares that many;
  // each node gets the declaration for its own value (with_port_counts in
  // registry.h), so ports, links, files and the editor all follow it. Only
  // ports may depend on it, never parameters; it cannot be exposed.
  ParamBuilder& sets_port_count();
  std::size_t index() const { return index_; }

 private:
  friend class NodeDecl;
  ParamBuilder(std::vector<ParamDecl>& params, std::size_t i) : params_(&params), index_(i) {}
  ParamDecl& p() { return (*params_)[index_]; }
  std::vector<ParamDecl>* params_;
  std::size_t index_;
};

// For nodes that can hand an input through unchanged (a disabled switch, an
// offset by zero): given the parameters, return the input index whose value
// and hash output `output` forwards, or nullopt to compute normally. Must be
// cheap and depend only on parameters.
using PassThroughFn = std::optional<std::size_t> (*)(const std::vector<Value>& params, std::size_t output);

// Upgrades the parameters a file saved for an older version of this node type
// (an object of name -> JSON value) in place: rename, convert, drop. Throw
// std::invalid_argument to refuse. Called by the .pxg loader before it reads them.
using UpgradeFn = void (*)(int saved_version, nlohmann::json& params);

// Adds to a node's cache key what its result depends on beyond parameters and
// inputs -- typically the size and modification time of a file it reads, so an
// edited file is read again (relative paths resolve against `folder`, see
// EvalOptions::folder; `versions` is a batch's, EvalOptions::file_versions,
// else null). Must be cheap: it runs whenever the graph is hashed.
using HashExtraFn = void (*)(const std::vector<Value>& params, const std::filesystem::path& folder,
                             FileVersionMemo* versions, Hasher& h);

// What a HashExtraFn usually adds for a file it reads: its version
// (base/file_version.h: size, modification time and a hash of its bytes; a
// missing file hashes as such, and reading it fails later), as `versions`
// first saw it where a batch keeps them.
void hash_file_stamp(const std::filesystem::path& file, FileVersionMemo* versions, Hasher& h);

// Levels of detail, counted as CityGML counts them: 0 the footprint, 1 a
// block, 2 the shape, kFullDetail everything. An evaluation shows one
// (EvalOptions::lod, or the recipe's graph input `lod`).
inline constexpr int kFullDetail = 3;

class NodeDecl {
 public:
  NodeDecl() = default;
  NodeDecl(std::string type_name, int version) : type_name_(std::move(type_name)), version_(version) {}

  // Declare ports and parameters, in the order they are shown and hashed.
  // T = Value declares a port that accepts any type.
  template <class T>
  PortBuilder input(std::string name) {
    return add_input(std::move(name), value_type<T>());
  }
  template <class T>
  PortBuilder output(std::string name) {
    return add_output(std::move(name), value_type<T>());
  }
  // Parameters of types without JSON support are refused (they could not be saved).
  template <class T>
  ParamBuilder param(std::string name) {
    return add_param(std::move(name), value_type<T>());
  }
  // Default: the first choice unless given.
  ParamBuilder param_enum(std::string name, std::vector<std::string> choices, std::string default_choice = {});

  PortBuilder add_input(std::string name, const ValueType& type);
  PortBuilder add_output(std::string name, const ValueType& type);
  ParamBuilder add_param(std::string name, const ValueType& type);

  NodeDecl& doc(std::string text) {
    doc_ = std::move(text);
    return *this;
  }
  NodeDecl& category(std::string c) {
    category_ = std::move(c);
    return *this;
  }
  NodeDecl& pass_through(PassThroughFn fn) {
    pass_through_ = fn;
    return *this;
  }
  // The node adds detail first shown at level of detail `level` (windows at
  // kFullDetail): evaluated below it, every output hands on input 0 as a
  // pass-through, so nothing the node adds is computed, cached or shown.
  NodeDecl& detail_level(int level) {
    detail_level_ = level;
    return *this;
  }
  NodeDecl& upgrade(UpgradeFn fn) {
    upgrade_ = fn;
    return *this;
  }
  NodeDecl& hash_extra(HashExtraFn fn) {
    hash_extra_ = fn;
    return *this;
  }

  const std::string& type_name() const { return type_name_; }
  int version() const { return version_; }
  const std::string& doc() const { return doc_; }
  const std::string& category() const { return category_; }
  const std::vector<PortDecl>& inputs() const { return inputs_; }
  const std::vector<PortDecl>& outputs() const { return outputs_; }
  const std::vector<ParamDecl>& params() const { return params_; }
  PassThroughFn pass_through() const { return pass_through_; }
  int detail_level() const { return detail_level_; }
  UpgradeFn upgrade() const { return upgrade_; }
  HashExtraFn hash_extra() const { return hash_extra_; }

  // Index by name, or nullopt.
  std::optional<std::size_t> input_index(std::string_view name) const;
  std::optional<std::size_t> output_index(std::string_view name) const;
  std::optional<std::size_t> param_index(std::string_view name) const;

  // The default value of every parameter, in declaration order.
  std::vector<Value> default_params() const;

  // For declare functions: the port count that the (already declared)
  // parameter `name` asks for in the node being declared -- its default when
  // the type is registered, a node's own value for that node's variant.
  std::size_t count_of(std::string_view name) const;
  // Used by with_port_counts before it runs the declare function again:
  // parameter name -> count.
  void set_counts(std::map<std::string, std::size_t, std::less<>> counts) { counts_ = std::move(counts); }

  // Ok, or the first mistake in the declaration (duplicate or malformed names,
  // missing defaults, defaults outside their range). Checked at registration.
  Status validate() const;

  // Markdown documentation of the node (for `procex nodes --markdown`).
  std::string markdown() const;

 private:
  std::string type_name_;
  int version_ = 1;
  std::string doc_, category_;
  std::vector<PortDecl> inputs_, outputs_;
  std::vector<ParamDecl> params_;
  PassThroughFn pass_through_ = nullptr;
  int detail_level_ = 0;
  UpgradeFn upgrade_ = nullptr;
  HashExtraFn hash_extra_ = nullptr;
  std::map<std::string, std::size_t, std::less<>> counts_;
};

// Names of ports, parameters and graph inputs/outputs: [a-z0-9_]+, starting with a letter.
bool is_identifier(std::string_view name);

}  // namespace procex
