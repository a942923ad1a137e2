// SPDX-License-Identifier: MIT
// `volpost info` and `volpost render` as processes: output, exit codes, messages.
#include "FloatPictures.hpp"
#include "ProcessRunner.hpp"
#include "support/TestSupport.hpp"
#include "support/VideoFrames.hpp"

#include <QImage>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

using volpost::test::dataFile;
using volpost::test::runVolpost;

TEST(InfoCommand, PrintsCountsFieldsAndRanges) {
  const auto r = runVolpost("info " + dataFile("bar/bar_tet4.vtu"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* text : {"nodes:    3091", "cells:    12431", "tet4      12431", "x [0, 10]", "symmetric tensor",
                           "S von Mises [58.5463, 102.712]", "region           cell", "defects:  none found"})
    EXPECT_NE(r.output.find(text), std::string::npos) << "missing '" << text << "' in\n" << r.output;
}

TEST(InfoCommand, ListsTheQuantitiesEachFieldOffersByTheirWrittenForm) {
  const auto r = runVolpost("info " + dataFile("bar/bar_tet4.vtu"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* text : {"quantities: U.magnitude U.x U.y U.z U.anglex", "quantities: S.mises S.p1 S.p2 S.p3 S.xx",
                           "S.tresca", "S.pressure", "S.triaxiality", "S.lode"})
    EXPECT_NE(r.output.find(text), std::string::npos) << "missing '" << text << "' in\n" << r.output;
  // the per-cell scalar "region" is one quantity: no list
  EXPECT_EQ(r.output.find("region."), std::string::npos) << r.output;
}

TEST(InfoCommand, PrintsWhereAGridLiesAtFullPrecision) {
  // A survey's UTM coordinates need 8 and more digits: printed to 6, the northing of a grid
  // at 6073556.25 read 6.07356e+06, 10 m off.
  std::ifstream in(dataFile("formats/image_ascii.vti"));
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::string from = "Origin=\"10 -2 0.5\"";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "Origin=\"605835.123456789 6073556.25 -0.001\"");
  const auto path = std::filesystem::path(::testing::TempDir()) / "volpost_utm.vti";
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  const auto r = runVolpost("info " + path.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // The grid's first point is the origin moved to the extent's start (1 0 2) along the
  // rotated axes: every digit of it, and of the bounds.
  for (const char* expected : {"origin       (605835.6011250335, 6073556.397760103, 3.999)",
                               "i            step (0.477668244562803, 0.14776010333066977, 0)",
                               "bounds:   x [605835.3794848785, 605837.5117980117]  y [6073556.397760103, "})
    EXPECT_NE(r.output.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << r.output;
  EXPECT_EQ(r.output.find("e+06"), std::string::npos) << r.output;
}

// The bundled synthetic cube with its inline numbers moved from byte 189 to byte 17 of
// every trace header (120 traces of 240 + 40 x 2 bytes after the 3600 bytes of headers).
std::string segyWithMovedInlines() {
  const auto path = std::filesystem::path(::testing::TempDir()) / "volpost_moved_inlines.sgy";
  std::ifstream in(dataFile("seismic/synthetic_12x10x40.sgy"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(bytes.size(), 42000u);
  for (std::size_t t = 0; t < 120; ++t) {
    char* h = bytes.data() + 3600 + t * 320;
    std::copy(h + 188, h + 192, h + 16);
    std::fill(h + 188, h + 192, char(0));
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  return path.string();
}

// --reader-option: the reader's settings on every verb that reads a model, listed by
// `info --reader-options`; a wrong name or value is a usage error naming it; `render`
// keeps them in the state it saves, so `render --state` reads the file the same way.
TEST(InfoCommand, ReaderOptionsAreListedHonouredAndKeptInTheState) {
  const auto list = runVolpost("info --reader-options");
  ASSERT_EQ(list.exitCode, 0) << list.output;
  EXPECT_NE(list.output.find("inline-byte=BYTE"), std::string::npos) << list.output;
  const std::string moved = segyWithMovedInlines();
  const auto plain = runVolpost("info " + moved);
  EXPECT_EQ(plain.exitCode, 1);
  EXPECT_NE(plain.output.find("at least 2"), std::string::npos) << plain.output;
  const auto read = runVolpost("info --reader-option inline-byte=17 " + moved);
  ASSERT_EQ(read.exitCode, 0) << read.output;
  EXPECT_NE(read.output.find("12 inline (1000 .. 1011 by 1)"), std::string::npos) << read.output;
  for (const char* bad : {"inline-byte=238", "inline-byte=x", "inline=17", "inline-byte"}) {
    const auto r = runVolpost(std::string("info --reader-option ") + bad + " " + moved);
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find(std::string(bad).substr(0, 6)), std::string::npos) << "names the option: " << r.output;
  }
  EXPECT_EQ(runVolpost("info --reader-option offset=1 " + dataFile("formats/golden.frd")).exitCode, 2)
      << "a reader without options refuses them";
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string a = (dir / "moved_a.png").string(), b = (dir / "moved_b.png").string(),
                    state = (dir / "moved.json").string();
  const auto r = runVolpost("render " + moved + " --reader-option inline-byte=17 --field amplitude --size 64x48 -o " + a +
                            " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream saved(state);
  const std::string json((std::istreambuf_iterator<char>(saved)), {});
  EXPECT_NE(json.find("\"inline-byte\": \"17\""), std::string::npos) << json;
  ASSERT_EQ(runVolpost("render --state " + state + " --size 64x48 -o " + b).exitCode, 0);
  // Bit for bit, though this cube lies 6e6 model units from the origin (the state keeps the
  // camera's rotation and distance, which eye - target would round).
  EXPECT_EQ(QImage(QString::fromStdString(a)), QImage(QString::fromStdString(b)));
  EXPECT_EQ(runVolpost("probe " + moved + " --reader-option inline-byte=17 --at 620050,6080150,-80").exitCode, 0);
  EXPECT_EQ(runVolpost("probe " + moved + " --reader-option inline-byte=300 --at 620050,6080150,-80").exitCode, 2);
}

// --slice: a survey's inline, crossline and time slices in the surface view and, opaque,
// in the volume; kept in the state (render --state gives the same picture); refused on a
// mesh, for an axis the grid lacks and outside the grid, naming them.
// Each option is refused, before any reading, by the renderers that say (in their traits)
// they do not take it, and the message names the ones that do; the same options pass the
// renderers that take them.
TEST(RenderCommand, OptionsARendererDoesNotTakeAreRefusedNamingTheOnesThatDo) {
  const std::string out = (std::filesystem::temp_directory_path() / "volpost_traits.png").string();
  const std::string common = "render " + dataFile("bar/bar_tet4.vtu") + " --field S.mises --size 32x24 -o " + out;
  const auto refused = [&](const std::string& extra, const std::string& says) {
    const auto r = runVolpost(common + " " + extra);
    EXPECT_EQ(r.exitCode, 2) << extra << ": " << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << extra << ": " << r.output;
  };
  refused("--renderer cpu --mode linear", "cpu integrates exactly");
  refused("--renderer reference --mode linear", "reference integrates exactly");
  refused("--renderer raycast --threads 2", "--threads sets the threads of reference, not of raycast");
  refused("--renderer vicp --shading", "(cpu, texture-raymarch, texture-slices, reference), not by vicp");
  refused("--renderer reference --termination 0", "not used by reference (it never stops early)");
  refused("--renderer reference --sampling-step 0.1", "not used by reference (it integrates exactly)");
  refused("--renderer cpu --sampling-step 0.1", "not used by cpu on meshes");
  refused("--renderer reference --volume-edges", "which draws the volume alone");
  refused("--renderer nope",
          "--renderer nope is not one of: surface, raycast, vicp, vicp-exact, cpu, "
          "texture-raymarch, texture-slices, reference");
  for (const char* ok :
       {"--renderer raycast --mode sampling --sampling-step 0.1 --termination 0", "--renderer vicp --mode iso-table",
        "--renderer cpu --termination 0", "--renderer reference --threads 1"})
    EXPECT_EQ(runVolpost(common + " " + ok).exitCode, 0) << ok;
}

TEST(RenderCommand, GridSlicesOfASurvey) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string cube = dataFile("seismic/synthetic_12x10x40.sgy"), common = " --field amplitude --size 64x48 ";
  const std::string plain = (dir / "slices_none.png").string(), sliced = (dir / "slices.png").string(),
                    again = (dir / "slices_again.png").string(), state = (dir / "slices.json").string();
  ASSERT_EQ(runVolpost("render " + cube + common + "--no-surface -o " + plain).exitCode, 0);
  const auto r = runVolpost("render " + cube + common +
                            "--no-surface --slice inline=1004 --slice time=80 -o " + sliced + " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(QImage(QString::fromStdString(plain)), QImage(QString::fromStdString(sliced)));
  ASSERT_EQ(runVolpost("render --state " + state + " --size 64x48 -o " + again).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(again)), QImage(QString::fromStdString(sliced)));
  std::ifstream saved(state);
  const std::string json((std::istreambuf_iterator<char>(saved)), {});
  EXPECT_NE(json.find("\"gridSlices\""), std::string::npos) << json;
  for (const char* renderer : {"cpu", "texture-raymarch"}) {
    const std::string volume = (dir / "slices_volume.png").string(), volumeSliced = (dir / "slices_volume2.png").string();
    ASSERT_EQ(runVolpost("render " + cube + common + "--renderer " + renderer + " -o " + volume).exitCode, 0);
    ASSERT_EQ(runVolpost("render " + cube + common + "--renderer " + renderer + " --slice time=80 -o " + volumeSliced).exitCode, 0);
    EXPECT_NE(QImage(QString::fromStdString(volume)), QImage(QString::fromStdString(volumeSliced))) << renderer;
  }
  // A clip plane cuts the slices as it cuts the surface and the volume: half of the time
  // slice seen from above goes.
  const std::string whole = (dir / "slice_whole.png").string(), cut = (dir / "slice_cut.png").string();
  const std::string top = common + "--no-surface --slice time=80 --camera +z --no-legend --no-triad ";
  ASSERT_EQ(runVolpost("render " + cube + top + "-o " + whole).exitCode, 0);
  ASSERT_EQ(runVolpost("render " + cube + top + "--clip-box -1e9,1e9,-1e9,1e9,-1e9,1e9 -o " + cut).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(whole)), QImage(QString::fromStdString(cut))) << "a box round it all cuts nothing";
  const auto covered = [](const QImage& image) {
    int n = 0;
    const QRgb background = image.pixel(0, 0);
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) n += image.pixel(x, y) != background;
    return n;
  };
  {
    // The survey spans x 619887 .. 620238: keep x above the middle.
    QImage full(QString::fromStdString(whole));
    ASSERT_EQ(runVolpost("render " + cube + top + "--clip 620062,0,0,1,0,0 -o " + cut).exitCode, 0);
    const int before = covered(full), after = covered(QImage(QString::fromStdString(cut)));
    EXPECT_GT(before, 200);
    EXPECT_LT(after, 0.7 * before) << "the clip plane cut the slice";
    EXPECT_GT(after, 0.3 * before);
  }
  const auto outside = runVolpost("render " + cube + common + "--slice inline=999 -o " + plain);
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.output.find("the inline slice at 999 lies outside the grid's inline 1000 .. 1011"), std::string::npos)
      << outside.output;
  EXPECT_EQ(runVolpost("render " + cube + common + "--slice depth=3 -o " + plain).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + dataFile("formats/golden.frd") + " --field T --slice i=1 -o " + plain).exitCode, 2);
  // The reference renderer draws the volume alone: a slice it would leave out is refused
  // (it exited 0 with the slice missing), from the option and from a state file.
  const auto before = QImage(QString::fromStdString(plain));
  const auto reference = runVolpost("render " + cube + common + "--renderer reference --slice inline=1004 -o " + plain);
  EXPECT_EQ(reference.exitCode, 2) << reference.output;
  EXPECT_NE(reference.output.find("grid slices"), std::string::npos) << reference.output;
  const auto referenceState = runVolpost("render --state " + state + " --renderer reference -o " + plain);
  EXPECT_EQ(referenceState.exitCode, 2) << referenceState.output;
  EXPECT_EQ(QImage(QString::fromStdString(plain)), before) << "the refused pictures left the file as it was";
}

TEST(RenderCommand, TwoDimensionalTransferFunctionOfASurvey) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string cube = dataFile("seismic/synthetic_12x10x40.sgy"), common = " --field amplitude --size 64x48 ";
  const std::string tf = (dir / "boundaries.tf2d.json").string(), broken = (dir / "broken.tf2d.json").string();
  std::ofstream(tf) << R"({"format":"volpost-tf2d","version":1,"widgets":[
    {"shape":"triangle","value":0.0,"width":0.5,"gradient":[0.0,0.25],"color":[0.95,0.45,0.1],"extinction":0.02},
    {"shape":"rectangle","value":0.85,"width":0.6,"gradient":[0.0,0.04],"color":[0.2,0.5,1.0],"extinction":0.05}]})";
  std::ofstream(broken) << R"({"format":"volpost-tf2d","version":1,"widgets":[{"shape":"circle"}]})";
  const std::string plain = (dir / "tf1d.png").string(), twoD = (dir / "tf2d.png").string(),
                    again = (dir / "tf2d_again.png").string(), state = (dir / "tf2d.json").string();
  for (const char* renderer : {"texture-raymarch", "cpu"}) {
    ASSERT_EQ(runVolpost("render " + cube + common + "--renderer " + renderer + " -o " + plain).exitCode, 0);
    const auto r = runVolpost("render " + cube + common + "--renderer " + renderer + " --tf2d " + tf + " -o " + twoD +
                              " --save-state " + state);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(QImage(QString::fromStdString(plain)), QImage(QString::fromStdString(twoD))) << renderer;
    ASSERT_EQ(runVolpost("render --state " + state + " --size 64x48 -o " + again).exitCode, 0);
    EXPECT_EQ(QImage(QString::fromStdString(again)), QImage(QString::fromStdString(twoD))) << renderer;
  }
  const auto usage = [&](const std::string& extra, const std::string& says) {
    const auto r = runVolpost("render " + cube + common + extra + " -o " + plain);
    EXPECT_EQ(r.exitCode, 2) << extra;
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
  };
  usage("--renderer raycast --tf2d " + tf, "not by raycast");
  usage("--tf2d " + tf, "works with volume renderers");
  usage("--renderer cpu --tf2d " + tf + " --tf " + tf, "one transfer function");
  const auto bad = runVolpost("render " + cube + common + "--renderer cpu --tf2d " + broken + " -o " + plain);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("broken.tf2d.json: 2D transfer function JSON: widgets[0]"), std::string::npos) << bad.output;
  const auto mesh = runVolpost("render " + dataFile("formats/golden.frd") + " --field T --renderer cpu --tf2d " + tf +
                               " -o " + plain);
  EXPECT_NE(mesh.exitCode, 0);
  EXPECT_NE(mesh.output.find("this model is a mesh"), std::string::npos) << mesh.output;
}

TEST(RenderCommand, AGridLargerThanTheGpuMemoryBudgetIsDrawnInBricks) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string cube = dataFile("seismic/synthetic_12x10x40.sgy"), common = " --field amplitude --size 64x48 ";
  const std::string whole = (dir / "one_texture.png").string(), bricked = (dir / "bricked.png").string();
  for (const char* renderer : {"texture-raymarch", "texture-slices"}) {
    ASSERT_EQ(runVolpost("render " + cube + common + "--renderer " + renderer + " -o " + whole).exitCode, 0);
    // 12 x 10 x 40 integer samples take 4.7-9.4 KB on the GPU (1 or 2 bytes each): a 4 KB budget bricks them.
    const auto r = runVolpost("render " + cube + common + "--renderer " + renderer + " --gpu-memory-budget 4K -o " + bricked);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const QImage a(QString::fromStdString(whole)), b(QString::fromStdString(bricked));
    ASSERT_EQ(a.size(), b.size());
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
      for (int x = 0; x < a.width(); ++x)
        for (const auto& [p, q] : {std::pair{qRed(a.pixel(x, y)), qRed(b.pixel(x, y))},
                                   std::pair{qGreen(a.pixel(x, y)), qGreen(b.pixel(x, y))},
                                   std::pair{qBlue(a.pixel(x, y)), qBlue(b.pixel(x, y))}})
          worst = std::max(worst, std::abs(p - q));
    EXPECT_LE(worst, 3) << renderer << ": bricks give the one texture's picture within rounding";
  }
  const auto tiny = runVolpost("render " + cube + common + "--renderer texture-slices --gpu-memory-budget 16 -o " + bricked);
  EXPECT_EQ(tiny.exitCode, 1);
  EXPECT_NE(tiny.output.find("GPU memory budget of 16 bytes"), std::string::npos) << tiny.output;
  EXPECT_EQ(runVolpost("render " + cube + common + "--gpu-memory-budget lots -o " + bricked).exitCode, 2);
}

TEST(InfoCommand, ListsDefectsOfAFlaggedFile) {
  const auto r = runVolpost("info " + dataFile("bad/inverted_tets.vtu"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("inverted-cells"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("5 inverted cells"), std::string::npos) << r.output;
}

TEST(InfoCommand, BadFileGivesExitCode1AndALocatedMessage) {
  const auto r = runVolpost("info " + dataFile("bad/index_out_of_range.vtu"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("index_out_of_range.vtu:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cell 3 uses point 608"), std::string::npos) << r.output;
  const auto missing = runVolpost("info /no/such/model.vtu");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("cannot open"), std::string::npos) << missing.output;
  EXPECT_EQ(runVolpost("info").exitCode, 2);
}

TEST(RenderCommand, WritesAPngOfTheRequestedSize) {
  const std::string out = (std::filesystem::temp_directory_path() / "volpost_cli_render.png").string();
  std::filesystem::remove(out);
  const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --field S.mises --size 96x64 --camera iso,az=30 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(out), std::string::npos) << "prints the image path";
  const QImage image(QString::fromStdString(out));
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.size(), QSize(96, 64));
}

TEST(RenderCommand, ExplainsBadArguments) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const auto noField = runVolpost("render " + model + " --field S.bogus -o /tmp/x.png");
  EXPECT_EQ(noField.exitCode, 2);
  EXPECT_NE(noField.output.find("available: U.magnitude"), std::string::npos) << noField.output;
  const auto badSize = runVolpost("render " + model + " --size 0x5 -o /tmp/x.png");
  EXPECT_EQ(badSize.exitCode, 2);
  EXPECT_NE(badSize.output.find("--size 0x5"), std::string::npos) << badSize.output;
  const auto badCamera = runVolpost("render " + model + " --camera sideways -o /tmp/x.png");
  EXPECT_EQ(badCamera.exitCode, 2);
  EXPECT_NE(badCamera.output.find("unknown item 'sideways'"), std::string::npos) << badCamera.output;
  const auto badStep = runVolpost("render " + model + " --field S11 --step 3 -o /tmp/x.png");
  EXPECT_EQ(badStep.exitCode, 2);  // an option this model cannot honour is a usage error
  EXPECT_NE(badStep.output.find("step 3 does not exist"), std::string::npos) << badStep.output;
  EXPECT_EQ(runVolpost("render " + model).exitCode, 2);
  const auto outlineAlone = runVolpost("render " + model + " --field S.mises --undeformed -o /tmp/x.png");
  EXPECT_EQ(outlineAlone.exitCode, 2);
  EXPECT_NE(outlineAlone.output.find("add --deform"), std::string::npos) << outlineAlone.output;
  const auto outlineVolume =
      runVolpost("render " + model + " --field S.mises --deform U --undeformed --renderer raycast -o /tmp/x.png");
  EXPECT_EQ(outlineVolume.exitCode, 2);
  EXPECT_NE(outlineVolume.output.find("surface pictures only"), std::string::npos) << outlineVolume.output;
  const auto unwritable = runVolpost("render " + model + " -o /no/such/folder/x.png");
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_NE(unwritable.output.find("/no/such/folder does not exist"), std::string::npos) << unwritable.output;
}

TEST(RenderCommand, ReferenceVolumeRendererWritesPngAndFloatImages) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string png = (dir / "volpost_ref.png").string(), pfm = (dir / "volpost_ref.pfm").string();
  std::filesystem::remove(png);
  std::filesystem::remove(pfm);
  const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                            " --renderer reference --field S.xx --size 64x48 --clip 5,0,0,-1,0,0 -o " + png + " --float " + pfm);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(QImage(QString::fromStdString(png)).size(), QSize(64, 48));
  // PFM: header, then 64 x 48 x 3 floats.
  EXPECT_EQ(std::filesystem::file_size(pfm), std::string("PF\n64 48\n-1.0\n").size() + 64u * 48u * 3u * 4u);
}

TEST(RenderCommand, ReferenceRendererExplainsWhatItCannotDo) {
  const auto noResults = runVolpost("render " + dataFile("bad/ref_hex_block.vtu") + " --renderer reference --field x -o /tmp/x.png");
  EXPECT_EQ(noResults.exitCode, 2);
  EXPECT_NE(noResults.output.find("has no result fields"), std::string::npos) << noResults.output;
  const auto noField = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference -o /tmp/x.png");
  EXPECT_EQ(noField.exitCode, 2);
  EXPECT_NE(noField.output.find("needs --field"), std::string::npos) << noField.output;
  const auto badClip = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference --field S11 --clip 1,2,3 -o /tmp/x.png");
  EXPECT_EQ(badClip.exitCode, 2);
  EXPECT_NE(badClip.output.find("--clip 1,2,3"), std::string::npos) << badClip.output;
  const auto nanClip = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference --field S11 --clip nan,0,0,1,0,0 -o /tmp/x.png");
  EXPECT_EQ(nanClip.exitCode, 2);
  EXPECT_NE(nanClip.output.find("--clip nan,0,0,1,0,0"), std::string::npos) << nanClip.output;
  const auto infIso = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference --field S11 --iso inf -o /tmp/x.png");
  EXPECT_EQ(infIso.exitCode, 2) << infIso.output;
  const auto badTf = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference --field S11 --tf " +
                                dataFile("bar/analytic_check.json") + " -o /tmp/x.png");
  EXPECT_EQ(badTf.exitCode, 1);
  EXPECT_NE(badTf.output.find("not a volpost transfer function"), std::string::npos) << badTf.output;
}

TEST(RenderCommand, CpuRayCasterMatchesTheReferenceAndRefusesGpuOptions) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string png = (dir / "volpost_cpu.png").string(), cpuNpy = (dir / "volpost_cpu.npy").string(),
                    refNpy = (dir / "volpost_cpu_ref.npy").string();
  const std::string common = "render " + dataFile("bar/bar_tet4.vtu") + " --field S.mises --size 64x48 --clip 5,0,0,-1,0,0 -o " + png;
  const auto cpu = runVolpost(common + " --renderer cpu --termination 0 --float " + cpuNpy);
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  EXPECT_EQ(QImage(QString::fromStdString(png)).size(), QSize(64, 48));
  const auto ref = runVolpost(common + " --renderer reference --float " + refNpy);
  ASSERT_EQ(ref.exitCode, 0) << ref.output;
  const FloatPicturesApart apart = compareFloatPictures(cpuNpy, refNpy, 64u * 48u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_LE(apart.worst, 1e-4f) << "the CPU ray caster is exact up to float";
  const auto mode = runVolpost(common + " --renderer cpu --mode sampling");
  EXPECT_EQ(mode.exitCode, 2);
  EXPECT_NE(mode.output.find("integrates exactly"), std::string::npos) << mode.output;
  EXPECT_EQ(runVolpost(common + " --renderer cpu --sampling-step 0.1").exitCode, 2);
}

// A regular grid's per-cell field: the CPU renderer draws it through the grid's tetrahedra
// (its marcher samples point values), as the reference does; the texture renderers, which
// sample points only, refuse it as a usage error naming the renderers that can.
TEST(RenderCommand, APerCellFieldOnAGridIsDrawnByTheCpuRendererAndRefusedByTheTextureOnes) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string png = (dir / "per_cell.png").string(), cpuNpy = (dir / "per_cell_cpu.npy").string(),
                    refNpy = (dir / "per_cell_ref.npy").string();
  const std::string common = "render " + dataFile("formats/image_points_ascii.vtk") + " --field material --size 48x40 -o " + png;
  const auto cpu = runVolpost(common + " --renderer cpu --termination 0 --float " + cpuNpy);
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  const auto ref = runVolpost(common + " --renderer reference --float " + refNpy);
  ASSERT_EQ(ref.exitCode, 0) << ref.output;
  const FloatPicturesApart apart = compareFloatPictures(cpuNpy, refNpy, 48u * 40u * 4u);
  EXPECT_GT(apart.alpha, 0.05f) << "the volume shows";
  EXPECT_LE(apart.worst, 1e-4f);
  for (const char* renderer : {"texture-raymarch", "texture-slices"}) {
    const auto r = runVolpost(common + " --renderer " + renderer);
    EXPECT_EQ(r.exitCode, 2) << renderer;
    EXPECT_NE(r.output.find("'material' is given per cell: choose a renderer that draws meshes (raycast, vicp, "
                            "vicp-exact, cpu, reference)"),
              std::string::npos)
        << r.output;
  }
}

// The mixed wheel as a user renders it (default 800x600 isometric view, a narrow opacity
// peak, a translucent iso-surface): both GPU renderers against the reference. Rays grazing
// the silhouette enter through faces that project to slivers, which must still get their
// fragment (a capped mitre left a sliver's long edges without margin: one ray lost by the
// ray caster's entry maps, 0.0027 off).
TEST(RenderCommand, GpuRenderersDrawTheMixedWheelAsTheReference) {
  VOLPOST_SHARED_OR_SKIP(wheel, "wheel/mixed/wheel_mixed.frd");
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string tf = (dir / "wheel_peak.json").string(), png = (dir / "wheel.png").string();
  std::ofstream(tf) << R"({"format":"volpost-tf","version":1,"points":[
 {"value":0.3,"color":[0.1,0.2,0.9],"extinction":0.0}, {"value":3.0,"color":[0.2,0.6,0.9],"extinction":0.002},
 {"value":6.0,"color":[0.9,0.9,0.2],"extinction":0.05}, {"value":8.0,"color":[0.9,0.3,0.1],"extinction":0.002},
 {"value":39.3,"color":[0.8,0.1,0.1],"extinction":0.0}]})";
  const std::string common = "render " + wheel + " --field S --tf " + tf + " --iso 5:1,1,1:0.4 -o " + png;
  const std::string refNpy = (dir / "wheel_ref.npy").string();
  ASSERT_EQ(runVolpost(common + " --renderer reference --float " + refNpy).exitCode, 0);
  for (const char* renderer : {"raycast", "vicp"}) {
    const std::string npy = (dir / (std::string("wheel_") + renderer + ".npy")).string();
    const auto r = runVolpost(common + " --renderer " + renderer + " --termination 0 --float " + npy);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const FloatPicturesApart apart = compareFloatPictures(npy, refNpy, 800u * 600u * 4u);
    std::printf("%s, mixed wheel at 800x600 vs reference: max %.3g\n", renderer, double(apart.worst));
    EXPECT_GT(apart.alpha, 0.05f) << renderer;
    EXPECT_LE(apart.worst, 1e-3f) << renderer;
  }
}

TEST(RenderCommand, GpuRayCasterFromThePluginRendersHeadless) {
  const std::string png = (std::filesystem::temp_directory_path() / "volpost_raycast.png").string();
  std::filesystem::remove(png);
  const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                            " --renderer raycast --mode pre-integrated --field S.mises --size 80x60 -o " + png);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const QImage image(QString::fromStdString(png));
  ASSERT_EQ(image.size(), QSize(80, 60));
  int tinted = 0;  // pixels where the volume changed the light-gray background
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) tinted += std::abs(qRed(image.pixel(x, y)) - qBlue(image.pixel(x, y))) > 8;
  EXPECT_GT(tinted, 50);
  const auto badMode = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer raycast --mode fast --field S11 -o " + png);
  EXPECT_EQ(badMode.exitCode, 2);
  EXPECT_NE(badMode.output.find("--mode fast"), std::string::npos) << badMode.output;
  const auto unknown = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer splatting --field S11 -o " + png);
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("raycast, vicp, vicp-exact"), std::string::npos) << "lists the renderers there are: " << unknown.output;
}

TEST(RenderCommand, CellProjectionFromThePluginRendersHeadless) {
  const std::string png = (std::filesystem::temp_directory_path() / "volpost_vicp.png").string();
  std::filesystem::remove(png);
  for (const char* renderer : {"vicp", "vicp-exact"}) {
    const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer " + renderer +
                              " --field S.mises --size 80x60 --clip 5,0,0,1,0,0 -o " + png);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const QImage image(QString::fromStdString(png));
    ASSERT_EQ(image.size(), QSize(80, 60));
    int tinted = 0;
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 80; ++x) tinted += std::abs(qRed(image.pixel(x, y)) - qBlue(image.pixel(x, y))) > 8;
    EXPECT_GT(tinted, 30) << renderer;
  }
}

TEST(RenderCommand, IsoSurfaceOptionIsCheckedAndRendered) {
  const std::string png = (std::filesystem::temp_directory_path() / "volpost_iso.png").string();
  const auto ok = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                             " --renderer raycast --field S11 --iso 100:1,0,0:0.5 --size 48x32 -o " + png);
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  const auto bad = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer raycast --field S11 --iso 100:2,0,0 -o " + png);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--iso 100:2,0,0"), std::string::npos) << bad.output;
}

TEST(RenderCommand, MixedCellsAreTetrahedralizedForVolumeRendering) {
  // The bundled wheel: hexahedra, wedges, pyramids and tetrahedra.
  const std::string png = (std::filesystem::temp_directory_path() / "volpost_mixed.png").string();
  const auto r = runVolpost("render " + std::string(VOLPOST_SOURCE_DIR) + "/resources/examples/wheel_mixed.vtu" +
                            " --renderer reference --field S.mises --size 48x36 -o " + png);
  EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(ConvertCommand, WritesAVtuThatReadsBackTheSame) {
  const std::string out = ::testing::TempDir() + "/converted.vtu";
  const auto r = runVolpost("convert " + dataFile("formats/golden.nf") + " " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto info = runVolpost("info " + out);
  EXPECT_NE(info.output.find("nodes:    30"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("2 steps"), std::string::npos) << info.output;  // the steps of one field again
  EXPECT_NE(info.output.find("title:    golden neutral file"), std::string::npos) << info.output;
  EXPECT_EQ(runVolpost("convert " + dataFile("formats/golden.nf") + " out.txt").exitCode, 2);
  const auto bad = runVolpost("convert " + dataFile("bad/index_out_of_range.msh") + " " + out);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("index_out_of_range.msh:"), std::string::npos) << bad.output;
  // Both layouts read back; a layout that is neither is a usage error naming it.
  const std::string appended = ::testing::TempDir() + "/converted_appended.vtu";
  ASSERT_EQ(runVolpost("convert --layout appended " + dataFile("formats/golden.nf") + " " + appended).exitCode, 0);
  EXPECT_NE(runVolpost("info " + appended).output.find("nodes:    30"), std::string::npos);
  const auto wrong = runVolpost("convert --layout zipped " + dataFile("formats/golden.nf") + " " + out);
  EXPECT_EQ(wrong.exitCode, 2);
  EXPECT_NE(wrong.output.find("--layout zipped"), std::string::npos) << wrong.output;
}

TEST(SurfaceCommand, WritesBoundaryAndIsoSurfaces) {
  const std::string dir = ::testing::TempDir();
  const auto boundary = runVolpost("surface " + dataFile("bar/bar_tet4.vtu") + " " + dir + "/bar.obj");
  ASSERT_EQ(boundary.exitCode, 0) << boundary.output;
  EXPECT_TRUE(std::filesystem::file_size(dir + "/bar.obj") > 1000);
  const auto iso = runVolpost("surface " + dataFile("bar/bar_tet4.vtu") + " " + dir + "/iso.stl --field U.x --iso 0.002");
  ASSERT_EQ(iso.exitCode, 0) << iso.output;
  EXPECT_NE(iso.output.find("U.x = 0.002"), std::string::npos) << iso.output;
  EXPECT_EQ(runVolpost("surface " + dataFile("bar/bar_tet4.vtu") + " " + dir + "/x.obj --iso 1").exitCode, 2);
  const auto format = runVolpost("surface " + dataFile("bar/bar_tet4.vtu") + " " + dir + "/x.dxf");
  EXPECT_EQ(format.exitCode, 1);
  EXPECT_NE(format.output.find(".obj, .ply, .stl or .off"), std::string::npos) << format.output;
}

TEST(ProbeCommand, PrintsTheBarStressAtAPointAndFlagsOutsidePoints) {
  const auto r = runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --field S.xx --at 5,0.5,0.5");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto at = r.output.find("S.xx = ");
  ASSERT_NE(at, std::string::npos) << r.output;
  EXPECT_NEAR(std::stod(r.output.substr(at + 7)), 100.0, 0.01);
  const auto outside = runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --field S.xx --at 20,0,0");
  EXPECT_EQ(outside.exitCode, 1);
  EXPECT_NE(outside.output.find("outside the mesh"), std::string::npos);
  EXPECT_EQ(runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --field S.xx --at 1,2").exitCode, 2);
}

// The calculator on every verb: a formula's field is probed, listed, drawn and kept in the
// state; a bad one is a usage error naming the character at fault, and nothing is written.
TEST(Formulas, AFormulaWorksOnEveryVerbAndABadOneSaysWhere) {
  const std::string bar = dataFile("bar/bar_tet4.vtu");
  const auto probe = runVolpost("probe " + bar + " --formula \"ratio=S.xx/250\" --field ratio --at 5,0.5,0.5");
  ASSERT_EQ(probe.exitCode, 0) << probe.output;
  const auto at = probe.output.find("ratio = ");
  ASSERT_NE(at, std::string::npos) << probe.output;
  EXPECT_NEAR(std::stod(probe.output.substr(at + 8)), 100.0 / 250.0, 1e-4);

  const auto info = runVolpost("info " + bar + " --formula \"twice=S*2\"");
  EXPECT_NE(info.output.find("twice            node  symmetric tensor"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("quantities: twice.mises"), std::string::npos) << info.output;

  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string png = (dir / "volpost_formula.png").string(), state = (dir / "volpost_formula.json").string();
  std::filesystem::remove(png);
  const auto render = runVolpost("render " + bar + " --formula \"ux=U.x*1000\" --field ux --size 160x120 -o " + png +
                                 " --save-state " + state);
  ASSERT_EQ(render.exitCode, 0) << render.output;
  EXPECT_TRUE(std::filesystem::exists(png));
  std::ifstream saved(state);
  const std::string json((std::istreambuf_iterator<char>(saved)), {});
  EXPECT_NE(json.find("\"expression\": \"U.x*1000\""), std::string::npos) << json;
  const std::string png2 = (dir / "volpost_formula_again.png").string();
  const auto again = runVolpost("render --state " + state + " --size 160x120 -o " + png2);
  EXPECT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(QImage(QString::fromStdString(png)), QImage(QString::fromStdString(png2)));

  std::filesystem::remove(png);
  const auto bad = runVolpost("render " + bar + " --formula \"ux=U.x*+\" --field ux -o " + png);
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("formula 'ux': the expression ends with '+'"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("at character 5"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(png));
  const auto unknown = runVolpost("probe " + bar + " --formula \"r=S.mizes\" --at 5,0.5,0.5");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("no quantity or field named 'S.mizes' at character 1"), std::string::npos)
      << unknown.output;
  EXPECT_EQ(runVolpost("info " + bar + " --formula nothing").exitCode, 2);
  const auto undefined = runVolpost("info " + bar + " --formula \"nan=0/0\"");
  EXPECT_NE(undefined.output.find("nan: no finite value  (3091 NaN/inf values)"), std::string::npos)
      << undefined.output;
}

TEST(RenderCommand, ContourBandsSymmetricRangeAndReversedMaps) {
  const std::string bar = dataFile("bar/bar_tet4.vtu");
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string png = (dir / "volpost_bands.png").string(), state = (dir / "volpost_bands.json").string();
  const auto r = runVolpost("render " + bar +
                            " --field S.xy --bands 12 --symmetric --colormap viridis-reversed "
                            "--size 160x120 -o " +
                            png + " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream saved(state);
  const std::string json((std::istreambuf_iterator<char>(saved)), {});
  for (const char* text : {"\"bands\": 12", "\"symmetric\": true", "\"map\": \"viridis-reversed\""})
    EXPECT_NE(json.find(text), std::string::npos) << text << " in " << json;
  EXPECT_EQ(runVolpost("render " + bar + " --field S.xy --bands 1 -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.xy --symmetric --range 0:1 -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.xy --bands 4 --renderer reference -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.xy --colormap viridis-backwards -o " + png).exitCode, 2);
  // The legend's words and numbers.
  const auto legend = runVolpost("render " + bar +
                                 " --field S.mises --units S=MPa --legend-title Equivalent "
                                 "--legend-numbers fixed:1 --legend-labels 10 --size 160x120 -o " +
                                 png + " --save-state " + state);
  ASSERT_EQ(legend.exitCode, 0) << legend.output;
  std::ifstream again(state);
  const std::string saved2((std::istreambuf_iterator<char>(again)), {});
  EXPECT_NE(saved2.find("\"S\": \"MPa\""), std::string::npos) << saved2;
  EXPECT_NE(saved2.find("\"numbers\": \"fixed:1\""), std::string::npos) << saved2;
  EXPECT_EQ(runVolpost("render " + bar + " --field S.mises --units Q=MPa -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.mises --legend-numbers roman -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.mises --legend-labels 50 -o " + png).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + bar +
                       " --field S.xx --range 95:105 --below-color 0,0,0 --above-color 1,1,1 "
                       "--size 160x120 -o " +
                       png)
                .exitCode,
            0);
  EXPECT_EQ(runVolpost("render " + bar + " --field S.xx --below-color 0,0,2 -o " + png).exitCode, 2);
  EXPECT_EQ(
      runVolpost("render " + bar + " --field S.xx --title \"Bar, axial stress\" --size 160x120 -o " + png).exitCode, 0);
}

TEST(RenderCommand, RepresentationsSlicesAndTheVolumeOutline) {
  const std::string bar = dataFile("bar/bar_tet4.vtu");
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string png = (dir / "volpost_representation.png").string(),
                    state = (dir / "volpost_representation.json").string();
  const auto r = runVolpost("render " + bar +
                            " --field S.xx --representation points --point-size 6 --slice 5,0.5,0.5,0,1,0 "
                            "--size 160x120 -o " +
                            png + " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream saved(state);
  const std::string json((std::istreambuf_iterator<char>(saved)), {});
  for (const char* text : {"\"representation\": \"points\"", "\"pointSize\": 6.0", "\"slicePlanes\""})
    EXPECT_NE(json.find(text), std::string::npos) << text << " in " << json;
  const auto refused = [&](const std::string& options, const std::string& says) {
    const auto out = runVolpost("render " + bar + " " + options + " -o " + png);
    EXPECT_EQ(out.exitCode, 2) << options;
    EXPECT_NE(out.output.find(says), std::string::npos) << options << ": " << out.output;
  };
  refused("--field S.xx --representation mesh", "--representation mesh is not one of: surface, wireframe");
  refused("--field S.xx --point-size 4", "--point-size sizes the points of --representation points");
  refused("--field S.xx --representation points --point-size 100", "--point-size 100 is not a size");
  refused("--field S.xx --slice 1,2,3", "--slice 1,2,3 is not a plane px,py,pz,nx,ny,nz");
  refused("--field S.xx --slice inline=5", "this model is a mesh");
  refused("--field S.xx --renderer cpu --representation wireframe", "--representation chooses how the surface");
  refused("--field S.xx --volume-outline", "--volume-outline works with volume renderers");
  refused("--field S.xx --renderer reference --volume-outline", "--volume-outline is not drawn by reference");
  refused("--field S.xx --glyphs S11", "glyphs need a nodal vector or symmetric tensor field; 'S11' is not one");
  refused("--field S.xx --glyph-color S.mises", "glyph options need --glyphs FIELD");
  refused("--field S.xx --glyphs U --glyph-every 0", "--glyph-every 0 is not a count");
  refused("--field S.xx --glyphs U --glyph-nodes some", "--glyph-nodes some is not surface or all");
  refused("--field S.xx --glyphs U --renderer reference", "--glyphs are not drawn by reference");
  const auto glyphs =
      runVolpost("render " + bar + " --field S.xx --glyphs S --glyph-nodes all --glyph-every 50 --size 96x64 -o " +
                 png + " --save-state " + state);
  ASSERT_EQ(glyphs.exitCode, 0) << glyphs.output;
  std::ifstream withGlyphs(state);
  const std::string saved3((std::istreambuf_iterator<char>(withGlyphs)), {});
  EXPECT_NE(saved3.find("\"every\": 50"), std::string::npos) << saved3;
  refused("--field S.xx --deformation-sweep 3", "add --deform FIELD");
  refused("--field S.xx --deform U --deformation-sweep 1", "--deformation-sweep 1 is not a frame count");
  refused("--field S.xx --deform U --deformation-sweep 3 --all-steps", "give one");
  const std::string frames = (dir / "volpost_sweep.png").string();
  const auto sweep =
      runVolpost("render " + bar + " --field S.xx --deform U:200 --deformation-sweep 3 --size 96x64 -o " + frames);
  ASSERT_EQ(sweep.exitCode, 0) << sweep.output;
  const QImage first(QString::fromStdString((dir / "volpost_sweep_001.png").string()));
  const QImage last(QString::fromStdString((dir / "volpost_sweep_003.png").string()));
  ASSERT_FALSE(first.isNull());
  ASSERT_FALSE(last.isNull());
  EXPECT_NE(first, last) << "the shape grows from the first frame to the last";
  refused("--field S.xx --threshold S11:200:300", "no cell has S11 within 200 .. 300 at this step");
  refused("--field S.xx --threshold S11:200", "--threshold S11:200 is not Q:MIN:MAX");
  refused("--field S.xx --threshold-nodes any", "--threshold-nodes needs --threshold");
  const auto kept =
      runVolpost("render " + bar + " --field S.xx --threshold S11:99:101 --threshold-nodes any --size 96x64 -o " + png +
                 " --save-state " + state);
  ASSERT_EQ(kept.exitCode, 0) << kept.output;
  EXPECT_NE(kept.output.find("the threshold keeps"), std::string::npos) << kept.output;
  std::ifstream withThreshold(state);
  const std::string saved4((std::istreambuf_iterator<char>(withThreshold)), {});
  EXPECT_NE(saved4.find("\"nodes\": \"any\""), std::string::npos) << saved4;
  refused("--field S.xx --log-scale --symmetric", "a log scale has no zero to center");
  refused("--field S.xy --symmetric --no-symmetric", "--symmetric and --no-symmetric: give one");
  const auto noField = runVolpost("render " + bar + " --step-text -o " + png);
  EXPECT_EQ(noField.exitCode, 2);
  EXPECT_NE(noField.output.find("--step-text writes the shown result's step: add --field Q"), std::string::npos)
      << noField.output;
  refused("--field S.xx --log-scale --range -1:1", "a log scale needs a positive color range");
  refused("--field S.xx --log-scale --renderer cpu", "--log-scale colors the surface by the logarithm");
  refused("--field S.xx --background 2,0,0", "--background 2,0,0 is not a color");
  refused("--field S.xx --text-scale 50", "--text-scale 50 is not a factor from 0.25 to 8");
  const auto jpg = runVolpost("render " + bar + " --field S.xx --transparent -o " + (dir / "t.jpg").string());
  EXPECT_EQ(jpg.exitCode, 2);
  EXPECT_NE(jpg.output.find("--transparent needs a picture that keeps transparency"), std::string::npos) << jpg.output;
  const auto report =
      runVolpost("render " + bar + " --field S.xx --transparent --background navy --text-scale 2 --size 96x64 -o " +
                 png + " --save-state " + state);
  ASSERT_EQ(report.exitCode, 0) << report.output;
  const QImage written(QString::fromStdString(png));
  ASSERT_FALSE(written.isNull());
  EXPECT_TRUE(written.hasAlphaChannel());
  EXPECT_EQ(qAlpha(written.pixel(0, 0)), 0);
  std::ifstream again(state);
  const std::string saved2((std::istreambuf_iterator<char>(again)), {});
  EXPECT_NE(saved2.find("\"textScale\": 2.0"), std::string::npos) << saved2;
  const auto outline =
      runVolpost("render " + bar + " --field S.xx --renderer cpu --volume-outline --size 96x64 -o " + png);
  EXPECT_EQ(outline.exitCode, 0) << outline.output;
}

TEST(ProbeCommand, NodesAndElementsByTheirIds) {
  const std::string bar = dataFile("bar/bar_tet4.vtu");
  const auto r = runVolpost("probe " + bar + " --node 5 --element 100 --field S.xx --field region");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* text : {"node 5 at 10, 0, 1: in element", "the node's own values", "element 100 (tet4), centre",
                           "nodes: 327, 2294, 340, 2844", "at node 327 (", "region = 1"})
    EXPECT_NE(r.output.find(text), std::string::npos) << "missing '" << text << "' in\n" << r.output;
  const auto csv = runVolpost("probe " + bar + " --node 3 --field U.x --csv -");
  EXPECT_NE(csv.output.find("0,1,1,"), std::string::npos) << csv.output;  // node 3 is at (0, 1, 1)
  const auto missing = runVolpost("probe " + bar + " --node 99999");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("no node 99999"), std::string::npos) << missing.output;
  EXPECT_EQ(runVolpost("probe " + bar + " --element ten").exitCode, 2);
}

TEST(ProbeCommand, WritesEveryQuantityAtFullPrecisionAsCsvFromAPointsFile) {
  const auto dir = std::filesystem::temp_directory_path() / "volpost_cli_probe";
  std::filesystem::create_directories(dir);
  const std::string points = (dir / "points.txt").string(), csv = (dir / "probe.csv").string();
  {
    std::ofstream out(points);
    out << "x y z\n5 0.5 0.5\n# a comment\n20,0,0\n";
  }
  std::filesystem::remove(csv);
  const auto r = runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --points " + points + " --csv " + csv);
  EXPECT_EQ(r.exitCode, 1) << "one point is outside: " << r.output;
  EXPECT_NE(r.output.find("1 of 2 points are outside the mesh"), std::string::npos) << r.output;
  std::ifstream in(csv);
  std::string header, inside, outside;
  std::getline(in, header);
  std::getline(in, inside);
  std::getline(in, outside);
  EXPECT_EQ(header.rfind("x,y,z,element,element_type,node,U.magnitude,U.x,", 0), 0u) << header;
  EXPECT_NE(header.find(",S.mises,"), std::string::npos) << header;
  EXPECT_EQ(inside.rfind("5,0.5,0.5,", 0), 0u) << inside;
  EXPECT_NE(inside.find(",tet4,,"), std::string::npos) << inside;
  EXPECT_GT(inside.size(), 200u) << "shortest round-trip digits, not 6: " << inside;
  EXPECT_EQ(outside.rfind("20,0,0,,,,nan,", 0), 0u) << outside;

  const auto bad = runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --points " + csv);
  EXPECT_EQ(bad.exitCode, 1) << bad.output;
  EXPECT_NE(bad.output.find("probe.csv:2:"), std::string::npos) << "names the file and line: " << bad.output;
  const auto noField = runVolpost("probe " + dataFile("bar/bar_tet4.vtu") + " --at 5,0.5,0.5 --field S.bogus");
  EXPECT_NE(noField.exitCode, 0);
  EXPECT_NE(noField.output.find("S.bogus"), std::string::npos) << noField.output;
}

// Probed points and the min/max markers change the picture; a point off the model is
// drawn "outside" and noted; the markers need a quantity.
TEST(RenderCommand, MarksProbedPointsAndExtremesAndNotesPointsOutside) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string common = " --field S.mises --size 128x96 --no-legend --camera +y";
  const std::string bare = ::testing::TempDir() + "/bare.png", marked = ::testing::TempDir() + "/marked.png";
  ASSERT_EQ(runVolpost("render " + model + common + " -o " + bare).exitCode, 0);
  const auto r = runVolpost("render " + model + common + " --probe 5,1,0.5 --probe 50,0,0 --mark-extremes -o " + marked);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("probed point 2 (50, 0, 0) lies outside the mesh"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("probed point 1"), std::string::npos) << r.output;
  const QImage without(QString::fromStdString(bare)), with(QString::fromStdString(marked));
  ASSERT_EQ(without.size(), with.size());
  int changed = 0;
  for (int y = 0; y < with.height(); ++y)
    for (int x = 0; x < with.width(); ++x) changed += with.pixel(x, y) != without.pixel(x, y);
  EXPECT_GT(changed, 100) << "markers and their labels are drawn";
  EXPECT_EQ(runVolpost("render " + model + " --mark-extremes -o " + marked).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --probe 1,2 -o " + marked).exitCode, 2);
}

TEST(RenderCommand, ClipBoxKeepsTheInsideAndBadBoxesAreRefused) {
  const std::string out = ::testing::TempDir() + "/boxed.png";
  const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                            " --renderer reference --field S.mises --size 64x48 --clip-box 3,7,0,1,0,1 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(QImage(QString::fromStdString(out)).isNull());
  const auto bad = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --renderer reference --field S.mises --clip-box 7,3,0,1,0,1 -o " + out);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("min < max"), std::string::npos) << bad.output;
  const auto many = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                               " --renderer reference --field S.mises --clip-box 3,7,0,1,0,1 --clip 5,0,0,1,0,0"
                               " --clip 5,0,0,1,0,0 --clip 5,0,0,1,0,0 -o " + out);
  EXPECT_EQ(many.exitCode, 2);
  EXPECT_NE(many.output.find("at most 8"), std::string::npos) << many.output;
}

// The window without a display: one line that says so and what works instead, exit 1 (not
// Qt's abort with a page about platform plugins).
TEST(Window, WithoutADisplaySaysSoInOneLine) {
  const auto r = volpost::test::runVolpostLimited(dataFile("bar/bar_tet4.vtu"), 4L << 20, 30,
                                                  "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("no display to open the window on"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

// --all-steps: one numbered picture per step, on one color scale, so the steps differ; the
// options for one picture are refused.
TEST(RenderCommand, AllStepsWritesOneNumberedPicturePerStep) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "volpost_all_steps";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string model = dataFile("formats/golden.frd"), out = (dir / "t.png").string();
  const auto r = runVolpost("render " + model + " --field T --all-steps --size 96x64 --no-legend -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("step 2 of 2"), std::string::npos) << r.output;
  const QImage first(QString::fromStdString((dir / "t_001.png").string()));
  const QImage second(QString::fromStdString((dir / "t_002.png").string()));
  ASSERT_FALSE(first.isNull());
  ASSERT_FALSE(second.isNull());
  EXPECT_FALSE(std::filesystem::exists(dir / "t.png")) << "only the numbered pictures";
  EXPECT_NE(first, second) << "step 1 is half of step 2 on the common scale";
  // Per step, each step spans the whole map: T doubles and the pictures are the same.
  const std::string one = (dir / "one.png").string(), two = (dir / "two.png").string();
  ASSERT_EQ(runVolpost("render " + model + " --field T --step 1 --size 96x64 --no-legend -o " + one).exitCode, 0);
  ASSERT_EQ(runVolpost("render " + model + " --field T --step 2 --size 96x64 --no-legend -o " + two).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(one)), QImage(QString::fromStdString(two)));
  const std::string common = (dir / "common.png").string();
  ASSERT_EQ(runVolpost("render " + model + " --field T --step 2 --range all-steps --size 96x64 --no-legend -o " + common).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(common)), second) << "--range all-steps: the same scale as the animation";
  // Three frames between the two steps: five pictures, the in-between ones between them.
  const std::string smooth = (dir / "s.png").string();
  const auto between = runVolpost("render " + model +
                                  " --field T --all-steps --frames-between 3 --size 96x64 "
                                  "--no-legend -o " +
                                  smooth);
  ASSERT_EQ(between.exitCode, 0) << between.output;
  EXPECT_NE(between.output.find("frame 5 of 5 (step 2)"), std::string::npos) << between.output;
  EXPECT_EQ(QImage(QString::fromStdString((dir / "s_001.png").string())), first);
  EXPECT_EQ(QImage(QString::fromStdString((dir / "s_005.png").string())), second);
  const QImage middle(QString::fromStdString((dir / "s_003.png").string()));
  ASSERT_FALSE(middle.isNull());
  EXPECT_NE(middle, first);
  EXPECT_NE(middle, second);
  EXPECT_EQ(runVolpost("render " + model + " --field T --frames-between 3 -o " + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --all-steps --frames-between 200 -o " + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --all-steps --step 2 -o " + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --all-steps -o " + out).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --field T --range everything -o " + out).exitCode, 2);
}

// --all-steps to a video: one file whose frames are the numbered pictures (within the
// codec's loss), at the rate asked for; a video without --all-steps, or a rate for
// pictures, is refused before any work.
TEST(RenderCommand, AllStepsToAVideoHasTheStepsAsFrames) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "volpost_all_steps_video";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string model = dataFile("formats/golden.frd"), pictures = (dir / "t.png").string(),
                    video = (dir / "t.mp4").string();
  const std::string common = " --field T --all-steps --size 96x64 --no-legend ";
  ASSERT_EQ(runVolpost("render " + model + common + "-o " + pictures).exitCode, 0);
  const auto r = runVolpost("render " + model + common + "--fps 2 -o " + video);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(video), std::string::npos) << "the video's path is printed: " << r.output;
  const volpost::test::DecodedVideo decoded = volpost::test::decodeVideo(video);
  EXPECT_EQ(decoded.codec, "h264");
  EXPECT_NEAR(decoded.framesPerSecond, 2, 1e-9);
  ASSERT_EQ(decoded.frames.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const QImage picture(QString::fromStdString((dir / ("t_00" + std::to_string(k + 1) + ".png")).string()));
    EXPECT_LT(volpost::test::meanColorDifference(decoded.frames[std::size_t(k)], picture), 3) << "frame " << k;
  }
  EXPECT_GT(volpost::test::meanColorDifference(decoded.frames[0], decoded.frames[1]), 1) << "the steps differ";

  const auto single = runVolpost("render " + model + " --field T -o " + (dir / "one.mp4").string());
  EXPECT_EQ(single.exitCode, 2);
  EXPECT_NE(single.output.find("needs --all-steps"), std::string::npos) << single.output;
  EXPECT_EQ(runVolpost("render " + model + common + "--fps 2 -o " + pictures).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + common + "--fps 0 -o " + video).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + common + "-o " + (dir / "t.gif").string()).exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "one.mp4"));
}

TEST(CommandLine, EveryVerbsHelpNamesTheVerbAndExitsZero) {
  for (const char* verb : {"info", "render", "probe", "convert", "surface", "streamlines", "plugins", "plot"}) {
    const auto r = runVolpost(std::string(verb) + " --help");
    EXPECT_EQ(r.exitCode, 0) << verb;
    EXPECT_EQ(r.output.rfind("Usage: volpost " + std::string(verb) + " [options]", 0), 0u) << r.output;
  }
  // The renderers in their own words, and the options they take, from what they say of
  // themselves: the help names what is loaded.
  std::string help;  // the words as one line, whatever the wrapping
  for (const char c : runVolpost("render --help").output)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!help.empty() && help.back() != ' '))
      help += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  for (const char* entry :
       {"cpu: Ray casting on the CPU", "raycast: Ray casting", "reference: Exact reference",
        "texture-slices: View-aligned", "(drawn by cpu, texture-raymarch, texture-slices, reference)"})
    EXPECT_NE(help.find(entry), std::string::npos) << entry << "\n" << help;
  const auto unknown = runVolpost("render --no-such-option");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("no-such-option"), std::string::npos) << unknown.output;
}

TEST(RenderCommand, WarnsWhenTheTransferFunctionMissesTheResult) {
  const std::string tf = ::testing::TempDir() + "/other_field_tf.json", out = ::testing::TempDir() + "/tf_missing.png";
  std::ofstream(tf) << R"({"format": "volpost-tf", "version": 1, "points": [)"
                    << R"({"value": 1000, "color": [0,0,1], "extinction": 0.5}, {"value": 2000, "color": [1,0,0], "extinction": 1}]})";
  const auto r = runVolpost("render " + dataFile("bar/bar_tet4.vtu") +
                            " --field S.mises --renderer reference --size 32x32 --tf " + tf + " -o " + out);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the transfer function spans 1000 to 2000 but S von Mises spans"), std::string::npos)
      << r.output;
}

// An explicit camera: the state file keeps it, and renders the same picture back.
TEST(RenderCommand, ExplicitCameraRoundTripsThroughTheStateFile) {
  const std::string dir = ::testing::TempDir(), model = dataFile("bar/bar_tet4.vtu");
  const std::string first = dir + "/explicit.png", again = dir + "/explicit_again.png", state = dir + "/explicit.json";
  const auto r = runVolpost("render " + model + " --field S.mises --eye 5,-20,0.5 --target 5,0.5,0.5 --up 0,0,1 "
                            "--view-angle 40 --size 96x64 -o " + first + " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(state);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"fieldOfView\": 40.0"), std::string::npos) << text;
  ASSERT_EQ(runVolpost("render --state " + state + " --size 96x64 -o " + again).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(first)), QImage(QString::fromStdString(again)));
  EXPECT_EQ(runVolpost("render " + model + " --eye 5,0.5,0.5 --target 5,0.5,0.5 -o " + first).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --view-angle 180 -o " + first).exitCode, 2);
  EXPECT_EQ(runVolpost("render " + model + " --up 0,0 -o " + first).exitCode, 2);
}

// --view NAME draws a view saved in the state file (the window's View > Saved Views) as
// the same camera given as the state's own would; an unknown name lists the saved ones.
TEST(RenderCommand, AViewSavedInTheStateFileIsDrawnByName) {
  const std::string dir = ::testing::TempDir(), model = dataFile("bar/bar_tet4.vtu");
  const std::string camera = R"({"eye": [5, -20, 0.5], "target": [5, 0.5, 0.5], "up": [0, 0, 1], "fieldOfView": 40})";
  const std::string head = R"({"format": "volpost-state", "version": 1, "model": ")" + model +
                           R"(", "result": {"quantity": "S.mises", "step": 1}, )";
  const std::string own = dir + "/own_camera.json", named = dir + "/named_view.json";
  std::ofstream(own) << head << R"("camera": )" << camera << "}";
  std::ofstream(named) << head << R"("views": [{"name": "side", "camera": )" << camera << "}]}";
  const std::string a = dir + "/own_camera.png", b = dir + "/named_view.png";
  ASSERT_EQ(runVolpost("render --state " + own + " --size 64x48 -o " + a).exitCode, 0);
  const auto r = runVolpost("render --state " + named + " --view side --size 64x48 -o " + b);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(QImage(QString::fromStdString(a)), QImage(QString::fromStdString(b)));
  const auto unknown = runVolpost("render --state " + named + " --view top -o " + b);
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("no view is saved as \"top\"; the saved views: \"side\""), std::string::npos)
      << unknown.output;
  EXPECT_EQ(runVolpost("render --state " + named + " --view side --camera +x -o " + b).exitCode, 2);
}

// A picture drawn by the reference renderer saves a state that draws it again with the
// reference (it said raycast: `render --state` drew another renderer's picture).
TEST(RenderCommand, AReferencePicturesStateDrawsItWithTheReferenceAgain) {
  const std::string dir = ::testing::TempDir(), model = dataFile("bar/bar_tet4.vtu");
  const std::string first = dir + "/reference.png", again = dir + "/reference_again.png",
                    state = dir + "/reference.json";
  const auto r = runVolpost("render " + model + " --field S.mises --renderer reference --size 48x32 -o " + first +
                            " --save-state " + state);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(state);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"renderer\": \"reference\""), std::string::npos) << text;
  ASSERT_EQ(runVolpost("render --state " + state + " --size 48x32 -o " + again).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(first)), QImage(QString::fromStdString(again)));
}

// The orientation axes sit in the lower left corner; --no-triad leaves them out, and the
// state file keeps the choice.
TEST(RenderCommand, OrientationAxesInTheCornerUnlessTurnedOff) {
  const std::string dir = ::testing::TempDir(), model = dataFile("bar/bar_tet4.vtu");
  const std::string with = dir + "/triad.png", without = dir + "/no_triad.png", state = dir + "/no_triad.json";
  ASSERT_EQ(runVolpost("render " + model + " --size 128x96 --no-legend -o " + with).exitCode, 0);
  ASSERT_EQ(runVolpost("render " + model + " --size 128x96 --no-legend --no-triad -o " + without + " --save-state " + state).exitCode, 0);
  const QImage a(QString::fromStdString(with)), b(QString::fromStdString(without));
  int corner = 0, elsewhere = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.pixel(x, y) != b.pixel(x, y)) (x < 80 && y > a.height() - 80 ? corner : elsewhere)++;
  EXPECT_GT(corner, 20);
  EXPECT_EQ(elsewhere, 0);
  std::ifstream in(state);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"triad\": false"), std::string::npos);
}

// A section cut in the surface view: the bar (fixed at x = 0, pulled at x = 10, so U.x
// grows linearly) cut at x = 5 and seen from +x shows the cut face in the middle color of
// the map, where the uncut bar shows its loaded end in the top color, and a hollow shell
// would show the fixed end's inside in the bottom color.
TEST(RenderCommand, ASectionCutShowsTheCutFaceColoredByTheResult) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string common = " --field U.x --camera +x,ortho --flat --no-legend --no-triad --no-edges --size 64x64 -o ";
  const std::string whole = ::testing::TempDir() + "/bar_whole.png", cut = ::testing::TempDir() + "/bar_cut.png";
  ASSERT_EQ(runVolpost("render " + model + common + whole).exitCode, 0);
  const auto r = runVolpost("render " + model + common + cut + " --clip 5,0.5,0.5,-1,0,0");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const QColor end = QImage(QString::fromStdString(whole)).pixelColor(32, 32);
  const QColor middle = QImage(QString::fromStdString(cut)).pixelColor(32, 32);
  EXPECT_GT(end.red() - end.blue(), 100) << "the loaded end: the top of cool-warm";
  EXPECT_LT(std::abs(middle.red() - middle.blue()), 40) << "halfway: the middle of cool-warm, not the fixed end's blue";
  EXPECT_GT(middle.green(), 150);
  EXPECT_EQ(runVolpost("render " + model + " --clip 1,2,3 -o " + cut).exitCode, 2);
}

// Iso-surfaces in the surface view: opaque, in their own color, also with the surface hidden.
TEST(RenderCommand, IsoSurfacesShowInTheSurfaceView) {
  const std::string model = dataFile("bar/bar_tet4.vtu"), out = ::testing::TempDir() + "/bar_iso_surface.png";
  const auto r = runVolpost("render " + model + " --field U.x --iso 0.002:0,1,0 --no-surface --flat --no-legend "
                            "--no-triad --camera +x --size 64x64 -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const QImage image(QString::fromStdString(out));
  const QColor centre = image.pixelColor(32, 32);
  EXPECT_GT(centre.green(), 200) << "the iso-surface across the bar, seen end on, in its color";
  EXPECT_LT(centre.red(), 60);
}

// Plot over line: the bar's stress along its axis is F/A = 100 away from the ends; a line
// that starts outside the mesh has gaps (nan) there; the chart is written.
TEST(PlotCommand, HistoryAtANodeAnElementAndAPointAsATableAndAChart) {
  const std::string golden = dataFile("formats/golden.frd");  // T at two steps, t = 1 and 2
  const auto r = runVolpost("plot " + golden + " --history --node 10 --element 102 --at 1.5,0.5,0.5 --field T --csv -");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("step,label,time,T at node 10,T at element 102,\"T at (1.5, 0.5, 0.5)\""), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("2,\"step 2, t = 2\",2,0,109.33333333333331,113"), std::string::npos) << r.output;
  const auto png = (std::filesystem::path(::testing::TempDir()) / "volpost_history.png").string();
  const auto chart =
      runVolpost("plot " + golden + " --history --node 10 --element 102 --field T -o " + png + " --size 400x300");
  ASSERT_EQ(chart.exitCode, 0) << chart.output;
  EXPECT_EQ(QImage(QString::fromStdString(png)).size(), QSize(400, 300));
  // Refusals: a line's options, an id the file lacks, places outside only.
  EXPECT_EQ(runVolpost("plot " + golden + " --history --node 10 --from 0,0,0 --csv -").exitCode, 2);
  EXPECT_EQ(runVolpost("plot " + golden + " --node 10 --from 0,0,0 --to 1,0,0 --csv -").exitCode, 2);
  const auto missing = runVolpost("plot " + golden + " --history --node 5 --csv -");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("no node 5 "), std::string::npos) << missing.output;
  EXPECT_EQ(runVolpost("plot " + golden + " --history --at 50,0,0 --csv -").exitCode, 1);
}

TEST(PlotCommand, SamplesALineAsATableAndAChart) {
  const std::string model = dataFile("bar/bar_tet4.vtu");
  const std::string csv = ::testing::TempDir() + "/line.csv", png = ::testing::TempDir() + "/line.png";
  const auto r = runVolpost("plot " + model + " --from -1,0.5,0.5 --to 10,0.5,0.5 --samples 23 --field S.xx --field U.x"
                            " --csv " + csv + " -o " + png + " --size 320x200");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("samples lie outside the mesh"), std::string::npos) << r.output;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "arc_length,x,y,z,element,S.xx,U.x");
  int rows = 0, gaps = 0, hundred = 0;
  while (std::getline(in, line)) {
    ++rows;
    gaps += line.find(",nan,nan") != std::string::npos;
    const auto x = std::stod(line.substr(line.find(',') + 1));
    if (x > 3.0 && x < 7.0) {  // away from the ends: uniform stress
      const auto sxx = line.substr(0, line.rfind(','));
      EXPECT_NEAR(std::stod(sxx.substr(sxx.rfind(',') + 1)), 100.0, 0.5) << line;
      ++hundred;
    }
  }
  EXPECT_EQ(rows, 23);
  EXPECT_EQ(gaps, 2) << "x = -1 and -0.5 lie before the bar";
  EXPECT_GT(hundred, 5);
  EXPECT_EQ(QImage(QString::fromStdString(png)).size(), QSize(320, 200));
  EXPECT_NE(runVolpost("plot " + model + " --from 1,1,1 --to 1,1,1 --csv " + csv).exitCode, 0);
  EXPECT_EQ(runVolpost("plot " + model + " --from 1,1,1 --to 2,1,1").exitCode, 2) << "no output asked for";
  EXPECT_EQ(runVolpost("plot " + model + " --from 1,1,1 --to 2,1,1 --samples 1 --csv " + csv).exitCode, 2);
  EXPECT_NE(runVolpost("plot " + model + " --from 20,5,5 --to 30,5,5 --csv " + csv).exitCode, 0) << "all outside";
  // A quantity or step the model does not have is a usage error, as the README says.
  EXPECT_EQ(runVolpost("plot " + model + " --from 1,1,1 --to 2,1,1 --field S.nope --csv " + csv).exitCode, 2);
  EXPECT_EQ(runVolpost("plot " + model + " --from 1,1,1 --to 2,1,1 --step 3 --csv " + csv).exitCode, 2);
  EXPECT_EQ(runVolpost("probe " + model + " --at 5,0.5,0.5 --field S.nope").exitCode, 2);
}

// ---- seismic volumes ------------------------------------------------------------------

TEST(SeismicCommands, InfoDescribesTheGridAndRenderersDrawIt) {
  const std::string cube = dataFile("seismic/synthetic_12x10x40.sgy");
  const auto info = runVolpost("info " + cube);
  EXPECT_EQ(info.exitCode, 0) << info.output;
  EXPECT_NE(info.output.find("SEG-Y seismic volume (revision 1, big-endian)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("grid:     12 inline (1000 .. 1011 by 1) x 10 crossline (2000 .. 2009 by 1) x 40 time (ms) "
                             "(0 .. 156 by 4)"),
            std::string::npos)
      << info.output;
  EXPECT_NE(info.output.find("samples:  16-bit integer (format 3) in the file"), std::string::npos) << info.output;
  const std::string out = (std::filesystem::temp_directory_path() / "volpost_seismic.png").string();
  for (const std::string renderer : {"texture-raymarch", "texture-slices --shading", "cpu --sampling-step 2 --shading",
                                     "reference --shading", "surface"}) {
    std::filesystem::remove(out);
    const auto r = runVolpost("render " + cube + " --field amplitude --size 64x48 --renderer " + renderer + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << renderer << ": " << r.output;
    EXPECT_TRUE(std::filesystem::exists(out)) << renderer;
  }
}

TEST(SeismicCommands, ProbeSaysWhereInTheSurveyAPointIs) {
  // Inline 1005, crossline 2003, 120 ms of the 30-degree survey (origin 620000, 6080000; 25 m bins).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double x = 620000.0 + 5 * 25 * c - 3 * 25 * s, y = 6080000.0 + 5 * 25 * s + 3 * 25 * c;
  char at[96];
  std::snprintf(at, sizeof at, "%.6f,%.6f,-120", x, y);
  const auto r = runVolpost("probe " + dataFile("seismic/synthetic_12x10x40.sgy") + " --at " + at +
                            " --field amplitude --field envelope");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("inline 1005, crossline 2003, time (ms) 120"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("amplitude = "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("envelope = "), std::string::npos) << r.output;
}

TEST(SeismicCommands, GridRenderersAndGridOptionsRefuseMeshesByName) {
  const std::string mesh = dataFile("bar/bar_tet4.vtu");
  const std::string out = (std::filesystem::temp_directory_path() / "volpost_refused.png").string();
  std::filesystem::remove(out);
  const auto grid = runVolpost("render " + mesh + " --field S.mises --renderer texture-raymarch -o " + out);
  EXPECT_EQ(grid.exitCode, 2) << grid.output;
  EXPECT_NE(grid.output.find("draws regular grids"), std::string::npos) << grid.output;
  const auto shadedMesh = runVolpost("render " + mesh + " --field S.mises --renderer cpu --shading -o " + out);
  EXPECT_EQ(shadedMesh.exitCode, 2) << shadedMesh.output;
  EXPECT_NE(shadedMesh.output.find("regular grids"), std::string::npos) << shadedMesh.output;
  const auto shadedTets = runVolpost("render " + dataFile("seismic/synthetic_12x10x40.sgy") +
                                     " --field amplitude --renderer raycast --shading -o " + out);
  EXPECT_EQ(shadedTets.exitCode, 2) << shadedTets.output;
  const auto step = runVolpost("render " + mesh + " --field S.mises --renderer cpu --sampling-step 0.1 -o " + out);
  EXPECT_EQ(step.exitCode, 2) << step.output;
  EXPECT_NE(step.output.find("--sampling-step"), std::string::npos) << step.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(SeismicCommands, DamagedSegyFilesAreRefusedNamingTheByte) {
  const std::string cube = dataFile("seismic/synthetic_12x10x40.sgy");
  const auto truncated = (std::filesystem::temp_directory_path() / "volpost_truncated.sgy").string();
  std::filesystem::copy_file(cube, truncated, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(truncated, std::filesystem::file_size(cube) - 7);
  const auto r = runVolpost("info " + truncated);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find(truncated + ": byte "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ends inside trace 120"), std::string::npos) << r.output;
}

TEST(SetsOnTheCommandLine, InfoListsThemAndRenderShowsOrHidesThem) {
  const std::string deck = dataFile("formats/golden.inp");
  const auto info = runVolpost("info " + deck);
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_NE(info.output.find("sets:     4"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("E_WEDGE                          1 element  (ELSET)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("NALL                            37 nodes    (NSET)"), std::string::npos) << info.output;

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "volpost_sets_cli";
  std::filesystem::create_directories(dir);
  const std::string all = (dir / "all.png").string(), wedge = (dir / "wedge.png").string();
  const std::string again = (dir / "again.png").string(), state = (dir / "sets.json").string();
  const std::string common = "render " + deck + " --field 'element set' --size 96x64 ";
  ASSERT_EQ(runVolpost(common + "-o " + all).exitCode, 0);
  const auto shown = runVolpost(common + "--show-set e_wedge --show-set E_TET --hide-set E_TET -o " + wedge +
                                " --save-state " + state);
  ASSERT_EQ(shown.exitCode, 0) << shown.output;
  EXPECT_NE(shown.output.find("the chosen sets hold 1 of the 3 cells"), std::string::npos) << shown.output;
  EXPECT_NE(QImage(QString::fromStdString(all)), QImage(QString::fromStdString(wedge)));
  std::ifstream saved(state);
  const std::string text((std::istreambuf_iterator<char>(saved)), {});
  EXPECT_NE(text.find("\"hidden\""), std::string::npos) << text;
  ASSERT_EQ(runVolpost("render --state " + state + " --size 96x64 -o " + again).exitCode, 0);
  EXPECT_EQ(QImage(QString::fromStdString(again)), QImage(QString::fromStdString(wedge)))
      << "the state draws the same part";

  const auto refused = [&](const std::string& options, const std::string& message) {
    const auto r = runVolpost(common + options + " -o " + (dir / "refused.png").string());
    EXPECT_EQ(r.exitCode, 2) << options;
    EXPECT_NE(r.output.find(message), std::string::npos) << options << "\n" << r.output;
  };
  const std::string marked = (dir / "marked.png").string();
  const auto mark = runVolpost(common + "--mark-set NALL -o " + marked);
  ASSERT_EQ(mark.exitCode, 0) << mark.output;
  EXPECT_NE(mark.output.find("37 nodes of NALL are marked"), std::string::npos) << mark.output;
  EXPECT_NE(QImage(QString::fromStdString(all)), QImage(QString::fromStdString(marked)));
  const std::string numbered = (dir / "numbered.png").string();
  ASSERT_EQ(runVolpost(common + "--mark-set NALL --set-numbers -o " + numbered).exitCode, 0);
  EXPECT_NE(QImage(QString::fromStdString(marked)), QImage(QString::fromStdString(numbered)));
  refused("--set-numbers", "--set-numbers writes the marked set's numbers: add --mark-set NAME");
  const std::string colored = (dir / "colored.png").string();
  const auto colors = runVolpost(common + "--color-by-set -o " + colored);
  ASSERT_EQ(colors.exitCode, 0) << colors.output;
  EXPECT_NE(colors.output.find("colored by 3 element sets"), std::string::npos) << colors.output;
  EXPECT_NE(QImage(QString::fromStdString(all)), QImage(QString::fromStdString(colored)));
  refused("--color-by-set --renderer cpu", "--color-by-set colors the surface, sections and slices");
  const std::string selected = (dir / "selected.png").string(), selectedState = (dir / "selected.json").string();
  const auto selection = runVolpost(common + "--select-elements 1-102 --show-set 'selected elements' -o " + selected +
                                    " --save-state " + selectedState);
  ASSERT_EQ(selection.exitCode, 0) << selection.output;
  EXPECT_NE(selection.output.find("the chosen sets hold 2 of the 3 cells"), std::string::npos) << selection.output;
  EXPECT_NE(selection.output.find("of selected elements are marked"), std::string::npos) << selection.output;
  std::ifstream selectedSaved(selectedState);
  const std::string selectedText((std::istreambuf_iterator<char>(selectedSaved)), {});
  EXPECT_NE(selectedText.find("\"elements\": \"101-102\""), std::string::npos) << selectedText;
  refused("--select-elements 104", "--select-elements 104: the model has no element 104");
  refused("--select-nodes 1,x", "--select-nodes 1,x: 'x' in '1,x' is not an id");
  const std::string measured = (dir / "measured.png").string();
  const std::string probes = "--probe 0.5,0.5,0.5 --probe 2.5,0.5,0.5 --probe 3.5,0.5,0.5 ";
  ASSERT_EQ(runVolpost(common + probes + "-o " + marked).exitCode, 0);
  const auto measure = runVolpost(common + probes + "--measure 1,2,3 -o " + measured);
  ASSERT_EQ(measure.exitCode, 0) << measure.output;
  EXPECT_NE(QImage(QString::fromStdString(marked)), QImage(QString::fromStdString(measured)));
  refused(probes + "--measure 1,4", "probe 4 is not there to measure (3 probes)");
  refused(probes + "--measure one,two", "--measure one,two is not probe numbers I,J[,K]");
  const auto probed = runVolpost("probe " + deck + " --element 103");
  ASSERT_EQ(probed.exitCode, 0) << probed.output;
  EXPECT_NE(probed.output.find("  element sets: E_TET\n"), std::string::npos) << probed.output;
  // A plot over a line crosses the chosen sets only.
  const std::string line =
      "plot " + deck + " --from 0.01,0.3,0.3 --to 1.5025,0.3,0.3 --field 'element set' --samples 4 --csv - ";
  const auto plotAll = runVolpost(line);
  ASSERT_EQ(plotAll.exitCode, 0) << plotAll.output;
  EXPECT_NE(plotAll.output.find(",102,2\n"), std::string::npos) << plotAll.output;
  const auto plotHex = runVolpost(line + "--show-set E_HEX");
  ASSERT_EQ(plotHex.exitCode, 0) << plotHex.output;
  EXPECT_EQ(plotHex.output.find(",102,2"), std::string::npos) << plotHex.output;
  EXPECT_NE(plotHex.output.find(",101,1\n"), std::string::npos) << plotHex.output;
  const auto extremes = runVolpost("plot " + deck +
                                   " --history --max-of E_TET --min-of e_tet --field 'element set' "
                                   "--csv -");
  ASSERT_EQ(extremes.exitCode, 0) << extremes.output;
  EXPECT_NE(extremes.output.find("element set at max over E_TET,element set at min over e_tet\n"), std::string::npos)
      << extremes.output;
  EXPECT_NE(extremes.output.find(",3,3\n"), std::string::npos) << extremes.output;
  const auto extremesBad = runVolpost("plot " + deck + " --history --max-of NOPE --csv -");
  EXPECT_EQ(extremesBad.exitCode, 2) << extremesBad.output;
  EXPECT_NE(extremesBad.output.find("no set is named 'NOPE'"), std::string::npos) << extremesBad.output;
  const auto plotBad = runVolpost(line + "--show-set NOPE");
  EXPECT_EQ(plotBad.exitCode, 2);
  EXPECT_NE(plotBad.output.find("no set is named 'NOPE'"), std::string::npos) << plotBad.output;
  refused("--mark-set NOSUCH", "no set is named 'NOSUCH' (its sets: NALL, E_HEX, E_WEDGE, E_TET)");
  refused("--show-set E_BEAM", "no set is named 'E_BEAM' (its element sets: E_HEX, E_WEDGE, E_TET)");
  refused("--hide-set NALL", "'NALL' is a set of 37 nodes");
  refused("--hide-set E_HEX --hide-set E_WEDGE --hide-set E_TET", "leaves no element to draw");
}

// Values that are not numbers (a diverged solver's, or a formula's outside its domain) are
// said on the terminal and in the legend, with what becomes of them: gray on the surface,
// left out of the volume.
TEST(RenderCommand, SaysHowManyValuesAreNotNumbersAndWhatBecomesOfThem) {
  const std::string common = "render " + dataFile("bar/bar_tet4.vtu") +
                             " --formula \"r=sqrt(S11-100)\" --field r --size 96x64 -o " + ::testing::TempDir() +
                             "/nan.png";
  const auto surface = runVolpost(common);
  ASSERT_EQ(surface.exitCode, 0) << surface.output;
  EXPECT_NE(surface.output.find("note: 439 values of r are not numbers (NaN or infinite): drawn gray"),
            std::string::npos)
      << surface.output;
  const auto volume = runVolpost(common + " --renderer cpu");
  ASSERT_EQ(volume.exitCode, 0) << volume.output;
  EXPECT_NE(volume.output.find("439 values of r are not numbers (NaN or infinite): the volume leaves out"),
            std::string::npos)
      << volume.output;
  const auto clean = runVolpost("render " + dataFile("bar/bar_tet4.vtu") + " --field S11 --size 32x32 -o " +
                                ::testing::TempDir() + "/clean.png");
  EXPECT_EQ(clean.output.find("not numbers"), std::string::npos) << clean.output;
}
