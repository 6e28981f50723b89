#include "graph/value.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace procex {

namespace {

using json = nlohmann::json;

std::string json_kind(const json& j) { return j.type_name(); }

double number_from_json(const json& j) {
  if (!j.is_number()) throw std::invalid_argument("expected a number, got " + json_kind(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw std::invalid_argument("number is not finite");
  return v;
}

void hash_double(const double& v, Hasher& h) { h.f64(v); }
void hash_int(const std::int64_t& v, Hasher& h) { h.i64(v); }
void hash_bool(const bool& v, Hasher& h) { h.boolean(v); }
void hash_string(const std::string& v, Hasher& h) { h.str(v); }
void hash_vec2(const Vec2& v, Hasher& h) { h.f64(v.x).f64(v.y); }
void hash_vec3(const Vec3& v, Hasher& h) { h.f64(v.x).f64(v.y).f64(v.z); }
void hash_enum(const EnumValue& v, Hasher& h) { h.str(v.choice); }

template <class T>
std::size_t size_of_plain(const T&) {
  return sizeof(T);
}
std::size_t size_of_string(const std::string& s) { return sizeof(s) + (s.capacity() > 15 ? s.capacity() + 1 : 0); }
std::size_t size_of_enum(const EnumValue& e) { return sizeof(e) - sizeof(e.choice) + size_of_string(e.choice); }

void double_to_json(const double& v, json& j) { j = v; }
double double_from_json(const json& j) { return number_from_json(j); }
void int_to_json(const std::int64_t& v, json& j) { j = v; }
std::int64_t int_from_json(const json& j) {
  if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
    throw std::invalid_argument("integer too large");
  if (j.is_number_integer()) return j.get<std::int64_t>();
  throw std::invalid_argument("expected an integer, got " + json_kind(j));
}
void bool_to_json(const bool& v, json& j) { j = v; }
bool bool_from_json(const json& j) {
  if (!j.is_boolean()) throw std::invalid_argument("expected true or false, got " + json_kind(j));
  return j.get<bool>();
}
void string_to_json(const std::string& v, json& j) { j = v; }
std::string string_from_json(const json& j) {
  if (!j.is_string()) throw std::invalid_argument("expected a string, got " + json_kind(j));
  return j.get<std::string>();
}
template <std::size_t N>
std::array<double, N> numbers_from_json(const json& j) {
  if (!j.is_array() || j.size() != N)
    throw std::invalid_argument("expected an array of " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = number_from_json(j[i]);
  return out;
}
void vec2_to_json(const Vec2& v, json& j) { j = json::array({v.x, v.y}); }
Vec2 vec2_from_json(const json& j) {
  const auto a = numbers_from_json<2>(j);
  return {a[0], a[1]};
}
void vec3_to_json(const Vec3& v, json& j) { j = json::array({v.x, v.y, v.z}); }
Vec3 vec3_from_json(const json& j) {
  const auto a = numbers_from_json<3>(j);
  return {a[0], a[1], a[2]};
}
void enum_to_json(const EnumValue& v, json& j) { j = v.choice; }
EnumValue enum_from_json(const json& j) { return EnumValue{string_from_json(j)}; }

// Stand-in C++ type of the wildcard: no value ever has it.
struct AnyTag {};

}  // namespace

struct ValueTypeRegistry::Impl {
  mutable std::mutex mutex;
  std::map<std::string, std::unique_ptr<ValueType>, std::less<>> by_name;
  std::map<std::type_index, const ValueType*> by_type;
};

ValueTypeRegistry::ValueTypeRegistry() : impl_(std::make_unique<Impl>()) {}

ValueTypeRegistry& ValueTypeRegistry::global() {
  static ValueTypeRegistry* const r = [] {
    auto* reg = new ValueTypeRegistry();  // never destroyed: values may outlive static destruction
    auto any = make("any", "Any type; checked when the value arrives", std::type_index(typeid(AnyTag)));
    any->any_ = true;
    any->hash_ = [](const void*, Hasher&) {};
    any->size_ = [](const void*) { return std::size_t{0}; };
    reg->any_ = &reg->insert(std::move(any));
    reg->add<double>({"float", "A real number", hash_double, size_of_plain<double>, double_to_json, double_from_json});
    reg->add<std::int64_t>({"int", "A whole number", hash_int, size_of_plain<std::int64_t>, int_to_json, int_from_json});
    reg->add<bool>({"bool", "true or false", hash_bool, size_of_plain<bool>, bool_to_json, bool_from_json});
    reg->add<std::string>({"string", "Text", hash_string, size_of_string, string_to_json, string_from_json});
    reg->add<Vec2>({"vec2", "A 2D vector [x, y]", hash_vec2, size_of_plain<Vec2>, vec2_to_json, vec2_from_json});
    reg->add<Vec3>({"vec3", "A 3D vector [x, y, z]", hash_vec3, size_of_plain<Vec3>, vec3_to_json, vec3_from_json});
    reg->add<EnumValue>({"enum", "One of a parameter's named choices", hash_enum, size_of_enum, enum_to_json, enum_from_json});
    reg->add_list<double>();
    reg->add_list<std::int64_t>();
    reg->add_list<bool>();
    reg->add_list<std::string>();
    reg->add_list<Vec2>();
    reg->add_list<Vec3>();
    reg->add_list<std::vector<Vec2>>();  // polylines: a polygon's holes, a step's outline
    return reg;
  }();
  return *r;
}

const ValueType& ValueTypeRegistry::insert(std::unique_ptr<ValueType> t) {
  std::lock_guard lock(impl_->mutex);
  if (impl_->by_name.count(t->name()) || impl_->by_type.count(t->cpp_type())) {
    std::fprintf(stderr, "procex: value type '%s' registered twice (or its C++ type already is)\n", t->name().c_str());
    std::abort();
  }
  const ValueType* p = t.get();
  impl_->by_type.emplace(t->cpp_type(), p);
  impl_->by_name.emplace(t->name(), std::move(t));
  return *p;
}

const ValueType* ValueTypeRegistry::find(std::string_view name) const {
  std::lock_guard lock(impl_->mutex);
  auto it = impl_->by_name.find(name);
  return it == impl_->by_name.end() ? nullptr : it->second.get();
}

const ValueType* ValueTypeRegistry::find(std::type_index t) const {
  std::lock_guard lock(impl_->mutex);
  auto it = impl_->by_type.find(t);
  return it == impl_->by_type.end() ? nullptr : it->second;
}

std::vector<const ValueType*> ValueTypeRegistry::all() const {
  std::lock_guard lock(impl_->mutex);
  std::vector<const ValueType*> out;
  for (const auto& [name, t] : impl_->by_name) out.push_back(t.get());
  return out;
}

template <>
const ValueType& value_type<Value>() {
  return ValueTypeRegistry::global().any();
}

void ValueType::to_json(const void* data, nlohmann::json& out) const {
  if (!to_json_) throw std::invalid_argument("values of type '" + name_ + "' cannot be written to a file");
  to_json_(data, out);
}

Value ValueType::from_json(const nlohmann::json& in) const {
  if (!from_json_) throw std::invalid_argument("values of type '" + name_ + "' cannot be read from a file");
  return from_json_(in);
}

Value ValueType::at_level_of_detail(const Value& v, int level) const { return detail_ ? detail_(v.raw(), level) : v; }

Hash128 Value::content_hash() const {
  Hasher h;
  hash(h);
  return h.result();
}

void Value::hash(Hasher& h) const {
  if (!data_) {
    h.u64(0x5bd1e9955bd1e995ull);
    return;
  }
  h.str(type_->name());
  type_->hash(data_.get(), h);
}

bool Value::same_content(const Value& other) const {
  return type_ == other.type_ && content_hash() == other.content_hash();
}

Result<Value> value_from_text(const ValueType& type, std::string_view text) {
  const json parsed = json::parse(text, nullptr, /*allow_exceptions=*/false);
  const bool bare_text_ok = type.name() == "string" || type.name() == "enum";
  std::string refusal = "'";
  refusal.append(text).append("' is not a ").append(type.name()).append(" value");
  if (parsed.is_discarded() && !bare_text_ok) return Status::error(refusal);
  const json j = bare_text_ok && !parsed.is_string() ? json(std::string(text)) : parsed;
  try {
    return type.from_json(j);
  } catch (const std::invalid_argument& e) {
    return Status::error(refusal.append(": ").append(e.what()));
  }
}

namespace detail {

void unregistered_value_type(const char* cpp_name) {
  std::fprintf(stderr,
               "procex: C++ type %s is not a registered value type; register it with "
               "PROCEX_REGISTER_VALUE_TYPE before declaring ports or making Values of it\n",
               cpp_name);
  std::abort();
}

void wrong_value_type(const ValueType* have, const ValueType& want) {
  std::fprintf(stderr, "procex: Value::get<%s>() on a value of type %s; check is<T>() first\n", want.name().c_str(),
               have ? have->name().c_str() : "(empty)");
  std::abort();
}

void list_to_json(const ValueType& element, const void* const* items, std::size_t n, nlohmann::json& out) {
  out = json::array();
  for (std::size_t i = 0; i < n; ++i) {
    json item;
    element.to_json(items[i], item);
    out.push_back(std::move(item));
  }
}

std::vector<Value> list_from_json(const ValueType& element, const nlohmann::json& in) {
  if (!in.is_array()) throw std::invalid_argument("expected an array of " + element.name() + ", got " + json_kind(in));
  std::vector<Value> out;
  out.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    try {
      out.push_back(element.from_json(in[i]));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("item " + std::to_string(i) + ": " + e.what());
    }
  }
  return out;
}

}  // namespace detail

}  // namespace procex
