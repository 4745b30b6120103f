// Progress lines of long cavity-modes work (modes/fe/progress.hpp): a tick prints only after the interval, a
// counted step carries the time left at the measured rate, and ticks go to the innermost installed Progress.
#include "progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

using rc::modes::Progress;

namespace {

void wait(double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); }

}  // namespace

TEST(Progress, TicksPrintOnlyAfterTheIntervalAndCarryTheTimeLeft) {
  std::vector<std::string> lines;
  Progress p([&](const std::string& l) { lines.push_back(l); }, 0.2);
  rc::modes::progress_tick();
  EXPECT_TRUE(lines.empty());  // nothing before the interval
  p.step("cluster 1/4", 1, 4);  // the first item: its rate is measured from the start
  EXPECT_TRUE(lines.empty());  // a step prints only after a second
  wait(0.25);
  rc::modes::progress_tick();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("cluster 1/4 (working)"), std::string::npos) << lines[0];
  rc::modes::progress_tick();
  EXPECT_EQ(lines.size(), 1u);  // the interval starts again
  wait(1.0);
  // Two items done in the elapsed time t (1.25 s, more on a loaded machine) since the count began: two left take t.
  p.step("cluster 2/4", 2, 4);
  const long expected = std::lround(p.elapsed());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[1].find("cluster 2/4, about " + std::to_string(expected) + " s left"), std::string::npos)
      << lines[1];
}

TEST(Progress, TicksGoToTheInnermostProgressAndNowhereWithoutOne) {
  std::vector<std::string> outer_lines, inner_lines;
  {
    Progress outer([&](const std::string& l) { outer_lines.push_back(l); }, 0.0);
    {
      Progress inner([&](const std::string& l) { inner_lines.push_back(l); }, 0.0);
      rc::modes::progress_tick();
    }
    rc::modes::progress_tick();
  }
  rc::modes::progress_tick();  // none installed: nothing, no crash
  EXPECT_EQ(inner_lines.size(), 1u);
  EXPECT_EQ(outer_lines.size(), 1u);
}

// A run of several counts (a response fit's first samples, then its refinement rounds) keeps one clock: the
// timestamps never go back between rounds, a round's time left says it is the round's, and a round's outcome
// (note) is printed even right after another line.
TEST(Progress, RoundsShareOneClockAndSayWhatTheTimeLeftIsOf) {
  std::vector<std::string> lines;
  Progress p([&](const std::string& l) { lines.push_back(l); }, 5.0);
  wait(1.05);
  p.step("first samples: 1/3 frequencies", 1, 3, " for the first samples");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("left for the first samples"), std::string::npos) << lines[0];
  p.note("refinement 1 (error): 6 samples");  // immediately after a line: printed all the same
  ASSERT_EQ(lines.size(), 2u);
  wait(1.05);
  p.step("refinement 2: 1/4 frequencies", 1, 4, " in this round");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[2].find("left in this round"), std::string::npos) << lines[2];
  double last = -1;
  for (const std::string& l : lines) {  // "[    1.1 s] ..."
    const double t = std::stod(l.substr(1));
    EXPECT_GE(t, last) << l;
    last = t;
  }
  EXPECT_GT(last, 2.0);  // the second round's line is on the run's clock, not a new one from 0
}
