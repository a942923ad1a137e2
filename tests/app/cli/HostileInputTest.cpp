// SPDX-License-Identifier: MIT
// Hostile files and options (tests/data/hostile, from ../shared/data/hostile, whose README
// says what each did before and must do): every one ends, under a memory cap and a time
// limit, in a clear message naming the file (and line where there is one) or loads with
// its defect flagged; nothing crashes, hangs or reaches gigabytes. Output faults (a full
// disk, a missing folder, a device) leave the previous file intact and say so.
#include "support/TestSupport.hpp"
#include "ProcessRunner.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>
#include <sys/stat.h>

using volpost::test::dataFile;
using volpost::test::runVolpost;
using volpost::test::runVolpostLimited;

namespace {

constexpr long kMemoryKB = 3'000'000;  // a hostile file may not need more than this...
constexpr int kSeconds = 30;           // ...nor take longer

std::string hostile(const std::string& name) { return dataFile("hostile/" + name); }

struct Refusal {
  const char* file;
  const char* message;  ///< a part of the message that says what is wrong
};

// Files that must be refused, each with the words that say why.
const Refusal kRefusals[] = {
    {"points_count_wraps.vtu", "NumberOfPoints"},
    {"zlib_blocksize_wraps_points.vtu", "compression header claims 3 blocks"},
    {"coord_too_small.exo", "variable coord holds 3 values where its dimensions say 3000000"},
    {"vtk_second_points_section.vtk", "a second POINTS section"},
    {"cells_twice_celldata.vtk", "a second CELLS section"},
    {"nodedata_strings_huge.msh", "the number of string tags 1000000000000000 is more than"},
    {"num_el_blk_1e8.exo", "num_el_blk is 100000000"},
    {"numrecs_1e8.exo", "100000000 records"},
    {"v41_nodeblock_2e27.msh", "is more than the"},
    {"v22_nodes_1e12.msh", "the number of nodes 1000000000000 is more than"},
    {"points_1e8_ascii.vtk", "POINTS declares 300000000 values"},
    {"negative_conn_second_piece.vtu", "uses point -4, outside this piece's 4 points"},
    {"include_dir.inp", "*INCLUDE, INPUT=/tmp: is a folder"},
};

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(HostileFiles, AreRefusedWithTheFileAndTheDefectNamed) {
  for (const Refusal& r : kRefusals) {
    const auto run = runVolpostLimited("info " + hostile(r.file), kMemoryKB, kSeconds);
    EXPECT_EQ(run.exitCode, 1) << r.file << ":\n" << run.output;
    EXPECT_NE(run.output.find(hostile(r.file)), std::string::npos) << r.file << " is not named:\n" << run.output;
    EXPECT_NE(run.output.find(r.message), std::string::npos) << r.file << ": expected '" << r.message << "' in\n"
                                                              << run.output;
    EXPECT_EQ(run.output.find("bad_alloc"), std::string::npos) << run.output;
  }
}

TEST(HostileFiles, TheLargerOnesFromSharedData) {
  struct Case {
    const char* file;
    const char* message;
    const char* environment;
  };
  const Case cases[] = {
      {"b64_many_arrays_offset0.vtu", "starts at offset 0 of the appended data", ""},
      {"exodus_truncated_90pct.exo", "the file is truncated", ""},
      // Files that legitimately expand: refused past a stated budget, with the line.
      {"many_components_1e4nodes_x_50000.frd", "more than the memory budget of 1 GB", "VOLPOST_MEMORY_BUDGET=1G"},
      {"nodal_vector_1000_labels_100k_nodes.nf", "more than the memory budget of 1 GB", "VOLPOST_MEMORY_BUDGET=1G"},
  };
  int run = 0;
  for (const Case& c : cases) {
    const std::string path = volpost::test::sharedFile(std::string("hostile/") + c.file);
    if (path.empty()) continue;
    ++run;
    const auto r = runVolpostLimited("info " + path, kMemoryKB, kSeconds, std::string("env ") + c.environment);
    EXPECT_EQ(r.exitCode, 1) << c.file << ":\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.file << ": expected '" << c.message << "' in\n" << r.output;
  }
  if (run == 0) GTEST_SKIP() << "not run: ../shared/data/hostile is absent";
}

TEST(HostileFiles, FlaggedDefectsLoadAndEveryVerbSkipsTheBadCell) {
  // A tet that repeats a node: flagged, and left out by the surface, probing and rendering
  // (each aborted in an OpenMesh assertion before).
  const std::string model = hostile("repeated_node_tet_abort.vtu");
  const auto info = runVolpostLimited("info " + model, kMemoryKB, kSeconds);
  EXPECT_EQ(info.exitCode, 0) << info.output;
  EXPECT_NE(info.output.find("repeated-node-cells"), std::string::npos) << info.output;
  const std::string out = ::testing::TempDir() + "/hostile_surface.stl";
  EXPECT_EQ(runVolpostLimited("surface " + model + " " + out, kMemoryKB, kSeconds).exitCode, 0);
  EXPECT_EQ(runVolpostLimited("probe " + model + " --field region --at 0.1,0.1,0.1", kMemoryKB, kSeconds).exitCode, 0);
  for (const char* renderer : {"surface", "raycast", "vicp", "reference"}) {
    const auto r = runVolpost("render " + model + " --field region --size 48x32 --renderer " + renderer + " -o " +
                              ::testing::TempDir() + "/hostile_render.png");
    EXPECT_EQ(r.exitCode, 0) << renderer << ":\n" << r.output;
  }
  const auto dup = runVolpostLimited("info " + hostile("dup_elem_id_elementdata.msh"), kMemoryKB, kSeconds);
  EXPECT_NE(dup.output.find("duplicate-element-ids"), std::string::npos) << dup.output;
  const auto tensor = runVolpostLimited("info " + hostile("tensors9_asym.vtk"), kMemoryKB, kSeconds);
  EXPECT_NE(tensor.output.find("is not symmetric"), std::string::npos) << tensor.output;
  EXPECT_NE(tensor.output.find("9 components"), std::string::npos) << tensor.output;
}

TEST(HostileFiles, HarmlessOdditiesAreRead) {
  EXPECT_EQ(runVolpostLimited("info " + hostile("bom.msh"), kMemoryKB, kSeconds).exitCode, 0);  // a UTF-8 byte-order mark
  const auto comma = runVolpostLimited("info " + hostile("trailing_comma_then_keyword.inp"), kMemoryKB, kSeconds);
  EXPECT_EQ(comma.exitCode, 0) << comma.output;  // a complete record ending in a comma
}

TEST(HostileFiles, WritersProduceWellFormedFilesWhateverTheNames) {
  // "--" in a name (it ended an XML comment), control characters, markup characters.
  for (const char* name : {"model--v2.vtu", "scalars_name_hostile.vtk"}) {
    const std::string out = ::testing::TempDir() + "/hostile_names.vtu";
    ASSERT_EQ(runVolpost("convert " + hostile(name) + " " + out).exitCode, 0) << name;
    const std::string text = readAll(out);
    const std::string xml = text.substr(0, text.find("<AppendedData"));
    // "--" may stand in attribute values, never inside a comment (it ended one early).
    for (std::size_t at = xml.find("<!--"); at != std::string::npos; at = xml.find("<!--", at + 4)) {
      const std::size_t end = xml.find("-->", at + 4);
      ASSERT_NE(end, std::string::npos);
      EXPECT_EQ(xml.substr(at + 4, end - at - 4).find("--"), std::string::npos) << name;
    }
    for (char c : xml) EXPECT_TRUE(c == '\n' || static_cast<unsigned char>(c) >= 0x20) << "control character in " << name;
    const auto back = runVolpost("info " + out);
    EXPECT_EQ(back.exitCode, 0) << back.output;
  }
  // Colliding step names: T's first step and a field named "T step 1" stay two fields, and
  // the steps keep their times.
  const std::string out = ::testing::TempDir() + "/hostile_steps.vtu";
  ASSERT_EQ(runVolpost("convert " + hostile("field_name_collision.msh") + " " + out).exitCode, 0);
  const auto back = runVolpost("info " + out);
  EXPECT_NE(back.output.find("T                node  scalar (1 component), 2 steps"), std::string::npos) << back.output;
  EXPECT_NE(back.output.find("step 2, t = 2"), std::string::npos) << back.output;
  EXPECT_NE(back.output.find("T step 1 "), std::string::npos) << back.output;
  // A model at UTM coordinates with 0.1-unit cells keeps its vertices apart in the output.
  const std::string obj = ::testing::TempDir() + "/hostile_utm.obj";
  ASSERT_EQ(runVolpost("surface " + hostile("surface_float_utm.vtu") + " " + obj).exitCode, 0);
  std::istringstream lines(readAll(obj));
  std::set<std::pair<long long, long long>> distinct;  // (x, y) in units of 0.01
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    double x = 0, y = 0;
    std::sscanf(line.c_str(), "v %lf %lf", &x, &y);
    distinct.insert({std::llround(x * 100.0), std::llround(y * 100.0)});
  }
  EXPECT_EQ(distinct.size(), 6u) << "3 x 2 distinct (x, y) positions";
}

TEST(HostileFiles, TransferFunctionFilesAreRefusedByName) {
  const std::string model = hostile("seed.vtu");
  const auto empty = runVolpost("render " + model + " --field T --renderer raycast --tf " + hostile("empty_points.json") +
                                " -o " + ::testing::TempDir() + "/tf.png");
  EXPECT_EQ(empty.exitCode, 1);
  EXPECT_NE(empty.output.find("empty_points.json: transfer function JSON: \"points\" is empty"), std::string::npos)
      << empty.output;
  const auto number = runVolpost("render " + model + " --field T --renderer raycast --tf " + hostile("format_number.json") +
                                 " -o " + ::testing::TempDir() + "/tf.png");
  EXPECT_EQ(number.exitCode, 1);
  EXPECT_NE(number.output.find("format_number.json: transfer function JSON: not a volpost transfer function"),
            std::string::npos)
      << number.output;
  EXPECT_EQ(number.output.find("json."), std::string::npos) << "no raw library exception";
}

TEST(HostileFiles, DevicesAndPipesAreNotModels) {
  const auto zero = runVolpostLimited("info /dev/zero", kMemoryKB, kSeconds);
  EXPECT_EQ(zero.exitCode, 1);
  EXPECT_NE(zero.output.find("/dev/zero: is a device"), std::string::npos) << zero.output;
  const std::string fifo = ::testing::TempDir() + "/volpost_fifo";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto pipe = runVolpostLimited("info " + fifo, kMemoryKB, kSeconds);
  EXPECT_EQ(pipe.exitCode, 1) << "a FIFO blocked the reader forever";
  EXPECT_NE(pipe.output.find("is a pipe"), std::string::npos) << pipe.output;
  const auto tf = runVolpostLimited("render " + hostile("seed.vtu") + " --field T --renderer raycast --tf " + fifo +
                                        " -o " + ::testing::TempDir() + "/x.png",
                                    8'000'000, kSeconds);
  EXPECT_EQ(tf.exitCode, 1) << tf.output;
  EXPECT_NE(tf.output.find("not a regular file"), std::string::npos) << tf.output;
  std::filesystem::remove(fifo);
}

TEST(HostileOptions, AreUsageErrorsOrHonoured) {
  const std::string model = hostile("seed.vtu"), out = " -o " + ::testing::TempDir() + "/opt.png --size 48x32";
  EXPECT_EQ(runVolpost("render " + model + " --field T --range=-inf:inf" + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --renderer raycast --iso 1:1,1,1:nan" + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --renderer raycast --clip 0,0,0,0,0,0" + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --threads 4" + out).exitCode, 2) << "threads are the reference's";
  // A normal of 1e308 is a direction like any other (its length overflows; it is scaled first).
  EXPECT_EQ(runVolpost("render " + model + " --field T --renderer raycast --clip 0,0,0,1e308,1e308,0" + out).exitCode, 0);
  // More threads than the system gives: the reference renderer uses those it gets.
  const auto threads = runVolpostLimited("render " + model + " --field T --renderer reference --threads 1000" + out,
                                         4'000'000, kSeconds);
  EXPECT_EQ(threads.exitCode, 0) << threads.output;
  EXPECT_EQ(threads.output.find("terminate"), std::string::npos) << threads.output;
}

TEST(OutputFaults, AFailedWriteKeepsThePreviousFileAndSaysSo) {
  const std::string dir = ::testing::TempDir() + "/volpost_outputs";
  std::filesystem::create_directories(dir);
  const std::string png = dir + "/picture.png";
  { std::ofstream(png) << "the previous picture"; }
  // A full disk, as a file-size limit (1 KB) makes every larger write fail.
  const std::string command = std::string("bash -c 'ulimit -f 1; exec ") + VOLPOST_EXECUTABLE + " render " +
                              hostile("seed.vtu") + " --field T -o " + png + " 2>&1'";
  FILE* p = popen(command.c_str(), "r");
  ASSERT_TRUE(p);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, p)) output += buffer;
  const int status = pclose(p);
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_NE(output.find("write failed"), std::string::npos) << output;
  EXPECT_EQ(readAll(png), "the previous picture");
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "no temporary file left behind";
  // No success for output that was not written: a missing folder, a device, a folder.
  for (const std::string& target : std::vector<std::string>{"/no/such/folder/out.stl", "/dev/full", dir}) {
    const auto r = runVolpost("surface " + hostile("seed.vtu") + " " + target);
    EXPECT_EQ(r.exitCode, 1) << target << ":\n" << r.output;
    EXPECT_NE(r.output.find(target), std::string::npos) << r.output;
  }
  const auto vtu = runVolpost("convert " + hostile("seed.vtu") + " /no/such/folder/out.vtu");
  EXPECT_EQ(vtu.exitCode, 1) << vtu.output;
  std::filesystem::remove_all(dir);
}
