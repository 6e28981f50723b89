#include "core/placement/split.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/geom/tolerances.h"
#include "core/placement/placement_error.h"
#include "core/placement/repeat.h"

namespace procex {

namespace {

[[noreturn]] void refuse(std::string_view text, std::size_t at, const std::string& what) {
  throw PlacementError("split '" + std::string(text) + "', character " + std::to_string(at + 1) + ": " + what);
}

double nominal(const std::vector<SplitItem>& items) {
  double sum = 0;
  for (const SplitItem& i : items) sum += i.size;
  return sum;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// ": sizes may also be named floor_height, bay_width", for a refusal.
std::string known_names(const SplitNames& names) {
  std::string out;
  for (const auto& [name, value] : names) out += (out.empty() ? ": sizes may also be named " : ", ") + name;
  return out;
}

bool any_flexible(const std::vector<SplitItem>& items) {
  for (const SplitItem& i : items)
    if (i.flexible) return true;
  return false;
}

}  // namespace

SplitSpec parse_split(std::string_view text, const SplitNames& names) {
  SplitSpec spec;
  std::vector<SplitItem>* into = &spec.before;
  std::size_t i = 0, group_at = 0;
  bool in_group = false;
  auto skip = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  };
  for (skip(); i < text.size(); skip()) {
    const char c = text[i];
    if (c == '{') {
      if (in_group) refuse(text, i, "groups do not nest");
      if (spec.has_repeat) refuse(text, i, "only one repeated group is allowed");
      in_group = spec.has_repeat = true;
      group_at = i++;
      into = &spec.repeated;
      continue;
    }
    if (c == '}') {
      if (!in_group) refuse(text, i, "'}' without '{'");
      if (spec.repeated.empty()) refuse(text, i, "the repeated group is empty");
      ++i;
      if (i >= text.size() || text[i] != '*') refuse(text, i, "'*' expected after the group ('{...}*' or '{...}*3')");
      ++i;
      if (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
        const auto [p, ec] = std::from_chars(text.data() + i, text.data() + text.size(), spec.count);
        if (ec != std::errc() || spec.count > static_cast<int>(kMaxRepeatItems)) refuse(text, i, "the count is too large");
        i = static_cast<std::size_t>(p - text.data());
      }
      in_group = false;
      into = &spec.after;
      continue;
    }
    SplitItem item;
    const std::size_t at = i;
    if (text[i] == '_') item.gap = true, ++i;
    if (i < text.size() && text[i] == '~') item.flexible = true, ++i;
    if (!names.empty() && i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) {  // '_' before it marks a gap
      std::size_t end = i;
      while (end < text.size() && is_name_char(text[end])) ++end;
      const std::string_view name = text.substr(i, end - i);
      const auto known = names.find(name);
      if (known == names.end()) refuse(text, i, "no size is named '" + std::string(name) + "'" + known_names(names));
      item.size = known->second;
      i = end;
    } else {
      const auto [p, ec] = std::from_chars(text.data() + i, text.data() + text.size(), item.size);
      if (ec != std::errc() || p == text.data() + i)
        refuse(text, i, i < text.size() ? "a size in metres expected, not '" + std::string(1, text[i]) + "'" + known_names(names)
                                        : "a size expected");
      i = static_cast<std::size_t>(p - text.data());
    }
    if (!std::isfinite(item.size) || item.size < 0) refuse(text, at, "sizes are finite and not negative");
    into->push_back(item);
  }
  if (in_group) refuse(text, group_at, "the group is not closed with '}*'");
  if (spec.has_repeat && spec.count < 0 && !(nominal(spec.repeated) > 0))
    refuse(text, group_at, "a group repeated as often as it fits needs a size above zero");
  return spec;
}

std::vector<SplitCell> split_length(const SplitSpec& spec, double length) {
  std::vector<SplitItem> items = spec.before;
  if (spec.has_repeat) {
    std::size_t n = spec.count >= 0 ? static_cast<std::size_t>(spec.count) : 0;
    if (spec.count < 0) {
      const double room = (length - nominal(spec.before) - nominal(spec.after)) / nominal(spec.repeated);
      const double q = room + kRepeatCountRelative * std::max(1.0, std::abs(room));
      if (room > 0) n = static_cast<std::size_t>(any_flexible(spec.repeated) ? std::max(1.0, std::round(room)) : std::floor(q));
    }
    if (n * spec.repeated.size() > kMaxRepeatItems)
      throw PlacementError("split: more than " + std::to_string(kMaxRepeatItems) + " cells over " + std::to_string(length) + " m");
    for (std::size_t k = 0; k < n; ++k) items.insert(items.end(), spec.repeated.begin(), spec.repeated.end());
  }
  items.insert(items.end(), spec.after.begin(), spec.after.end());
  double fixed = 0, flexible = 0;
  for (const SplitItem& i : items) (i.flexible ? flexible : fixed) += i.size;
  const double stretch = flexible > 0 ? std::max(0.0, (length - fixed) / flexible) : 1.0;
  std::vector<SplitCell> out;
  double at = 0;
  int index = 0;
  for (const SplitItem& i : items) {
    const double size = i.flexible ? i.size * stretch : i.size;
    if (size > 0) out.push_back({at, size, i.gap ? -1 : index++});
    at += size;
  }
  return out;
}

}  // namespace procex
