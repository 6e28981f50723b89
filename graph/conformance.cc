#include "graph/conformance.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "graph/evaluator.h"
#include "graph/pxg.h"

namespace procex {

namespace {

double moved(double v, const ParamDecl& p, double step) {
  if (!p.max || v + step <= *p.max) return v + step;
  if (!p.min || v - step >= *p.min) return v - step;
  return (*p.min + *p.max) / 2 == v ? *p.min : (*p.min + *p.max) / 2;
}

Value sample_for(const ValueType* t, const SampleInputs& samples) {
  if (auto it = samples.find(t); it != samples.end()) return it->second;
  if (t == &value_type<double>()) return Value::make(1.5);
  if (t == &value_type<std::int64_t>()) return Value::make<std::int64_t>(3);
  if (t == &value_type<bool>()) return Value::make(true);
  if (t == &value_type<std::string>()) return Value::make(std::string("sample"));
  if (t == &value_type<Vec2>()) return Value::make(Vec2{1, 2});
  if (t == &value_type<Vec3>()) return Value::make(Vec3{1, 2, 3});
  if (t->is_any()) return Value::make(2.5);
  return {};
}

}  // namespace

Value vary_param(const ParamDecl& p) {
  const Value& d = p.default_value;
  if (const double* v = d.get_if<double>()) {
    double x = moved(*v, p, 1.0);
    if (x == *v) x = moved(*v, p, 1e-3);
    return x == *v ? Value() : Value::make(x);
  }
  if (const std::int64_t* v = d.get_if<std::int64_t>()) {
    const auto x = static_cast<std::int64_t>(moved(static_cast<double>(*v), p, 1.0));
    return x == *v ? Value() : Value::make<std::int64_t>(x);
  }
  if (const bool* v = d.get_if<bool>()) return Value::make(!*v);
  if (const std::string* v = d.get_if<std::string>()) return Value::make(*v + "x");
  if (const Vec2* v = d.get_if<Vec2>()) return Value::make(Vec2{v->x + 1, v->y});
  if (const Vec3* v = d.get_if<Vec3>()) return Value::make(Vec3{v->x + 1, v->y, v->z});
  if (const EnumValue* v = d.get_if<EnumValue>()) {
    for (const std::string& c : p.choices)
      if (c != v->choice) return Value::make(EnumValue{c});
    return {};
  }
  // Other types through their JSON form: lists lose their last item, or (when
  // they set a port count, so that connected ports stay) repeat their first.
  if (p.type->has_json()) {
    nlohmann::json j;
    p.type->to_json(d.raw(), j);
    if (j.is_array() && !j.empty()) {
      nlohmann::json other = j;
      if (p.sets_port_count) other.push_back(j.front());
      else other.erase(other.size() - 1);
      try {
        return p.type->from_json(other);
      } catch (const std::invalid_argument&) {
        return {};
      }
    }
  }
  return {};
}

namespace {

// "folder/file.cc": what identifies a source file however __FILE__ spelled it.
std::filesystem::path source_key(const std::filesystem::path& file) {
  const std::filesystem::path p = file.lexically_normal();
  return p.parent_path().filename() / p.filename();
}

}  // namespace

bool registered_in(const NodeType& type, const std::filesystem::path& dir) {
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::weakly_canonical(dir, ec);
  return source_key(type.source_file) == folder.filename() / std::filesystem::path(type.source_file).filename();
}

std::vector<std::filesystem::path> unregistered_node_files(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::set<fs::path> registered;
  for (const auto& t : NodeRegistry::global().all()) registered.insert(source_key(t->source_file));
  static const std::regex kRegistration(R"(^\s*PROCEX_REGISTER_NODE\()", std::regex::multiline);
  std::vector<fs::path> missing;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".cc") continue;
    std::ifstream in(entry.path());
    std::ostringstream text;
    text << in.rdbuf();
    std::error_code ec;
    if (std::regex_search(text.str(), kRegistration) && !registered.count(source_key(fs::weakly_canonical(entry.path(), ec))))
      missing.push_back(entry.path());
  }
  std::sort(missing.begin(), missing.end());
  return missing;
}

std::vector<std::string> check_pxg_round_trip(const std::filesystem::path& file) {
  std::vector<std::string> problems;
  try {
    const Graph g = load_pxg(file);
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string saved = to_pxg(g);
    if (saved != text) problems.push_back(file.string() + ": saving does not reproduce the file byte for byte");
    const Graph back = parse_pxg(saved, file);
    ResultCache cache(1 << 20);
    Evaluator ev(cache, "round-trip");
    const EvalResult a = ev.hash_outputs(g, {});
    const EvalResult b = ev.hash_outputs(back, {});
    for (std::size_t i = 0; i < a.outputs.size() && i < b.outputs.size(); ++i)
      if (a.outputs[i].hash != b.outputs[i].hash)
        problems.push_back(file.string() + ": output '" + a.outputs[i].name + "' hashes differently after a round trip");
  } catch (const PxgError& e) {
    problems.push_back(e.what());
  }
  return problems;
}

std::vector<std::string> check_node_type(const NodeType& type, const SampleInputs& samples,
                                         const std::filesystem::path& folder) {
  std::vector<std::string> problems;
  const std::string who = "node type '" + type.name() + "': ";
  const NodeDecl& decl = type.decl;
  Graph g;
  const NodeId id = g.add_node(std::shared_ptr<const NodeType>(std::shared_ptr<const NodeType>{}, &type)).value();
  Bindings bindings;
  for (std::uint32_t i = 0; i < decl.inputs().size(); ++i) {
    const PortDecl& in = decl.inputs()[i];
    Value v = sample_for(in.type, samples);
    if (v.empty()) {
      problems.push_back(who + "no sample value for input '" + in.name + "' of type " + in.type->name());
      return problems;
    }
    const std::string name = "in_" + in.name;
    (void)g.add_input(GraphInput{name, in.type->is_any() ? v.type() : in.type, {}, {}});
    (void)g.connect(PortRef{kGraphInputs, i}, PortRef{id, i});
    bindings[name] = v;
  }
  for (std::uint32_t o = 0; o < decl.outputs().size(); ++o) {
    (void)g.add_output(GraphOutput{"out_" + decl.outputs()[o].name, decl.outputs()[o].type, {}});
    (void)g.connect(PortRef{id, o}, PortRef{kGraphOutputs, o});
  }

  ResultCache cache(64 << 20);
  Evaluator ev(cache, "conformance");
  EvalOptions options;
  options.folder = folder;
  auto hashes = [&](const Graph& graph) {
    std::vector<Hash128> out;
    for (const OutputResult& r : ev.hash_outputs(graph, bindings, {}, options).outputs) out.push_back(r.hash);
    return out;
  };
  const auto base = hashes(g);

  // Defaults evaluate: errors are allowed (reported on the node), escapes are not.
  EvalResult r = ev.evaluate(g, bindings, {}, options);
  for (const OutputResult& o : r.outputs)
    if (o.hash != base[&o - r.outputs.data()]) problems.push_back(who + "evaluation and hashing disagree on " + o.name);

  for (std::size_t p = 0; p < decl.params().size(); ++p) {
    const ParamDecl& pd = decl.params()[p];
    Value other = vary_param(pd);
    if (other.empty()) continue;  // a single-choice enum or a pinned range: nothing to vary
    Graph changed = g;
    if (Status s = changed.set_param(id, p, other); !s) {
      problems.push_back(who + "varied parameter '" + pd.name + "' refused: " + s.message());
      continue;
    }
    const auto h = hashes(changed);
    for (std::size_t o = 0; o < h.size(); ++o) {
      const bool passes = decl.pass_through() && (decl.pass_through()(changed.node(id)->params, o) ||
                                                  decl.pass_through()(g.node(id)->params, o));
      if (h[o] == base[o] && !passes)
        problems.push_back(who + "changing parameter '" + pd.name + "' leaves the hash of output '" +
                           decl.outputs()[o].name + "' unchanged");
    }
    // Round trip of the changed graph too: the varied value must survive the file.
    const std::string text = to_pxg(changed);
    try {
      Graph back = parse_pxg(text, "conformance.pxg");
      if (to_pxg(back) != text) problems.push_back(who + "file round trip with '" + pd.name + "' changed is not byte-identical");
      if (hashes(back) != h) problems.push_back(who + "file round trip with '" + pd.name + "' changed moves the hash");
    } catch (const PxgError& e) {
      problems.push_back(who + "file round trip failed: " + e.what());
    }
  }
  const std::string text = to_pxg(g);
  try {
    Graph back = parse_pxg(text, "conformance.pxg");
    if (to_pxg(back) != text) problems.push_back(who + "file round trip is not byte-identical");
    if (hashes(back) != base) problems.push_back(who + "file round trip moves the hash");
  } catch (const PxgError& e) {
    problems.push_back(who + "file round trip failed: " + e.what());
  }
  return problems;
}

}  // namespace procex
