#include <gtest/gtest.h>

#include "graph/conformance.h"

namespace procex {
namespace {

// Every registered node type: each parameter moves the output hash, defaults
// evaluate, and a file round trip keeps hash and bytes.
TEST(Conformance, EveryRegisteredNodeType) {
  for (const auto& type : NodeRegistry::global().all()) {
    SCOPED_TRACE(type->name());
    EXPECT_EQ(check_node_type(*type, {}), std::vector<std::string>{});
  }
}

// The check must be able to fail.
void eval_nothing(EvalContext&) {}

TEST(Conformance, MissingSamplesAreReported) {
  NodeType t;
  t.decl = NodeDecl("local.NeedsList", 1);
  t.decl.input<std::vector<Vec3>>("points");
  t.decl.output<double>("n");
  t.evaluate = eval_nothing;
  const auto problems = check_node_type(t, {});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "node type 'local.NeedsList': no sample value for input 'points' of type list<vec3>");
}

TEST(Conformance, VariesEveryBuiltinParameterType) {
  auto t = NodeRegistry::global().find("test.Everything");
  for (const ParamDecl& p : t->decl.params()) {
    Value v = vary_param(p);
    ASSERT_FALSE(v.empty()) << p.name;
    EXPECT_TRUE(p.check(v)) << p.name;
    EXPECT_NE(v.content_hash(), p.default_value.content_hash()) << p.name;
  }
}

}  // namespace
}  // namespace procex
