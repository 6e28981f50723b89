#include "nodes/support/profile_rules.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace procex {
namespace {

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::vector<std::string_view> split(std::string_view s, std::string_view separators) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i)
    if (i == s.size() || separators.find(s[i]) != std::string_view::npos) {
      out.push_back(trim(s.substr(start, i - start)));
      start = i + 1;
    }
  return out;
}

bool parse_number(std::string_view s, double& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

bool parse_index(std::string_view s, std::size_t& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// "normal:a-b" -> (a, b); false if malformed.
bool parse_normal_range(std::string_view label, double& from, double& to) {
  if (label.substr(0, 7) != "normal:") return false;
  const std::string_view range = label.substr(7);
  const auto dash = range.find('-', 1);
  return dash != std::string_view::npos && parse_number(range.substr(0, dash), from) &&
         parse_number(range.substr(dash + 1), to);
}

bool known_label(std::string_view l) {
  static const std::string_view kWords[] = {"*", "short", "medium", "long", "street", "side",
                                            "back", "outer", "inner", "selected", "party"};
  for (std::string_view w : kWords)
    if (l == w) return true;
  double a, b;
  std::size_t id;
  return (l.size() > 1 && l[0] == '#' && parse_index(l.substr(1), id)) || parse_normal_range(l, a, b);
}

}  // namespace

std::vector<ProfileRule> parse_profile_rules(std::string_view text, const std::vector<Profile>& profiles) {
  std::vector<ProfileRule> rules;
  std::size_t number = 0;
  for (std::string_view part : split(text, ";\n")) {
    if (part.empty()) continue;
    ++number;
    const std::string where = "rule " + std::to_string(number) + " ('" + std::string(part) + "')";
    const auto eq = part.find('=');
    if (eq == std::string_view::npos) throw std::invalid_argument(where + " has no '=' between labels and profiles");
    ProfileRule rule;
    for (std::string_view l : split(trim(part.substr(0, eq)), " \t&")) {
      if (l.empty()) continue;
      if (!known_label(l))
        throw std::invalid_argument(where + ": unknown label '" + std::string(l) +
                                    "' (use short, medium, long, street, side, back, outer, inner, selected, party, "
                                    "#<edge id>, normal:<from>-<to> or *)");
      rule.labels.emplace_back(l);
    }
    if (rule.labels.empty()) throw std::invalid_argument(where + " has no labels (use * for every edge)");
    for (std::string_view c : split(part.substr(eq + 1), ",")) {
      const auto colon = c.find(':');
      const std::string_view name = trim(c.substr(0, colon));
      ProfileChoice choice;
      if (colon != std::string_view::npos && (!parse_number(trim(c.substr(colon + 1)), choice.weight) || choice.weight < 0))
        throw std::invalid_argument(where + ": weight of '" + std::string(name) + "' is not a number >= 0");
      bool found = false;
      for (std::size_t i = 0; i < profiles.size() && !found; ++i)
        if (profiles[i].name == name) choice.profile = i, found = true;
      if (!found && parse_index(name, choice.profile)) found = choice.profile < profiles.size();
      if (!found)
        throw std::invalid_argument(where + ": no profile named '" + std::string(name) + "' among the " +
                                    std::to_string(profiles.size()) + " profiles given");
      rule.choices.push_back(choice);
    }
    double total = 0;
    for (const ProfileChoice& c : rule.choices) total += c.weight;
    if (total <= 0) throw std::invalid_argument(where + ": the weights add up to zero");
    rules.push_back(std::move(rule));
  }
  return rules;
}

bool label_matches(std::string_view l, const EdgeLabels& e, bool selected) {
  if (l == "*") return true;
  if (l == "short") return e.length_class == LengthClass::Short;
  if (l == "medium") return e.length_class == LengthClass::Medium;
  if (l == "long") return e.length_class == LengthClass::Long;
  if (l == "street") return e.orientation == Orientation::Street;
  if (l == "side") return e.orientation == Orientation::Side;
  if (l == "back") return e.orientation == Orientation::Back;
  if (l == "outer") return !e.inner;
  if (l == "inner") return e.inner;
  if (l == "selected") return selected;
  if (l == "party") return e.party;
  std::size_t id;
  if (l[0] == '#' && parse_index(l.substr(1), id)) return e.id >= 0 && static_cast<std::size_t>(e.id) == id;
  double from, to;
  if (parse_normal_range(l, from, to)) {
    from = std::fmod(std::fmod(from, 360.0) + 360.0, 360.0);
    to = std::fmod(std::fmod(to, 360.0) + 360.0, 360.0);
    return from <= to ? e.normal_deg >= from && e.normal_deg < to : e.normal_deg >= from || e.normal_deg < to;
  }
  return false;
}

std::size_t pick_profile(const std::vector<ProfileChoice>& choices, double u) {
  double total = 0;
  for (const ProfileChoice& c : choices) total += c.weight;
  double x = u * total;
  std::size_t last = choices.front().profile;  // rounding can leave x just past the end
  for (const ProfileChoice& c : choices) {
    if (c.weight <= 0) continue;
    if (x < c.weight) return c.profile;
    x -= c.weight;
    last = c.profile;
  }
  return last;
}

}  // namespace procex
