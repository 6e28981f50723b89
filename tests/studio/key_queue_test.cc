#include "app/studio/editor/key_queue.h"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

namespace procex::studio {
namespace {

// Tab, then "ab" typed, all during one slow frame: Tab is seen down, then
// up, and each letter comes in the frame that shows its key pressed, so the
// field Tab opened has the keyboard before the first letter arrives.
TEST(KeyQueue, KeysArrivingInOneFrameAreShownChangeByChangeWithTheirCharacters) {
  KeyQueue q;
  q.key(GLFW_KEY_TAB, true);
  q.key(GLFW_KEY_TAB, false);
  q.key(GLFW_KEY_A, true);
  q.character('a');
  q.key(GLFW_KEY_A, false);
  q.key(GLFW_KEY_B, true);
  q.character('b');
  q.key(GLFW_KEY_B, false);
  const KeyQueue::Frame tab = q.next(), tab_up = q.next(), a = q.next(), a_up = q.next(), b = q.next(), b_up = q.next();
  EXPECT_TRUE(tab.down[GLFW_KEY_TAB]);
  EXPECT_TRUE(tab.characters.empty());
  EXPECT_FALSE(tab_up.down[GLFW_KEY_TAB]);
  EXPECT_TRUE(a.down[GLFW_KEY_A]);
  EXPECT_EQ(a.characters, std::vector<std::uint32_t>{'a'});
  EXPECT_FALSE(a_up.down[GLFW_KEY_A]);
  EXPECT_TRUE(a_up.characters.empty());
  EXPECT_TRUE(b.down[GLFW_KEY_B]);
  EXPECT_EQ(b.characters, std::vector<std::uint32_t>{'b'});
  EXPECT_FALSE(b_up.down[GLFW_KEY_B]);
  EXPECT_FALSE(q.pending());
  EXPECT_FALSE(q.next().down.any());
}

// A chord: Ctrl stays down while Z goes down and up, in that order.
TEST(KeyQueue, AModifierHeldAroundAQuickPressIsDownWhenTheKeyIs) {
  KeyQueue q;
  for (auto [key, down] : {std::pair{GLFW_KEY_LEFT_CONTROL, true}, {GLFW_KEY_Z, true}, {GLFW_KEY_Z, false}, {GLFW_KEY_LEFT_CONTROL, false}})
    q.key(key, down);
  const KeyQueue::Frame ctrl = q.next(), z = q.next(), z_up = q.next(), up = q.next();
  EXPECT_TRUE(ctrl.down[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(ctrl.down[GLFW_KEY_Z]);
  EXPECT_TRUE(z.down[GLFW_KEY_LEFT_CONTROL] && z.down[GLFW_KEY_Z]);
  EXPECT_TRUE(z_up.down[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(z_up.down[GLFW_KEY_Z]);
  EXPECT_FALSE(up.down.any());
}

// Characters with no key change before them (a held key repeating, an input
// method) come together in the next frame; unknown keys are no change.
TEST(KeyQueue, CharactersWithoutAKeyChangeComeTogether) {
  KeyQueue q;
  q.character('x');
  q.character('y');
  q.key(GLFW_KEY_UNKNOWN, true);
  const KeyQueue::Frame f = q.next();
  EXPECT_EQ(f.characters, (std::vector<std::uint32_t>{'x', 'y'}));
  EXPECT_FALSE(q.pending());
}

}  // namespace
}  // namespace procex::studio
