#include "nodes/support/profile_rules.h"

#include <gtest/gtest.h>

#include "nodes/support/profile_presets.h"

namespace procex {
namespace {

std::vector<Profile> presets() {
  std::vector<Profile> out;
  for (const std::string& name : preset_names()) out.push_back(make_preset(name, {}));
  return out;
}

TEST(ProfilePresets, AllAreValidProfiles) {
  for (const Profile& p : presets()) {
    SCOPED_TRACE(p.name);
    EXPECT_NO_THROW(check_profile(p));
  }
  EXPECT_EQ(make_preset("mansard", {}).segments(), 2u);
  EXPECT_EQ(make_preset("overhanging_eave", {}).tags, (std::vector<std::string>{"wall", "soffit", "roof"}));
  EXPECT_NEAR(make_preset("hip", {}).angle_deg(0), 45, 1e-9);
  EXPECT_THROW(make_preset("mansard", {.height = 40}), std::invalid_argument);
}

TEST(ProfileRules, ParsesNamesIndicesAndWeights) {
  const auto rules = parse_profile_rules("street = gable_end; back long = hip:0.7, 3:0.3\n* = 0", presets());
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0].labels, std::vector<std::string>{"street"});
  EXPECT_EQ(rules[0].choices[0].profile, 2u);
  EXPECT_EQ(rules[1].labels, (std::vector<std::string>{"back", "long"}));
  EXPECT_EQ(rules[1].choices[1].profile, 3u);
  EXPECT_DOUBLE_EQ(rules[1].choices[0].weight, 0.7);
}

TEST(ProfileRules, ErrorsNameTheRule) {
  auto message = [](const char* text) {
    try {
      parse_profile_rules(text, presets());
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("* = hip; streat = hip"),
            "rule 2 ('streat = hip'): unknown label 'streat' (use short, medium, long, street, side, back, outer, "
            "inner, selected, party, #<edge id>, normal:<from>-<to> or *)");
  EXPECT_EQ(message("* = pagoda"), "rule 1 ('* = pagoda'): no profile named 'pagoda' among the 9 profiles given");
  EXPECT_EQ(message("* = 9"), "rule 1 ('* = 9'): no profile named '9' among the 9 profiles given");
  EXPECT_EQ(message("* hip"), "rule 1 ('* hip') has no '=' between labels and profiles");
  EXPECT_EQ(message("* = hip:-1"), "rule 1 ('* = hip:-1'): weight of 'hip' is not a number >= 0");
  EXPECT_EQ(message("* = hip:0"), "rule 1 ('* = hip:0'): the weights add up to zero");
}

TEST(ProfileRules, LabelsMatch) {
  EdgeLabels e;
  e.id = 7, e.length_class = LengthClass::Long, e.orientation = Orientation::Back, e.normal_deg = 350;
  EXPECT_TRUE(label_matches("long", e, false));
  EXPECT_TRUE(label_matches("back", e, false));
  EXPECT_FALSE(label_matches("street", e, false));
  EXPECT_TRUE(label_matches("#7", e, false));
  EXPECT_FALSE(label_matches("#8", e, false));
  EXPECT_TRUE(label_matches("normal:300-20", e, false));  // wraps past 360
  EXPECT_FALSE(label_matches("normal:0-180", e, false));
  EXPECT_TRUE(label_matches("selected", e, true));
  EXPECT_TRUE(label_matches("outer", e, false));
  EXPECT_FALSE(label_matches("party", e, false));
  e.party = true;
  EXPECT_TRUE(label_matches("party", e, false));
}

TEST(ProfileRules, PickFollowsWeights) {
  const std::vector<ProfileChoice> c = {{4, 0.25}, {1, 0}, {2, 0.75}};
  EXPECT_EQ(pick_profile(c, 0.0), 4u);
  EXPECT_EQ(pick_profile(c, 0.2499), 4u);
  EXPECT_EQ(pick_profile(c, 0.25), 2u);
  EXPECT_EQ(pick_profile(c, 0.999999), 2u);
}

}  // namespace
}  // namespace procex
