// SPDX-License-Identifier: MIT
// The second set of hostile inputs (tests/data/hostile/set2, copies of the small files of
// ../shared/data/hostile/set2, whose README says what each did and must give): seismic
// volumes, regular grids, state and transfer-function files, streamlines, probing and
// outputs. Each ends in seconds, within a memory cap, with exit 1 (a bad file) or 2 (a bad
// option) and words that say what is wrong, or is read whole with its defect flagged.
#include "ProcessRunner.hpp"
#include "support/TestSupport.hpp"

#include <sys/stat.h>
#include <filesystem>
#include <fstream>
#include <sstream>

using volpost::test::dataFile;
using volpost::test::runVolpost;
using volpost::test::runVolpostLimited;

namespace {

constexpr long kMemoryKB = 3'000'000;
constexpr int kSeconds = 30;

std::string set2(const std::string& name) { return dataFile("hostile/set2/" + name); }
std::string temp(const std::string& name) { return ::testing::TempDir() + "/volpost_set2_" + name; }
const std::string kWheel = std::string(VOLPOST_SOURCE_DIR) + "/resources/examples/wheel_mixed.vtu";
const std::string kSurvey = dataFile("seismic/synthetic_12x10x40.sgy");

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void expectSays(const volpost::test::RunResult& r, int exitCode, const std::string& words) {
  EXPECT_EQ(r.exitCode, exitCode) << r.output;
  EXPECT_NE(r.output.find(words), std::string::npos) << "expected '" << words << "' in\n" << r.output;
  EXPECT_EQ(r.output.find("json.exception"), std::string::npos) << r.output;
}

// JSON nested 100,000 deep inside an otherwise good file.
std::string deeplyNested(const std::string& before, const std::string& after) {
  return before + std::string(100000, '[') + std::string(100000, ']') + after;
}

}  // namespace

TEST(HostileSecondSet, DeeplyNestedJsonIsRefusedNamingTheKey) {
  // A serializer recursing on a sub-tree 100,000 deep overflowed the stack (SIGSEGV).
  const std::string state = temp("deep_state.json"), tf = temp("deep_tf.json"), tf2d = temp("deep.tf2d.json");
  std::ofstream(state) << deeplyNested(
      R"({"format": "volpost-state", "version": 1, "model": "", "volume": {"transferFunction": {"points": )", "}}}");
  std::ofstream(tf) << deeplyNested(R"({"format": "volpost-tf", "version": )", R"(, "points": []})");
  std::ofstream(tf2d) << deeplyNested(R"({"format": "volpost-tf2d", "version": 1, "widgets": [{"shape": )", "}]}");
  expectSays(runVolpostLimited("render --state " + state + " -o " + temp("x.png"), kMemoryKB, kSeconds), 1,
             "nested more than 64 deep under \"volume.transferFunction.points\"");
  expectSays(
      runVolpostLimited("render " + kWheel + " --renderer cpu --field S.mises --tf " + tf + " -o " + temp("x.png"),
                        kMemoryKB, kSeconds),
      1, "deep_tf.json: transfer function JSON: lists and objects nested more than 64 deep under \"version\"");
  expectSays(runVolpostLimited(
                 "render " + kSurvey + " --renderer cpu --field amplitude --tf2d " + tf2d + " -o " + temp("x.png"),
                 kMemoryKB, kSeconds),
             1, "nested more than 64 deep under \"widgets.shape\"");
}

TEST(HostileSecondSet, WidgetsBeyondADoublesSpanAreRefused) {
  for (const char* renderer : {"cpu", "reference"})
    expectSays(runVolpostLimited(std::string("render ") + kSurvey + " --renderer " + renderer +
                                     " --field amplitude --size 32x32 --tf2d " +
                                     set2("crash_tf2d_far_apart.tf2d.json") + " -o " + temp("x.png"),
                                 kMemoryKB, kSeconds),
               1, "too wide for one table");
}

TEST(HostileSecondSet, SamplesBeyondAFloatAreDrawnAndFlagged) {
  // One sample beyond a float's range made the CPU grid renderer loop for ever (NaN values
  // walking the transfer function's points).
  const auto segy = runVolpostLimited("render " + set2("hang_segy_ibm_junk_sample.sgy") +
                                          " --renderer cpu --field amplitude --size 16x16 -o " + temp("junk.png"),
                                      kMemoryKB, kSeconds);
  EXPECT_EQ(segy.exitCode, 0) << segy.output;
  const auto nrrd = runVolpostLimited("render " + set2("hang_nrrd_double_1e39.nrrd") +
                                          " --renderer cpu --field values --size 16x16 -o " + temp("junk.png"),
                                      kMemoryKB, kSeconds);
  EXPECT_EQ(nrrd.exitCode, 0) << nrrd.output;
  expectSays(runVolpostLimited("info " + set2("hang_segy_ibm_junk_sample.sgy"), kMemoryKB, kSeconds), 0,
             "samples-beyond-float   1 sample beyond a 32-bit float's range (up to 7.23701e+75)");
  expectSays(runVolpostLimited("render " + set2("unclear_nrrd_double_extremes.nrrd") +
                                   " --renderer cpu --field values -o " + temp("junk.png"),
                               kMemoryKB, kSeconds),
             1, "the values of values run from -1.7e+308 to 1.7e+308: the width of that range is beyond a double");
}

TEST(HostileSecondSet, StateFilesSayWhatIsWrongInTheirOwnKeys) {
  expectSays(runVolpostLimited("render " + kSurvey + " --state " + set2("hang_state_sampling_step.json") +
                                   " --size 32x32 -o " + temp("x.png"),
                               kMemoryKB, kSeconds),
             2, "the sampling step 1e-06 (--sampling-step, or \"volume\": {\"samplingStep\"} in a state file)");
  expectSays(runVolpost("render --state " + set2("unclear_state_number_overflow.json") + " -o " + temp("x.png")), 1,
             "unclear_state_number_overflow.json: not valid JSON: number overflow parsing '1e999'");
  expectSays(runVolpost("render --state " + set2("unclear_state_format_number.json") + " -o " + temp("x.png")), 1,
             "not a volpost state file");
  const auto renderer =
      runVolpost("render " + kWheel + " --state " + set2("unclear_state_renderer.json") + " -o " + temp("x.png"));
  expectSays(renderer, 2, "unclear_state_renderer.json: \"volume\": {\"renderer\": \"nope\"} names no volume renderer");
  EXPECT_EQ(renderer.output.find("--renderer nope"), std::string::npos) << "an option the user never typed";
  expectSays(runVolpost("render " + kWheel + " --state " + set2("unclear_state_step.json") + " -o " + temp("x.png")), 2,
             "the state's result step (\"result\": {\"step\": 1000000000000}) does not exist");
}

TEST(HostileSecondSet, SmallFilesClaimingHugeGridsAreRefusedBeforeTheMemoryIsTaken) {
  expectSays(runVolpostLimited("info " + set2("mem_nrrd_gzip_64_bytes_claims_864MB.nrrd"), kMemoryKB, kSeconds), 1,
             "bytes of gzip data cannot hold the 864000000 bytes");
  for (const char* file : {"mem_segy_3_traces_250M_points.sgy", "mem_segy_3_traces_8M_points.sgy"})
    expectSays(runVolpostLimited(std::string("info ") + set2(file), kMemoryKB, kSeconds), 1,
               "3 traces span inlines 1 .. 1000 and crosslines 1 .. 1000");
  // 40 arrays each within the budget, not together: the fields read so far count.
  const auto vti = runVolpostLimited("info " + set2("mem_vti_40_arrays_64M_points.vti"), kMemoryKB, kSeconds,
                                     "env VOLPOST_MEMORY_BUDGET=1300M");
  expectSays(vti, 1, "and the fields read so far hold");
  EXPECT_NE(vti.output.find("could not be read"), std::string::npos) << vti.output;
}

TEST(HostileSecondSet, ProbingAMillionPointsStreamsTheTable) {
  // Every result held every quantity: a million points took 2.5 GB, then bad_alloc.
  const std::string points = temp("million.txt"), csv = temp("million.csv");
  {
    std::ofstream out(points);
    for (int i = 0; i < 1000000; ++i) out << "0 -90 15\n";
  }
  const auto r =
      runVolpostLimited("probe " + kWheel + " --field S.mises --points " + points + " --csv " + csv, 700'000, 120);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::ifstream table(csv);
  std::size_t lines = 0;
  for (std::string line; std::getline(table, line);) ++lines;
  EXPECT_EQ(lines, 1000001u) << "the header and a row per point";
  std::filesystem::remove(points);
  std::filesystem::remove(csv);
}

TEST(HostileSecondSet, StreamlinesAreBoundedInPoints) {
  // A state file's line allowed 1e8 steps and an endless length: 1.7 GB, then bad_alloc.
  VOLPOST_SHARED_OR_SKIP(helix, "hostile/set2/helix.vtu");
  const std::string state = temp("forever.json");
  std::ofstream(state) << R"({"format": "volpost-state", "version": 1, "model": ")" << helix << R"(",
    "result": {"quantity": "T", "step": 1},
    "streamlines": {"shown": true, "field": "velocity", "seeds": ["point:0.5,0,0.5"], "maxSteps": 1e8,
                    "maxLength": 1e300, "closedOrbits": false}})";
  const auto r = runVolpostLimited("render --state " + state + " --size 64x64 -o " + temp("lines.png"), 1'500'000, 60);
  expectSays(r, 0, "1 streamline reached the limit of 2,097,152 points for all lines together");
}

TEST(HostileSecondSet, SilentlyWrongReadsAreRefusedOrFlagged) {
  expectSays(runVolpostLimited("info " + set2("silent_nrrd_lineskip_reads_header.nrrd"), kMemoryKB, kSeconds), 1,
             "the data ends within the 1 line the header's line skip passes over");
  expectSays(runVolpostLimited("info " + set2("unclear_nrrd_lineskip_says_changed.nrrd"), kMemoryKB, kSeconds), 1,
             "the data ends within");
  // Two pieces of the same extent left half the image reading 0.
  const auto gap = runVolpostLimited("info " + set2("silent_vti_overlapping_pieces.vti"), kMemoryKB, kSeconds);
  expectSays(gap, 0, "32 of the 64 points of \"value\" lie in no <Piece>");
  expectSays(
      runVolpostLimited("probe " + set2("silent_vti_overlapping_pieces.vti") + " --at 1,1,3", kMemoryKB, kSeconds), 0,
      "value = nan");
  expectSays(runVolpostLimited("info " + set2("silent_segy_trace_delays_differ.sgy"), kMemoryKB, kSeconds), 0,
             "8 of 9 traces start at another time than the first (delay recording time, bytes 109-110: 0 .. 1600 ms)");
  expectSays(runVolpostLimited("info " + set2("low_segy_rev2_interval_1e300.sgy"), kMemoryKB, kSeconds), 1,
             "the sample interval is 1e+300 microseconds");
  // Concatenated gzip members are read one after the other, as gunzip does.
  expectSays(runVolpostLimited("info " + set2("low_nrrd_gzip_two_members.nrrd"), kMemoryKB, kSeconds), 0,
             "values [0, 11]");
  // A point array and a cell array of one name: both offered, under names of their own.
  const auto both = runVolpostLimited("info " + set2("low_vti_point_and_cell_value.vti"), kMemoryKB, kSeconds);
  expectSays(both, 0, "value (cells)");
  EXPECT_NE(both.output.find("field-renamed"), std::string::npos) << both.output;
}

TEST(HostileSecondSet, OutputsAreAllWrittenOrNone) {
  // The picture was replaced, then its float image failed: a picture without its data.
  const std::string dir = temp("outputs");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string png = dir + "/a.png", npy = dir + "/b.npy";
  std::ofstream(png) << "OLD\n";
  std::ofstream(npy) << "OLD\n";
  // The picture fits in 40 KB, the float image does not.
  const std::string command = std::string("bash -c 'ulimit -f 40; trap \"\" XFSZ; exec ") + VOLPOST_EXECUTABLE +
                              " render " + kWheel + " --renderer cpu --field S.mises --size 64x64 -o " + png +
                              " --float " + npy + " 2>&1'";
  FILE* p = popen(command.c_str(), "r");
  ASSERT_TRUE(p);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, p)) output += buffer;
  const int status = pclose(p);
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_EQ(readAll(png), "OLD\n") << "the picture is left as it was";
  EXPECT_EQ(readAll(npy), "OLD\n");
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 2u) << "no temporary left";

  // A private picture stays private; a link is written through (the link stays).
  ASSERT_EQ(chmod(png.c_str(), 0600), 0);
  ASSERT_EQ(runVolpost("render " + kWheel + " --field S.mises --size 32x32 -o " + png).exitCode, 0);
  struct stat st {};
  ASSERT_EQ(stat(png.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  const std::string link = dir + "/link.png";
  std::filesystem::create_symlink(png, link);
  ASSERT_EQ(runVolpost("render " + kWheel + " --field S.mises --size 48x48 -o " + link).exitCode, 0);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(readAll(png).substr(1, 3), "PNG");
  EXPECT_EQ(readAll(link), readAll(png));
  std::filesystem::remove_all(dir);
}
