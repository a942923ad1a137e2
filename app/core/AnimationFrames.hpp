// SPDX-License-Identifier: MIT
// An animation over the steps of a result, for the window's File > Export Animation and
// `volpost render --all-steps`: numbered pictures, or one video when the path names a
// video file (.mp4, .mkv, .webm, .avi).
#pragma once

#include "VideoFile.hpp"

#include <QImage>
#include <QString>

#include <cstddef>
#include <memory>

namespace volpost::app {

/// The path of frame `index` (0-based) of `count`: the number, from 1 and zero-padded to
/// the digits of `count` (at least 3), inserted before the extension of `path`:
/// frames/wheel.png -> frames/wheel_001.png.
QString framePath(const QString& path, std::size_t index, std::size_t count);

/// Where the frames of an animation go: `count` numbered pictures beside `path`, each
/// written as it comes, or one video at `path` (written whole by finish(), at
/// `framesPerSecond`). Throws WriteError naming the file that failed.
class AnimationOutput {
 public:
  /// The default rate of a video: slow enough to read a step's colors.
  static constexpr double kDefaultFramesPerSecond = 4;

  AnimationOutput(QString path, std::size_t count, double framesPerSecond = kDefaultFramesPerSecond);

  bool isVideo() const { return VideoFile::isVideoPath(path_); }
  /// The next frame; returns the file it went to (the picture's, or the video's).
  QString add(const QImage& picture);
  /// For a video, writes it; returns the video's path (for pictures: the first one's).
  QString finish();
  std::size_t added() const { return added_; }

 private:
  QString path_;
  std::size_t count_;
  double framesPerSecond_;
  std::size_t added_ = 0;
  std::unique_ptr<VideoFile> video_;
};

}  // namespace volpost::app
