#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "graph/value.h"

namespace procex {
namespace {

TEST(Value, BuiltinsHaveStableNames) {
  EXPECT_EQ(value_type<double>().name(), "float");
  EXPECT_EQ(value_type<std::int64_t>().name(), "int");
  EXPECT_EQ(value_type<bool>().name(), "bool");
  EXPECT_EQ(value_type<std::string>().name(), "string");
  EXPECT_EQ(value_type<Vec2>().name(), "vec2");
  EXPECT_EQ(value_type<Vec3>().name(), "vec3");
  EXPECT_EQ(value_type<EnumValue>().name(), "enum");
  EXPECT_EQ(value_type<std::vector<double>>().name(), "list<float>");
  EXPECT_EQ(value_type<std::vector<double>>().element_type(), &value_type<double>());
  EXPECT_TRUE(value_type<Value>().is_any());
  EXPECT_EQ(ValueTypeRegistry::global().find("list<vec3>"), &value_type<std::vector<Vec3>>());
}

TEST(Value, SharedAndImmutable) {
  Value a = Value::make(std::string("abc"));
  Value b = a;
  EXPECT_EQ(a.raw(), b.raw());  // copies share, never copy the payload
  EXPECT_TRUE(a.is<std::string>());
  EXPECT_FALSE(a.is<double>());
  EXPECT_EQ(a.get_if<double>(), nullptr);
  EXPECT_EQ(a.get<std::string>(), "abc");
  EXPECT_GE(a.memory_size(), sizeof(std::string));
  EXPECT_TRUE(Value().empty());
}

TEST(Value, ContentHashSeparatesTypesAndValues) {
  EXPECT_EQ(Value::make(1.0).content_hash(), Value::make(1.0).content_hash());
  EXPECT_NE(Value::make(1.0).content_hash(), Value::make(2.0).content_hash());
  EXPECT_NE(Value::make(1.0).content_hash(), Value::make<std::int64_t>(1).content_hash());
  EXPECT_EQ(Value::make(0.0).content_hash(), Value::make(-0.0).content_hash());
  EXPECT_NE(Value::make(std::string("ab")).content_hash(), Value::make(std::string("ab\0", 3)).content_hash());
  EXPECT_NE(Value::make(std::vector<double>{1, 2}).content_hash(), Value::make(std::vector<double>{2, 1}).content_hash());
  EXPECT_NE(Value::make(Vec3{1, 2, 3}).content_hash(), Value::make(Vec3{1, 3, 2}).content_hash());
  EXPECT_NE(Value().content_hash(), Value::make(0.0).content_hash());
}

TEST(Value, HasherDistinguishesSplitsOfTheSameBytes) {
  EXPECT_NE(Hasher().str("ab").str("c").result(), Hasher().str("a").str("bc").result());
  EXPECT_NE(Hasher().u64(1).result(), Hasher().u64(2).result());
  EXPECT_EQ(Hasher().u64(1).result().hex().size(), 32u);
}

TEST(Value, JsonRoundTripOfEveryBuiltin) {
  const std::vector<Value> values = {Value::make(2.5),
                                     Value::make<std::int64_t>(-7),
                                     Value::make(true),
                                     Value::make(std::string("x y")),
                                     Value::make(Vec2{1, -2}),
                                     Value::make(Vec3{0.1, 0.2, 0.3}),
                                     Value::make(EnumValue{"north"}),
                                     Value::make(std::vector<double>{1.5, 2}),
                                     Value::make(std::vector<std::string>{"a", "b"}),
                                     Value::make(std::vector<Vec2>{{1, 2}, {3, 4}})};
  for (const Value& v : values) {
    nlohmann::json j;
    v.type()->to_json(v.raw(), j);
    Value back = v.type()->from_json(j);
    EXPECT_EQ(back.type(), v.type());
    EXPECT_EQ(back.content_hash(), v.content_hash()) << v.type()->name() << " " << j.dump();
  }
}

TEST(Value, BadJsonSaysWhatIsWrong) {
  auto error_of = [](const ValueType& t, const char* text) {
    try {
      t.from_json(nlohmann::json::parse(text));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(value_type<double>(), "\"1\""), "expected a number, got string");
  EXPECT_EQ(error_of(value_type<std::int64_t>(), "1.5"), "expected an integer, got number");
  EXPECT_EQ(error_of(value_type<std::int64_t>(), "18446744073709551615"), "integer too large");
  EXPECT_EQ(error_of(value_type<Vec2>(), "[1]"), "expected an array of 2 numbers");
  EXPECT_EQ(error_of(value_type<std::vector<double>>(), "[1, \"a\"]"), "item 1: expected a number, got string");
  EXPECT_EQ(error_of(value_type<bool>(), "0"), "expected true or false, got number");
}

TEST(Value, FromCommandLineText) {
  EXPECT_EQ(value_from_text(value_type<double>(), "2.5").value().get<double>(), 2.5);
  EXPECT_EQ(value_from_text(value_type<std::int64_t>(), "7").value().get<std::int64_t>(), 7);
  EXPECT_EQ(value_from_text(value_type<Vec2>(), "[1, 2]").value().get<Vec2>(), (Vec2{1, 2}));
  EXPECT_EQ(value_from_text(value_type<std::string>(), "gothic").value().get<std::string>(), "gothic");
  EXPECT_EQ(value_from_text(value_type<std::string>(), "12").value().get<std::string>(), "12");
  EXPECT_EQ(value_from_text(value_type<EnumValue>(), "north").value().get<EnumValue>().choice, "north");
  EXPECT_EQ(value_from_text(value_type<double>(), "tall").message(), "'tall' is not a float value");
  EXPECT_EQ(value_from_text(value_type<std::int64_t>(), "1.5").message(),
            "'1.5' is not a int value: expected an integer, got number");
}

// A type registered the way nodes/ registers its geometry.
struct Polyline {
  std::vector<Vec2> points;
};
void hash_polyline(const Polyline& p, Hasher& h) {
  h.u64(p.points.size());
  for (const Vec2& v : p.points) h.f64(v.x).f64(v.y);
}
std::size_t size_polyline(const Polyline& p) { return sizeof(p) + p.points.capacity() * sizeof(Vec2); }
PROCEX_REGISTER_VALUE_TYPE(Polyline, (ValueTypeSpec<Polyline>{"test_polyline", "points", hash_polyline, size_polyline}));

TEST(Value, ModulesRegisterTheirOwnTypes) {
  const ValueType& t = value_type<Polyline>();
  EXPECT_EQ(t.name(), "test_polyline");
  EXPECT_FALSE(t.has_json());
  Value v = Value::make(Polyline{{{0, 0}, {1, 0}, {1, 1}}});
  EXPECT_EQ(v.memory_size(), sizeof(Polyline) + 3 * sizeof(Vec2));
  EXPECT_NE(v.content_hash(), Value::make(Polyline{{{0, 0}, {1, 0}}}).content_hash());
  const ValueType& list = ValueTypeRegistry::global().add_list<Polyline>();
  EXPECT_EQ(list.name(), "list<test_polyline>");
  EXPECT_EQ(ValueTypeRegistry::global().find("list<test_polyline>"), &list);
}

}  // namespace
}  // namespace procex
