// value.h -- immutable, shared, typed values that flow along links.
//
// A Value is a shared_ptr<const T> plus a pointer to T's registered ValueType.
// Copying a Value never copies T. Types are registered once per process (the
// built-ins below by graph/, geometry types by nodes/) with a stable name, a
// hash, a memory size and, for types usable as parameters, JSON conversion.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "graph/hash.h"
#include "graph/status.h"

namespace procex {

class Value;

// Built-in value types besides double ("float"), std::int64_t ("int"),
// bool ("bool") and std::string ("string").
struct Vec2 {
  double x = 0, y = 0;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};
struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};
// The chosen entry of an enum parameter, stored by name so files and hashes
// survive reordering of the choices.
struct EnumValue {
  std::string choice;
  friend bool operator==(const EnumValue&, const EnumValue&) = default;
};
// Lists are std::vector<T> of a registered element type T; graph/ registers
// lists of every built-in ("list<float>", ...); use register_list_type<T>() for yours.

// The registered description of one C++ type. Obtain with value_type<T>() or
// ValueTypeRegistry::find(name).
class ValueType {
 public:
  using HashFn = std::function<void(const void*, Hasher&)>;
  using SizeFn = std::function<std::size_t(const void*)>;
  using ToJsonFn = std::function<void(const void*, nlohmann::json&)>;
  // Throws std::invalid_argument with a message naming what is wrong.
  using FromJsonFn = std::function<Value(const nlohmann::json&)>;
  using DetailFn = std::function<Value(const void*, int level)>;

  const std::string& name() const { return name_; }
  const std::string& doc() const { return doc_; }
  std::type_index cpp_type() const { return cpp_type_; }
  // The element type when this is a list type, else null.
  const ValueType* element_type() const { return element_; }
  // True for the wildcard type of ports declared with input<Value>/output<Value>.
  bool is_any() const { return any_; }
  bool has_json() const { return static_cast<bool>(to_json_); }

  void hash(const void* data, Hasher& h) const { hash_(data, h); }
  std::size_t memory_size(const void* data) const { return size_(data); }
  void to_json(const void* data, nlohmann::json& out) const;
  Value from_json(const nlohmann::json& in) const;
  // `v` (of this type) as a graph output shows it at a level of detail below
  // kFullDetail (node_decl.h): a mesh becomes its block or its footprint.
  // Types without a reduction show `v` itself.
  Value at_level_of_detail(const Value& v, int level) const;

  // Whether a link from an output of type `from` may feed an input of type `to`.
  static bool can_link(const ValueType& from, const ValueType& to) {
    return &from == &to || from.is_any() || to.is_any();
  }

 private:
  friend class ValueTypeRegistry;
  ValueType(std::string name, std::string doc, std::type_index t) : name_(std::move(name)), doc_(std::move(doc)), cpp_type_(t) {}
  std::string name_, doc_;
  std::type_index cpp_type_;
  const ValueType* element_ = nullptr;
  bool any_ = false;
  HashFn hash_;
  SizeFn size_;
  ToJsonFn to_json_;
  FromJsonFn from_json_;
  DetailFn detail_;
};

// What a module provides to register type T.
template <class T>
struct ValueTypeSpec {
  std::string name;  // stable: appears in files and messages ("footprint")
  std::string doc;
  void (*hash)(const T&, Hasher&) = nullptr;       // required: contribute the whole content
  std::size_t (*memory_size)(const T&) = nullptr;  // required: bytes owned, including sizeof(T)
  void (*to_json)(const T&, nlohmann::json&) = nullptr;  // optional: needed for parameters
  T (*from_json)(const nlohmann::json&) = nullptr;       // optional: throw std::invalid_argument on bad input
  T (*at_level_of_detail)(const T&, int level) = nullptr;  // optional: ValueType::at_level_of_detail
};

class ValueTypeRegistry {
 public:
  // The process-wide registry; the built-in types are registered on first use.
  static ValueTypeRegistry& global();

  template <class T>
  const ValueType& add(const ValueTypeSpec<T>& spec);
  const ValueType* find(std::string_view name) const;
  const ValueType* find(std::type_index t) const;
  // Registered types, sorted by name.
  std::vector<const ValueType*> all() const;
  // The wildcard type ("any").
  const ValueType& any() const { return *any_; }

  // Registers std::vector<T> as "list<name of T>"; T must be registered.
  template <class T>
  const ValueType& add_list();

 private:
  ValueTypeRegistry();
  const ValueType& insert(std::unique_ptr<ValueType> t);
  static std::unique_ptr<ValueType> make(std::string name, std::string doc, std::type_index t) {
    return std::unique_ptr<ValueType>(new ValueType(std::move(name), std::move(doc), t));
  }
  template <class T>
  static void set_list_fns(ValueType& t, const ValueType& element);
  struct Impl;
  std::unique_ptr<Impl> impl_;
  const ValueType* any_ = nullptr;
};

// The registered type of T. Aborts with a message if T was never registered:
// register it with PROCEX_REGISTER_VALUE_TYPE (or ValueTypeRegistry::add) first.
template <class T>
const ValueType& value_type();

template <>
const ValueType& value_type<Value>();  // the wildcard "any"

// An immutable, shared value of a registered type; empty when default-constructed.
class Value {
 public:
  Value() = default;

  template <class T>
  static Value make(T v) {
    return Value(std::make_shared<const T>(std::move(v)), &value_type<T>());
  }
  template <class T>
  static Value share(std::shared_ptr<const T> p) {
    return Value(std::move(p), &value_type<T>());
  }

  bool empty() const { return !data_; }
  explicit operator bool() const { return !empty(); }
  const ValueType* type() const { return type_; }
  template <class T>
  bool is() const {
    return type_ == &value_type<T>();
  }
  // Null when empty or of another type.
  template <class T>
  const T* get_if() const {
    return is<T>() ? static_cast<const T*>(data_.get()) : nullptr;
  }
  // Asserts the type; check is<T>() first when unsure.
  template <class T>
  const T& get() const;
  const void* raw() const { return data_.get(); }

  // Content hash (type name + content). Empty values hash to a fixed constant.
  Hash128 content_hash() const;
  void hash(Hasher& h) const;
  std::size_t memory_size() const { return data_ ? type_->memory_size(data_.get()) : 0; }
  // Same type and same content hash.
  bool same_content(const Value& other) const;

 private:
  Value(std::shared_ptr<const void> d, const ValueType* t) : data_(std::move(d)), type_(t) {}
  std::shared_ptr<const void> data_;
  const ValueType* type_ = nullptr;
};

// A value of `type` from command-line text: JSON ("2.5", "[1, 2]", "true"),
// or for strings and enums also the bare text ("--set style=gothic").
Result<Value> value_from_text(const ValueType& type, std::string_view text);

// ---- implementation details of the templates above ----

namespace detail {
[[noreturn]] void unregistered_value_type(const char* cpp_name);
[[noreturn]] void wrong_value_type(const ValueType* have, const ValueType& want);
}  // namespace detail

template <class T>
const ValueType& value_type() {
  static const ValueType* const t = [] {
    const ValueType* found = ValueTypeRegistry::global().find(std::type_index(typeid(T)));
    if (!found) detail::unregistered_value_type(typeid(T).name());
    return found;
  }();
  return *t;
}

template <class T>
const T& Value::get() const {
  if (!is<T>()) detail::wrong_value_type(type_, value_type<T>());
  return *static_cast<const T*>(data_.get());
}

template <class T>
const ValueType& ValueTypeRegistry::add(const ValueTypeSpec<T>& spec) {
  auto t = make(spec.name, spec.doc, std::type_index(typeid(T)));
  auto hash = spec.hash;
  auto size = spec.memory_size;
  t->hash_ = [hash](const void* p, Hasher& h) { hash(*static_cast<const T*>(p), h); };
  t->size_ = [size](const void* p) { return size(*static_cast<const T*>(p)); };
  if (spec.to_json && spec.from_json) {
    auto to = spec.to_json;
    auto from = spec.from_json;
    t->to_json_ = [to](const void* p, nlohmann::json& j) { to(*static_cast<const T*>(p), j); };
    t->from_json_ = [from](const nlohmann::json& j) { return Value::make<T>(from(j)); };
  }
  if (auto detail = spec.at_level_of_detail)
    t->detail_ = [detail](const void* p, int level) { return Value::make<T>(detail(*static_cast<const T*>(p), level)); };
  return insert(std::move(t));
}

template <class T>
const ValueType& ValueTypeRegistry::add_list() {
  const ValueType* found = find(std::type_index(typeid(T)));
  if (!found) detail::unregistered_value_type(typeid(T).name());
  const ValueType& element = *found;
  auto t = make("list<" + element.name() + ">", "A list of " + element.name(), std::type_index(typeid(std::vector<T>)));
  t->element_ = &element;
  set_list_fns<T>(*t, element);
  return insert(std::move(t));
}

namespace detail {
void list_to_json(const ValueType& element, const void* const* items, std::size_t n, nlohmann::json& out);
// Converts each array item with element.from_json; throws std::invalid_argument.
std::vector<Value> list_from_json(const ValueType& element, const nlohmann::json& in);
}  // namespace detail

template <class T>
void ValueTypeRegistry::set_list_fns(ValueType& t, const ValueType& element) {
  const ValueType* e = &element;
  t.hash_ = [e](const void* p, Hasher& h) {
    const auto& v = *static_cast<const std::vector<T>*>(p);
    h.u64(v.size());
    for (const T& item : v) e->hash(&item, h);
  };
  t.size_ = [e](const void* p) {
    const auto& v = *static_cast<const std::vector<T>*>(p);
    std::size_t n = sizeof(v) + (v.capacity() - v.size()) * sizeof(T);
    for (const T& item : v) n += e->memory_size(&item);
    return n;
  };
  if (element.has_json()) {
    t.to_json_ = [e](const void* p, nlohmann::json& j) {
      const auto& v = *static_cast<const std::vector<T>*>(p);
      std::vector<const void*> items;
      items.reserve(v.size());
      for (const T& item : v) items.push_back(&item);
      detail::list_to_json(*e, items.data(), items.size(), j);
    };
    t.from_json_ = [e](const nlohmann::json& j) {
      std::vector<T> out;
      for (const Value& item : detail::list_from_json(*e, j)) out.push_back(item.get<T>());
      return Value::make<std::vector<T>>(std::move(out));
    };
  }
}

}  // namespace procex

// Registers a value type from a single .cc file (in an OBJECT library, so the
// registration is linked). spec is a ValueTypeSpec<T>.
#define PROCEX_REGISTER_VALUE_TYPE_CAT2(a, b) a##b
#define PROCEX_REGISTER_VALUE_TYPE_CAT(a, b) PROCEX_REGISTER_VALUE_TYPE_CAT2(a, b)
#define PROCEX_REGISTER_VALUE_TYPE(T, spec)                                                            \
  [[maybe_unused]] static const ::procex::ValueType& PROCEX_REGISTER_VALUE_TYPE_CAT(procex_value_type_, \
                                                                                    __LINE__) =         \
      ::procex::ValueTypeRegistry::global().add<T>(spec)
