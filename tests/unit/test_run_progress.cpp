// The progress report of a chunked run (run/progress.h) and the profile file continued by
// `append yes` (darcy/output.h): what a user reads and what a continued run keeps.
#include "darcy/output.h"
#include "input/keywords.h"
#include "input/settings.h"
#include "run/progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace porewater;

TEST(RunProgress, RateAndTimeLeftFromTheLastChunk)
{
  // 1,000 steps in 4 s: 250 steps/s; 9,000 steps left: 36 s
  const ChunkProgress p{1000, 10000, 0.5, 2.5, 1000, 4.0};
  EXPECT_DOUBLE_EQ(steps_per_second(p), 250.0);
  EXPECT_DOUBLE_EQ(seconds_left(p), 36.0);
  const ChunkProgress done{10000, 10000, 5.0, 2.5, 1000, 4.0};
  EXPECT_DOUBLE_EQ(seconds_left(done), 0.0);
  const ChunkProgress untimed{10, 100, 0.0, 0.0, 0, 0.0};
  EXPECT_LT(seconds_left(untimed), 0.0);
}

TEST(RunProgress, DurationsAsAUserReadsThem)
{
  EXPECT_EQ(format_duration(0.4), "00:00:00");
  EXPECT_EQ(format_duration(3725.0), "01:02:05");
  EXPECT_EQ(format_duration(2 * 86400.0 + 3600.0 + 61.0), "2 d 01:01:01");
  EXPECT_EQ(format_duration(-1.0), "?");
}

TEST(RunProgress, LineNamesStepCycleRateAndFinish)
{
  const ChunkProgress p{1000, 10000, 0.5, 2.5, 1000, 4.0};
  const std::string line = progress_line(p, 1700000000);    // 2023-11-14 22:13:20 UTC
  EXPECT_NE(line.find("step 1000 of 10000 (10.0 %)"), std::string::npos) << line;
  EXPECT_NE(line.find("cycle 0.200"), std::string::npos) << line;
  EXPECT_NE(line.find("250 steps/s"), std::string::npos) << line;
  EXPECT_NE(line.find("left 00:00:36"), std::string::npos) << line;
  EXPECT_NE(line.find("done at 2023-11-1"), std::string::npos) << line;
  const ChunkProgress no_cycle{1000, 10000, 0.5, 0.0, 1000, 4.0};
  EXPECT_EQ(progress_line(no_cycle, 1700000000).find("cycle"), std::string::npos);
}

TEST(RunProgress, StopsBeforeAChunkThatWouldPassTheLimit)
{
  // 100 s used of 200, chunks of 40 s: with safety 1.5 the next one (60 s) still fits
  EXPECT_FALSE(next_chunk_passes_limit(100.0, 200.0, 40.0, 1.5));
  EXPECT_TRUE(next_chunk_passes_limit(150.0, 200.0, 40.0, 1.5));
  EXPECT_FALSE(next_chunk_passes_limit(1e9, 0.0, 40.0, 1.5));    // no limit
}

TEST(RunProgress, WallTimesAsBatchQueuesWriteThem)
{
  EXPECT_DOUBLE_EQ(parse_wall_time("48:00:00"), 48 * 3600.0);
  EXPECT_DOUBLE_EQ(parse_wall_time("01:30"), 90.0);
  EXPECT_DOUBLE_EQ(parse_wall_time("600"), 600.0);
  EXPECT_LT(parse_wall_time("1:2:3:4"), 0.0);
  EXPECT_LT(parse_wall_time("ten"), 0.0);
  EXPECT_LT(parse_wall_time("1::2"), 0.0);
}

TEST(RunProgress, SyntaxNamesTheKeywordAndWhatItTakes)
{
  KeywordReader ok("fix progress", {"end", "1000", "period", "2.5", "walltime", "01:00:00"});
  const ProgressSettings s = parse_progress(ok);
  EXPECT_EQ(s.end_step, 1000);
  EXPECT_DOUBLE_EQ(s.walltime, 3600.0);
  KeywordReader bad("fix progress", {"end", "1000", "walltime", "soon"});
  try {
    parse_progress(bad);
    FAIL() << "walltime soon accepted";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("walltime expects HH:MM:SS, MM:SS, seconds (> 0) or none, got 'soon'"), std::string::npos) << e.what();
  }
  KeywordReader none("fix progress", {"end", "10", "walltime", "none"});
  EXPECT_EQ(parse_progress(none).walltime, 0.0);
  KeywordReader missing("fix progress", {"period", "2.5"});
  EXPECT_THROW(parse_progress(missing), InputError);
  KeywordReader fraction("fix progress", {"end", "10.5"});
  EXPECT_THROW(parse_progress(fraction), InputError);
}

namespace {
std::string read_all(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}    // namespace

// A killed run wrote blocks at steps 0, 10, 20 and half of 30; continued from step 20, the
// file keeps its header and the blocks of steps 0, 10 and 20 (the restart's step: written
// by the run that wrote the restart file, not again), and appends after them.
TEST(RunProgress, ContinuedProfileKeepsTheBlocksUpToTheRestart)
{
  const std::string path = "pw_test_profile_continue.txt";
  const std::string header = "# fix d darcy/pressure: x-y averages\n# step time nlayers active_layers\n";
  const std::string b0 = "0 0 2 2\n1 0.1 5 0.4 1e-12 0\n2 0.3 6 0.4 1e-12 0\n";
  const std::string b10 = "10 1e-05 2 2\n1 0.1 7 0.4 1e-12 0\n2 0.3 8 0.4 1e-12 0\n";
  const std::string b20 = "20 2e-05 2 2\n1 0.1 9 0.4 1e-12 0\n2 0.3 1 0.4 1e-12 0\n";
  {
    std::ofstream out(path);
    out << header << b0 << b10 << b20 << "30 3e-05 2 2\n1 0.1 9 0.4";    // cut by the kill
  }
  bool has_header = false;
  std::FILE *fp = continue_profile(path, 20, has_header);
  ASSERT_NE(fp, nullptr);
  EXPECT_TRUE(has_header);
  std::fputs("30 again\n", fp);
  std::fclose(fp);
  EXPECT_EQ(read_all(path), header + b0 + b10 + b20 + "30 again\n");

  // a torn block header line and a block missing rows are dropped too
  {
    std::ofstream out(path);
    out << header << b0 << "10 1e-05 2 2\n1 0.1 7 0.4 1e-12 0\n";
  }
  fp = continue_profile(path, 50, has_header);
  ASSERT_NE(fp, nullptr);
  std::fclose(fp);
  EXPECT_EQ(read_all(path), header + b0);

  // no file yet: an empty one, without header (the fix writes it)
  std::remove(path.c_str());
  fp = continue_profile(path, 20, has_header);
  ASSERT_NE(fp, nullptr);
  std::fclose(fp);
  EXPECT_FALSE(has_header);
  EXPECT_EQ(read_all(path), "");
  std::remove(path.c_str());
}
