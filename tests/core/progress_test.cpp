// The progress bar: what its line says, and that it stays silent when told to.
#include "core/progress.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <sstream>

namespace convray::render {
namespace {

TEST(Progress, LineShowsBarPercentElapsedAndEta) {
  // 47 of 100 in 12 s: 14 of 30 cells; the remaining 53 at the same rate take 13.5 s.
  EXPECT_EQ(format_progress("render", 47, 100, 12.0),
            "render [##############----------------]  47%  elapsed 0:12  ETA 0:14");
  EXPECT_EQ(format_progress("render", 0, 100, 0.2),
            "render [------------------------------]   0%  elapsed 0:00  ETA --:--");
  EXPECT_EQ(format_progress("render", 100, 100, 3725.0, 10),
            "render [##########] 100%  elapsed 1:02:05");
}

TEST(Progress, DurationsReadAsClockTimes) {
  EXPECT_EQ(format_duration(0.4), "0:00");
  EXPECT_EQ(format_duration(59.6), "1:00");
  EXPECT_EQ(format_duration(601), "10:01");
  EXPECT_EQ(format_duration(3600), "1:00:00");
}

TEST(Progress, DisabledPrintsNothing) {
  std::ostringstream out;
  {
    Progress progress("render", 1000, out, false);
    tbb::parallel_for(0, 1000, [&](int) { progress.advance(1); });
    progress.finish();
  }
  EXPECT_EQ(out.str(), "");
}

TEST(Progress, EnabledRedrawsOneLineInPlaceAndEndsIt) {
  std::ostringstream out;
  {
    Progress progress("render", 1000, out, true);
    tbb::parallel_for(0, 1000, [&](int) { progress.advance(1); });
    progress.finish();
  }
  const std::string text = out.str();
  EXPECT_EQ(text.front(), '\r');
  EXPECT_EQ(text.find('\n'), text.size() - 1);  // one line, ended once
  EXPECT_NE(text.rfind("100%"), std::string::npos);
  EXPECT_EQ(text.find("ETA", text.rfind('\r')), std::string::npos);  // the last state has none
}

TEST(Progress, AnAbandonedBarEndsItsLine) {
  std::ostringstream out;
  { Progress progress("render", 10, out, true); }
  EXPECT_EQ(out.str().back(), '\n');
}

}  // namespace
}  // namespace convray::render
