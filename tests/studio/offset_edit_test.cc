// Profile Offset handles in the profile editor, without a window: where a
// handle sits on a profile, what a drag to a point sets (within the node's
// ranges), which Profile Offsets a profile feeds, and a drag as one undo step.
#include "app/studio/editor/offset_edit.h"

#include <gtest/gtest.h>

#include "app/studio/editor/document.h"
#include "app/studio/editor/downstream.h"

namespace procex::studio {
namespace {

// A wall to 6 m, a ledge stepping in 1 m, a wall to 9 m, a roof.
const std::vector<Vec2> kProfile = {{0, 0}, {0, 6}, {-1, 6}, {-1, 9}, {-4, 12}};

TEST(OffsetEdit, TheProfilesOffsetAtAHeight) {
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, 3), 0.0);
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, 6), 0.0) << "a ledge: its lower end";
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, 7.5), -1.0);
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, 10.5), -2.5);
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, 20), -4.0) << "above the top: the top's offset";
  EXPECT_DOUBLE_EQ(profile_offset_at(kProfile, -1), 0.0);
  EXPECT_DOUBLE_EQ(profile_offset_at({}, 2), 0.0);
}

// Extrude #4 <- Profile Offset #3 <- Assign Profiles #2 <- Profile List <- Profile #1.
struct Chain {
  Document doc;
  NodeId profile = 0, list = 0, assign = 0, offset = 0, extrude = 0;
  Chain() {
    profile = *doc.add_node("Profile", 0, 0);
    list = *doc.add_node("Profile List", 200, 0);
    assign = *doc.add_node("Assign Profiles", 400, 0);
    offset = *doc.add_node("Profile Offset", 600, 0);
    extrude = *doc.add_node("Extrude", 800, 0);
    EXPECT_TRUE(doc.connect({profile, 0}, {list, 0}));
    EXPECT_TRUE(doc.connect({list, 0}, {assign, 1}));
    EXPECT_TRUE(doc.connect({assign, 0}, {offset, 0}));
    EXPECT_TRUE(doc.connect({offset, 0}, {extrude, 0}));
  }
  double param(const char* name) const {
    const Node* n = doc.graph().node(offset);
    return n->params[*n->decl().param_index(name)].get<double>();
  }
};

TEST(OffsetEdit, AProfileFindsTheProfileOffsetsItFeeds) {
  Chain c;
  EXPECT_EQ(downstream_of_type(c.doc.graph(), c.profile, "Profile Offset"), std::vector<NodeId>{c.offset});
  EXPECT_EQ(downstream_of_type(c.doc.graph(), c.profile, "Extrude"), std::vector<NodeId>{c.extrude});
  EXPECT_TRUE(downstream_of_type(c.doc.graph(), c.extrude, "Profile Offset").empty()) << "only downstream";
}

TEST(OffsetEdit, AHandleStandsForDistanceAndHeight) {
  Chain c;
  const Node& node = *c.doc.graph().node(c.offset);
  const Vec2 at = offset_handle(kProfile, 0.5, 7.5);
  EXPECT_EQ(at, (Vec2{-0.5, 7.5}));
  const OffsetParams back = offset_params(kProfile, at, node);
  EXPECT_DOUBLE_EQ(back.distance, 0.5);
  EXPECT_DOUBLE_EQ(back.height, 7.5);
  // Dragged below the ground and far out: held at height 0 and the largest distance declared (10 m).
  const OffsetParams held = offset_params(kProfile, {40, -3}, node);
  EXPECT_DOUBLE_EQ(held.height, 0.0);
  EXPECT_DOUBLE_EQ(held.distance, 10.0);
}

TEST(OffsetEdit, ADragIsOneUndoStep) {
  Chain c;
  const Node& node = *c.doc.graph().node(c.offset);
  const std::size_t distance = *node.decl().param_index("distance"), height = *node.decl().param_index("height");
  const double d0 = c.param("distance"), h0 = c.param("height");
  c.doc.begin_gesture("move profile offset");
  for (const Vec2 to : {Vec2{0.3, 4}, Vec2{0.9, 5}, Vec2{1.2, 5.5}}) {
    const OffsetParams p = offset_params(kProfile, to, *c.doc.graph().node(c.offset));
    ASSERT_TRUE(c.doc.set_param(c.offset, distance, Value::make(p.distance)));
    ASSERT_TRUE(c.doc.set_param(c.offset, height, Value::make(p.height)));
  }
  c.doc.end_gesture();
  EXPECT_DOUBLE_EQ(c.param("distance"), 1.2);
  EXPECT_DOUBLE_EQ(c.param("height"), 5.5);
  EXPECT_TRUE(c.doc.undo());
  EXPECT_DOUBLE_EQ(c.param("distance"), d0);
  EXPECT_DOUBLE_EQ(c.param("height"), h0);
}

}  // namespace
}  // namespace procex::studio
