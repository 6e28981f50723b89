#include "tests/nodes/node_runner.h"

#include <stdexcept>

namespace procex::test {

bool NodeRun::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::kError) return false;
  return true;
}

std::string NodeRun::messages() const {
  std::string out;
  for (const Diagnostic& d : diagnostics) out += d.to_string() + "\n";
  return out;
}

NodeRun run_node(const std::string& type, const std::map<std::string, Value>& params,
                 const std::map<std::string, Value>& inputs, const std::filesystem::path& folder) {
  Graph g;
  const auto id = g.add_node(type);
  if (!id) throw std::invalid_argument(id.message());
  for (const auto& [name, v] : params)
    if (Status s = g.set_param(*id, name, v); !s) throw std::invalid_argument(s.message());
  const NodeDecl& decl = g.node(*id)->decl();  // after the parameters: they may set port counts
  Bindings bindings;
  for (const auto& [name, v] : inputs) {
    const auto index = decl.input_index(name);
    if (!index) throw std::invalid_argument("no input " + name);
    if (Status s = g.add_input({name, v.type(), "", {}}); !s) throw std::invalid_argument(s.message());
    const auto port = static_cast<std::uint32_t>(*g.input_index(name));
    if (Status s = g.connect({kGraphInputs, port}, {*id, static_cast<std::uint32_t>(*index)}); !s)
      throw std::invalid_argument(s.message());
    bindings[name] = v;
  }
  std::vector<std::string> names;
  for (std::uint32_t o = 0; o < decl.outputs().size(); ++o) {
    names.push_back("out_" + decl.outputs()[o].name);
    (void)g.add_output({names.back(), decl.outputs()[o].type, ""});
    (void)g.connect({*id, o}, {kGraphOutputs, o});
  }
  ResultCache cache(64 << 20);
  Evaluator ev(cache, "nodes test");
  EvalOptions options;
  options.folder = folder;
  EvalResult r = ev.evaluate(g, bindings, names, options);
  NodeRun run;
  for (const OutputResult& o : r.outputs) run.outputs.push_back(o.value);
  run.diagnostics = std::move(r.diagnostics);
  return run;
}

EvalResult evaluate_mesh(const Graph& g, const std::filesystem::path& folder) {
  ResultCache cache(64 << 20);
  Evaluator ev(cache, "nodes test");
  EvalOptions options;
  options.folder = folder;
  return ev.evaluate(g, {}, {"mesh"}, options);
}

}  // namespace procex::test
