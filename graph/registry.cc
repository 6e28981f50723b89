#include "graph/registry.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

namespace procex {

namespace {

struct Pending {
  int version;
  DeclareFn declare;
  EvaluateFn evaluate;
  std::string file;
};

Hash128 type_key(const NodeDecl& d) {
  return Hasher().str("node").str(d.type_name()).i64(d.version()).result();
}

}  // namespace

struct NodeRegistry::Impl {
  mutable std::mutex mutex;
  std::map<std::string, Pending, std::less<>> pending;  // declared on first lookup
  mutable std::map<std::string, std::shared_ptr<const NodeType>, std::less<>> types;

  // Runs every pending declare; called under the mutex.
  void declare_pending() const {
    auto& self = const_cast<Impl&>(*this);
    for (auto& [name, p] : self.pending) {
      auto t = std::make_shared<NodeType>();
      t->decl = NodeDecl(name, p.version);
      p.declare(t->decl);
      if (Status s = t->decl.validate(); !s) {
        std::fprintf(stderr, "procex: %s (registered in %s)\n", s.message().c_str(), p.file.c_str());
        std::abort();
      }
      t->evaluate = p.evaluate;
      t->declare = p.declare;
      t->source_file = p.file;
      t->key = type_key(t->decl);
      types.emplace(name, std::move(t));
    }
    self.pending.clear();
  }
};

NodeRegistry::NodeRegistry() : impl_(std::make_unique<Impl>()) {}
NodeRegistry::~NodeRegistry() = default;

NodeRegistry& NodeRegistry::global() {
  static NodeRegistry* const r = new NodeRegistry();  // never destroyed: types outlive static destruction
  return *r;
}

void NodeRegistry::add(std::string type_name, int version, DeclareFn declare, EvaluateFn evaluate,
                       std::string source_file) {
  std::lock_guard lock(impl_->mutex);
  if (impl_->pending.count(type_name) || impl_->types.count(type_name)) {
    std::fprintf(stderr, "procex: node type '%s' registered twice (second time in %s); names must be unique\n",
                 type_name.c_str(), source_file.c_str());
    std::abort();
  }
  if (!declare || !evaluate) {
    std::fprintf(stderr, "procex: node type '%s' needs both a declare and an evaluate function\n", type_name.c_str());
    std::abort();
  }
  impl_->pending.emplace(std::move(type_name), Pending{version, declare, evaluate, std::move(source_file)});
}

std::shared_ptr<const NodeType> NodeRegistry::find(std::string_view type_name) const {
  std::lock_guard lock(impl_->mutex);
  if (!impl_->pending.empty()) impl_->declare_pending();
  auto it = impl_->types.find(type_name);
  return it == impl_->types.end() ? nullptr : it->second;
}

std::vector<std::shared_ptr<const NodeType>> NodeRegistry::all() const {
  std::lock_guard lock(impl_->mutex);
  if (!impl_->pending.empty()) impl_->declare_pending();
  std::vector<std::shared_ptr<const NodeType>> out;
  for (const auto& [name, t] : impl_->types) out.push_back(t);
  return out;
}

std::shared_ptr<const NodeType> with_port_counts(const std::shared_ptr<const NodeType>& type,
                                                 const std::vector<Value>& params) {
  const NodeDecl& decl = type->decl;
  std::map<std::string, std::size_t, std::less<>> counts;
  std::vector<std::size_t> wanted, own;  // in parameter order
  for (std::size_t i = 0; i < decl.params().size(); ++i) {
    const ParamDecl& p = decl.params()[i];
    if (!p.sets_port_count) continue;
    counts.emplace(p.name, port_count_of(params.at(i)));
    wanted.push_back(port_count_of(params.at(i)));
    own.push_back(decl.count_of(p.name));
  }
  if (wanted == own) return type;
  assert(type->declare && "with_port_counts: only registered types have port-count parameters");

  // Every type asked for, by name, version and counts (the registered one
  // among them, so that returning to its counts gives it back): few, and small.
  using Key = std::tuple<std::string, int, std::vector<std::size_t>>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const NodeType>> variants;
  std::lock_guard lock(mutex);
  variants.try_emplace(Key{decl.type_name(), decl.version(), own}, type);
  const Key key{decl.type_name(), decl.version(), wanted};
  if (auto it = variants.find(key); it != variants.end()) return it->second;
  auto t = std::make_shared<NodeType>(*type);
  t->decl = NodeDecl(decl.type_name(), decl.version());
  t->decl.set_counts(std::move(counts));
  type->declare(t->decl);
  const bool same_params = t->decl.params().size() == decl.params().size() &&
                           std::equal(decl.params().begin(), decl.params().end(), t->decl.params().begin(),
                                      [](const ParamDecl& a, const ParamDecl& b) { return a.name == b.name && a.type == b.type; });
  if (Status s = t->decl.validate(); !s || !same_params) {
    std::fprintf(stderr, "procex: node type '%s' (registered in %s): %s\n", decl.type_name().c_str(),
                 type->source_file.c_str(),
                 s ? "its parameters depend on a port count; only ports may" : s.message().c_str());
    std::abort();
  }
  variants.emplace(key, t);
  return t;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

std::string NodeRegistry::closest_name(std::string_view name) const {
  if (name.size() > 256) return {};  // untrusted input: keep the quadratic distance bounded
  std::string best;
  std::size_t best_d = 0;
  for (const auto& t : all()) {
    const std::size_t d = edit_distance(name, t->name());
    if (best.empty() || d < best_d) {
      best = t->name();
      best_d = d;
    }
  }
  // Beyond half the name changed, a suggestion misleads more than it helps.
  if (best.empty() || best_d > std::max<std::size_t>(2, std::max(name.size(), best.size()) / 2)) return {};
  return best;
}

std::string NodeRegistry::unknown_type_message(std::string_view name) const {
  std::string msg = "unknown node type '";
  msg.append(name).append("'");
  if (std::string near = closest_name(name); !near.empty()) msg.append("; did you mean '").append(near).append("'?");
  return msg;
}

std::string NodeRegistry::markdown() const {
  std::map<std::string, std::vector<std::shared_ptr<const NodeType>>> by_category;
  for (const auto& t : all()) by_category[t->decl.category().empty() ? "Other" : t->decl.category()].push_back(t);
  std::ostringstream md;
  md << "# Node types\n\n";
  for (const auto& [category, types] : by_category) {
    md << "## " << category << "\n\n";
    for (const auto& t : types) md << t->decl.markdown();
  }
  return md.str();
}

namespace detail {
bool register_node(const char* type_name, int version, DeclareFn declare, EvaluateFn evaluate, const char* file) {
  NodeRegistry::global().add(type_name, version, declare, evaluate, file);
  return true;
}
}  // namespace detail

}  // namespace procex
