// Writing .pxg files: canonical JSON (sorted keys, nodes by id, links by
// destination) so that saving the same graph twice gives the same bytes.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "graph/pxg.h"

namespace procex {

namespace {

using json = nlohmann::json;

json param_json(const Value& v) {
  json j;
  v.type()->to_json(v.raw(), j);
  return j;
}

std::string link_end(const Graph& g, PortRef p, bool is_output) { return g.port_name(p, is_output); }

json graph_json(const Graph& g) {
  json j = json::object();
  j["metadata"] = {{"name", g.metadata.name}, {"description", g.metadata.description}, {"author", g.metadata.author}};
  // Newer fields only when set: older recipes save byte for byte as before.
  if (!g.metadata.licence.empty()) j["metadata"]["licence"] = g.metadata.licence;
  if (!g.metadata.thumbnail.empty()) j["metadata"]["thumbnail"] = g.metadata.thumbnail;
  json inputs = json::array();
  for (const GraphInput& in : g.inputs()) {
    json e = {{"name", in.name}, {"type", in.type->name()}, {"doc", in.doc}};
    if (!in.default_value.empty()) e["default"] = param_json(in.default_value);
    inputs.push_back(std::move(e));
  }
  j["inputs"] = std::move(inputs);
  json outputs = json::array();
  for (const GraphOutput& out : g.outputs()) outputs.push_back({{"name", out.name}, {"type", out.type->name()}, {"doc", out.doc}});
  j["outputs"] = std::move(outputs);

  json nodes = json::array();
  json editor = json::object();
  for (const auto& [id, n] : g.nodes()) {
    json e = {{"id", id}};
    if (n.group.empty()) {
      e["type"] = n.type->name();
      e["version"] = n.type->version();
    } else {
      e["group"] = n.group;
    }
    json params = json::object();
    const auto& decls = n.decl().params();
    for (std::size_t i = 0; i < decls.size(); ++i) {
      auto expr = n.expressions.find(static_cast<std::uint32_t>(i));
      params[decls[i].name] = expr == n.expressions.end() ? param_json(n.params[i]) : json{{"expr", expr->second->text()}};
    }
    e["params"] = std::move(params);
    nodes.push_back(std::move(e));
    editor[std::to_string(id)] = {{"x", n.editor.x}, {"y", n.editor.y}, {"comment", n.editor.comment}, {"collapsed", n.editor.collapsed}};
  }
  j["nodes"] = std::move(nodes);

  json links = json::array();
  for (const auto& [to, from] : g.links()) links.push_back({{"from", link_end(g, from, true)}, {"to", link_end(g, to, false)}});
  j["links"] = std::move(links);

  json exposed = json::array();
  for (const ExposedParam& e : g.exposed_params()) {
    json x = {{"name", e.name}, {"node", e.node}, {"param", g.node(e.node)->decl().params()[e.param].name}};
    if (!e.label.empty()) x["label"] = e.label;
    if (!e.unit.empty()) x["unit"] = e.unit;
    if (e.min) x["min"] = *e.min;
    if (e.max) x["max"] = *e.max;
    exposed.push_back(std::move(x));
  }
  j["exposed"] = std::move(exposed);
  json presets = json::array();
  for (const Preset& p : g.presets()) {
    json values = json::object();
    for (const auto& [name, v] : p.values)
      if (std::any_of(g.exposed_params().begin(), g.exposed_params().end(),
                      [&key = name](const ExposedParam& e) { return e.name == key; }))  // Clang < 16: no binding captures
        values[name] = param_json(v);
    presets.push_back({{"name", p.name}, {"values", std::move(values)}});
  }
  if (!presets.empty()) j["presets"] = std::move(presets);

  json groups = json::array();
  for (const auto& [name, def] : g.groups()) {
    if (def.file.empty()) groups.push_back({{"name", name}, {"graph", graph_json(*def.type->body)}});
    else groups.push_back({{"name", name}, {"file", def.file}});
  }
  j["groups"] = std::move(groups);
  j["editor"] = {{"nodes", std::move(editor)}};
  return j;
}

// Two-space indentation, except that a container at most two levels deep and
// short enough stays on one line; lists of objects always get one line per
// object. One link, one node, one editor entry per line keeps diffs readable.
constexpr std::size_t kOneLineWidth = 100;

// Strings set through the API may hold invalid UTF-8; replace rather than throw.
std::string text_of(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

std::size_t depth(const json& j) {
  std::size_t d = 0;
  if (j.is_structured())
    for (const json& e : j) d = std::max(d, depth(e));
  return j.is_structured() ? d + 1 : 0;
}

void one_line(const json& j, std::string& out) {
  if (!j.is_structured()) {
    out += text_of(j);
    return;
  }
  const bool obj = j.is_object();
  out.push_back(obj ? '{' : '[');
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out.append(", ");
    first = false;
    if (obj) {
      out += text_of(json(it.key()));
      out.append(": ");
    }
    one_line(*it, out);
  }
  out.push_back(obj ? '}' : ']');
}

void print(const json& j, std::size_t indent, std::string& out) {
  if (!j.is_structured() || j.empty()) {
    out += text_of(j);
    return;
  }
  const bool list_of_objects = j.is_array() && j.front().is_object();
  if (depth(j) <= 2 && !list_of_objects) {
    std::string line;
    one_line(j, line);
    if (line.size() + indent <= kOneLineWidth) {
      out += line;
      return;
    }
  }
  const bool obj = j.is_object();
  out.push_back(obj ? '{' : '[');
  out.push_back('\n');
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out.append(",\n");
    first = false;
    out.append(indent + 2, ' ');
    if (obj) {
      out += text_of(json(it.key()));
      out.append(": ");
    }
    print(*it, indent + 2, out);
  }
  out.push_back('\n');
  out.append(indent, ' ');
  out.push_back(obj ? '}' : ']');
}

}  // namespace

std::string to_pxg(const Graph& g) {
  json j = graph_json(g);
  j["format"] = kPxgFormat;
  j["version"] = kPxgVersion;
  std::string out;
  print(j, 0, out);
  return out + "\n";
}

void save_pxg(const Graph& g, const std::filesystem::path& file) { write_file_atomically(file, to_pxg(g)); }

}  // namespace procex
