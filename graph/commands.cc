#include "graph/commands.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace procex {

namespace {

class AddNode final : public Command {
 public:
  AddNode(std::shared_ptr<const NodeType> type, std::string group, EditorState e)
      : type_(std::move(type)), group_(std::move(group)), editor_(std::move(e)) {}
  std::string label() const override { return "add " + (group_.empty() ? type_->name() : group_); }
  Status apply(Graph& g) override {
    // Redo recreates the same id, so later commands that name it stay valid.
    Result<NodeId> r = group_.empty() ? g.add_node(type_, id_) : g.add_group_node(group_, id_);
    if (!r) return r.status();
    id_ = *r;
    return g.set_editor_state(id_, editor_);
  }
  void revert(Graph& g) override { (void)g.remove_node(id_); }
  NodeId id() const { return id_; }

 private:
  std::shared_ptr<const NodeType> type_;
  std::string group_;
  EditorState editor_;
  NodeId id_ = 0;
};

class RemoveNode final : public Command {
 public:
  explicit RemoveNode(NodeId id) : id_(id) {}
  std::string label() const override { return "remove node " + std::to_string(id_); }
  Status apply(Graph& g) override {
    const Node* n = g.node(id_);
    if (!n) return Status::error("no node " + std::to_string(id_));
    node_ = *n;
    links_.clear();
    for (const auto& [to, from] : g.links())
      if (to.node == id_ || from.node == id_) links_.push_back(Link{from, to});
    exposed_ = g.exposed_params();
    return g.remove_node(id_);
  }
  void revert(Graph& g) override {
    (void)g.restore_node(node_);
    for (const Link& l : links_) (void)g.connect(l.from, l.to);
    // Exposed parameters keep their order: it is the order of a group's parameters.
    for (const ExposedParam& e : g.exposed_params()) (void)g.unexpose_param(std::string(e.name));
    for (const ExposedParam& e : exposed_) (void)g.expose_param(e);
  }

 private:
  NodeId id_;
  Node node_;
  std::vector<Link> links_;
  std::vector<ExposedParam> exposed_;
};

class Connect final : public Command {
 public:
  Connect(PortRef from, PortRef to) : from_(from), to_(to) {}
  std::string label() const override { return "connect"; }
  Status apply(Graph& g) override {
    previous_ = g.source(to_);
    if (previous_) (void)g.disconnect(to_);
    Status s = g.connect(from_, to_);
    if (!s && previous_) (void)g.connect(*previous_, to_);
    return s;
  }
  void revert(Graph& g) override {
    (void)g.disconnect(to_);
    if (previous_) (void)g.connect(*previous_, to_);
  }

 private:
  PortRef from_, to_;
  std::optional<PortRef> previous_;
};

class Disconnect final : public Command {
 public:
  explicit Disconnect(PortRef to) : to_(to) {}
  std::string label() const override { return "disconnect"; }
  Status apply(Graph& g) override {
    auto src = g.source(to_);
    if (!src) return Status::error("input " + g.port_name(to_, false) + " has no link");
    from_ = *src;
    return g.disconnect(to_);
  }
  void revert(Graph& g) override { (void)g.connect(from_, to_); }

 private:
  PortRef to_, from_;
};

// A parameter's value or expression replaced: undo puts back both the value
// and the expression it had (a value set over an expression removes it).
class ParamCommand : public Command {
 public:
  ParamCommand(NodeId id, std::string param) : id_(id), param_(std::move(param)) {}
  Status apply(Graph& g) final {
    const Node* n = g.node(id_);
    if (!n) return Status::error("no node " + std::to_string(id_));
    auto i = n->decl().param_index(param_);
    if (!i) return Status::error("node " + std::to_string(id_) + " (" + n->type->name() + ") has no parameter '" + param_ + "'");
    index_ = *i;
    previous_ = n->params[index_];
    const auto e = n->expressions.find(static_cast<std::uint32_t>(index_));
    previous_expression_ = e == n->expressions.end() ? nullptr : e->second;
    return set(g, id_, index_);
  }
  void revert(Graph& g) override {
    (void)g.set_param(id_, index_, previous_);
    if (previous_expression_) (void)g.set_expression(id_, index_, previous_expression_->text());
  }

 protected:
  virtual Status set(Graph& g, NodeId id, std::size_t index) = 0;
  const std::string& param() const { return param_; }

 private:
  NodeId id_;
  std::string param_;
  Value previous_;
  std::shared_ptr<const Expression> previous_expression_;
  std::size_t index_ = 0;
};

class SetParam final : public ParamCommand {
 public:
  SetParam(NodeId id, std::string param, Value v) : ParamCommand(id, std::move(param)), value_(std::move(v)) {}
  std::string label() const override { return "set " + param(); }

 private:
  Status set(Graph& g, NodeId id, std::size_t index) override { return g.set_param(id, index, value_); }
  Value value_;
};

class SetExpression final : public ParamCommand {
 public:
  SetExpression(NodeId id, std::string param, std::string text) : ParamCommand(id, std::move(param)), text_(std::move(text)) {}
  std::string label() const override { return "set " + param() + " to " + text_; }

 private:
  Status set(Graph& g, NodeId id, std::size_t index) override { return g.set_expression(id, index, text_); }
  std::string text_;
};

class SetEditorState final : public Command {
 public:
  SetEditorState(NodeId id, EditorState s, std::string label) : id_(id), state_(std::move(s)), label_(std::move(label)) {}
  std::string label() const override { return label_; }
  Status apply(Graph& g) override {
    const Node* n = g.node(id_);
    if (!n) return Status::error("no node " + std::to_string(id_));
    previous_ = n->editor;
    return g.set_editor_state(id_, state_);
  }
  void revert(Graph& g) override { (void)g.set_editor_state(id_, previous_); }
  bool merge(const Command& next) override {
    const auto* m = dynamic_cast<const SetEditorState*>(&next);
    if (!m || m->id_ != id_ || m->label_ != label_) return false;
    state_ = m->state_;
    return true;
  }

 private:
  NodeId id_;
  EditorState state_, previous_;
  std::string label_;
};

// Picks `base`, or base_2, base_3... if taken.
std::string unique_name(const std::string& base, const std::set<std::string>& taken) {
  if (!taken.count(base)) return base;
  for (int i = 2;; ++i)
    if (std::string n = base + "_" + std::to_string(i); !taken.count(n)) return n;
}

// Edits that touch much of the graph (grouping) apply to a copy, so a refusal
// half way leaves the graph untouched, and revert by restoring a snapshot.
class SnapshotCommand : public Command {
 public:
  Status apply(Graph& g) override {
    before_ = g;
    Graph work = g;
    Status s = edit(work);
    if (s) g = std::move(work);
    return s;
  }
  void revert(Graph& g) override { g = before_; }

 protected:
  virtual Status edit(Graph& g) = 0;

 private:
  Graph before_;
};

class MakeGroup final : public SnapshotCommand {
 public:
  MakeGroup(std::vector<NodeId> nodes, std::string name) : ids_(std::move(nodes)), name_(std::move(name)) {
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
  }
  std::string label() const override { return "group as " + name_; }
  NodeId instance() const { return instance_; }


 private:
  Status edit(Graph& g) override {
    if (ids_.empty()) return Status::error("select at least one node to group");
    if (g.groups().count(name_)) return Status::error("there is already a group named '" + name_ + "'");
    for (NodeId id : ids_)
      if (!g.node(id)) return Status::error("no node " + std::to_string(id));
    const std::set<NodeId> inside(ids_.begin(), ids_.end());
    auto body = std::make_shared<Graph>();
    body->metadata.name = name_;
    double x = 0, y = 0;
    for (NodeId id : ids_) {
      const Node& n = *g.node(id);
      if (!n.group.empty() && !body->groups().count(n.group)) {
        const GroupDef& def = g.groups().find(n.group)->second;
        if (Status s = body->add_group(def.name, def.type->body, def.file); !s) return s;
      }
      if (Status s = body->restore_node(n); !s) return s;
      x += n.editor.x / static_cast<double>(ids_.size());
      y += n.editor.y / static_cast<double>(ids_.size());
    }
    std::vector<PortRef> in_sources;                         // outside sources, one body input each
    std::vector<std::pair<PortRef, std::vector<PortRef>>> out_links;  // inside source -> outside destinations
    std::set<std::string> in_names, out_names;
    for (const auto& link : g.links()) {
      const PortRef to = link.first, from = link.second;
      const bool to_in = inside.count(to.node) > 0, from_in = inside.count(from.node) > 0;
      if (to_in && from_in) {
        if (Status s = body->connect(from, to); !s) return s;
      } else if (to_in) {
        auto it = std::find(in_sources.begin(), in_sources.end(), from);
        if (it == in_sources.end()) {
          const PortDecl& port = g.node(to.node)->decl().inputs()[to.port];
          const ValueType* type = port.type->is_any() ? g.output_type(from) : port.type;
          std::string name = unique_name(port.name, in_names);
          in_names.insert(name);
          if (Status s = body->add_input(GraphInput{name, type, port.doc, {}}); !s) return s;
          in_sources.push_back(from);
          it = in_sources.end() - 1;
        }
        const auto k = static_cast<std::uint32_t>(it - in_sources.begin());
        if (Status s = body->connect(PortRef{kGraphInputs, k}, to); !s) return s;
      } else if (from_in) {
        auto it = std::find_if(out_links.begin(), out_links.end(), [&](const auto& o) { return o.first == from; });
        if (it == out_links.end()) {
          const PortDecl& port = g.node(from.node)->decl().outputs()[from.port];
          std::string name = unique_name(port.name, out_names);
          out_names.insert(name);
          if (Status s = body->add_output(GraphOutput{name, port.type, port.doc}); !s) return s;
          const auto k = static_cast<std::uint32_t>(out_links.size());
          if (Status s = body->connect(from, PortRef{kGraphOutputs, k}); !s) return s;
          out_links.push_back({from, {}});
          it = out_links.end() - 1;
        }
        it->second.push_back(to);
      }
    }
    // Parameters exposed on the outer graph keep their names, now through the group.
    std::vector<ExposedParam> carried;
    for (const ExposedParam& e : g.exposed_params())
      if (inside.count(e.node)) carried.push_back(e);
    for (const ExposedParam& e : carried)
      if (Status s = body->expose_param(e); !s) return s;
    if (Status s = g.add_group(name_, body); !s) return s;
    for (NodeId id : ids_) (void)g.remove_node(id);
    Result<NodeId> inst = g.add_group_node(name_, instance_);
    if (!inst) return inst.status();
    instance_ = *inst;
    (void)g.set_editor_state(instance_, EditorState{x, y, {}, false});
    for (std::uint32_t k = 0; k < in_sources.size(); ++k)
      if (Status s = g.connect(in_sources[k], PortRef{instance_, k}); !s) return s;
    for (std::uint32_t k = 0; k < out_links.size(); ++k)
      for (const PortRef& to : out_links[k].second)
        if (Status s = g.connect(PortRef{instance_, k}, to); !s) return s;
    for (std::uint32_t k = 0; k < carried.size(); ++k) {
      ExposedParam outer = carried[k];  // its name, label, unit and range, now on the group's parameter k
      outer.node = instance_;
      outer.param = k;
      if (Status s = g.expose_param(std::move(outer)); !s) return s;
    }
    return Status::ok();
  }

  std::vector<NodeId> ids_;
  std::string name_;
  NodeId instance_ = 0;
};

class Ungroup final : public SnapshotCommand {
 public:
  explicit Ungroup(NodeId id) : id_(id) {}
  std::string label() const override { return "ungroup node " + std::to_string(id_); }
  const std::vector<NodeId>& created() const { return created_; }


 private:
  Status edit(Graph& g) override {
    const Node* n = g.node(id_);
    if (!n || n->group.empty()) return Status::error("node " + std::to_string(id_) + " is not a group instance");
    const Node inst = *n;  // a copy: the instance is removed below
    const Graph& body = *inst.type->body;
    // What fed the instance and what it fed, before it goes.
    std::vector<std::optional<PortRef>> fed_by(body.inputs().size());
    for (std::uint32_t i = 0; i < fed_by.size(); ++i) fed_by[i] = g.source(PortRef{inst.id, i});
    const std::vector<Link> feeds = g.links_from(inst.id);
    const std::vector<ExposedParam> exposed = g.exposed_params();
    (void)g.remove_node(inst.id);

    std::map<NodeId, NodeId> remap;
    created_.clear();
    for (const auto& [old_id, inner] : body.nodes()) {
      Node copy = inner;
      if (!inner.group.empty()) {
        const GroupDef& def = body.groups().find(inner.group)->second;
        auto existing = g.groups().find(inner.group);
        if (existing == g.groups().end()) {
          if (Status s = g.add_group(def.name, def.type->body, def.file); !s) return s;
          existing = g.groups().find(inner.group);
        } else if (existing->second.type->body != def.type->body) {
          return Status::error("cannot ungroup: this recipe already has a different group named '" + inner.group + "'");
        }
        copy.type = existing->second.type;
      }
      copy.id = g.next_id();
      copy.editor.x += inst.editor.x;
      copy.editor.y += inst.editor.y;
      if (Status s = g.restore_node(std::move(copy)); !s) return s;
      remap[old_id] = g.next_id() - 1;
      created_.push_back(g.next_id() - 1);
    }
    const auto& inner_exposed = body.exposed_params();
    for (std::size_t k = 0; k < inner_exposed.size(); ++k)
      if (Status s = g.set_param(remap.at(inner_exposed[k].node), inner_exposed[k].param, inst.params[k]); !s) return s;
    // Where an inner output port now comes from in the outer graph (nullopt: nothing).
    auto outer_source = [&](PortRef inner) -> std::optional<PortRef> {
      if (inner.node == kGraphInputs) return fed_by[inner.port];
      return PortRef{remap.at(inner.node), inner.port};
    };
    for (const auto& [to, from] : body.links()) {
      if (to.node == kGraphOutputs) continue;
      if (auto src = outer_source(from))
        if (Status s = g.connect(*src, PortRef{remap.at(to.node), to.port}); !s) return s;
    }
    for (const Link& l : feeds) {
      auto inner = body.source(PortRef{kGraphOutputs, l.from.port});
      if (!inner) continue;
      if (auto src = outer_source(*inner))
        if (Status s = g.connect(*src, l.to); !s) return s;
    }
    // Parameters the outer graph exposed through the instance now point inside.
    for (const ExposedParam& e : g.exposed_params()) (void)g.unexpose_param(std::string(e.name));
    for (ExposedParam e : exposed) {
      if (e.node == inst.id) {
        const ExposedParam& inner = inner_exposed[e.param];
        e.node = remap.at(inner.node);
        e.param = inner.param;
      }
      if (Status s = g.expose_param(e); !s) return s;
    }
    return Status::ok();
  }

  NodeId id_;
  std::vector<NodeId> created_;
};

class InGroup final : public Command {
 public:
  InGroup(std::vector<NodeId> path, std::unique_ptr<Command> inner) : path_(std::move(path)), inner_(std::move(inner)) {}
  std::string label() const override { return inner_->label(); }
  Status apply(Graph& g) override {
    return edit(g, [this](Graph& body) { return inner_->apply(body); });
  }
  void revert(Graph& g) override {
    (void)edit(g, [this](Graph& body) {
      inner_->revert(body);
      return Status::ok();
    });
  }
  bool merge(const Command& next) override {
    const auto* m = dynamic_cast<const InGroup*>(&next);
    return m && m->path_ == path_ && inner_->merge(*m->inner_);
  }

 private:
  // `change` made to a copy of the innermost group's graph, then each level's
  // new graph set as its group's in a copy of the level above; `g` itself
  // changes last, so a refusal on the way up changes nothing.
  Status edit(Graph& g, const std::function<Status(Graph&)>& change) {
    Result<std::vector<const Graph*>> levels = group_levels(g, path_, true);
    if (!levels) return levels.status();
    auto body = std::make_shared<Graph>(*(*levels).back());
    if (Status s = change(*body); !s) return s;
    for (std::size_t i = path_.size(); i-- > 1;) {
      auto above = std::make_shared<Graph>(*(*levels)[i]);
      if (Status s = above->set_group_body(above->node(path_[i])->group, std::move(body)); !s) return s;
      body = std::move(above);
    }
    return g.set_group_body(std::string(g.node(path_[0])->group), std::move(body));
  }

  std::vector<NodeId> path_;
  std::unique_ptr<Command> inner_;
};

class Macro final : public Command {
 public:
  explicit Macro(std::string label) : label_(std::move(label)) {}
  std::string label() const override { return label_; }
  Status apply(Graph& g) override {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (Status s = steps[i]->apply(g); !s) {
        while (i-- > 0) steps[i]->revert(g);
        return s;
      }
    }
    return Status::ok();
  }
  void revert(Graph& g) override {
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)->revert(g);
  }
  std::vector<std::unique_ptr<Command>> steps;

 private:
  std::string label_;
};

}  // namespace

struct UndoStack::Macro {
  std::unique_ptr<::procex::Macro> command;
};

UndoStack::UndoStack(Graph& g, std::size_t limit) : graph_(g), limit_(limit) {}
UndoStack::~UndoStack() = default;

void UndoStack::record(std::unique_ptr<Command> c) {
  if (!macros_.empty()) {
    macros_.back()->command->steps.push_back(std::move(c));
    return;
  }
  undone_.clear();
  if (merge_open_ && !done_.empty() && done_.back()->merge(*c)) return;
  done_.push_back(std::move(c));
  if (done_.size() > limit_) done_.erase(done_.begin());
}

Status UndoStack::push(std::unique_ptr<Command> c) {
  c = at_scope(std::move(c));
  Status s = c->apply(graph_);
  if (!s) return s;
  record(std::move(c));
  merge_open_ = false;
  return s;
}

bool UndoStack::undo() {
  if (done_.empty() || !macros_.empty()) return false;
  done_.back()->revert(graph_);
  undone_.push_back(std::move(done_.back()));
  done_.pop_back();
  merge_open_ = false;
  trim_scope();
  return true;
}

bool UndoStack::redo() {
  if (undone_.empty() || !macros_.empty()) return false;
  if (!undone_.back()->apply(graph_)) return false;  // only if the graph was edited behind the stack's back
  done_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  merge_open_ = false;
  trim_scope();
  return true;
}

std::string UndoStack::undo_label() const { return done_.empty() ? std::string() : done_.back()->label(); }
std::string UndoStack::redo_label() const { return undone_.empty() ? std::string() : undone_.back()->label(); }

void UndoStack::clear() {
  done_.clear();
  undone_.clear();
  merge_open_ = false;
}

void UndoStack::begin_macro(std::string label) {
  macros_.push_back(std::make_unique<Macro>(Macro{std::make_unique<::procex::Macro>(std::move(label))}));
}

void UndoStack::end_macro() {
  if (macros_.empty()) return;
  std::unique_ptr<::procex::Macro> m = std::move(macros_.back()->command);
  macros_.pop_back();
  if (!m->steps.empty()) record(std::move(m));
  merge_open_ = false;
}

void UndoStack::abort_macro() {
  if (macros_.empty()) return;
  macros_.back()->command->revert(graph_);
  macros_.pop_back();
}

Result<NodeId> UndoStack::add_node(std::string_view type_name, EditorState editor) {
  auto type = NodeRegistry::global().find(type_name);
  if (!type) return Status::error(NodeRegistry::global().unknown_type_message(type_name));
  auto c = std::make_unique<AddNode>(std::move(type), std::string(), std::move(editor));
  AddNode& ref = *c;
  if (Status s = push(std::move(c)); !s) return s;
  return ref.id();
}

Result<NodeId> UndoStack::add_group_node(std::string_view group_name, EditorState editor) {
  auto it = scoped().groups().find(group_name);
  if (it == scoped().groups().end()) return Status::error("no group named '" + std::string(group_name) + "'");
  auto c = std::make_unique<AddNode>(it->second.type, it->second.name, std::move(editor));
  AddNode& ref = *c;
  if (Status s = push(std::move(c)); !s) return s;
  return ref.id();
}

Status UndoStack::remove_node(NodeId id) { return push(remove_node_command(id)); }
Status UndoStack::connect(PortRef from, PortRef to) { return push(connect_command(from, to)); }
Status UndoStack::disconnect(PortRef to) { return push(disconnect_command(to)); }
Status UndoStack::set_param(NodeId id, std::string_view param, Value v) {
  return push(set_param_command(id, std::string(param), std::move(v)));
}

Status UndoStack::set_expression(NodeId id, std::string_view param, std::string_view text) {
  return push(set_expression_command(id, std::string(param), std::string(text)));
}

Status UndoStack::move(NodeId id, double x, double y) {
  const Node* n = scoped().node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  EditorState s = n->editor;
  s.x = x;
  s.y = y;
  auto c = at_scope(editor_state_command(id, std::move(s), "move"));
  if (Status st = c->apply(graph_); !st) return st;
  record(std::move(c));
  merge_open_ = true;
  return Status::ok();
}

Status UndoStack::set_editor_state(NodeId id, EditorState s) { return push(editor_state_command(id, std::move(s), "edit note")); }

Result<NodeId> UndoStack::group(std::vector<NodeId> nodes, std::string group_name) {
  auto c = std::make_unique<MakeGroup>(std::move(nodes), std::move(group_name));
  MakeGroup& ref = *c;
  if (Status s = push(std::move(c)); !s) return s;
  return ref.instance();
}

Result<std::vector<NodeId>> UndoStack::ungroup(NodeId instance) {
  auto c = std::make_unique<Ungroup>(instance);
  Ungroup& ref = *c;
  if (Status s = push(std::move(c)); !s) return s;
  return ref.created();
}

Status UndoStack::set_scope(std::vector<NodeId> path) {
  if (Result<std::vector<const Graph*>> levels = group_levels(graph_, path, true); !levels) return levels.status();
  scope_ = std::move(path);
  merge_open_ = false;
  return Status::ok();
}

const Graph& UndoStack::scoped() const { return *(*group_levels(graph_, scope_, false)).back(); }

std::unique_ptr<Command> UndoStack::at_scope(std::unique_ptr<Command> c) const {
  return scope_.empty() ? std::move(c) : in_group_command(scope_, std::move(c));
}

void UndoStack::trim_scope() {
  while (!group_levels(graph_, scope_, true)) scope_.pop_back();
}

Result<std::vector<const Graph*>> group_levels(const Graph& g, const std::vector<NodeId>& path, bool editable) {
  std::vector<const Graph*> levels{&g};
  for (NodeId id : path) {
    const Graph& at = *levels.back();
    const Node* n = at.node(id);
    if (!n || n->group.empty()) return Status::error("node " + std::to_string(id) + " is not a group node");
    const std::string& file = at.groups().find(n->group)->second.file;
    if (editable && !file.empty())
      return Status::error("group '" + n->group + "' is read from " + file +
                           ", which other recipes may use too: open that file to edit it, or Ungroup to edit a copy here");
    levels.push_back(n->type->body.get());
  }
  return levels;
}

std::unique_ptr<Command> add_node_command(std::shared_ptr<const NodeType> type, std::string group, EditorState e) {
  return std::make_unique<AddNode>(std::move(type), std::move(group), std::move(e));
}
std::unique_ptr<Command> remove_node_command(NodeId id) { return std::make_unique<RemoveNode>(id); }
std::unique_ptr<Command> connect_command(PortRef from, PortRef to) { return std::make_unique<Connect>(from, to); }
std::unique_ptr<Command> disconnect_command(PortRef to) { return std::make_unique<Disconnect>(to); }
std::unique_ptr<Command> set_param_command(NodeId id, std::string param, Value v) {
  return std::make_unique<SetParam>(id, std::move(param), std::move(v));
}

std::unique_ptr<Command> set_expression_command(NodeId id, std::string param, std::string text) {
  return std::make_unique<SetExpression>(id, std::move(param), std::move(text));
}
std::unique_ptr<Command> editor_state_command(NodeId id, EditorState s, std::string label) {
  return std::make_unique<SetEditorState>(id, std::move(s), std::move(label));
}
std::unique_ptr<Command> group_command(std::vector<NodeId> nodes, std::string group_name) {
  return std::make_unique<MakeGroup>(std::move(nodes), std::move(group_name));
}
std::unique_ptr<Command> ungroup_command(NodeId instance) { return std::make_unique<Ungroup>(instance); }
std::unique_ptr<Command> in_group_command(std::vector<NodeId> path, std::unique_ptr<Command> inner) {
  return std::make_unique<InGroup>(std::move(path), std::move(inner));
}

}  // namespace procex
