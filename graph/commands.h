// commands.h -- undoable edits of a Graph, for the studio.
//
//   UndoStack stack(graph);
//   auto id = stack.add_node("Offset", {.x = 100, .y = 40});
//   stack.connect({fp, 0}, {*id, 0});
//   stack.set_param(*id, "distance", Value::make(2.0));
//   stack.undo();  stack.redo();
//
// Every edit goes through a Command that can apply and revert itself exactly,
// so undo restores the graph bit for bit -- and with it the hashes, so an
// undone edit finds its earlier results still in the cache.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/graph.h"
#include "graph/status.h"

namespace procex {

class Command {
 public:
  virtual ~Command() = default;
  virtual std::string label() const = 0;
  // First application and redo. A refused command leaves the graph unchanged.
  virtual Status apply(Graph& g) = 0;
  // Only called after a successful apply, on the graph as apply left it.
  virtual void revert(Graph& g) = 0;
  // Fold `next` (already applied) into this command; true if done. Lets a
  // drag of a node become one undo step.
  virtual bool merge(const Command& /*next*/) { return false; }
};

class UndoStack {
 public:
  explicit UndoStack(Graph& g, std::size_t limit = 1000);
  ~UndoStack();
  UndoStack(const UndoStack&) = delete;
  UndoStack& operator=(const UndoStack&) = delete;

  // Applies the command; on success records it and drops the redo history.
  Status push(std::unique_ptr<Command> c);
  bool undo();
  bool redo();
  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  std::string undo_label() const;
  std::string redo_label() const;
  void clear();
  // Ends merging of moves: the next move starts a new undo step.
  void end_interaction() { merge_open_ = false; }

  // Several edits as one undo step (nestable). A refused edit inside a macro
  // does not undo the others; call abort_macro() to roll them all back.
  void begin_macro(std::string label);
  void end_macro();
  void abort_macro();

  // ---- the edits ----
  Result<NodeId> add_node(std::string_view type_name, EditorState editor = {});
  Result<NodeId> add_group_node(std::string_view group_name, EditorState editor = {});
  Status remove_node(NodeId id);  // with its links and exposed parameters
  // Replaces whatever fed `to` before (undo puts it back).
  Status connect(PortRef from, PortRef to);
  Status disconnect(PortRef to);
  Status set_param(NodeId id, std::string_view param, Value v);
  // Gives the parameter an expression (Graph::set_expression); undo brings
  // back what it held, a value or another expression.
  Status set_expression(NodeId id, std::string_view param, std::string_view text);
  // Editor-only: changes no hash. Consecutive moves of one node merge.
  Status move(NodeId id, double x, double y);
  Status set_editor_state(NodeId id, EditorState s);
  // Replaces `nodes` by one instance of a new group `group_name` holding them;
  // links crossing the boundary become the group's inputs and outputs.
  Result<NodeId> group(std::vector<NodeId> nodes, std::string group_name);
  // Replaces a group instance by a copy of the group's nodes (new ids, returned),
  // wired as the instance was, with its exposed parameter values applied.
  Result<std::vector<NodeId>> ungroup(NodeId instance);

  Graph& graph() { return graph_; }

  // ---- editing inside groups ----
  // Edits from now on apply inside the group instances of `path` (ids,
  // outermost first: path[0] a node of the graph, path[1] a node of its
  // group's graph...; empty: the graph itself), changing that group for
  // every instance of it. Refused, naming the node, when a step is no group
  // instance or its group is read from a library file.
  Status set_scope(std::vector<NodeId> path);
  const std::vector<NodeId>& scope() const { return scope_; }
  // The graph edits apply to: the body of the scope's innermost group.
  const Graph& scoped() const;

 private:
  struct Macro;
  void record(std::unique_ptr<Command> c);
  // `c` made to apply at the scope.
  std::unique_ptr<Command> at_scope(std::unique_ptr<Command> c) const;
  // After undo or redo: the scope cut back to the instances that still exist.
  void trim_scope();

  Graph& graph_;
  std::vector<NodeId> scope_;
  std::size_t limit_;
  std::vector<std::unique_ptr<Command>> done_, undone_;
  std::vector<std::unique_ptr<Macro>> macros_;
  bool merge_open_ = false;
};

// The commands themselves, for callers that build their own (or batch them).
std::unique_ptr<Command> add_node_command(std::shared_ptr<const NodeType> type, std::string group, EditorState e);
std::unique_ptr<Command> remove_node_command(NodeId id);
std::unique_ptr<Command> connect_command(PortRef from, PortRef to);
std::unique_ptr<Command> disconnect_command(PortRef to);
std::unique_ptr<Command> set_param_command(NodeId id, std::string param, Value v);
std::unique_ptr<Command> set_expression_command(NodeId id, std::string param, std::string text);
std::unique_ptr<Command> editor_state_command(NodeId id, EditorState s, std::string label);
std::unique_ptr<Command> group_command(std::vector<NodeId> nodes, std::string group_name);
std::unique_ptr<Command> ungroup_command(NodeId instance);
// `inner` applied to the graph of the group instance at `path` (see
// UndoStack::set_scope); the group's new graph replaces the old one level by
// level (Graph::set_group_body). Consecutive edits at one path merge as
// `inner` does.
std::unique_ptr<Command> in_group_command(std::vector<NodeId> path, std::unique_ptr<Command> inner);
// The group graphs along `path` from `g`: [0] is &g, [i + 1] the body of
// instance path[i] of [i]; an error names the first step that is no group
// instance, or (`editable`) whose group is read from a library file.
Result<std::vector<const Graph*>> group_levels(const Graph& g, const std::vector<NodeId>& path, bool editable);

}  // namespace procex
