// The experiment's progress line: what it says, and that it draws only where asked.
#include "tools/experiment/progress_line.h"

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

namespace hexplore::experiment {
namespace {

using station_service::StationProgress;

TEST(ProgressLine, SaysWhereTheMissionIsAndTheMostItCanStillTake) {
  StationProgress p;
  p.started = true;
  p.mission_time_s = 600.0;
  p.team_completeness = 0.769;
  p.live_robots = 4;
  // 600 s of sim time in 300 s of wall: 2x real time, so the 3,900 s to the limit take 32:30.
  EXPECT_EQ(ProgressLine::text("run 1/5 seed 3", p, 4500.0, 300.0),
            "[experiment] run 1/5 seed 3: t=600 of 4500 s, completeness 76.9%, 4 live, 2.00x real time, 5:00 wall, "
            "at most 32:30 left");
  p.mission_time_s = 100.0;  // slower than real time, and past an hour of wall
  EXPECT_EQ(ProgressLine::text("run 2/2 seed 1", p, 4500.0, 4000.0),
            "[experiment] run 2/2 seed 1: t=100 of 4500 s, completeness 76.9%, 4 live, 0.03x real time, 1:06:40 wall, "
            "at most 48:53:20 left");
}

TEST(ProgressLine, BeforeTheStartItSaysSo) {
  EXPECT_EQ(ProgressLine::text("run 1/1 seed 1", StationProgress{}, 600.0, 2.4),
            "[experiment] run 1/1 seed 1: starting (0:02 wall)");
}

TEST(ProgressLine, RedrawsInPlaceAtMostOnceASecondAndEndsTheLine) {
  char* buffer = nullptr;
  size_t size = 0;
  FILE* out = open_memstream(&buffer, &size);
  ASSERT_NE(out, nullptr);
  {
    ProgressLine line(out, "run 1/1 seed 1", 600.0);
    StationProgress p;
    line.update(p);
    line.update(p);  // within the second: not drawn again
  }
  std::fclose(out);
  const std::string written(buffer, size);
  std::free(buffer);
  EXPECT_EQ(written, "\r[experiment] run 1/1 seed 1: starting (0:00 wall)\033[K\n");
}

TEST(ProgressLine, AMemoryStreamIsNoTerminal) {
  char* buffer = nullptr;
  size_t size = 0;
  FILE* out = open_memstream(&buffer, &size);
  ASSERT_NE(out, nullptr);
  EXPECT_FALSE(is_terminal(out));
  std::fclose(out);
  std::free(buffer);
}

}  // namespace
}  // namespace hexplore::experiment
