#include "app/studio/editor/document.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>

#include "app/studio/editor/auto_layout.h"
#include "app/studio/editor/canvas_layout.h"
#include "graph/pxg.h"

namespace procex::studio {

namespace {

// A recipe-interface edit: whatever `edit` does, undone by restoring the
// graph as it was (copies share node types, values and group bodies: cheap).
class RecipeEdit : public Command {
 public:
  RecipeEdit(std::string label, std::function<Status(Graph&)> edit) : label_(std::move(label)), edit_(std::move(edit)) {}
  std::string label() const override { return label_; }
  Status apply(Graph& g) override {
    before_ = g;
    Status s = edit_(g);
    if (!s) g = before_;
    return s;
  }
  void revert(Graph& g) override { g = before_; }

 private:
  std::string label_;
  std::function<Status(Graph&)> edit_;
  Graph before_;
};

EditorState editor_at(double x, double y) {
  EditorState e;
  e.x = x;
  e.y = y;
  return e;
}
// Revisions of every document come from one counter: an evaluation of one
// recipe is never taken for that of another opened in its place at the same count.
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

}  // namespace

Document::Document() : Document(Graph{}, {}) {}

Document::Document(Graph graph, std::filesystem::path path)
    : graph_(std::move(graph)), stack_(graph_), path_(std::move(path)), saved_text_(to_pxg(graph_)) {
  revision_ = saved_revision_ = next_revision();
}

std::unique_ptr<Document> Document::open(const std::filesystem::path& file) {
  Graph g = load_pxg(file);
  place_stacked_nodes(g);
  return std::unique_ptr<Document>(new Document(std::move(g), file));
}

std::unique_ptr<Document> Document::recovered(Graph graph, std::filesystem::path file) {
  auto doc = std::unique_ptr<Document>(new Document(Graph{}, std::move(file)));
  doc->graph_ = std::move(graph);
  doc->revision_ = next_revision();  // differs from the saved revision and text: dirty until saved
  return doc;
}

std::string Document::title() const { return path_.empty() ? "untitled" : path_.filename().string(); }

bool Document::dirty() const {
  if (revision_ == saved_revision_) return false;
  if (dirty_revision_ != revision_) {
    dirty_ = to_pxg(graph_) != saved_text_;
    dirty_revision_ = revision_;
  }
  return dirty_;
}

void Document::save() {
  if (path_.empty()) throw std::runtime_error("the recipe has no file name yet: use Save As");
  std::string text = to_pxg(graph_);
  write_file_atomically(path_, text);
  saved_text_ = std::move(text);
  saved_revision_ = revision_;
}

void Document::save_as(const std::filesystem::path& file) {
  std::string text = to_pxg(graph_);
  write_file_atomically(file, text);
  path_ = file;
  saved_text_ = std::move(text);
  saved_revision_ = revision_;
}

const Graph& Document::graph() const {
  if (scope().empty()) return graph_;
  const std::vector<const Graph*> levels = *group_levels(graph_, scope(), false);
  const std::shared_ptr<const Graph>& body = levels[levels.size() - 2]->node(scope().back())->type->body;
  if (handed_out_.empty() || handed_out_.back() != body) handed_out_.push_back(body);
  return *body;
}

template <class R>
R Document::changed(R r) {
  if (r) revision_ = next_revision();
  std::erase_if(selection_, [this](NodeId id) { return graph().node(id) == nullptr; });
  return r;
}

Result<NodeId> Document::add_node(std::string_view type_name, double x, double y) {
  Result<NodeId> r = stack_.add_node(type_name, editor_at(x, y));
  if (r) selection_ = {*r};
  return changed(std::move(r));
}

Result<NodeId> Document::add_group_node(std::string_view group_name, double x, double y) {
  Result<NodeId> r = stack_.add_group_node(group_name, editor_at(x, y));
  if (r) selection_ = {*r};
  return changed(std::move(r));
}

Result<NodeId> Document::add_node_wired(std::string_view name, bool group, double x, double y, NodeId from) {
  end_gesture();
  stack_.begin_macro("add " + std::string(name));
  Result<NodeId> r = group ? stack_.add_group_node(name, editor_at(x, y)) : stack_.add_node(name, editor_at(x, y));
  if (!r) {
    stack_.abort_macro();
    return changed(std::move(r));
  }
  const Node* source = graph().node(from);
  const Node& added = *graph().node(*r);
  bool wired = false;
  for (std::uint32_t o = 0; source && !wired && o < source->decl().outputs().size(); ++o)
    for (std::uint32_t i = 0; !wired && i < added.decl().inputs().size(); ++i)
      if (graph().can_connect({from, o}, {*r, i})) wired = static_cast<bool>(stack_.connect({from, o}, {*r, i}));
  stack_.end_macro();
  selection_ = {*r};
  return changed(std::move(r));
}

Status Document::connect(PortRef from, PortRef to) { return changed(stack_.connect(from, to)); }

Status Document::disconnect(PortRef to) { return changed(stack_.disconnect(to)); }

Status Document::set_param(NodeId id, std::size_t param, Value v) {
  const Node* n = graph().node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  if (param >= n->decl().params().size()) return Status::error("node " + std::to_string(id) + " has no parameter " + std::to_string(param));
  // Keeps drags that end where they began out of the history; the same value over an expression replaces it.
  if (n->params[param].same_content(v) && !n->expressions.count(static_cast<std::uint32_t>(param))) return Status::ok();
  return changed(stack_.set_param(id, n->decl().params()[param].name, std::move(v)));
}

Status Document::set_expression(NodeId id, std::size_t param, std::string_view text) {
  const Node* n = graph().node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  if (param >= n->decl().params().size()) return Status::error("node " + std::to_string(id) + " has no parameter " + std::to_string(param));
  const auto now = n->expressions.find(static_cast<std::uint32_t>(param));
  if (now != n->expressions.end() && now->second->text() == text) return Status::ok();
  end_gesture();
  return changed(stack_.set_expression(id, n->decl().params()[param].name, text));
}

Status Document::set_port_count(NodeId id, std::size_t param, std::size_t count) {
  const Node* n = graph().node(id);
  if (!n) return Status::error("no node " + std::to_string(id));
  if (param >= n->decl().params().size() || !n->decl().params()[param].sets_port_count)
    return Status::error("node " + std::to_string(id) + " has no port-count parameter " + std::to_string(param));
  const Value& now = n->params[param];
  if (now.is<std::int64_t>()) return set_param(id, param, Value::make(static_cast<std::int64_t>(count)));
  if (now.is<std::vector<std::string>>()) {
    std::vector<std::string> entries = now.get<std::vector<std::string>>();
    entries.resize(count);
    return set_param(id, param, Value::make(std::move(entries)));
  }
  return Status::error("parameter '" + n->decl().params()[param].name + "' sets a port count but is neither an int nor a list of strings");
}

Status Document::move_selection(double dx, double dy) {
  if (selection_.empty() || (dx == 0 && dy == 0)) return Status::ok();
  stack_.begin_macro(selection_.size() == 1 ? "move node" : "move nodes");
  for (NodeId id : selection_) {
    const Node* n = graph().node(id);
    if (!n) continue;
    if (Status s = stack_.move(id, n->editor.x + dx, n->editor.y + dy); !s) {
      stack_.abort_macro();
      return s;
    }
  }
  stack_.end_macro();
  stack_.end_interaction();
  return changed(Status::ok());
}

Status Document::remove_selection() {
  if (selection_.empty()) return Status::ok();
  stack_.begin_macro(selection_.size() == 1 ? "delete node" : "delete nodes");
  for (NodeId id : std::vector<NodeId>(selection_.begin(), selection_.end())) {
    if (Status s = stack_.remove_node(id); !s) {
      stack_.abort_macro();
      return s;
    }
  }
  stack_.end_macro();
  return changed(Status::ok());
}

Result<NodeId> Document::group_selection() {
  if (selection_.empty()) return Status::error("select the nodes to group first");
  Result<NodeId> r = stack_.group(std::vector<NodeId>(selection_.begin(), selection_.end()), free_group_name("group", 1));
  if (r) selection_ = {*r};
  return changed(std::move(r));
}

std::string Document::free_group_name(const std::string& base, int first_number) const {
  const auto free = [&](const std::string& name) { return !graph().groups().count(name) && !NodeRegistry::global().find(name); };
  if (first_number > 1 && free(base)) return base;
  for (int i = first_number;; ++i)
    if (std::string name = base + std::to_string(i); free(name)) return name;
}

std::vector<std::string> library_files(const std::filesystem::path& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder / "lib", ec), end; !ec && it != end; it.increment(ec))
    // Links could lead out of the recipe's folder, which the loader refuses: only plain files are listed.
    if (it->path().extension() == ".pxg" && it->symlink_status(ec).type() == std::filesystem::file_type::regular)
      out.push_back("lib/" + it->path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

Result<std::filesystem::path> Document::library_folder(const std::string& what) const {
  if (path_.empty()) return Status::error("save the recipe first: " + what + " the lib folder beside it");
  return std::filesystem::absolute(path_).parent_path();
}

Result<std::filesystem::path> Document::save_group_to_library() {
  const Node* n = graph().node(selected());
  if (!n || n->group.empty()) return Status::error("select one group node to save its group to the library");
  Result<std::filesystem::path> folder = library_folder("the library is");
  if (!folder) return folder;
  const std::filesystem::path file = *folder / "lib" / (n->group + ".pxg");
  try {
    std::filesystem::create_directories(file.parent_path());
    save_pxg(*n->type->body, file);
  } catch (const std::exception& e) {
    return Status::error(e.what());
  }
  return file;
}

Result<NodeId> Document::place_library_group(const std::string& file, double x, double y) {
  Result<std::filesystem::path> folder = library_folder("placing from the library reads");
  if (!folder) return folder.status();
  std::shared_ptr<const Graph> body;
  try {
    body = std::make_shared<const Graph>(load_pxg(*folder / file));
  } catch (const std::exception& e) {
    return Status::error(e.what());
  }
  const std::string name = free_group_name(std::filesystem::path(file).stem().string(), 2);
  // Kept by the undo stack and run again by redo: everything by value, the node's id from the first run.
  auto placed = std::make_shared<NodeId>(0);
  Status s = edit_recipe("place " + name, [=](Graph& g) -> Status {
    const std::vector<NodeBox> others = layout(g);
    if (Status added = g.add_group(name, body, file); !added) return added;
    Result<NodeId> r = g.add_group_node(name, *placed);
    if (!r) return r.status();
    *placed = *r;
    const NodeDecl& decl = g.node(*placed)->decl();
    const glm::vec2 corner = free_spot(others, {x, y}, node_size(decl.inputs().size(), decl.outputs().size()));
    return g.set_editor_state(*placed, editor_at(corner.x, corner.y));
  });
  if (!s) return s;
  selection_ = {*placed};
  return *placed;
}

Status Document::tidy_layout() {
  const std::map<NodeId, glm::vec2> corners = layered_layout(graph());
  end_gesture();
  stack_.begin_macro("tidy layout");
  for (const auto& [id, c] : corners) {
    if (Status s = stack_.move(id, c.x, c.y); !s) {
      stack_.abort_macro();
      return s;
    }
  }
  stack_.end_macro();
  stack_.end_interaction();
  return changed(Status::ok());
}

Result<std::vector<NodeId>> Document::ungroup_selection() {
  const Node* n = graph().node(selected());
  if (!n || n->group.empty()) return Status::error("select one group node to ungroup");
  end_gesture();
  Result<std::vector<NodeId>> r = stack_.ungroup(n->id);
  if (r) selection_ = std::set<NodeId>((*r).begin(), (*r).end());
  return changed(std::move(r));
}

Status Document::edit_recipe(std::string label, std::function<Status(Graph&)> edit) {
  end_gesture();
  return changed(stack_.push(std::make_unique<RecipeEdit>(std::move(label), std::move(edit))));
}

Status Document::expose(NodeId id, std::size_t param, ExposedParam p, Value default_value) {
  p.node = id;
  p.param = static_cast<std::uint32_t>(param);
  return edit_recipe("expose " + p.name, [p, default_value](Graph& g) {
    if (Status s = g.expose_param(p); !s) return s;
    if (!default_value.empty()) return g.set_param(p.node, p.param, default_value);
    return Status::ok();
  });
}

Status Document::save_preset(const std::string& name) {
  Preset p{name, {}};
  for (const ExposedParam& e : graph().exposed_params()) p.values[e.name] = graph().node(e.node)->params[e.param];
  if (p.values.empty()) return Status::error("expose a parameter first: a preset holds exposed values");
  return edit_recipe("save preset " + name, [p](Graph& g) { return g.set_preset(p); });
}

Status Document::apply_preset(const std::string& name) {
  return edit_recipe("apply preset " + name, [name](Graph& g) { return g.apply_preset(name); });
}

Status Document::enter_group(NodeId id) {
  std::vector<NodeId> path = scope();
  path.push_back(id);
  end_gesture();
  if (Status s = stack_.set_scope(std::move(path)); !s) return s;
  selection_.clear();
  return Status::ok();
}

void Document::leave_group(std::size_t depth) {
  if (depth >= scope().size()) return;
  end_gesture();
  const NodeId left = scope()[depth];
  (void)stack_.set_scope(std::vector<NodeId>(scope().begin(), scope().begin() + static_cast<std::ptrdiff_t>(depth)));
  selection_ = {left};
}

std::vector<std::string> Document::breadcrumb() const {
  std::vector<std::string> out{title()};
  const Graph* at = &graph_;
  for (NodeId id : scope()) {
    const Node& n = *at->node(id);
    out.push_back(n.group);
    at = n.type->body.get();
  }
  return out;
}

bool Document::undo() { return history_step(&UndoStack::undo); }

bool Document::redo() { return history_step(&UndoStack::redo); }

bool Document::history_step(bool (UndoStack::*step)()) {
  end_gesture();
  const std::size_t depth = scope().size();
  const bool done = (stack_.*step)();
  // Backed out of a group whose node went: the selected ids would name other nodes here.
  if (scope().size() != depth) selection_.clear();
  return changed(done);
}

void Document::begin_gesture(std::string label) {
  if (gesture_open_) return;
  stack_.begin_macro(std::move(label));
  gesture_open_ = true;
}

void Document::end_gesture() {
  if (!gesture_open_) return;
  stack_.end_macro();
  gesture_open_ = false;
}

void Document::abort_gesture() {
  if (!gesture_open_) return;
  stack_.abort_macro();
  gesture_open_ = false;
  (void)changed(Status::ok());
}

std::string Document::copy_selection() const {
  Graph clip;
  for (NodeId id : selection_) {
    const Node* n = graph().node(id);
    if (!n) continue;
    Result<NodeId> added = NodeId{0};
    if (n->group.empty()) {
      added = clip.add_node(n->type, id);
    } else {
      // Embedded in the clipboard: a paste needs the group's name, not its library file.
      if (!clip.groups().count(n->group)) (void)clip.add_group(n->group, n->type->body);
      added = clip.add_group_node(n->group, id);
    }
    if (!added) continue;
    for (std::size_t p = 0; p < n->params.size(); ++p) (void)clip.set_param(id, p, n->params[p]);
    (void)clip.set_editor_state(id, n->editor);
  }
  for (const auto& [to, from] : graph().links())
    if (selection_.count(to.node) && selection_.count(from.node)) (void)clip.connect(from, to);
  return to_pxg(clip);
}

Result<std::vector<NodeId>> Document::paste(std::string_view text, double dx, double dy) {
  Graph clip;
  try {
    clip = parse_pxg(text, path_.empty() ? std::filesystem::path("clipboard.pxg") : path_.parent_path() / "clipboard.pxg");
  } catch (const PxgError& e) {
    return Status::error("the clipboard holds no procex nodes: " + e.where() + ": " + e.message());
  }
  if (clip.nodes().empty()) return Status::error("the clipboard holds no procex nodes");
  end_gesture();
  stack_.begin_macro("paste");
  std::map<NodeId, NodeId> ids;  // clipboard id -> new id
  auto fail = [&](Status s) -> Result<std::vector<NodeId>> {
    stack_.abort_macro();
    return s;
  };
  for (const auto& [old_id, n] : clip.nodes()) {
    EditorState e = n.editor;
    e.x += dx;
    e.y += dy;
    if (!n.group.empty() && !graph().groups().count(n.group))
      return fail(Status::error("node " + std::to_string(old_id) + " is an instance of group '" + n.group + "', which this recipe does not define"));
    Result<NodeId> r = n.group.empty() ? stack_.add_node(n.type->name(), e) : stack_.add_group_node(n.group, e);
    if (!r) return fail(r.status());
    ids[old_id] = *r;
    const Node& added = *graph().node(*r);
    for (std::size_t p = 0; p < n.params.size() && p < added.params.size(); ++p) {
      if (added.params[p].same_content(n.params[p])) continue;
      if (Status s = stack_.set_param(*r, added.decl().params()[p].name, n.params[p]); !s) return fail(s);
    }
  }
  for (const auto& [to, from] : clip.links()) {
    if (!ids.count(from.node) || !ids.count(to.node)) continue;
    if (Status s = stack_.connect({ids[from.node], from.port}, {ids[to.node], to.port}); !s) return fail(s);
  }
  stack_.end_macro();
  std::vector<NodeId> added;
  selection_.clear();
  for (const auto& [old_id, id] : ids) {
    added.push_back(id);
    selection_.insert(id);
  }
  return changed(Result<std::vector<NodeId>>(std::move(added)));
}

void Document::select_only(NodeId id) { selection_ = {id}; }

void Document::select(const std::vector<NodeId>& ids, bool add) {
  if (!add) selection_.clear();
  selection_.insert(ids.begin(), ids.end());
}

void Document::toggle(NodeId id) {
  if (!selection_.erase(id)) selection_.insert(id);
}

}  // namespace procex::studio
