#include "app/studio/editor/mouse_queue.h"

#include <gtest/gtest.h>

namespace procex::studio {
namespace {

MouseButtonEvent press(std::uint32_t ms, float x = 100, float y = 50) { return {0, true, ms, x, y}; }
MouseButtonEvent release(std::uint32_t ms, float x = 100, float y = 50) { return {0, false, ms, x, y}; }

// A double click that reached the studio during one slow frame: all four
// changes at once. Each is shown in a frame of its own, and the second press
// is a double click by its own time, not the frames'.
TEST(MouseQueue, ADoubleClickArrivingInOneFrameIsShownChangeByChange) {
  MouseQueue q;
  q.push(press(1000));
  q.push(release(1040));
  q.push(press(1140));
  q.push(release(1180));
  const MouseQueue::Frame a = q.next(), b = q.next(), c = q.next(), d = q.next();
  EXPECT_TRUE(a.down[0]);
  EXPECT_EQ(a.clicks[0], 1);
  EXPECT_FALSE(b.down[0]);
  EXPECT_EQ(b.clicks[0], 0);
  EXPECT_TRUE(c.down[0]);
  EXPECT_EQ(c.clicks[0], 2);
  EXPECT_FALSE(d.down[0]);
  EXPECT_FALSE(q.pending());
  const MouseQueue::Frame idle = q.next();
  EXPECT_FALSE(idle.at);
  EXPECT_FALSE(idle.down[0]);
}

// However far apart the frames that show them, two quick presses are a double click.
TEST(MouseQueue, CountsClicksByEventTimeWhateverTheFrames) {
  MouseQueue q;
  q.push(press(5000));
  (void)q.next();
  q.push(release(5050));
  (void)q.next();
  q.push(press(5200));  // shown a second later, say: the time is the event's
  EXPECT_EQ(q.next().clicks[0], 2);
  q.push(release(5250));
  q.push(press(5400));  // a third quick one counts on
  (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 3);
}

TEST(MouseQueue, ASlowOrDistantSecondPressIsASingleClick) {
  MouseQueue q;
  q.push(press(0));
  q.push(release(40));
  q.push(press(340));  // 0.34 s later
  q.push(release(380));
  q.push(press(420, 110, 50));  // 10 px away
  for (int i = 0; i < 2; ++i) (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 1);
  (void)q.next();
  const MouseQueue::Frame f = q.next();
  EXPECT_EQ(f.clicks[0], 1);
  ASSERT_TRUE(f.at);
  EXPECT_EQ((*f.at)[0], 110);
}

// The X server's millisecond clock wraps after 49 days: a double click across it is one.
TEST(MouseQueue, CountsAcrossTheServerClocksWrap) {
  MouseQueue q;
  q.push(press(0xFFFFFFF0u));
  q.push(release(0xFFFFFFFAu));
  q.push(press(60));
  for (int i = 0; i < 2; ++i) (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 2);
}

// Buttons are counted apart: a right press between two left ones does not break the double click.
TEST(MouseQueue, ButtonsAreCountedApart) {
  MouseQueue q;
  q.push(press(0));
  q.push(release(20));
  q.push({1, true, 60, 100, 50});
  q.push({1, false, 80, 100, 50});
  q.push(press(120));
  for (int i = 0; i < 2; ++i) (void)q.next();
  const MouseQueue::Frame right = q.next();
  EXPECT_TRUE(right.down[1]);
  EXPECT_EQ(right.clicks[1], 1);
  (void)q.next();
  EXPECT_EQ(q.next().clicks[0], 2);
}

}  // namespace
}  // namespace procex::studio
