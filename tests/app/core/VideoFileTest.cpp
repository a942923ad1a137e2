// SPDX-License-Identifier: MIT
// Videos of animations: what is encoded decodes back to the same frames (count, size,
// rate, colors within the loss of the codec), in every container offered, and a failed or
// abandoned video leaves no file and what was at the path intact.
#include "core/AnimationFrames.hpp"
#include "core/VideoFile.hpp"
#include "support/TestSupport.hpp"
#include "support/VideoFrames.hpp"

#include <volpost/core/Error.hpp>

#include <QPainter>

#include <filesystem>
#include <fstream>

namespace volpost::app {
namespace {

namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("volpost_video_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A picture like a result's: a smooth color ramp that moves with `k`, and a block of solid
// color, so both gradients and flat areas are checked.
QImage testPicture(int width, int height, int k) {
  QImage picture(width, height, QImage::Format_RGB32);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      picture.setPixel(x, y, qRgb((x * 255) / width, (y * 255) / height, (40 * k) % 256));
  QPainter painter(&picture);
  painter.fillRect(width / 4, height / 4, width / 3, height / 3, QColor(200, 30 + 20 * k, 90));
  return picture;
}

TEST(VideoFile, FramesDecodeBackWithTheirColorsInEveryContainer) {
  const fs::path dir = freshFolder("containers");
  const struct {
    const char* extension;
    const char* codec;
    double tolerance;  // mean difference per channel, of 255
  } cases[] = {{"mp4", "h264", 3}, {"mkv", "h264", 3}, {"webm", "vp9", 4}, {"avi", "mpeg4", 5}};
  for (const auto& c : cases) {
    const std::string path = (dir / (std::string("steps.") + c.extension)).string();
    std::vector<QImage> pictures;
    {
      VideoFile video(QString::fromStdString(path), 96, 64, 2.5);
      for (int k = 0; k < 5; ++k) {
        pictures.push_back(testPicture(96, 64, k));
        video.add(pictures.back());
      }
      EXPECT_FALSE(fs::exists(path)) << "the file appears only when it is complete";
      video.finish();
    }
    const test::DecodedVideo decoded = test::decodeVideo(path);
    EXPECT_EQ(decoded.codec, c.codec) << path;
    EXPECT_NEAR(decoded.framesPerSecond, 2.5, 1e-6) << path;
    ASSERT_EQ(decoded.frames.size(), pictures.size()) << path;
    for (std::size_t k = 0; k < pictures.size(); ++k) {
      EXPECT_LT(test::meanColorDifference(decoded.frames[k], pictures[k]), c.tolerance) << path << " frame " << k;
      if (k > 0) EXPECT_GT(test::meanColorDifference(decoded.frames[k], pictures[k - 1]), 5) << "frames are not all alike";
    }
  }
}

// 4:2:0 color needs even sizes: an odd picture is scaled to the next even size, and a
// frame of another size (a window resized during an export) is scaled to the video's.
TEST(VideoFile, OddAndChangingSizesBecomeTheVideosEvenSize) {
  const fs::path dir = freshFolder("sizes");
  const std::string path = (dir / "odd.mp4").string();
  VideoFile video(QString::fromStdString(path), 97, 63, 4);
  EXPECT_EQ(video.width(), 98);
  EXPECT_EQ(video.height(), 64);
  video.add(testPicture(97, 63, 1));
  video.add(testPicture(200, 130, 2));
  video.finish();
  const test::DecodedVideo decoded = test::decodeVideo(path);
  ASSERT_EQ(decoded.frames.size(), 2u);
  EXPECT_EQ(decoded.frames[0].size(), QSize(98, 64));
  EXPECT_LT(test::meanColorDifference(decoded.frames[1], testPicture(98, 64, 2)), 6);
}

TEST(VideoFile, AnAbandonedOrFailedVideoLeavesWhatWasThere) {
  const fs::path dir = freshFolder("abandon");
  const fs::path path = dir / "kept.mp4";
  std::ofstream(path) << "the user's earlier video";
  {
    VideoFile video(QString::fromStdString(path.string()), 64, 64, 4);
    video.add(testPicture(64, 64, 0));
  }  // dropped before finish (an export cancelled)
  std::ifstream in(path);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "the user's earlier video");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "no temporary file left";

  EXPECT_THROW(VideoFile((dir / "missing" / "v.mp4").string().c_str(), 64, 64, 4), WriteError);
  EXPECT_THROW(VideoFile((dir / "v.gif").string().c_str(), 64, 64, 4), WriteError);
  EXPECT_THROW(VideoFile((dir / "v.mp4").string().c_str(), 64, 64, 0), std::invalid_argument);
  EXPECT_THROW(VideoFile((dir / "v.mp4").string().c_str(), 0, 64, 4), std::invalid_argument);
  VideoFile empty((dir / "empty.mp4").string().c_str(), 64, 64, 4);
  EXPECT_THROW(empty.finish(), WriteError) << "a video needs a frame";
  EXPECT_FALSE(fs::exists(dir / "empty.mp4"));
}

TEST(AnimationOutput, PicturesAreNumberedAndAVideoIsOneFile) {
  const fs::path dir = freshFolder("animation");
  AnimationOutput pictures(QString::fromStdString((dir / "s.png").string()), 2);
  EXPECT_FALSE(pictures.isVideo());
  EXPECT_EQ(pictures.add(testPicture(32, 32, 0)).toStdString(), (dir / "s_001.png").string());
  EXPECT_EQ(pictures.add(testPicture(32, 32, 1)).toStdString(), (dir / "s_002.png").string());
  EXPECT_TRUE(fs::exists(dir / "s_002.png"));

  AnimationOutput video(QString::fromStdString((dir / "s.webm").string()), 3, 1);
  EXPECT_TRUE(video.isVideo());
  for (int k = 0; k < 3; ++k) video.add(testPicture(32, 32, k));
  EXPECT_EQ(video.finish().toStdString(), (dir / "s.webm").string());
  EXPECT_EQ(test::decodeVideo((dir / "s.webm").string()).frames.size(), 3u);
}

}  // namespace
}  // namespace volpost::app
