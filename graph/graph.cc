#include "graph/graph.h"

#include <algorithm>
#include <optional>
#include <set>

#include "graph/expression_value.h"

namespace procex {

namespace {

std::string q(std::string_view s) { return "'" + std::string(s) + "'"; }

// Shifts the port index of pseudo-node links above `removed` down by one.
void renumber_after_removal(std::map<PortRef, PortRef>& links, NodeId pseudo, std::uint32_t removed, bool as_source) {
  std::map<PortRef, PortRef> out;
  for (const auto& link : links) {
    PortRef to = link.first, from = link.second;
    PortRef& p = as_source ? from : to;
    if (p.node == pseudo && p.port > removed) --p.port;
    out.emplace(to, from);
  }
  links = std::move(out);
}

}  // namespace

Result<NodeId> Graph::add_node(std::string_view type_name, NodeId id, const NodeRegistry& registry) {
  auto type = registry.find(type_name);
  if (!type) return Status::error(registry.unknown_type_message(type_name));
  return add_node(std::move(type), id);
}

Result<NodeId> Graph::add_node(std::shared_ptr<const NodeType> type, NodeId id) {
  if (!type) return Status::error("add_node: no node type given");
  if (id == 0) id = next_id_;
  if (id > kMaxNodeId) return Status::error("node id " + std::to_string(id) + " is out of range (1.." + std::to_string(kMaxNodeId) + ")");
  if (nodes_.count(id)) return Status::error("node id " + std::to_string(id) + " is already taken");
  Node n;
  n.id = id;
  n.params = type->decl.default_params();
  n.type = with_port_counts(type, n.params);  // a variant given: back to the declared counts
  nodes_.emplace(id, std::move(n));
  next_id_ = std::max(next_id_, id + 1);
  return id;
}

Result<NodeId> Graph::add_group_node(std::string_view group_name, NodeId id) {
  auto it = groups_.find(group_name);
  if (it == groups_.end()) return Status::error("no group named " + q(group_name) + " in this recipe");
  Result<NodeId> r = add_node(it->second.type, id);
  if (r) nodes_.at(*r).group = it->second.name;
  return r;
}

Status Graph::remove_node(NodeId id) {
  if (!nodes_.erase(id)) return Status::error("no node " + std::to_string(id));
  std::erase_if(links_, [id](const auto& l) { return l.first.node == id || l.second.node == id; });
  std::erase_if(exposed_, [id](const ExposedParam& p) { return p.node == id; });
  return Status::ok();
}

Status Graph::restore_node(Node node) {
  if (!node.type) return Status::error("restore_node: node has no type");
  if (node.id == 0 || node.id > kMaxNodeId || nodes_.count(node.id))
    return Status::error("node id " + std::to_string(node.id) + " is invalid or taken");
  next_id_ = std::max(next_id_, node.id + 1);
  nodes_.emplace(node.id, std::move(node));
  return Status::ok();
}

const Node* Graph::node(NodeId id) const {
  auto it = nodes_.find(id);
  return it == nodes_.end() ? nullptr : &it->second;
}

Status Graph::set_param(NodeId id, std::string_view param, Value v) {
  const Node* n = node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  auto i = n->decl().param_index(param);
  if (!i) return Status::error("node " + std::to_string(id) + " (" + n->type->name() + ") has no parameter " + q(param));
  return set_param(id, *i, std::move(v));
}

Status Graph::set_param(NodeId id, std::size_t param, Value v) {
  auto it = nodes_.find(id);
  if (it == nodes_.end()) return Status::error("no node " + std::to_string(id));
  Node& n = it->second;
  if (param >= n.params.size()) return Status::error("node " + std::to_string(id) + " has no parameter #" + std::to_string(param));
  const ParamDecl& decl = n.decl().params()[param];
  if (Status s = decl.check(v); !s) return s;
  if (decl.sets_port_count) {
    std::vector<Value> params = n.params;
    params[param] = v;
    std::shared_ptr<const NodeType> variant = with_port_counts(n.type, params);
    std::map<PortRef, PortRef> relinked;
    if (Status s = ports_kept(links_, id, variant->decl, q(decl.name) + " = " + std::to_string(port_count_of(v)), relinked); !s) return s;
    links_ = std::move(relinked);
    n.type = std::move(variant);
  }
  n.params[param] = std::move(v);
  n.expressions.erase(static_cast<std::uint32_t>(param));
  return Status::ok();
}

std::optional<ExprType> Graph::expression_name_type(std::string_view name) const {
  if (auto i = input_index(name)) return expression_type(*inputs_[*i].type);
  for (const ExposedParam& e : exposed_)
    if (e.name == name) return expression_type(*node(e.node)->decl().params()[e.param].type);
  return std::nullopt;
}

Status Graph::set_expression(NodeId id, std::string_view param, std::string_view text) {
  const Node* n = node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  auto i = n->decl().param_index(param);
  if (!i) return Status::error("node " + std::to_string(id) + " (" + n->type->name() + ") has no parameter " + q(param));
  return set_expression(id, *i, text);
}

Status Graph::set_expression(NodeId id, std::size_t param, std::string_view text) {
  auto it = nodes_.find(id);
  if (it == nodes_.end()) return Status::error("no node " + std::to_string(id));
  Node& n = it->second;
  if (param >= n.params.size()) return Status::error("node " + std::to_string(id) + " has no parameter #" + std::to_string(param));
  const ParamDecl& decl = n.decl().params()[param];
  const std::string where = "node " + std::to_string(id) + " (" + n.type->name() + "), parameter " + q(decl.name) + ": ";
  const std::optional<ExprType> want = expression_type(*decl.type);
  if (!want || decl.sets_port_count)
    return Status::error(where + "a " + decl.type->name() + " parameter" + (want ? " that sets the number of ports" : "") +
                         " cannot hold an expression (float, int, bool, string and enum parameters can)");
  auto parsed = Expression::parse(text);
  if (!parsed) return Status::error(where + parsed.message());
  const Expression& e = **parsed;
  auto type = e.check([this](std::string_view name) { return expression_name_type(name); });
  if (!type) return Status::error(where + type.message());
  if (*type != *want)
    return Status::error(where + "column 1: the expression gives a " + to_string(*type) + " but the parameter takes a " +
                         decl.type->name());
  // An exposed parameter whose expression reads itself, directly or through others, has no value.
  std::vector<std::string> todo = e.names();
  std::set<std::string, std::less<>> seen;
  while (!todo.empty()) {
    const std::string name = todo.back();
    todo.pop_back();
    if (!seen.insert(name).second) continue;
    for (const ExposedParam& x : exposed_) {
      if (x.name != name) continue;
      if (x.node == id && x.param == param)
        return Status::error(where + "the expression reads " + q(name) + ", which is this parameter itself");
      const Node& target = nodes_.at(x.node);
      if (auto te = target.expressions.find(x.param); te != target.expressions.end())
        todo.insert(todo.end(), te->second->names().begin(), te->second->names().end());
    }
  }
  n.expressions[static_cast<std::uint32_t>(param)] = *parsed;
  return Status::ok();
}

Status Graph::ports_kept(const std::map<PortRef, PortRef>& links, NodeId id, const NodeDecl& next, const std::string& change,
                         std::map<PortRef, PortRef>& relinked) const {
  const NodeDecl& now = node(id)->decl();
  auto refuse = [&](const char* what, const std::string& port) {
    return Status::error("node " + std::to_string(id) + " (" + now.type_name() + "): " + change + " would remove " + what + " " +
                         q(port) + ", which is connected; disconnect it first");
  };
  // Where port i of `now` is in `next`, if it is still there.
  auto moved = [](const std::vector<PortDecl>& a, const std::vector<PortDecl>& b, std::uint32_t i) {
    const auto it = std::find_if(b.begin(), b.end(),
                                 [&](const PortDecl& p) { return p.name == a[i].name && p.type == a[i].type; });
    return it == b.end() ? std::optional<std::uint32_t>() : static_cast<std::uint32_t>(it - b.begin());
  };
  relinked.clear();
  for (const auto& link : links) {
    PortRef to = link.first, from = link.second;
    if (to.node == id) {
      const auto at = moved(now.inputs(), next.inputs(), to.port);
      if (!at) return refuse("input", now.inputs()[to.port].name);
      to.port = *at;
    }
    if (from.node == id) {
      const auto at = moved(now.outputs(), next.outputs(), from.port);
      if (!at) return refuse("output", now.outputs()[from.port].name);
      from.port = *at;
    }
    relinked.emplace(to, from);
  }
  return Status::ok();
}

Status Graph::set_editor_state(NodeId id, EditorState s) {
  auto it = nodes_.find(id);
  if (it == nodes_.end()) return Status::error("no node " + std::to_string(id));
  it->second.editor = std::move(s);
  return Status::ok();
}

const ValueType* Graph::output_type(PortRef p) const {
  if (p.node == kGraphInputs) return p.port < inputs_.size() ? inputs_[p.port].type : nullptr;
  const Node* n = node(p.node);
  if (!n || p.port >= n->decl().outputs().size()) return nullptr;
  return n->decl().outputs()[p.port].type;
}

const ValueType* Graph::input_type(PortRef p) const {
  if (p.node == kGraphOutputs) return p.port < outputs_.size() ? outputs_[p.port].type : nullptr;
  const Node* n = node(p.node);
  if (!n || p.port >= n->decl().inputs().size()) return nullptr;
  return n->decl().inputs()[p.port].type;
}

std::string Graph::port_name(PortRef p, bool is_output) const {
  if (p.node == kGraphInputs && is_output && p.port < inputs_.size()) return "@" + inputs_[p.port].name;
  if (p.node == kGraphOutputs && !is_output && p.port < outputs_.size()) return "@" + outputs_[p.port].name;
  const Node* n = node(p.node);
  if (n) {
    const auto& ports = is_output ? n->decl().outputs() : n->decl().inputs();
    if (p.port < ports.size()) return std::to_string(p.node) + "." + ports[p.port].name;
  }
  return std::to_string(p.node) + ".#" + std::to_string(p.port);
}

const Graph::CarriedTypes& Graph::carried_types(PortRef from, std::map<PortRef, CarriedTypes>& known) const {
  if (const auto k = known.find(from); k != known.end()) return k->second;
  CarriedTypes out;
  const ValueType* type = output_type(from);
  const Node* n = from.node == kGraphInputs ? nullptr : node(from.node);
  if (type && !type->is_any()) {
    out.emplace_back(type, from);
  } else if (n && n->decl().pass_through()) {
    const auto& inputs = n->decl().inputs();
    for (std::uint32_t i = 0; i < inputs.size(); ++i) {
      const auto link = links_.find(PortRef{from.node, i});
      if (!inputs[i].type->is_any() || link == links_.end()) continue;
      for (const auto& c : carried_types(link->second, known))  // the graph has no cycles: this ends
        if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
    }
  }
  return known[from] = std::move(out);
}

bool Graph::reaches(NodeId from, NodeId to) const {
  // Walks upstream from `to`: inputs of a node are contiguous in links_.
  std::vector<NodeId> stack{to};
  std::set<NodeId> seen;
  while (!stack.empty()) {
    const NodeId n = stack.back();
    stack.pop_back();
    if (n == from) return true;
    if (!seen.insert(n).second) continue;
    for (auto it = links_.lower_bound(PortRef{n, 0}); it != links_.end() && it->first.node == n; ++it)
      stack.push_back(it->second.node);
  }
  return false;
}

Status Graph::can_connect(PortRef from, PortRef to) const {
  const ValueType* ft = output_type(from);
  if (!ft) return Status::error("there is no output " + port_name(from, true) + " to link from");
  const ValueType* tt = input_type(to);
  if (!tt) return Status::error("there is no input " + port_name(to, false) + " to link to");
  if (auto it = links_.find(to); it != links_.end())
    return Status::error("input " + port_name(to, false) + " is already fed by " + port_name(it->second, true) +
                         "; disconnect it first");
  if (!ValueType::can_link(*ft, *tt))
    return Status::error("cannot link " + port_name(from, true) + " (" + ft->name() + ") to " + port_name(to, false) +
                         " (" + tt->name() + "): the types differ");
  const bool real_ends = from.node != kGraphInputs && to.node != kGraphOutputs;
  if (real_ends && reaches(to.node, from.node))
    return Status::error("linking " + port_name(from, true) + " to " + port_name(to, false) +
                         " would make a cycle: node " + std::to_string(from.node) + " already depends on node " +
                         std::to_string(to.node));
  return Status::ok();
}

Status Graph::connect(PortRef from, PortRef to) {
  if (Status s = can_connect(from, to); !s) return s;
  links_.emplace(to, from);
  return Status::ok();
}

Status Graph::connect(NodeId from, std::string_view output, NodeId to, std::string_view input) {
  const Node* a = node(from);
  const Node* b = node(to);
  if (!a || !b) return Status::error("no node " + std::to_string(a ? to : from));
  auto o = a->decl().output_index(output);
  if (!o) return Status::error("node " + std::to_string(from) + " (" + a->type->name() + ") has no output " + q(output));
  auto i = b->decl().input_index(input);
  if (!i) return Status::error("node " + std::to_string(to) + " (" + b->type->name() + ") has no input " + q(input));
  return connect(PortRef{from, static_cast<std::uint32_t>(*o)}, PortRef{to, static_cast<std::uint32_t>(*i)});
}

Status Graph::disconnect(PortRef to) {
  if (!links_.erase(to)) return Status::error("input " + port_name(to, false) + " has no link");
  return Status::ok();
}

std::optional<PortRef> Graph::source(PortRef to) const {
  auto it = links_.find(to);
  if (it == links_.end()) return std::nullopt;
  return it->second;
}

std::vector<Link> Graph::links_from(NodeId node) const {
  std::vector<Link> out;
  for (const auto& [to, from] : links_)
    if (from.node == node) out.push_back(Link{from, to});
  return out;
}

namespace {
template <class Port>
Status check_interface_port(const std::vector<Port>& existing, const Port& p, const char* what) {
  if (!is_identifier(p.name)) return Status::error(std::string(what) + " name " + q(p.name) + " is not an identifier ([a-z][a-z0-9_]*)");
  if (!p.type) return Status::error(std::string(what) + " " + q(p.name) + " has no type");
  for (const Port& e : existing)
    if (e.name == p.name) return Status::error("there is already a " + std::string(what) + " named " + q(p.name));
  return Status::ok();
}
}  // namespace

Status Graph::add_input(GraphInput in) {
  if (Status s = check_interface_port(inputs_, in, "graph input"); !s) return s;
  if (!in.default_value.empty() && in.default_value.type() != in.type)
    return Status::error("graph input " + q(in.name) + " is " + in.type->name() + " but its default is " +
                         in.default_value.type()->name());
  inputs_.push_back(std::move(in));
  return Status::ok();
}

Status Graph::add_output(GraphOutput out) {
  if (Status s = check_interface_port(outputs_, out, "graph output"); !s) return s;
  outputs_.push_back(std::move(out));
  return Status::ok();
}

Status Graph::remove_input(std::string_view name) {
  auto i = input_index(name);
  if (!i) return Status::error("no graph input " + q(name));
  const auto port = static_cast<std::uint32_t>(*i);
  std::erase_if(links_, [port](const auto& l) { return l.second.node == kGraphInputs && l.second.port == port; });
  renumber_after_removal(links_, kGraphInputs, port, /*as_source=*/true);
  inputs_.erase(inputs_.begin() + static_cast<std::ptrdiff_t>(*i));
  return Status::ok();
}

Status Graph::remove_output(std::string_view name) {
  auto i = output_index(name);
  if (!i) return Status::error("no graph output " + q(name));
  const auto port = static_cast<std::uint32_t>(*i);
  links_.erase(PortRef{kGraphOutputs, port});
  renumber_after_removal(links_, kGraphOutputs, port, /*as_source=*/false);
  outputs_.erase(outputs_.begin() + static_cast<std::ptrdiff_t>(*i));
  return Status::ok();
}

std::optional<std::size_t> Graph::input_index(std::string_view name) const {
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    if (inputs_[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> Graph::output_index(std::string_view name) const {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (outputs_[i].name == name) return i;
  return std::nullopt;
}

Status Graph::expose_param(ExposedParam p) {
  if (!is_identifier(p.name)) return Status::error("exposed parameter name " + q(p.name) + " is not an identifier");
  for (const ExposedParam& e : exposed_)
    if (e.name == p.name) return Status::error("there is already an exposed parameter named " + q(p.name));
  const Node* n = node(p.node);
  if (!n) return Status::error("exposed parameter " + q(p.name) + " refers to missing node " + std::to_string(p.node));
  if (p.param >= n->params.size())
    return Status::error("exposed parameter " + q(p.name) + ": node " + std::to_string(p.node) + " has no parameter #" +
                         std::to_string(p.param));
  if (n->decl().params()[p.param].sets_port_count)
    return Status::error("exposed parameter " + q(p.name) + ": " + q(n->decl().params()[p.param].name) + " of node " +
                         std::to_string(p.node) + " sets its number of ports, which a group's users cannot change");
  if (p.min && p.max && *p.min > *p.max) return Status::error("exposed parameter " + q(p.name) + ": min is above max");
  exposed_.push_back(std::move(p));
  return Status::ok();
}

Status Graph::unexpose_param(std::string_view name) {
  if (!std::erase_if(exposed_, [name](const ExposedParam& e) { return e.name == name; }))
    return Status::error("no exposed parameter " + q(name));
  return Status::ok();
}

Status Graph::set_exposed(std::string_view name, Value v) {
  for (const ExposedParam& e : exposed_)
    if (e.name == name) return set_param(e.node, e.param, std::move(v));
  return Status::error("no exposed parameter " + q(name));
}

namespace {
bool same_value(const Value& a, const Value& b) { return a.raw() == b.raw() ? a.type() == b.type() : a.same_content(b); }

bool same_node(const Node& a, const Node& b) {
  if (a.id != b.id || a.type != b.type || a.params.size() != b.params.size() ||
      !std::equal(a.params.begin(), a.params.end(), b.params.begin(), same_value))
    return false;
  return std::equal(a.expressions.begin(), a.expressions.end(), b.expressions.begin(), b.expressions.end(),
                    [](const auto& x, const auto& y) {
                      return x.first == y.first && (x.second == y.second || x.second->text() == y.second->text());
                    });
}
}  // namespace

bool Graph::evaluates_like(const Graph& other) const {
  const auto same_input = [](const GraphInput& a, const GraphInput& b) {
    return a.name == b.name && a.type == b.type && same_value(a.default_value, b.default_value);
  };
  const auto same_output = [](const GraphOutput& a, const GraphOutput& b) { return a.name == b.name && a.type == b.type; };
  const auto same_exposed = [](const ExposedParam& a, const ExposedParam& b) {
    return a.name == b.name && a.node == b.node && a.param == b.param;
  };
  return links_ == other.links_ &&
         std::equal(nodes_.begin(), nodes_.end(), other.nodes_.begin(), other.nodes_.end(),
                    [](const auto& a, const auto& b) { return same_node(a.second, b.second); }) &&
         std::equal(inputs_.begin(), inputs_.end(), other.inputs_.begin(), other.inputs_.end(), same_input) &&
         std::equal(outputs_.begin(), outputs_.end(), other.outputs_.begin(), other.outputs_.end(), same_output) &&
         std::equal(exposed_.begin(), exposed_.end(), other.exposed_.begin(), other.exposed_.end(), same_exposed);
}

Status Graph::set_preset(Preset p) {
  if (p.name.empty()) return Status::error("a preset needs a name");
  for (const auto& [name, v] : p.values) {
    // An init-capture: Clang before 16 cannot capture a structured binding.
    auto e = std::find_if(exposed_.begin(), exposed_.end(), [&key = name](const ExposedParam& x) { return x.name == key; });
    if (e == exposed_.end()) return Status::error("preset " + q(p.name) + ": no exposed parameter " + q(name));
    const ValueType* want = nodes_.at(e->node).decl().params()[e->param].type;
    if (v.type() != want)
      return Status::error("preset " + q(p.name) + ": " + q(name) + " takes a " + want->name() + ", not a " + (v.type() ? v.type()->name() : "nothing"));
  }
  for (Preset& existing : presets_)
    if (existing.name == p.name) {
      existing = std::move(p);
      return Status::ok();
    }
  presets_.push_back(std::move(p));
  return Status::ok();
}

Status Graph::remove_preset(std::string_view name) {
  if (!std::erase_if(presets_, [name](const Preset& p) { return p.name == name; })) return Status::error("no preset " + q(name));
  return Status::ok();
}

Status Graph::apply_preset(std::string_view name) {
  for (const Preset& p : presets_) {
    if (p.name != name) continue;
    for (const auto& [param, v] : p.values)
      if (Status s = set_exposed(param, v); !s) return s;
    return Status::ok();
  }
  std::string known;
  for (const Preset& p : presets_) known += (known.empty() ? "" : ", ") + p.name;
  return Status::error("no preset " + q(name) + (known.empty() ? " (the recipe has none)" : " (it has: " + known + ")"));
}

Status Graph::add_group(std::string name, std::shared_ptr<const Graph> body, std::string file) {
  if (!is_identifier(name)) return Status::error("group name " + q(name) + " is not an identifier ([a-z][a-z0-9_]*)");
  if (groups_.count(name)) return Status::error("there is already a group named " + q(name));
  auto type = make_group_type(name, std::move(body));
  if (!type) return type.status();
  groups_.emplace(name, GroupDef{name, *type, std::move(file)});
  return Status::ok();
}

Status Graph::remove_group(std::string_view name) {
  auto it = groups_.find(name);
  if (it == groups_.end()) return Status::error("no group named " + q(name));
  for (const auto& [id, n] : nodes_)
    if (n.group == name) return Status::error("group " + q(name) + " is still used by node " + std::to_string(id));
  groups_.erase(it);
  return Status::ok();
}

Status Graph::set_group_body(std::string_view name, std::shared_ptr<const Graph> body) {
  auto it = groups_.find(name);
  if (it == groups_.end()) return Status::error("no group named " + q(name));
  if (!it->second.file.empty())
    return Status::error("group " + q(name) + " is read from " + it->second.file + ": its graph is that file's, edited there");
  auto type = make_group_type(it->second.name, std::move(body));
  if (!type) return type.status();
  const NodeDecl& next = (*type)->decl;
  const std::string change = "the edit of group " + q(name);
  // Everything is worked out before anything changes, so a refusal leaves the graph as it was.
  std::map<PortRef, PortRef> links = links_;
  std::map<NodeId, Node> instances;
  for (const auto& [id, n] : nodes_) {
    if (n.group != name) continue;
    std::map<PortRef, PortRef> relinked;
    if (Status s = ports_kept(links, id, next, change, relinked); !s) return s;
    links = std::move(relinked);
    Node& now = instances[id] = n;
    now.type = *type;
    now.params = next.default_params();
    now.expressions.clear();
    for (std::size_t j = 0; j < next.params().size(); ++j) {
      const auto i = n.decl().param_index(next.params()[j].name);
      if (!i || n.decl().params()[*i].type != next.params()[j].type) continue;
      now.params[j] = n.params[*i];
      if (auto e = n.expressions.find(static_cast<std::uint32_t>(*i)); e != n.expressions.end())
        now.expressions[static_cast<std::uint32_t>(j)] = e->second;
    }
  }
  std::vector<ExposedParam> exposed = exposed_;
  for (ExposedParam& e : exposed) {
    auto inst = instances.find(e.node);
    if (inst == instances.end()) continue;
    const ParamDecl& was = nodes_.at(e.node).decl().params()[e.param];
    const auto j = next.param_index(was.name);
    if (!j || next.params()[*j].type != was.type)
      return Status::error("node " + std::to_string(e.node) + " (" + std::string(name) + "): " + change + " would remove parameter " +
                           q(was.name) + ", which this graph exposes as " + q(e.name) + "; unexpose it first");
    e.param = static_cast<std::uint32_t>(*j);
  }
  it->second.type = *type;
  for (auto& [id, n] : instances) nodes_.at(id) = std::move(n);
  links_ = std::move(links);
  exposed_ = std::move(exposed);
  return Status::ok();
}

std::vector<Diagnostic> Graph::validate() const {
  std::vector<Diagnostic> out;
  for (const auto& [id, n] : nodes_) {
    const auto& inputs = n.decl().inputs();
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (!inputs[i].optional && !links_.count(PortRef{id, static_cast<std::uint32_t>(i)}))
        out.push_back({Severity::kError, {id}, n.type->name(), "input " + q(inputs[i].name) + " is not connected"});
  }
  for (const auto& [id, n] : nodes_)
    for (const auto& [param, e] : n.expressions) {
      auto type = e->check([this](std::string_view name) { return expression_name_type(name); });
      if (!type)
        out.push_back({Severity::kError, {id}, n.type->name(), "parameter " + q(n.decl().params()[param].name) + ": " + type.message()});
    }
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (!links_.count(PortRef{kGraphOutputs, static_cast<std::uint32_t>(i)}))
      out.push_back({Severity::kError, {}, {}, "graph output " + q(outputs_[i].name) + " is not connected"});
  std::map<PortRef, CarriedTypes> carried;
  for (const auto& [to, from] : links_) {
    const ValueType* want = input_type(to);
    if (!want || want->is_any() || !output_type(from) || !output_type(from)->is_any()) continue;  // add_link checked the rest
    for (const auto& [type, origin] : carried_types(from, carried)) {
      if (type == want) continue;
      const std::string message = "input " + q(port_name(to, false)) + " takes " + want->name() + " but " +
                                  port_name(from, true) + " may hand on " + type->name() + " from " +
                                  port_name(origin, true) + ": connect a " + want->name() + " there";
      if (to.node == kGraphOutputs) out.push_back({Severity::kError, {}, {}, message});
      else out.push_back({Severity::kError, {to.node}, node(to.node)->type->name(), message});
    }
  }
  for (const auto& [name, g] : groups_) {
    for (Diagnostic d : g.type->body->validate()) {
      d.message = "in group " + q(name) + ": " + d.message;
      out.push_back(std::move(d));
    }
  }
  return out;
}

Result<std::shared_ptr<const NodeType>> make_group_type(std::string name, std::shared_ptr<const Graph> body) {
  if (!body) return Status::error("group " + q(name) + " has no body");
  auto t = std::make_shared<NodeType>();
  t->decl = NodeDecl(name, 1);
  t->decl.doc(body->metadata.description).category("Groups");
  for (const GraphInput& in : body->inputs()) t->decl.add_input(in.name, *in.type).doc(in.doc).optional(!in.default_value.empty());
  for (const GraphOutput& out : body->outputs()) t->decl.add_output(out.name, *out.type).doc(out.doc);
  for (const ExposedParam& e : body->exposed_params()) {
    const Node& inner = *body->node(e.node);
    ParamDecl p = inner.decl().params()[e.param];
    ParamBuilder b = t->decl.add_param(e.name, *p.type);
    b.default_value_of(inner.params[e.param]).unit(e.unit.empty() ? p.unit : e.unit).doc(e.label.empty() ? p.doc : e.label + (p.doc.empty() ? "" : ": " + p.doc));
    if (e.min || p.min) b.min(e.min ? *e.min : *p.min);
    if (e.max || p.max) b.max(e.max ? *e.max : *p.max);
    // Enum choices live on the declaration; copy them with the rest.
    const_cast<ParamDecl&>(t->decl.params().back()).choices = p.choices;
  }
  if (Status s = t->decl.validate(); !s) return Status::error("group " + q(name) + ": " + s.message());
  t->body = std::move(body);
  t->key = Hasher().str("group").str(name).result();
  return std::shared_ptr<const NodeType>(std::move(t));
}

}  // namespace procex
