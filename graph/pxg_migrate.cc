// Migrations of older .pxg versions, one function per step.
//
// Version 1 (procex 0.0) kept editor state inside each node ("pos": [x, y],
// "comment"), parameters as an array of {"name", "value"}, and links as
// {"from": {"node": 3, "port": "result"}, "to": {"node": 4, "port": "footprint"}}
// with graph ports written {"input": "footprint"} / {"output": "mesh"}.
#include "graph/pxg_migrate.h"

#include "graph/pxg.h"

namespace procex::detail {

namespace {

using json = nlohmann::json;

std::string v1_link_end(const json& e, const std::string& ptr, const char* graph_key, const PxgFail& fail) {
  if (!e.is_object()) fail(ptr, "expected an object such as {\"node\": 3, \"port\": \"result\"}");
  if (auto it = e.find(graph_key); it != e.end()) {
    if (!it->is_string()) fail(ptr + "/" + graph_key, "expected a string");
    std::string end = "@";
    end += it->get<std::string>();
    return end;
  }
  auto node = e.find("node");
  auto port = e.find("port");
  if (node == e.end() || !node->is_number_unsigned()) fail(ptr + "/node", "expected a node id");
  if (port == e.end() || !port->is_string()) fail(ptr + "/port", "expected a port name");
  return std::to_string(node->get<std::uint64_t>()) + "." + port->get<std::string>();
}

void v1_to_v2(json& j, const PxgFail& fail) {
  json editor = json::object();
  if (auto nodes = j.find("nodes"); nodes != j.end() && nodes->is_array()) {
    for (std::size_t i = 0; i < nodes->size(); ++i) {
      json& n = (*nodes)[i];
      const std::string ptr = "/nodes/" + std::to_string(i);
      if (!n.is_object()) fail(ptr, "expected an object");
      if (auto params = n.find("params"); params != n.end()) {
        if (!params->is_array()) fail(ptr + "/params", "version 1 keeps parameters in an array of {name, value}");
        json obj = json::object();
        for (std::size_t k = 0; k < params->size(); ++k) {
          const json& p = (*params)[k];
          const std::string pp = ptr + "/params/" + std::to_string(k);
          if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("value"))
            fail(pp, "expected {\"name\": ..., \"value\": ...}");
          obj[p["name"].get<std::string>()] = p["value"];
        }
        *params = std::move(obj);
      }
      json state = json::object();
      if (auto pos = n.find("pos"); pos != n.end()) {
        if (!pos->is_array() || pos->size() != 2 || !(*pos)[0].is_number() || !(*pos)[1].is_number())
          fail(ptr + "/pos", "expected [x, y]");
        state["x"] = (*pos)[0];
        state["y"] = (*pos)[1];
        n.erase("pos");
      }
      if (auto comment = n.find("comment"); comment != n.end()) {
        state["comment"] = *comment;
        n.erase("comment");
      }
      if (!state.empty() && n.contains("id") && n["id"].is_number_unsigned())
        editor[std::to_string(n["id"].get<std::uint64_t>())] = std::move(state);
    }
  }
  if (auto links = j.find("links"); links != j.end() && links->is_array()) {
    for (std::size_t i = 0; i < links->size(); ++i) {
      json& l = (*links)[i];
      const std::string ptr = "/links/" + std::to_string(i);
      if (!l.is_object() || !l.contains("from") || !l.contains("to")) fail(ptr, "expected {\"from\": ..., \"to\": ...}");
      l = json{{"from", v1_link_end(l["from"], ptr + "/from", "input", fail)},
               {"to", v1_link_end(l["to"], ptr + "/to", "output", fail)}};
    }
  }
  j["editor"] = {{"nodes", std::move(editor)}};
  j["version"] = 2;
}

}  // namespace

void migrate_pxg(json& j, int version, const PxgFail& fail) {
  if (version == 1) {
    v1_to_v2(j, fail);
    version = 2;
  }
  if (version != kPxgVersion) fail("/version", "no migration from version " + std::to_string(version));
}

}  // namespace procex::detail
