// document.h -- one open recipe in the studio: the graph, its undo stack, its
// file, and the editor's selection.
//
// The studio owns no recipe data besides the Graph: every edit below is a
// command on the UndoStack (one undo step each; gestures that span frames use
// begin_gesture/end_gesture to become one step). `revision()` grows with every
// change, so the UI knows when to re-evaluate and whether the file is dirty;
// no two documents share one, so it also tells a recipe opened in another's place.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "graph/commands.h"
#include "graph/graph.h"
#include "graph/status.h"

namespace procex::studio {

// The group files of the library beside a recipe in `folder`: the regular
// .pxg files of folder/lib, as "lib/NAME.pxg", sorted.
std::vector<std::string> library_files(const std::filesystem::path& folder);

class Document {
 public:
  Document();  // an untitled, empty recipe
  // Loads a recipe; throws PxgError (file and location) on bad input. Nodes
  // stacked on one spot (a recipe written without positions) are laid out.
  static std::unique_ptr<Document> open(const std::filesystem::path& file);
  // A document whose graph came from elsewhere (autosave recovery): dirty, named `file`.
  static std::unique_ptr<Document> recovered(Graph graph, std::filesystem::path file);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  // The whole recipe: what is evaluated, saved and exported.
  const Graph& recipe() const { return graph_; }
  // The graph being edited: the recipe, or the graph of the group entered
  // (see enter_group). Edits, the selection and the clipboard are of this graph.
  // References into it stay valid until end_frame(), across edits: an edit
  // inside a group replaces the group's graph, so each one handed out is held.
  const Graph& graph() const;
  // The UI holds no reference into graph() any more: the replaced group graphs go.
  void end_frame() { handed_out_.clear(); }
  const std::filesystem::path& path() const { return path_; }  // empty when untitled
  std::string title() const;                                    // file name or "untitled"
  std::uint64_t revision() const { return revision_; }
  bool dirty() const;
  // Whether dirty() is cheap now (known for this revision without serialising the graph).
  bool dirty_known() const { return revision_ == saved_revision_ || dirty_revision_ == revision_; }

  // Atomic (temp file + rename); throws std::runtime_error naming the file.
  void save();
  void save_as(const std::filesystem::path& file);

  // ---- edits (each one undo step) ----
  Result<NodeId> add_node(std::string_view type_name, double x, double y);
  // An instance of one of the recipe's groups.
  Result<NodeId> add_group_node(std::string_view group_name, double x, double y);
  // Either of the above (`group`: a group's name), then wired from node
  // `from`'s first output that fits one of the new node's inputs, if any:
  // one undo step (the node search's Enter with a node selected).
  Result<NodeId> add_node_wired(std::string_view name, bool group, double x, double y, NodeId from);
  Status connect(PortRef from, PortRef to);
  Status disconnect(PortRef to);
  // A value replaces the parameter's expression, if it has one.
  Status set_param(NodeId id, std::size_t param, Value v);
  // Gives the parameter an expression (docs/expressions.md); a refusal names
  // the node, the parameter and the column, and changes nothing.
  Status set_expression(NodeId id, std::size_t param, std::string_view text);
  // Variadic ports: sets the count asked for by port-count parameter `param`
  // (an int to `count`; a list of strings cut at the end, or padded with empty
  // entries). Refused, naming the port, when a connected port would go.
  Status set_port_count(NodeId id, std::size_t param, std::size_t count);
  // Moves every selected node by (dx, dy) canvas units.
  Status move_selection(double dx, double dy);
  Status remove_selection();
  Result<NodeId> group_selection();
  // ---- the group library: the recipe folder's lib/*.pxg ----
  // Writes the selected group instance's group to lib/<group>.pxg beside the
  // recipe (atomically; replaced if there); returns the path. The recipe is unchanged.
  Result<std::filesystem::path> save_group_to_library();
  // Adds library file `file` (as library_files lists it, e.g. "lib/facade.pxg")
  // as a group named after it (a number added if the name is taken), read from
  // that file when the recipe loads, and places an instance centred at (x, y),
  // or at the nearest spot where it covers no other node (free_spot): one
  // undo step. A file that does not load is refused, naming the file.
  Result<NodeId> place_library_group(const std::string& file, double x, double y);
  // Lays the whole graph out in layers from inputs to outputs (one undo step).
  Status tidy_layout();
  // Replaces the selected group instance by the group's nodes (selected after).
  Result<std::vector<NodeId>> ungroup_selection();
  // An edit of the recipe's interface (exposed parameters, graph inputs and
  // outputs, metadata, presets) as one undo step: `edit` changes the graph or
  // refuses, and undo puts the graph back as it was.
  Status edit_recipe(std::string label, std::function<Status(Graph&)> edit);
  // Exposes parameter `param` of node `id` as `p.name`, presented as `p` says,
  // with `default_value` (the inner parameter's value; empty: unchanged).
  Status expose(NodeId id, std::size_t param, ExposedParam p, Value default_value);
  // Stores the current values of every exposed parameter as preset `name`.
  Status save_preset(const std::string& name);
  Status apply_preset(const std::string& name);
  // ---- editing inside groups ----
  // Opens group node `id` of graph(): graph() is then its group's graph, and
  // edits there change the group (every instance of it). Refused, saying why,
  // for a node that is no group, or whose group is read from a library file
  // (other recipes may share that file: it is edited by opening it).
  Status enter_group(NodeId id);
  // Back out to `depth` groups deep (0: the recipe); the group node left is selected.
  void leave_group(std::size_t depth);
  // The group nodes entered, outermost first (their ids in the graph above each).
  const std::vector<NodeId>& scope() const { return stack_.scope(); }
  // The recipe's title, then the name of each group entered.
  std::vector<std::string> breadcrumb() const;
  // Undo and redo reach edits made at any depth; the view backs out of a group whose node they remove.
  bool undo();
  bool redo();
  bool can_undo() const { return stack_.can_undo(); }
  bool can_redo() const { return stack_.can_redo(); }
  std::string undo_label() const { return stack_.undo_label(); }
  std::string redo_label() const { return stack_.redo_label(); }

  // Edits between begin and end become one undo step (a slider drag).
  void begin_gesture(std::string label);
  void end_gesture();
  // Rolls back every edit since begin_gesture (a multi-step edit refused half way).
  void abort_gesture();
  bool in_gesture() const { return gesture_open_; }

  // ---- clipboard: selected nodes and the links among them, as .pxg text ----
  std::string copy_selection() const;
  // Adds the nodes of `text` shifted by (dx, dy) and selects them. Group
  // instances need their group in this recipe.
  Result<std::vector<NodeId>> paste(std::string_view text, double dx, double dy);

  // ---- selection (editor state; not undone) ----
  const std::set<NodeId>& selection() const { return selection_; }
  void select_only(NodeId id);
  void select(const std::vector<NodeId>& ids, bool add);
  void toggle(NodeId id);
  void clear_selection() { selection_.clear(); }
  // The single selected node, or 0.
  NodeId selected() const { return selection_.size() == 1 ? *selection_.begin() : 0; }

 private:
  Document(Graph graph, std::filesystem::path path);
  // `base`, else base followed by 2, 3...: the first name no group or node type has.
  std::string free_group_name(const std::string& base, int first_number) const;
  // The recipe's folder, refused while it has none (untitled).
  Result<std::filesystem::path> library_folder(const std::string& what) const;
  // Undo or redo (`step`).
  bool history_step(bool (UndoStack::*step)());
  // Every change ends here: bumps the revision and drops vanished nodes from the selection.
  template <class R>
  R changed(R r);

  Graph graph_;
  UndoStack stack_;
  std::filesystem::path path_;
  std::uint64_t revision_ = 0;  // set by the constructor
  std::uint64_t saved_revision_ = 0;
  std::string saved_text_;  // the file's text as last loaded or saved
  // dirty() serialises the graph: asked every frame, it is worked out once per revision.
  mutable std::uint64_t dirty_revision_ = 0;
  mutable bool dirty_ = false;
  bool gesture_open_ = false;
  std::set<NodeId> selection_;
  // The group graphs graph() returned since end_frame (see graph()).
  mutable std::vector<std::shared_ptr<const Graph>> handed_out_;
};

}  // namespace procex::studio
