// Reading .pxg files. Everything in a file is untrusted: each check names the
// file and a JSON pointer (or line and column for syntax errors).
#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "base/confined_path.h"
#include "base/json_depth.h"
#include "base/read_file.h"
#include "graph/pxg.h"
#include "graph/pxg_migrate.h"

namespace procex {

namespace fs = std::filesystem;
using json = nlohmann::json;

PxgError::PxgError(std::string file, std::string where, std::string message)
    : std::runtime_error(file + (where.empty() ? "" : ": " + where) + ": " + message),
      file_(std::move(file)),
      where_(std::move(where)),
      message_(std::move(message)) {}

namespace {

std::string line_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// JSON pointer escaping of one reference token (RFC 6901).
std::string token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

struct Loader {
  const PxgOptions& options;
  fs::path root;                       // group files must stay inside
  std::vector<fs::path> chain;         // files being loaded, for cycles between libraries
  // Each library file is read once per load, however often it is referenced
  // (references that fan out level after level would otherwise multiply).
  std::map<fs::path, std::shared_ptr<const Graph>> libraries;
  std::vector<std::string> warnings;
  // Parameters saved as {"expr": "..."}: typed once the graph's inputs and
  // exposed parameters are known (read_graph).
  struct PendingExpression {
    NodeId node;
    std::size_t param;
    std::string text, ptr;
  };
  std::vector<PendingExpression> expressions = {};

  [[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& message) const {
    throw PxgError(file, where, message);
  }

  Graph parse_file_text(std::string_view text, const fs::path& path, std::size_t group_depth) {
    const std::string file = path.string();
    if (text.size() > options.limits.max_file_bytes)
      fail(file, "", "file is " + std::to_string(text.size()) + " bytes; the limit is " +
                         std::to_string(options.limits.max_file_bytes));
    if (const auto at = json_too_deep_at(text, options.limits.max_depth))
      fail(file, line_column(text, *at), "nesting deeper than " + std::to_string(options.limits.max_depth) + " levels");
    json j;
    try {
      j = json::parse(text);
    } catch (const json::parse_error& e) {
      std::string what = e.what();
      // nlohmann prefixes "[json.exception.parse_error.101] parse error at line L, column C: "; keep the reason.
      if (auto colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
      fail(file, line_column(text, e.byte > 0 ? e.byte - 1 : 0), "malformed JSON: " + what);
    } catch (const json::exception& e) {  // a number beyond double range (out_of_range.406)
      fail(file, "", std::string("unreadable JSON: ") + e.what());
    }
    if (!j.is_object()) fail(file, "", "expected a JSON object at the top");
    auto format = j.find("format");
    if (format == j.end() || !format->is_string() || *format != kPxgFormat)
      fail(file, "/format", std::string("not a procex recipe: expected \"format\": \"") + kPxgFormat + "\"");
    auto version = j.find("version");
    if (version == j.end() || !version->is_number_integer()) fail(file, "/version", "expected an integer version");
    const std::int64_t v = version->get<std::int64_t>();
    if (v > kPxgVersion)
      fail(file, "/version", "written by a newer procex (format version " + std::to_string(v) + "); this build reads up to " +
                                 std::to_string(kPxgVersion));
    if (v < 1) fail(file, "/version", "unknown format version " + std::to_string(v));
    if (v < kPxgVersion) {
      detail::migrate_pxg(j, static_cast<int>(v), [&](const std::string& ptr, const std::string& msg) { fail(file, ptr, msg); });
      warnings.push_back(file + ": migrated from format version " + std::to_string(v) + " to " + std::to_string(kPxgVersion) +
                         "; saving writes the new version");
    }
    for (const auto& [key, value] : j.items()) {
      static const std::set<std::string, std::less<>> kKnown = {"format", "version", "metadata", "inputs", "outputs", "nodes",
                                                                "links", "exposed", "presets", "groups", "editor"};
      if (!kKnown.count(key)) warnings.push_back(file + ": /" + token(key) + ": unknown key ignored");
    }
    return read_graph(j, "", path, group_depth);
  }

  Graph load_file(const fs::path& path, const std::string& from_file, const std::string& where, std::size_t group_depth) {
    std::string text;
    try {
      text = read_file(path, options.limits.max_file_bytes);
    } catch (const IoError& e) {
      fail(from_file, where, e.what());
    }
    return parse_file_text(text, path, group_depth);
  }

  // ---- typed access with pointers ----

  struct Ctx {
    const std::string& file;
    std::string ptr;
  };

  const json& member(const json& obj, const char* key, const Ctx& c, json::value_t type, bool required = true) const {
    static const json kNull;
    auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail(c.file, c.ptr, std::string("missing \"") + key + "\"");
      return kNull;
    }
    const bool ok = type == json::value_t::number_integer ? it->is_number_integer() : it->type() == type;
    if (!ok) fail(c.file, c.ptr + "/" + key, std::string("expected ") + json(type).type_name() + ", got " + it->type_name());
    return *it;
  }

  std::string string_member(const json& obj, const char* key, const Ctx& c, bool required = true) const {
    const json& s = member(obj, key, c, json::value_t::string, required);
    if (s.is_null()) return {};
    std::string out = s.get<std::string>();
    if (out.size() > options.limits.max_string)
      fail(c.file, c.ptr + "/" + key, "string of " + std::to_string(out.size()) + " bytes is too long");
    return out;
  }

  const json& array_member(const json& obj, const char* key, const Ctx& c, std::size_t limit) const {
    static const json kEmpty = json::array();
    auto it = obj.find(key);
    if (it == obj.end()) return kEmpty;
    if (!it->is_array()) fail(c.file, c.ptr + "/" + key, std::string("expected an array, got ") + it->type_name());
    if (it->size() > limit)
      fail(c.file, c.ptr + "/" + key, std::to_string(it->size()) + " entries; the limit is " + std::to_string(limit));
    return *it;
  }

  // Calls read(entry, ctx) for each entry of obj's array `key` (absent reads
  // as empty; at most `limit` entries), each of which must be an object; the
  // message for one that is not says what the object holds.
  template <class Read>
  void for_each_object(const json& obj, const char* key, const Ctx& c, std::size_t limit, const char* expected,
                       Read&& read) const {
    const json& entries = array_member(obj, key, c, limit);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const Ctx at{c.file, c.ptr + "/" + key + "/" + std::to_string(i)};
      if (!entries[i].is_object()) fail(c.file, at.ptr, expected);
      read(entries[i], at);
    }
  }

  const ValueType& value_type_named(const std::string& name, const Ctx& c) const {
    const ValueType* t = ValueTypeRegistry::global().find(name);
    if (!t) {
      std::string known;
      for (const ValueType* v : ValueTypeRegistry::global().all()) known += (known.empty() ? "" : ", ") + v->name();
      fail(c.file, c.ptr, "unknown value type '" + name + "' (known: " + known + ")");
    }
    return *t;
  }

  Value value_from(const ValueType& type, const json& j, const Ctx& c) const {
    try {
      return type.from_json(j);
    } catch (const std::invalid_argument& e) {
      fail(c.file, c.ptr, "bad " + type.name() + " value: " + e.what());
    }
  }

  // ---- the graph ----

  Graph read_graph(const json& j, const std::string& base, const fs::path& path, std::size_t group_depth) {
    const std::string file = path.string();
    Graph g;
    if (auto m = j.find("metadata"); m != j.end()) {
      Ctx c{file, base + "/metadata"};
      if (!m->is_object()) fail(file, c.ptr, "expected an object");
      g.metadata.name = string_member(*m, "name", c, false);
      g.metadata.description = string_member(*m, "description", c, false);
      g.metadata.author = string_member(*m, "author", c, false);
      g.metadata.licence = string_member(*m, "licence", c, false);
      g.metadata.thumbnail = string_member(*m, "thumbnail", c, false);
    }
    read_groups(g, j, base, path, group_depth);
    read_interface(g, j, base, file);
    std::map<NodeId, std::string> node_ptr;
    const std::size_t first_expression = expressions.size();  // group bodies, read above, took theirs
    read_nodes(g, j, base, file, node_ptr);
    read_links(g, j, base, file);
    read_exposed(g, j, base, file);
    for (std::size_t i = first_expression; i < expressions.size(); ++i) {
      const PendingExpression& e = expressions[i];
      if (Status s = g.set_expression(e.node, e.param, e.text); !s) fail(file, e.ptr, s.message());
    }
    expressions.resize(first_expression);
    read_presets(g, j, base, file);
    read_editor(g, j, base, file);
    return g;
  }

  void read_groups(Graph& g, const json& j, const std::string& base, const fs::path& path, std::size_t group_depth) {
    const std::string file = path.string();
    for_each_object(j, "groups", Ctx{file, base}, options.limits.max_nodes, "expected an object", [&](const json& e, const Ctx& c) {
      const std::string name = string_member(e, "name", c);
      if (group_depth + 1 > options.limits.max_group_depth)
        fail(file, c.ptr, "groups nested deeper than " + std::to_string(options.limits.max_group_depth) + " levels");
      std::shared_ptr<const Graph> body;
      std::string ref;
      if (e.contains("file")) {
        ref = string_member(e, "file", c);
        body = load_library(ref, file, c.ptr + "/file", group_depth + 1);
      } else if (e.contains("graph")) {
        const json& inner = member(e, "graph", c, json::value_t::object);
        body = std::make_shared<const Graph>(read_graph(inner, c.ptr + "/graph", path, group_depth + 1));
      } else {
        fail(file, c.ptr, "a group needs \"file\" (a library file) or \"graph\" (embedded)");
      }
      if (Status s = g.add_group(name, body, ref); !s) fail(file, c.ptr, s.message());
    });
  }

  std::shared_ptr<const Graph> load_library(const std::string& ref, const std::string& file, const std::string& where,
                                            std::size_t group_depth) {
    const fs::path rel(ref);
    if (ref.empty() || rel.is_absolute() || rel.has_root_name())
      fail(file, where, "group file '" + ref + "' must be a path relative to the recipe's folder");
    const fs::path from_dir = fs::path(file).parent_path();
    fs::path target;
    try {
      std::error_code ec;
      target = confined_path(root, fs::absolute(from_dir / rel, ec).string(), options.allowed_folders);
    } catch (const IoError& e) {
      fail(file, where, "group file '" + ref + "': " + e.what());
    }
    if (std::find(chain.begin(), chain.end(), target) != chain.end())
      fail(file, where, "group file '" + ref + "' includes itself (through " + std::to_string(chain.size()) + " files)");
    if (auto known = libraries.find(target); known != libraries.end()) return known->second;
    chain.push_back(target);
    auto g = std::make_shared<const Graph>(load_file(target, file, where, group_depth));
    chain.pop_back();
    libraries.emplace(target, g);
    return g;
  }

  // Name, type and doc of a graph input or output.
  template <class Port>
  Port read_port(const json& e, const Ctx& c) const {
    Port p;
    p.name = string_member(e, "name", c);
    p.type = &value_type_named(string_member(e, "type", c), Ctx{c.file, c.ptr + "/type"});
    p.doc = string_member(e, "doc", c, false);
    return p;
  }

  void read_interface(Graph& g, const json& j, const std::string& base, const std::string& file) {
    for_each_object(j, "inputs", Ctx{file, base}, 4096, "expected an object", [&](const json& e, const Ctx& c) {
      GraphInput in = read_port<GraphInput>(e, c);
      if (auto d = e.find("default"); d != e.end()) in.default_value = value_from(*in.type, *d, Ctx{file, c.ptr + "/default"});
      if (Status s = g.add_input(std::move(in)); !s) fail(file, c.ptr, s.message());
    });
    for_each_object(j, "outputs", Ctx{file, base}, 4096, "expected an object", [&](const json& e, const Ctx& c) {
      if (Status s = g.add_output(read_port<GraphOutput>(e, c)); !s) fail(file, c.ptr, s.message());
    });
  }

  void read_nodes(Graph& g, const json& j, const std::string& base, const std::string& file, std::map<NodeId, std::string>& seen) {
    for_each_object(j, "nodes", Ctx{file, base}, options.limits.max_nodes, "expected an object", [&](const json& e, const Ctx& c) {
      auto id_it = e.find("id");
      if (id_it == e.end() || !id_it->is_number_unsigned() || id_it->get<std::uint64_t>() == 0 ||
          id_it->get<std::uint64_t>() > kMaxNodeId)
        fail(file, c.ptr + "/id", "expected a node id from 1 to " + std::to_string(kMaxNodeId));
      const auto id = static_cast<NodeId>(id_it->get<std::uint64_t>());
      if (auto prev = seen.find(id); prev != seen.end())
        fail(file, c.ptr + "/id", "duplicate node id " + std::to_string(id) + " (also at " + prev->second + ")");
      seen.emplace(id, c.ptr);
      Result<NodeId> added = NodeId{0};
      int saved_version = 1;
      if (e.contains("group")) {
        const std::string group = string_member(e, "group", c);
        added = g.add_group_node(group, id);
        if (!added) fail(file, c.ptr + "/group", added.message());
      } else {
        const std::string type = string_member(e, "type", c);
        auto t = options.registry->find(type);
        if (!t) fail(file, c.ptr + "/type", options.registry->unknown_type_message(type));
        const json& version = member(e, "version", c, json::value_t::number_integer);
        const std::int64_t v = version.get<std::int64_t>();
        if (v > t->version())
          fail(file, c.ptr + "/version", "node type '" + type + "' version " + std::to_string(v) +
                                             " is newer than this build's version " + std::to_string(t->version()));
        if (v < 1) fail(file, c.ptr + "/version", "node versions start at 1");
        if (v < t->version())
          warnings.push_back(file + ": " + c.ptr + ": '" + type + "' saved at version " + std::to_string(v) + ", now " +
                             std::to_string(t->version()) +
                             (t->decl.upgrade() ? "; parameters were upgraded" : "; parameters were matched by name"));
        saved_version = static_cast<int>(v);
        added = g.add_node(t, id);
        if (!added) fail(file, c.ptr, added.message());
      }
      read_params(g, id, e, c, saved_version);
    });
  }

  void read_params(Graph& g, NodeId id, const json& e, const Ctx& c, int saved_version) {
    auto found = e.find("params");
    if (found == e.end()) return;
    const std::string ptr = c.ptr + "/params";
    if (!found->is_object()) fail(c.file, ptr, "expected an object of parameter values");
    const NodeDecl& decl = g.node(id)->decl();
    json upgraded;
    const json* params = &*found;
    if (saved_version < decl.version() && decl.upgrade()) {
      upgraded = *found;
      try {
        decl.upgrade()(saved_version, upgraded);
      } catch (const std::invalid_argument& err) {
        fail(c.file, ptr, "cannot upgrade '" + decl.type_name() + "' from version " + std::to_string(saved_version) + ": " + err.what());
      }
      if (!upgraded.is_object()) fail(c.file, ptr, "the upgrade of '" + decl.type_name() + "' did not leave an object");
      params = &upgraded;
    }
    for (const auto& [name, value] : params->items()) {
      const std::string pp = ptr + "/" + token(name);
      auto index = decl.param_index(name);
      if (!index) {
        std::string msg = "'" + decl.type_name() + "' has no parameter '" + name + "'";
        std::string best;
        std::size_t best_d = 3;
        for (const ParamDecl& p : decl.params())
          if (std::size_t d = edit_distance(name, p.name); d < best_d) best = p.name, best_d = d;
        if (!best.empty()) msg += "; did you mean '" + best + "'?";
        fail(c.file, pp, msg);
      }
      const ParamDecl& p = decl.params()[*index];
      if (value.is_object()) {
        auto text = value.find("expr");
        if (value.size() != 1 || text == value.end() || !text->is_string())
          fail(c.file, pp, "expected a value, or {\"expr\": \"an expression\"}");
        expressions.push_back({id, *index, text->get<std::string>(), pp + "/expr"});
        continue;
      }
      Value v = value_from(*p.type, value, Ctx{c.file, pp});
      if (Status s = g.set_param(id, *index, std::move(v)); !s) fail(c.file, pp, s.message());
    }
  }

  // "12.result" / "@name" to a port; is_output says which side of the link.
  PortRef parse_end(const Graph& g, const json& j, const Ctx& c, bool is_output) const {
    if (!j.is_string()) fail(c.file, c.ptr, "expected \"node.port\" or \"@name\"");
    const std::string s = j.get<std::string>();
    if (!s.empty() && s[0] == '@') {
      const std::string name = s.substr(1);
      auto i = is_output ? g.input_index(name) : g.output_index(name);
      if (!i) fail(c.file, c.ptr, std::string("no graph ") + (is_output ? "input" : "output") + " named '" + name + "'");
      return PortRef{is_output ? kGraphInputs : kGraphOutputs, static_cast<std::uint32_t>(*i)};
    }
    const auto dot = s.find('.');
    if (dot == std::string::npos || dot == 0 || dot > 10 || !std::all_of(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(dot), [](char ch) { return ch >= '0' && ch <= '9'; }))
      fail(c.file, c.ptr, "'" + s + "' is not \"node.port\" or \"@name\"");
    const std::uint64_t id = std::stoull(s.substr(0, dot));
    const std::string port = s.substr(dot + 1);
    const Node* n = id <= kMaxNodeId ? g.node(static_cast<NodeId>(id)) : nullptr;
    if (!n) fail(c.file, c.ptr, "dangling link: there is no node " + std::to_string(id));
    auto i = is_output ? n->decl().output_index(port) : n->decl().input_index(port);
    if (!i)
      fail(c.file, c.ptr, "node " + std::to_string(id) + " (" + n->type->name() + ") has no " + (is_output ? "output" : "input") +
                              " '" + port + "'");
    return PortRef{static_cast<NodeId>(id), static_cast<std::uint32_t>(*i)};
  }

  void read_links(Graph& g, const json& j, const std::string& base, const std::string& file) {
    const char* const expected = "expected {\"from\": ..., \"to\": ...}";
    for_each_object(j, "links", Ctx{file, base}, options.limits.max_links, expected, [&](const json& l, const Ctx& c) {
      if (!l.contains("from") || !l.contains("to")) fail(file, c.ptr, expected);
      const PortRef from = parse_end(g, l["from"], Ctx{file, c.ptr + "/from"}, true);
      const PortRef to = parse_end(g, l["to"], Ctx{file, c.ptr + "/to"}, false);
      if (Status s = g.connect(from, to); !s) fail(file, c.ptr, s.message());
    });
  }

  void read_exposed(Graph& g, const json& j, const std::string& base, const std::string& file) {
    for_each_object(j, "exposed", Ctx{file, base}, 4096, "expected an object", [&](const json& e, const Ctx& c) {
      ExposedParam p;
      p.name = string_member(e, "name", c);
      const json& node = member(e, "node", c, json::value_t::number_integer);
      const std::int64_t id = node.get<std::int64_t>();
      const Node* n = id > 0 && id <= kMaxNodeId ? g.node(static_cast<NodeId>(id)) : nullptr;
      if (!n) fail(file, c.ptr + "/node", "there is no node " + std::to_string(id));
      p.node = static_cast<NodeId>(id);
      const std::string param = string_member(e, "param", c);
      auto index = n->decl().param_index(param);
      if (!index) fail(file, c.ptr + "/param", "node " + std::to_string(id) + " has no parameter '" + param + "'");
      p.param = static_cast<std::uint32_t>(*index);
      p.label = string_member(e, "label", c, false);
      p.unit = string_member(e, "unit", c, false);
      for (auto [key, bound] : {std::pair{"min", &p.min}, std::pair{"max", &p.max}}) {
        auto it = e.find(key);
        if (it == e.end()) continue;
        if (!it->is_number() || !std::isfinite(it->get<double>())) fail(file, c.ptr + "/" + key, "expected a finite number");
        *bound = it->get<double>();
      }
      if (Status s = g.expose_param(std::move(p)); !s) fail(file, c.ptr, s.message());
    });
  }

  void read_presets(Graph& g, const json& j, const std::string& base, const std::string& file) {
    const char* const expected = "expected {\"name\": ..., \"values\": {...}}";
    for_each_object(j, "presets", Ctx{file, base}, 4096, expected, [&](const json& e, const Ctx& c) {
      Preset p;
      p.name = string_member(e, "name", c);
      const json& values = member(e, "values", c, json::value_t::object);
      for (const auto& [name, v] : values.items()) {
        Ctx vc{file, c.ptr + "/values/" + token(name)};
        auto ex = std::find_if(g.exposed_params().begin(), g.exposed_params().end(),
                               [&key = name](const ExposedParam& x) { return x.name == key; });  // Clang < 16: no binding captures
        if (ex == g.exposed_params().end()) fail(file, vc.ptr, "no exposed parameter named '" + name + "'");
        p.values[name] = value_from(*g.node(ex->node)->decl().params()[ex->param].type, v, vc);
      }
      for (const Preset& earlier : g.presets())
        if (earlier.name == p.name) fail(file, c.ptr + "/name", "a second preset named '" + p.name + "'");
      if (Status s = g.set_preset(std::move(p)); !s) fail(file, c.ptr, s.message());
    });
  }

  void read_editor(Graph& g, const json& j, const std::string& base, const std::string& file) {
    auto editor = j.find("editor");
    if (editor == j.end()) return;
    Ctx c{file, base + "/editor"};
    if (!editor->is_object()) fail(file, c.ptr, "expected an object");
    auto nodes = editor->find("nodes");
    if (nodes == editor->end()) return;
    if (!nodes->is_object()) fail(file, c.ptr + "/nodes", "expected an object keyed by node id");
    for (const auto& item : nodes->items()) {
      const std::string& key = item.key();
      const json& e = item.value();
      Ctx n{file, c.ptr + "/nodes/" + token(key)};
      NodeId id = 0;
      if (key.empty() || key.size() > 10 || !std::all_of(key.begin(), key.end(), [](char ch) { return ch >= '0' && ch <= '9'; }) ||
          std::stoull(key) > kMaxNodeId || !g.node(id = static_cast<NodeId>(std::stoull(key))))
        fail(file, n.ptr, "editor state for a node that does not exist");
      if (!e.is_object()) fail(file, n.ptr, "expected an object");
      EditorState s;
      auto number = [&](const char* k) {
        auto it = e.find(k);
        if (it == e.end()) return 0.0;
        if (!it->is_number()) fail(file, n.ptr + "/" + k, "expected a number");
        return it->get<double>();
      };
      s.x = number("x");
      s.y = number("y");
      s.comment = string_member(e, "comment", n, false);
      if (auto col = e.find("collapsed"); col != e.end()) {
        if (!col->is_boolean()) fail(file, n.ptr + "/collapsed", "expected true or false");
        s.collapsed = col->get<bool>();
      }
      (void)g.set_editor_state(id, std::move(s));
    }
  }
};

fs::path root_for(const fs::path& file, const PxgOptions& options) {
  std::error_code ec;
  fs::path root = options.root.empty() ? fs::absolute(file, ec).parent_path() : options.root;
  fs::path canonical = fs::weakly_canonical(root, ec);
  return ec ? root : canonical;
}

void hand_over_warnings(const Loader& l, const PxgOptions& options) {
  if (options.warnings) options.warnings->insert(options.warnings->end(), l.warnings.begin(), l.warnings.end());
}

}  // namespace

Graph parse_pxg(std::string_view text, const fs::path& file, const PxgOptions& options) {
  Loader l{options, root_for(file, options), {}, {}, {}};
  std::error_code ec;
  l.chain.push_back(fs::weakly_canonical(fs::absolute(file, ec), ec));
  Graph g = l.parse_file_text(text, file, 0);
  hand_over_warnings(l, options);
  return g;
}

Graph load_pxg(const fs::path& file, const PxgOptions& options) {
  Loader l{options, root_for(file, options), {}, {}, {}};
  std::error_code ec;
  l.chain.push_back(fs::weakly_canonical(fs::absolute(file, ec), ec));
  Graph g = l.load_file(file, file.string(), "", 0);
  hand_over_warnings(l, options);
  return g;
}

}  // namespace procex
