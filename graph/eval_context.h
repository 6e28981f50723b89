// eval_context.h -- what a node's evaluate function sees.
//
//   static void evaluate(EvalContext& ctx) {
//     const auto& fp = ctx.input<Footprint>(0);
//     const double d = ctx.param<double>(0);
//     if (d == 0) ctx.warning("distance 0 does nothing");
//     ctx.set_output(0, offset(fp, d));       // errors: ctx.error(...) and return, or throw
//   }
//
// Inputs and parameters are addressed by declaration index (fast) or by name.
// A std::exception escaping evaluate becomes an error on this node; outputs
// left unset after evaluate also make it an error.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/confined_path.h"
#include "base/confined_path_memo.h"
#include "base/file_version_memo.h"
#include "graph/cancel.h"
#include "graph/diagnostic.h"
#include "graph/node_decl.h"
#include "graph/value.h"

namespace procex {

// Thrown by EvalContext::throw_if_cancelled(); the evaluator catches it.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("evaluation cancelled") {}
};

class EvalContext {
 public:
  EvalContext(const NodeDecl& decl, const std::vector<Value>& params, const std::vector<Value>& inputs,
              const CancelToken& cancel, const std::filesystem::path& folder = {},
              std::span<const std::filesystem::path> allowed_folders = {}, ConfinedPathMemo* resolved_paths = nullptr,
              FileVersionMemo* file_versions = nullptr)
      : decl_(decl),
        params_(params),
        inputs_(inputs),
        outputs_(decl.outputs().size()),
        cancel_(cancel),
        folder_(folder),
        allowed_folders_(allowed_folders),
        resolved_paths_(resolved_paths),
        file_versions_(file_versions) {}

  const NodeDecl& decl() const { return decl_; }
  // Where relative file paths in parameters resolve (EvalOptions::folder; usually the recipe's).
  const std::filesystem::path& folder() const { return folder_; }
  // The file a parameter names, resolved against folder() and confined to it
  // or to EvalOptions::allowed_folders, symlinks followed (a shared recipe
  // must not read or write elsewhere). Throws IoError naming it otherwise,
  // which fails the node. Every node that reads or writes a file uses this.
  // In a batch the answer is the one its first building got
  // (EvalOptions::resolved_paths).
  std::filesystem::path file(std::string_view name) const {
    return resolved_paths_ ? resolved_paths_->resolve(folder_, name, allowed_folders_)
                           : confined_path(folder_, name, allowed_folders_);
  }

  // The versions of the files this evaluation reads, a batch's
  // (EvalOptions::file_versions); null: each file's own, looked at again.
  FileVersionMemo* file_versions() const { return file_versions_; }

  // False for an unconnected optional input.
  bool has_input(std::size_t i) const { return !inputs_.at(i).empty(); }
  const Value& input_value(std::size_t i) const { return inputs_.at(i); }
  template <class T>
  const T& input(std::size_t i) const {
    return inputs_.at(i).get<T>();
  }
  template <class T>
  const T& input(std::string_view name) const {
    return input<T>(index_of(decl_.input_index(name), name));
  }

  const Value& param_value(std::size_t i) const { return params_.at(i); }
  template <class T>
  const T& param(std::size_t i) const {
    return params_.at(i).get<T>();
  }
  template <class T>
  const T& param(std::string_view name) const {
    return param<T>(index_of(decl_.param_index(name), name));
  }
  // The chosen entry of an enum parameter.
  const std::string& choice(std::size_t i) const { return param<EnumValue>(i).choice; }
  // Its position among the declared choices.
  std::size_t choice_index(std::size_t i) const;

  template <class T>
  void set_output(std::size_t i, T v) {
    set_output_value(i, Value::make<T>(std::move(v)));
  }
  template <class T>
  void set_output(std::string_view name, T v) {
    set_output(index_of(decl_.output_index(name), name), std::move(v));
  }
  // A value whose type differs from the declared one makes the node fail.
  void set_output_value(std::size_t i, Value v);

  // Diagnostics for this node. An error marks the node failed: its outputs are
  // discarded, nothing is cached, downstream nodes report "input failed".
  void error(std::string message) { add(Severity::kError, std::move(message)); }
  void warning(std::string message) { add(Severity::kWarning, std::move(message)); }

  // Long computations should poll one of these between steps.
  bool cancelled() const { return cancel_.cancelled(); }
  void throw_if_cancelled() const {
    if (cancelled()) throw Cancelled();
  }

  // Read by the evaluator after evaluate returns.
  std::vector<Value>& outputs() { return outputs_; }
  const std::vector<std::pair<Severity, std::string>>& messages() const { return messages_; }
  bool failed() const { return failed_; }

 private:
  std::size_t index_of(std::optional<std::size_t> i, std::string_view name) const;
  void add(Severity s, std::string m) {
    if (s == Severity::kError) failed_ = true;
    messages_.emplace_back(s, std::move(m));
  }

  const NodeDecl& decl_;
  const std::vector<Value>& params_;
  const std::vector<Value>& inputs_;
  std::vector<Value> outputs_;
  std::vector<std::pair<Severity, std::string>> messages_;
  bool failed_ = false;
  const CancelToken& cancel_;
  std::filesystem::path folder_;
  std::span<const std::filesystem::path> allowed_folders_;
  ConfinedPathMemo* resolved_paths_;  // null: resolve every time
  FileVersionMemo* file_versions_;    // null: look at every time
};

}  // namespace procex
