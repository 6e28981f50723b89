#include "graph/node_decl.h"

#include <algorithm>
#include <cassert>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/file_version_memo.h"
#include "graph/hash.h"

namespace procex {

namespace {

bool is_number_type(const ValueType* t) { return t == &value_type<double>() || t == &value_type<std::int64_t>(); }

double as_double(const Value& v) {
  if (const double* d = v.get_if<double>()) return *d;
  return static_cast<double>(v.get<std::int64_t>());
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::optional<std::size_t> find_by_name(const auto& items, std::string_view name) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) return i;
  return std::nullopt;
}

}  // namespace

bool is_identifier(std::string_view name) {
  if (name.empty() || name.size() > 64 || !(name[0] >= 'a' && name[0] <= 'z')) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

Status ParamDecl::check(const Value& v) const {
  if (v.empty()) return Status::error("parameter '" + name + "' needs a value");
  if (v.type() != type)
    return Status::error("parameter '" + name + "' takes " + type->name() + ", not " + v.type()->name());
  if (is_number_type(type)) {
    const double x = as_double(v);
    if ((min && x < *min) || (max && x > *max)) {
      return Status::error("parameter '" + name + "' = " + format_number(x) + " is outside its range [" +
                           (min ? format_number(*min) : "-inf") + ", " + (max ? format_number(*max) : "inf") + "]");
    }
  }
  if (sets_port_count && port_count_of(v) > kMaxPortCount)
    return Status::error("parameter '" + name + "' asks for " + std::to_string(port_count_of(v)) +
                         " ports; at most " + std::to_string(kMaxPortCount));
  if (!choices.empty()) {
    const std::string& c = v.get<EnumValue>().choice;
    if (std::find(choices.begin(), choices.end(), c) == choices.end()) {
      std::string all;
      for (const auto& ch : choices) all += (all.empty() ? "" : ", ") + ch;
      return Status::error("parameter '" + name + "' has no choice '" + c + "' (choices: " + all + ")");
    }
  }
  return Status::ok();
}

std::size_t port_count_of(const Value& v) {
  if (const auto* list = v.get_if<std::vector<std::string>>()) return list->size();
  const std::int64_t n = v.get<std::int64_t>();
  return n < 0 ? 0 : static_cast<std::size_t>(n);
}

PortBuilder& PortBuilder::doc(std::string text) {
  (*ports_)[index_].doc = std::move(text);
  return *this;
}
PortBuilder& PortBuilder::optional(bool yes) {
  (*ports_)[index_].optional = yes;
  return *this;
}

ParamBuilder& ParamBuilder::default_value_of(Value v) {
  p().default_value = std::move(v);
  return *this;
}
ParamBuilder& ParamBuilder::range(double lo, double hi) { return min(lo).max(hi); }
ParamBuilder& ParamBuilder::min(double v) {
  p().min = v;
  return *this;
}
ParamBuilder& ParamBuilder::max(double v) {
  p().max = v;
  return *this;
}
ParamBuilder& ParamBuilder::unit(std::string u) {
  p().unit = std::move(u);
  return *this;
}
ParamBuilder& ParamBuilder::doc(std::string text) {
  p().doc = std::move(text);
  return *this;
}
ParamBuilder& ParamBuilder::sets_port_count() {
  p().sets_port_count = true;
  return *this;
}

PortBuilder NodeDecl::add_input(std::string name, const ValueType& type) {
  inputs_.push_back(PortDecl{std::move(name), &type, {}, false});
  return PortBuilder(inputs_, inputs_.size() - 1);
}

PortBuilder NodeDecl::add_output(std::string name, const ValueType& type) {
  outputs_.push_back(PortDecl{std::move(name), &type, {}, false});
  return PortBuilder(outputs_, outputs_.size() - 1);
}

ParamBuilder NodeDecl::add_param(std::string name, const ValueType& type) {
  ParamDecl p;
  p.name = std::move(name);
  p.type = &type;
  params_.push_back(std::move(p));
  return ParamBuilder(params_, params_.size() - 1);
}

ParamBuilder NodeDecl::param_enum(std::string name, std::vector<std::string> choices, std::string default_choice) {
  assert(!choices.empty() && "param_enum: give at least one choice");
  if (default_choice.empty() && !choices.empty()) default_choice = choices.front();
  ParamBuilder b = add_param(std::move(name), value_type<EnumValue>());
  params_.back().choices = std::move(choices);
  b.default_value(EnumValue{std::move(default_choice)});
  return b;
}

std::optional<std::size_t> NodeDecl::input_index(std::string_view name) const { return find_by_name(inputs_, name); }
std::optional<std::size_t> NodeDecl::output_index(std::string_view name) const { return find_by_name(outputs_, name); }
std::optional<std::size_t> NodeDecl::param_index(std::string_view name) const { return find_by_name(params_, name); }

std::vector<Value> NodeDecl::default_params() const {
  std::vector<Value> out;
  out.reserve(params_.size());
  for (const ParamDecl& p : params_) out.push_back(p.default_value);
  return out;
}

std::size_t NodeDecl::count_of(std::string_view name) const {
  const auto i = param_index(name);
  assert(i && params_[*i].sets_port_count && "count_of: declare the parameter first, with .sets_port_count()");
  if (auto it = counts_.find(name); it != counts_.end()) return it->second;
  return port_count_of(params_[*i].default_value);
}

Status NodeDecl::validate() const {
  const std::string who = "node type '" + type_name_ + "': ";
  if (type_name_.empty()) return Status::error("node type without a name");
  if (version_ < 1) return Status::error(who + "version must be 1 or more");
  auto check_names = [&](const auto& items, const char* what) -> Status {
    std::set<std::string_view> seen;
    for (const auto& item : items) {
      if (!is_identifier(item.name))
        return Status::error(who + what + " '" + item.name + "' is not an identifier ([a-z][a-z0-9_]*)");
      if (!seen.insert(item.name).second) return Status::error(who + "two " + what + "s named '" + item.name + "'");
    }
    return Status::ok();
  };
  if (Status s = check_names(inputs_, "input"); !s) return s;
  if (Status s = check_names(outputs_, "output"); !s) return s;
  if (Status s = check_names(params_, "parameter"); !s) return s;
  for (const PortDecl& o : outputs_)
    if (o.optional) return Status::error(who + "output '" + o.name + "' cannot be optional");
  for (const ParamDecl& p : params_) {
    if (!p.type->has_json())
      return Status::error(who + "parameter '" + p.name + "' has type " + p.type->name() +
                           ", which cannot be saved; make it an input");
    if (p.default_value.empty()) return Status::error(who + "parameter '" + p.name + "' has no default value");
    if ((p.min || p.max) && !is_number_type(p.type))
      return Status::error(who + "parameter '" + p.name + "' has a range but is not a number");
    if (Status s = p.check(p.default_value); !s) return Status::error(who + "default: " + s.message());
    if (p.sets_port_count && !(p.type == &value_type<std::vector<std::string>>() ||
                               (p.type == &value_type<std::int64_t>() && p.min && *p.min >= 0 && p.max &&
                                *p.max <= static_cast<double>(kMaxPortCount))))
      return Status::error(who + "parameter '" + p.name + "' sets a port count: make it a list<string>, or an int "
                                 "with a range within 0.." + std::to_string(kMaxPortCount));
  }
  return Status::ok();
}

std::string NodeDecl::markdown() const {
  std::ostringstream md;
  md << "### " << type_name_ << " (v" << version_ << ")\n\n";
  if (!doc_.empty()) md << doc_ << "\n\n";
  if (detail_level_ > 0)
    md << "Shown from level of detail " << detail_level_ << " on: below it (`--lod`, the graph input `lod`) its "
       << inputs_.front().name << " passes through unchanged.\n\n";
  auto ports = [&](const char* title, const std::vector<PortDecl>& list) {
    if (list.empty()) return;
    md << "**" << title << "**\n\n";
    for (const PortDecl& p : list) {
      md << "- `" << p.name << "` (" << p.type->name() << (p.optional ? ", optional" : "") << ")";
      if (!p.doc.empty()) md << ": " << p.doc;
      md << "\n";
    }
    md << "\n";
  };
  ports("Inputs", inputs_);
  if (!params_.empty()) {
    md << "**Parameters**\n\n| name | type | default | range | unit | description |\n|---|---|---|---|---|---|\n";
    for (const ParamDecl& p : params_) {
      nlohmann::json d;
      p.type->to_json(p.default_value.raw(), d);
      std::string range;
      if (p.min || p.max)
        range = (p.min ? format_number(*p.min) : "") + " .. " + (p.max ? format_number(*p.max) : "");
      for (const std::string& c : p.choices) range += (range.empty() ? "" : ", ") + c;
      md << "| `" << p.name << "` | " << p.type->name() << " | `" << d.dump() << "` | " << range << " | " << p.unit
         << " | " << p.doc << (p.sets_port_count ? " (sets the number of ports)" : "") << " |\n";
    }
    md << "\n";
  }
  ports("Outputs", outputs_);
  return md.str();
}

void hash_file_stamp(const std::filesystem::path& file, FileVersionMemo* versions, Hasher& h) {
  const FileVersion v = file_version(file, versions);
  h.u64(v.size).i64(v.time).u64(v.content);
}

}  // namespace procex
