#include "tests/graph/test_nodes.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "graph/registry.h"

namespace procex::test {

namespace {
std::mutex g_mutex;
std::map<std::string, int>& per_type() {
  static std::map<std::string, int> m;
  return m;
}
void count(const EvalContext& ctx) {
  ++evaluations();
  std::lock_guard lock(g_mutex);
  ++per_type()[ctx.decl().type_name()];
}

// test.Const: a number.
void declare_const(NodeDecl& d) {
  d.doc("A constant number.").category("Test");
  d.param<double>("value").default_value(1.0).range(-1e6, 1e6).doc("the number");
  d.output<double>("out");
}
void eval_const(EvalContext& ctx) {
  count(ctx);
  ctx.set_output(0, ctx.param<double>(0));
}

// test.Add: a + b (b optional) times scale. Version 1 called `scale` "factor".
void upgrade_add(int saved_version, nlohmann::json& params) {
  if (saved_version < 2 && params.contains("factor")) {
    params["scale"] = params["factor"];
    params.erase("factor");
  }
}
void declare_add(NodeDecl& d) {
  d.upgrade(upgrade_add);
  d.doc("Adds two numbers and scales the sum.").category("Test");
  d.input<double>("a");
  d.input<double>("b").optional();
  d.param<double>("scale").default_value(1.0).range(-100, 100).unit("m");
  d.output<double>("sum");
}
void eval_add(EvalContext& ctx) {
  count(ctx);
  const double b = ctx.has_input(1) ? ctx.input<double>(1) : 0.0;
  ctx.set_output(0, (ctx.input<double>(0) + b) * ctx.param<double>(0));
}

// test.Mul: a * b.
void declare_mul(NodeDecl& d) {
  d.doc("Multiplies two numbers.").category("Test");
  d.input<double>("a");
  d.input<double>("b");
  d.output<double>("product");
}
void eval_mul(EvalContext& ctx) {
  count(ctx);
  ctx.set_output(0, ctx.input<double>(0) * ctx.input<double>(1));
}

// test.Fail: fails when `fail` is set or the input is negative; otherwise passes x + 1.
void declare_fail(NodeDecl& d) {
  d.doc("Fails on request, or on negative input.").category("Test");
  d.input<double>("x");
  d.param<bool>("fail").default_value(false);
  d.param_enum("how", {"error", "throw", "out_of_memory"});
  d.output<double>("out");
}
void eval_fail(EvalContext& ctx) {
  count(ctx);
  const double x = ctx.input<double>(0);
  if (ctx.param<bool>(0) || x < 0) {
    if (ctx.choice(1) == "throw") throw std::runtime_error("thrown on purpose");
    if (ctx.choice(1) == "out_of_memory") throw std::bad_alloc();
    ctx.error("failed on purpose");
    return;
  }
  if (x == 0) ctx.warning("x is zero");
  ctx.set_output(0, x + 1);
}

// test.Switch: doubles x when enabled; hands x through unchanged when disabled.
std::optional<std::size_t> switch_pass(const std::vector<Value>& params, std::size_t) {
  if (!params[0].get<bool>()) return std::size_t{0};
  return std::nullopt;
}
void declare_switch(NodeDecl& d) {
  d.doc("Doubles x, or passes it through when disabled.").category("Test");
  d.input<double>("x");
  d.param<bool>("enabled").default_value(true);
  d.output<double>("out");
  d.pass_through(switch_pass);
}
void eval_switch(EvalContext& ctx) {
  count(ctx);
  ctx.set_output(0, ctx.input<double>(0) * 2);
}

// test.Slow: sleeps in small steps, polling cancellation.
void declare_slow(NodeDecl& d) {
  d.doc("Waits `steps` milliseconds, checking for cancellation.").category("Test");
  d.input<double>("x");
  d.param<std::int64_t>("steps").default_value<std::int64_t>(1).range(0, 100000);
  d.output<double>("out");
}
void eval_slow(EvalContext& ctx) {
  count(ctx);
  for (std::int64_t i = 0; i < ctx.param<std::int64_t>(0); ++i) {
    ctx.throw_if_cancelled();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ctx.set_output(0, ctx.input<double>(0));
}

// test.FileSize: the size of a file, re-read when the file changes.
std::filesystem::path resolve(const std::vector<Value>& params, const std::filesystem::path& folder) {
  return folder / params[0].get<std::string>();
}
void hash_file_state(const std::vector<Value>& params, const std::filesystem::path& folder, FileVersionMemo* versions,
                     Hasher& h) {
  ++file_size_hashes();
  hash_file_stamp(resolve(params, folder), versions, h);
}
void declare_file_size(NodeDecl& d) {
  d.doc("Size of a file in bytes.").category("Test");
  d.param<std::string>("path").default_value(std::string("missing.txt")).doc("relative to the recipe's folder");
  d.output<std::int64_t>("bytes");
  d.hash_extra(hash_file_state);
}
void eval_file_size(EvalContext& ctx) {
  count(ctx);
  std::error_code ec;
  const auto size = std::filesystem::file_size(resolve({ctx.param_value(0)}, ctx.folder()), ec);
  if (ec) return ctx.error("cannot read " + ctx.param<std::string>(0) + ": " + ec.message());
  ctx.set_output(0, static_cast<std::int64_t>(size));
}

// test.Reroute: any type in, same value out.
std::optional<std::size_t> always_pass(const std::vector<Value>&, std::size_t) { return std::size_t{0}; }
void declare_reroute(NodeDecl& d) {
  d.doc("Hands its input on.").category("Test");
  d.input<Value>("in");
  d.output<Value>("out");
  d.pass_through(always_pass);
}
void eval_reroute(EvalContext& ctx) {
  count(ctx);
  ctx.set_output_value(0, ctx.input_value(0));
}

// test.Everything: a parameter of every built-in type, folded into a string.
void declare_everything(NodeDecl& d) {
  d.doc("Summarises parameters of every built-in type.").category("Test");
  d.input<std::string>("prefix").optional();
  d.param<double>("f").default_value(0.5).range(0, 1);
  d.param<std::int64_t>("i").default_value<std::int64_t>(3).min(0);
  d.param<bool>("b").default_value(false);
  d.param<std::string>("s").default_value(std::string("hello"));
  d.param<Vec2>("v2").default_value(Vec2{1, 2});
  d.param<Vec3>("v3").default_value(Vec3{1, 2, 3});
  d.param_enum("e", {"north", "south", "east"}, "south");
  d.param<std::vector<double>>("l").default_value(std::vector<double>{1, 2, 3});
  d.output<std::string>("summary");
  d.output<std::vector<std::int64_t>>("counts");
}
void eval_everything(EvalContext& ctx) {
  count(ctx);
  std::string s = ctx.has_input(0) ? ctx.input<std::string>(0) : "";
  s += std::to_string(ctx.param<double>(0)) + "|" + std::to_string(ctx.param<std::int64_t>(1)) + "|" +
       (ctx.param<bool>(2) ? "T" : "F") + "|" + ctx.param<std::string>(3) + "|" + std::to_string(ctx.param<Vec2>(4).x) +
       "|" + std::to_string(ctx.param<Vec3>(5).z) + "|" + ctx.choice(6) + "|" +
       std::to_string(ctx.param<std::vector<double>>(7).size());
  ctx.set_output(0, s);
  ctx.set_output(1, std::vector<std::int64_t>{ctx.param<std::int64_t>(1), static_cast<std::int64_t>(ctx.choice_index(6))});
}

// test.Pick: hands on input `which` (0 or 1) unchanged, like a building-type switch.
std::optional<std::size_t> pick_pass(const std::vector<Value>& params, std::size_t) {
  return static_cast<std::size_t>(params[0].get<std::int64_t>());
}
void declare_pick(NodeDecl& d) {
  d.doc("Hands on one of two inputs.").category("Test");
  d.param<std::int64_t>("which").default_value<std::int64_t>(0).range(0, 1).doc("0: first, 1: second");
  d.input<Value>("first");
  d.input<Value>("second");
  d.output<Value>("out");
  d.pass_through(pick_pass);
}
void eval_pick(EvalContext& ctx) {  // reached only when the chosen input is not connected
  count(ctx);
  ctx.set_output_value(0, ctx.input_value(static_cast<std::size_t>(ctx.param<std::int64_t>(0))));
}

// test.Sum: the sum of its connected terms; `terms` sets how many inputs it has
// (variadic ports). Version 1 had three fixed terms.
void upgrade_sum(int saved_version, nlohmann::json& params) {
  if (saved_version < 2) params["terms"] = 3;
}
void declare_sum(NodeDecl& d) {
  d.doc("Adds its connected terms.").category("Test");
  d.param<std::int64_t>("terms").default_value<std::int64_t>(2).range(1, 8).sets_port_count().doc("number of inputs");
  d.param<double>("offset").default_value(0.0).range(-100, 100).doc("added to the sum");
  for (std::size_t i = 1; i <= d.count_of("terms"); ++i) d.input<double>("term_" + std::to_string(i)).optional();
  d.output<double>("sum");
  d.upgrade(upgrade_sum);
}
void eval_sum(EvalContext& ctx) {
  count(ctx);
  double sum = ctx.param<double>(1);
  for (std::size_t i = 0; i < ctx.decl().inputs().size(); ++i)
    if (ctx.has_input(i)) sum += ctx.input<double>(i);
  ctx.set_output(0, sum);
}

}  // namespace

std::atomic<int>& evaluations() {
  static std::atomic<int> n{0};
  return n;
}

std::atomic<int>& file_size_hashes() {
  static std::atomic<int> n{0};
  return n;
}

int evaluations_of(const std::string& type) {
  std::lock_guard lock(g_mutex);
  auto it = per_type().find(type);
  return it == per_type().end() ? 0 : it->second;
}

void reset_evaluations() {
  evaluations() = 0;
  std::lock_guard lock(g_mutex);
  per_type().clear();
}

}  // namespace procex::test

namespace procex::test {
PROCEX_REGISTER_NODE("test.Const", 1, declare_const, eval_const);
PROCEX_REGISTER_NODE("test.Sum", 2, declare_sum, eval_sum);
PROCEX_REGISTER_NODE("test.Pick", 1, declare_pick, eval_pick);
PROCEX_REGISTER_NODE("test.Add", 2, declare_add, eval_add);
PROCEX_REGISTER_NODE("test.Mul", 1, declare_mul, eval_mul);
PROCEX_REGISTER_NODE("test.Fail", 1, declare_fail, eval_fail);
PROCEX_REGISTER_NODE("test.Switch", 1, declare_switch, eval_switch);
PROCEX_REGISTER_NODE("test.Slow", 1, declare_slow, eval_slow);
PROCEX_REGISTER_NODE("test.Reroute", 1, declare_reroute, eval_reroute);
PROCEX_REGISTER_NODE("test.FileSize", 1, declare_file_size, eval_file_size);
PROCEX_REGISTER_NODE("test.Everything", 1, declare_everything, eval_everything);
}  // namespace procex::test
