// SPDX-License-Identifier: MIT
// `volpost streamlines` and `volpost render --streamlines` as processes: files written,
// what is printed, and the errors for seeds, fields and options that cannot be honoured.
#include "support/TestSupport.hpp"
#include "ProcessRunner.hpp"

#include <QImage>

#include <filesystem>
#include <fstream>
#include <sstream>

using volpost::test::dataFile;
using volpost::test::runVolpost;

namespace {

std::string tempFile(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("volpost_streamcli_" + name);
  std::filesystem::remove(path);
  return path.string();
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A rake across the bar's fixed end: the displacement U grows along the bar, so lines run
// from it towards the loaded end.
const std::string kBarRake = " --seeds line:0.5,0.2,0.5:0.5,0.8,0.5:5";

}  // namespace

TEST(StreamlinesCommand, WritesCsvAndVtpWithOneLinePerSeed) {
  const std::string csv = tempFile("bar.csv");
  const auto r = runVolpost("streamlines " + dataFile("bar/bar_tet4.vtu") + " --field U" + kBarRake + " -o " + csv);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("5 streamlines"), std::string::npos) << r.output;
  const std::string table = readAll(csv);
  EXPECT_EQ(table.rfind("line,point,x,y,z,U_x,U_y,U_z,U speed\n", 0), 0u) << table.substr(0, 200);
  EXPECT_NE(table.find("\n4,0,"), std::string::npos) << "the fifth line is there";

  const std::string vtp = tempFile("bar.vtp");
  const auto v = runVolpost("streamlines " + dataFile("bar/bar_tet4.vtu") + " --field U --integrator rk45" + kBarRake +
                            " -o " + vtp);
  ASSERT_EQ(v.exitCode, 0) << v.output;
  const std::string xml = readAll(vtp);
  EXPECT_NE(xml.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfLines=\"5\""), std::string::npos) << xml.substr(0, 400);
}

TEST(StreamlinesCommand, ExplainsWhatItCannotDoAndWritesNothing) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string out = tempFile("never.csv");
  const auto scalar = runVolpost("streamlines " + model + " --field S" + kBarRake + " -o " + out);
  EXPECT_EQ(scalar.exitCode, 2) << scalar.output;
  const auto noSeeds = runVolpost("streamlines " + model + " --field U -o " + out);
  EXPECT_EQ(noSeeds.exitCode, 2) << noSeeds.output;
  const auto badSeed = runVolpost("streamlines " + model + " --field U --seeds line:0,0,0:1,1 -o " + out);
  EXPECT_EQ(badSeed.exitCode, 2) << badSeed.output;
  EXPECT_NE(badSeed.output.find("line:0,0,0:1,1"), std::string::npos) << badSeed.output;
  const auto badFormat = runVolpost("streamlines " + model + " --field U" + kBarRake + " -o lines.dxf");
  EXPECT_EQ(badFormat.exitCode, 2) << badFormat.output;
  const auto outside = runVolpost("streamlines " + model + " --field U --seeds point:50,0,0 -o " + out);
  EXPECT_EQ(outside.exitCode, 1) << outside.output;
  EXPECT_NE(outside.output.find("the seed lies outside the mesh (its bounds: x [0, 10]"), std::string::npos)
      << outside.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "no file for a failed run";
}

TEST(RenderCommand, DrawsStreamlinesAndNotesSeedsOutsideTheMesh) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string common = " --size 96x64 --no-legend --no-surface --camera +z";
  const std::string bare = tempFile("bare.png");
  ASSERT_EQ(runVolpost("render " + model + common + " -o " + bare).exitCode, 0);
  const std::string lines = tempFile("lines.png");
  // Two seeds of the rake lie beyond the bar (y = 1.25, 1.6): noted, not an error.
  const auto r = runVolpost("render " + model + common + " --streamlines U --tubes --seeds line:0.5,0.2,0.5:0.5,1.6,0.5:5 -o " +
                            lines);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("2 of the 5 seeds lie outside the mesh"), std::string::npos) << r.output;
  const QImage without(QString::fromStdString(bare)), with(QString::fromStdString(lines));
  ASSERT_EQ(without.size(), with.size());
  int changed = 0;
  for (int y = 0; y < with.height(); ++y)
    for (int x = 0; x < with.width(); ++x) changed += with.pixel(x, y) != without.pixel(x, y);
  EXPECT_GT(changed, 20) << "the streamlines are drawn";

  const auto noSeeds = runVolpost("render " + model + " --streamlines U -o " + lines);
  EXPECT_EQ(noSeeds.exitCode, 2) << noSeeds.output;
  EXPECT_NE(noSeeds.output.find("--seeds"), std::string::npos) << noSeeds.output;
  const auto tubesAlone = runVolpost("render " + model + " --tubes -o " + lines);
  EXPECT_EQ(tubesAlone.exitCode, 2) << tubesAlone.output;
  const auto allOutside = runVolpost("render " + model + " --streamlines U --seeds point:50,0,0 -o " + lines);
  EXPECT_EQ(allOutside.exitCode, 1) << allOutside.output;
}

TEST(RenderCommand, DrawsArrowsOnLitLinesAsOnTubes) {
  // --arrows without --tubes drew nothing more than the lines and exited 0.
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string common = " --size 128x64 --no-legend --no-surface --camera +z --streamlines U" + kBarRake;
  const auto differing = [](const std::string& a, const std::string& b) {
    const QImage first(QString::fromStdString(a)), second(QString::fromStdString(b));
    int changed = 0;
    for (int y = 0; y < first.height(); ++y)
      for (int x = 0; x < first.width(); ++x) changed += first.pixel(x, y) != second.pixel(x, y);
    return changed;
  };
  for (const std::string style : {"", " --tubes"}) {
    const std::string plain = tempFile("plain.png"), arrows = tempFile("arrows.png");
    ASSERT_EQ(runVolpost("render " + model + common + style + " -o " + plain).exitCode, 0);
    const auto r = runVolpost("render " + model + common + style + " --arrows -o " + arrows);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(differing(plain, arrows), 5) << "arrows drawn with" << (style.empty() ? " lit lines" : style);
  }
}
