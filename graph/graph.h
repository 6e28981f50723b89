// graph.h -- the recipe model: nodes, links, groups, graph inputs and outputs.
//
// Plain data with checked edits: every edit that a user can get wrong returns
// a Status explaining a refusal (type mismatch, cycle, unknown parameter...).
// Evaluation reads a const Graph; copies are cheap (node types, parameter
// values and group bodies are shared), so an editor can hand a snapshot to a
// background evaluation and keep editing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/expression.h"
#include "graph/registry.h"
#include "graph/status.h"
#include "graph/value.h"

namespace procex {

// Pseudo-nodes: graph inputs are the outputs of kGraphInputs, graph outputs
// the inputs of kGraphOutputs. Real node ids are 1..kMaxNodeId.
inline constexpr NodeId kGraphInputs = 0xFFFFFFF0u;
inline constexpr NodeId kGraphOutputs = 0xFFFFFFF1u;
inline constexpr NodeId kMaxNodeId = 0x7FFFFFFFu;

struct PortRef {
  NodeId node = 0;
  std::uint32_t port = 0;
  friend bool operator==(const PortRef&, const PortRef&) = default;
  friend auto operator<=>(const PortRef&, const PortRef&) = default;
};

struct Link {
  PortRef from;  // an output (or a graph input)
  PortRef to;    // an input (or a graph output)
  friend bool operator==(const Link&, const Link&) = default;
};

// Editor-only state: saved in the file's "editor" block, never hashed.
struct EditorState {
  double x = 0, y = 0;
  std::string comment;
  bool collapsed = false;
  friend bool operator==(const EditorState&, const EditorState&) = default;
};

struct Node {
  NodeId id = 0;
  std::shared_ptr<const NodeType> type;
  std::vector<Value> params;  // in declaration order, always complete
  // Parameters that hold an expression instead of a value (by parameter
  // index); params keeps the last value for editors to show.
  std::map<std::uint32_t, std::shared_ptr<const Expression>> expressions;
  std::string group;          // group instances: the name of the group in Graph::groups()
  EditorState editor;

  const NodeDecl& decl() const { return type->decl; }
};

// A value the caller binds when evaluating (the CLI's --input footprint=...).
struct GraphInput {
  std::string name;  // identifier
  const ValueType* type = nullptr;
  std::string doc;
  Value default_value;  // empty: must be bound
};

struct GraphOutput {
  std::string name;  // identifier
  const ValueType* type = nullptr;
  std::string doc;
};

// A parameter of an inner node shown on the graph's interface when the graph
// is used as a group (and settable from the CLI).
struct ExposedParam {
  ExposedParam() = default;
  ExposedParam(std::string n, NodeId id, std::uint32_t index) : name(std::move(n)), node(id), param(index) {}
  std::string name;  // identifier, unique among exposed parameters
  NodeId node = 0;
  std::uint32_t param = 0;
  // How the interface presents it; empty / unset: the inner parameter's own.
  // (Its default is the inner parameter's current value.)
  std::string label, unit;
  std::optional<double> min, max;
};

// A named set of exposed parameter values, recalled as one ("tall", "cheap").
struct Preset {
  std::string name;
  std::map<std::string, Value, std::less<>> values;  // exposed name -> value
};

// A group definition: a graph used as one node. Embedded in the recipe, or
// loaded from a library file (path relative to the recipe's folder).
struct GroupDef {
  std::string name;
  std::shared_ptr<const NodeType> type;  // type->body is the group's graph
  std::string file;                      // empty when embedded
};

struct GraphMetadata {
  std::string name, description, author, licence;
  std::string thumbnail;  // a PNG beside the recipe (relative path), or empty
  friend bool operator==(const GraphMetadata&, const GraphMetadata&) = default;
};

class Graph {
 public:
  GraphMetadata metadata;

  // ---- nodes ----
  // id 0 picks the next free id. Refuses unknown types and taken ids.
  Result<NodeId> add_node(std::string_view type_name, NodeId id = 0, const NodeRegistry& registry = NodeRegistry::global());
  Result<NodeId> add_node(std::shared_ptr<const NodeType> type, NodeId id = 0);
  // An instance of a group defined in groups().
  Result<NodeId> add_group_node(std::string_view group_name, NodeId id = 0);
  // Also removes its links and exposed parameters.
  Status remove_node(NodeId id);
  // Re-inserts a node exactly as it was (undo of remove), links not included.
  Status restore_node(Node node);

  const Node* node(NodeId id) const;
  // Ordered by id: the stable order of files and of evaluation statistics.
  const std::map<NodeId, Node>& nodes() const { return nodes_; }
  NodeId next_id() const { return next_id_; }

  // A value replaces the parameter's expression, if it had one.
  Status set_param(NodeId id, std::string_view param, Value v);
  Status set_param(NodeId id, std::size_t param, Value v);
  // Gives a float, int, bool, string or enum parameter an expression
  // (docs/expressions.md), typed against this graph's inputs and exposed
  // parameters. Refusals name the node, the parameter and the column.
  Status set_expression(NodeId id, std::string_view param, std::string_view text);
  Status set_expression(NodeId id, std::size_t param, std::string_view text);
  // The type an expression name has in this graph: a graph input or exposed
  // parameter of a float, int, bool, string or enum type; nullopt otherwise.
  std::optional<ExprType> expression_name_type(std::string_view name) const;
  Status set_editor_state(NodeId id, EditorState s);

  // ---- links ----
  // Refuses unknown nodes/ports, type mismatches, an input already fed, and cycles.
  Status connect(PortRef from, PortRef to);
  Status connect(NodeId from, std::string_view output, NodeId to, std::string_view input);
  // Removes the link into `to` (an input or a graph output).
  Status disconnect(PortRef to);
  // Links keyed by their destination: one link per input.
  const std::map<PortRef, PortRef>& links() const { return links_; }
  std::optional<PortRef> source(PortRef to) const;
  // Links leaving `node`.
  std::vector<Link> links_from(NodeId node) const;
  // Would connecting `from` to `to` be accepted? Same checks as connect().
  Status can_connect(PortRef from, PortRef to) const;

  // ---- graph interface ----
  Status add_input(GraphInput in);
  Status add_output(GraphOutput out);
  Status remove_input(std::string_view name);    // also removes its links
  Status remove_output(std::string_view name);   // also removes its link
  const std::vector<GraphInput>& inputs() const { return inputs_; }
  const std::vector<GraphOutput>& outputs() const { return outputs_; }
  std::optional<std::size_t> input_index(std::string_view name) const;
  std::optional<std::size_t> output_index(std::string_view name) const;
  // Graph outputs are fed like inputs: connect(from, {kGraphOutputs, index}).

  Status expose_param(ExposedParam p);
  Status unexpose_param(std::string_view name);
  // Sets the inner parameter behind an exposed name (the CLI's --set height=12).
  Status set_exposed(std::string_view name, Value v);
  const std::vector<ExposedParam>& exposed_params() const { return exposed_; }

  // ---- presets ----
  // Refused if a value names no exposed parameter or has the wrong type.
  // A value whose parameter is unexposed later stays (an undo may expose it
  // again) but is not saved, and applying the preset then names it.
  Status set_preset(Preset p);  // adds or replaces by name
  Status remove_preset(std::string_view name);
  Status apply_preset(std::string_view name);  // sets every value it holds
  const std::vector<Preset>& presets() const { return presets_; }

  // ---- groups ----
  // Registers `body` as group `name` (its inputs, outputs and exposed
  // parameters become the node's declaration). `file`: the library file it
  // came from, relative to the recipe's folder, or empty.
  Status add_group(std::string name, std::shared_ptr<const Graph> body, std::string file = {});
  Status remove_group(std::string_view name);  // refused while instances exist
  // Gives group `name` a new graph (an edit made inside it): every instance
  // takes the new declaration, keeping its links, parameter values,
  // expressions and outward exposures by name. Refused, changing nothing,
  // when a connected port or an exposed parameter would go, or when the group
  // is read from a library file (its graph is that file's).
  Status set_group_body(std::string_view name, std::shared_ptr<const Graph> body);
  const std::map<std::string, GroupDef, std::less<>>& groups() const { return groups_; }

  // Type of the port (output of `from` side or input of `to` side); null if no such port.
  const ValueType* output_type(PortRef p) const;
  const ValueType* input_type(PortRef p) const;
  // "12.result", "@footprint" (graph input), "@mesh" (graph output).
  std::string port_name(PortRef p, bool is_output) const;

  // Every structural problem at once (for `procex validate` and the loader):
  // unbound required inputs are not problems here, they are evaluation errors.
  // Types are checked through any-typed outputs too: a pass-through node (a
  // Switch) may hand on any of its linked any-typed inputs, so each of the
  // types they may carry must fit wherever its output goes.
  std::vector<Diagnostic> validate() const;

  // Whether `other` has the same nodes (types, parameters, expressions), links,
  // inputs, outputs and exposed parameters: everything evaluation reads, so
  // that one evaluates as the other for any bindings (editor state, metadata,
  // presets and group definitions aside: instances hold their group's type).
  // Quick for two copies of one graph, which share their values.
  bool evaluates_like(const Graph& other) const;

 private:
  bool reaches(NodeId from, NodeId to) const;  // is `to` downstream of (or equal to) `from`?
  // The concrete types the output `from` may carry, each with the output it
  // comes from ("1.profile"); none known for an any-typed output that is no
  // pass-through. `known` keeps each output's answer: chained Switches fed
  // twice by the same node would otherwise be walked 2^depth times.
  using CarriedTypes = std::vector<std::pair<const ValueType*, PortRef>>;
  const CarriedTypes& carried_types(PortRef from, std::map<PortRef, CarriedTypes>& known) const;
  // `links` with node `id`'s ports renumbered for `next` (its declaration
  // after `change`, e.g. "'count' = 3"): a port keeps its links where `next`
  // has one of the same name and type (a node with two variadic groups shifts
  // the second when the first grows); an error if a connected port would go.
  Status ports_kept(const std::map<PortRef, PortRef>& links, NodeId id, const NodeDecl& next, const std::string& change,
                    std::map<PortRef, PortRef>& relinked) const;

  std::map<NodeId, Node> nodes_;
  std::map<PortRef, PortRef> links_;
  std::vector<GraphInput> inputs_;
  std::vector<GraphOutput> outputs_;
  std::vector<ExposedParam> exposed_;
  std::vector<Preset> presets_;
  std::map<std::string, GroupDef, std::less<>> groups_;
  NodeId next_id_ = 1;
};

// The node type of a group: declaration derived from `body` (inputs, outputs,
// exposed parameters with the inner parameter's range, unit, doc and current value as default).
Result<std::shared_ptr<const NodeType>> make_group_type(std::string name, std::shared_ptr<const Graph> body);

}  // namespace procex
