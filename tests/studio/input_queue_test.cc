#include "app/studio/editor/input_queue.h"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

namespace procex::studio {
namespace {

MouseButtonEvent press(std::uint32_t ms, float x = 100, float y = 50) { return {0, true, ms, x, y}; }
MouseButtonEvent release(std::uint32_t ms, float x = 100, float y = 50) { return {0, false, ms, x, y}; }

// A click on a node, then Delete, all during one slow frame: the press, the
// release, Delete down and Delete up each come in a frame of their own, in
// that order, so the node is selected before the key that deletes the
// selection is seen (two queues, one per device, showed the press and Delete
// down in the same frame).
TEST(InputQueue, AClickThenAKeyInOneFrameApplyInOrder) {
  InputQueue q;
  q.button(press(1000, 300, 200));
  q.button(release(1040, 300, 200));
  q.key(GLFW_KEY_DELETE, true);
  q.key(GLFW_KEY_DELETE, false);
  const InputQueue::Frame down = q.next(), up = q.next(), del = q.next(), del_up = q.next();
  EXPECT_TRUE(down.buttons[0]);
  EXPECT_EQ(down.clicks[0], 1);
  ASSERT_TRUE(down.at);
  EXPECT_EQ((*down.at)[0], 300);
  EXPECT_FALSE(down.keys[GLFW_KEY_DELETE]);
  EXPECT_FALSE(up.buttons[0]);
  EXPECT_FALSE(up.keys[GLFW_KEY_DELETE]);
  EXPECT_TRUE(del.keys[GLFW_KEY_DELETE]);
  EXPECT_FALSE(del.buttons[0]);
  EXPECT_FALSE(del.at);  // a key change: the cursor stays where the click left it
  EXPECT_FALSE(del_up.keys[GLFW_KEY_DELETE]);
  EXPECT_FALSE(q.pending());
}

// The other way round: Ctrl held, then a click (Ctrl+click adds to the
// selection), then Ctrl released: the click sees Ctrl down, and what was
// typed before the click stays with its key, never with the click.
TEST(InputQueue, AKeyThenAClickApplyInOrderWithTheirCharacters) {
  InputQueue q;
  q.key(GLFW_KEY_A, true);
  q.character('a');
  q.key(GLFW_KEY_A, false);
  q.key(GLFW_KEY_LEFT_CONTROL, true);
  q.button(press(10));
  q.button(release(30));
  q.key(GLFW_KEY_LEFT_CONTROL, false);
  const InputQueue::Frame a = q.next(), a_up = q.next(), ctrl = q.next(), click = q.next(), click_up = q.next(), ctrl_up = q.next();
  EXPECT_TRUE(a.keys[GLFW_KEY_A]);
  EXPECT_EQ(a.characters, std::vector<std::uint32_t>{'a'});
  EXPECT_TRUE(a_up.characters.empty());
  EXPECT_TRUE(ctrl.keys[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(ctrl.buttons[0]);
  EXPECT_TRUE(click.buttons[0]);
  EXPECT_TRUE(click.keys[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_TRUE(click.characters.empty());
  EXPECT_FALSE(click_up.buttons[0]);
  EXPECT_TRUE(click_up.keys[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(ctrl_up.keys.any());
  EXPECT_FALSE(q.pending());
}

// Tab, then "ab" typed, all during one slow frame: Tab is seen down, then
// up, and each letter comes in the frame that shows its key pressed, so the
// field Tab opened has the keyboard before the first letter arrives.
TEST(InputQueue, KeysArrivingInOneFrameAreShownChangeByChangeWithTheirCharacters) {
  InputQueue q;
  q.key(GLFW_KEY_TAB, true);
  q.key(GLFW_KEY_TAB, false);
  q.key(GLFW_KEY_A, true);
  q.character('a');
  q.key(GLFW_KEY_A, false);
  q.key(GLFW_KEY_B, true);
  q.character('b');
  q.key(GLFW_KEY_B, false);
  const InputQueue::Frame tab = q.next(), tab_up = q.next(), a = q.next(), a_up = q.next(), b = q.next(), b_up = q.next();
  EXPECT_TRUE(tab.keys[GLFW_KEY_TAB]);
  EXPECT_TRUE(tab.characters.empty());
  EXPECT_FALSE(tab_up.keys[GLFW_KEY_TAB]);
  EXPECT_TRUE(a.keys[GLFW_KEY_A]);
  EXPECT_EQ(a.characters, std::vector<std::uint32_t>{'a'});
  EXPECT_FALSE(a_up.keys[GLFW_KEY_A]);
  EXPECT_TRUE(a_up.characters.empty());
  EXPECT_TRUE(b.keys[GLFW_KEY_B]);
  EXPECT_EQ(b.characters, std::vector<std::uint32_t>{'b'});
  EXPECT_FALSE(b_up.keys[GLFW_KEY_B]);
  EXPECT_FALSE(q.pending());
  EXPECT_FALSE(q.next().keys.any());
}

// A chord: Ctrl stays down while Z goes down and up, in that order.
TEST(InputQueue, AModifierHeldAroundAQuickPressIsDownWhenTheKeyIs) {
  InputQueue q;
  for (auto [key, down] : {std::pair{GLFW_KEY_LEFT_CONTROL, true}, {GLFW_KEY_Z, true}, {GLFW_KEY_Z, false}, {GLFW_KEY_LEFT_CONTROL, false}})
    q.key(key, down);
  const InputQueue::Frame ctrl = q.next(), z = q.next(), z_up = q.next(), up = q.next();
  EXPECT_TRUE(ctrl.keys[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(ctrl.keys[GLFW_KEY_Z]);
  EXPECT_TRUE(z.keys[GLFW_KEY_LEFT_CONTROL] && z.keys[GLFW_KEY_Z]);
  EXPECT_TRUE(z_up.keys[GLFW_KEY_LEFT_CONTROL]);
  EXPECT_FALSE(z_up.keys[GLFW_KEY_Z]);
  EXPECT_FALSE(up.keys.any());
}

// Characters with no key change before them (a held key repeating, an input
// method) come together in the next frame; unknown keys and buttons are no change.
TEST(InputQueue, CharactersWithoutAKeyChangeComeTogether) {
  InputQueue q;
  q.character('x');
  q.character('y');
  q.key(GLFW_KEY_UNKNOWN, true);
  q.button({InputQueue::kButtons, true, 0, 0, 0});
  const InputQueue::Frame f = q.next();
  EXPECT_EQ(f.characters, (std::vector<std::uint32_t>{'x', 'y'}));
  EXPECT_FALSE(q.pending());
}

// A double click that reached the studio during one slow frame: all four
// changes at once. Each is shown in a frame of its own, and the second press
// is a double click by its own time, not the frames'.
TEST(InputQueue, ADoubleClickArrivingInOneFrameIsShownChangeByChange) {
  InputQueue q;
  q.button(press(1000));
  q.button(release(1040));
  q.button(press(1140));
  q.button(release(1180));
  const InputQueue::Frame a = q.next(), b = q.next(), c = q.next(), d = q.next();
  EXPECT_TRUE(a.buttons[0]);
  EXPECT_EQ(a.clicks[0], 1);
  EXPECT_FALSE(b.buttons[0]);
  EXPECT_EQ(b.clicks[0], 0);
  EXPECT_TRUE(c.buttons[0]);
  EXPECT_EQ(c.clicks[0], 2);
  EXPECT_FALSE(d.buttons[0]);
  EXPECT_FALSE(q.pending());
  const InputQueue::Frame idle = q.next();
  EXPECT_FALSE(idle.at);
  EXPECT_FALSE(idle.buttons[0]);
}

// However far apart the frames that show them, two quick presses are a double
// click, and a key change between them does not break it.
TEST(InputQueue, CountsClicksByEventTimeWhateverTheFrames) {
  InputQueue q;
  q.button(press(5000));
  (void)q.next();
  q.button(release(5050));
  (void)q.next();
  q.key(GLFW_KEY_LEFT_SHIFT, true);
  (void)q.next();
  q.button(press(5200));  // shown a second later, say: the time is the event's
  EXPECT_EQ(q.next().clicks[0], 2);
  q.button(release(5250));
  q.button(press(5400));  // a third quick one counts on
  (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 3);
}

TEST(InputQueue, ASlowOrDistantSecondPressIsASingleClick) {
  InputQueue q;
  q.button(press(0));
  q.button(release(40));
  q.button(press(340));  // 0.34 s later
  q.button(release(380));
  q.button(press(420, 110, 50));  // 10 px away
  for (int i = 0; i < 2; ++i) (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 1);
  (void)q.next();
  const InputQueue::Frame f = q.next();
  EXPECT_EQ(f.clicks[0], 1);
  ASSERT_TRUE(f.at);
  EXPECT_EQ((*f.at)[0], 110);
}

// The X server's millisecond clock wraps after 49 days: a double click across it is one.
TEST(InputQueue, CountsAcrossTheServerClocksWrap) {
  InputQueue q;
  q.button(press(0xFFFFFFF0u));
  q.button(release(0xFFFFFFFAu));
  q.button(press(60));
  for (int i = 0; i < 2; ++i) (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 2);
}

// Buttons are counted apart: a right press between two left ones does not break the double click.
TEST(InputQueue, ButtonsAreCountedApart) {
  InputQueue q;
  q.button(press(0));
  q.button(release(20));
  q.button({1, true, 60, 100, 50});
  q.button({1, false, 80, 100, 50});
  q.button(press(120));
  for (int i = 0; i < 2; ++i) (void)q.next();
  const InputQueue::Frame right = q.next();
  EXPECT_TRUE(right.buttons[1]);
  EXPECT_EQ(right.clicks[1], 1);
  (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 2);
}

}  // namespace
}  // namespace procex::studio
