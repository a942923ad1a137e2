// SPDX-License-Identifier: MIT
// A video of pictures (an animation over the steps of a result), encoded with FFmpeg's
// libraries as Debian ships them: .mp4 and .mkv as H.264, .webm as VP9, .avi as MPEG-4
// part 2, every one in 4:2:0 color, which players everywhere read. Written whole or not
// at all: the frames go to a temporary file beside the target, renamed over it by
// finish(); a failure (or a VideoFile dropped before finish) leaves what was there.
#pragma once

#include <QImage>
#include <QString>
#include <QStringList>

#include <memory>

namespace volpost::app {

class VideoFile {
 public:
  /// Whether `path`'s extension names a video container this class writes.
  static bool isVideoPath(const QString& path);
  /// The extensions isVideoPath accepts, lower case, without the dot.
  static QStringList extensions();

  /// Opens the encoder for frames of width x height (odd sizes are rounded up to even,
  /// which 4:2:0 color needs) at `framesPerSecond` (0.1 .. 120). Throws WriteError naming
  /// the file when the folder cannot be written or the encoder is missing, and
  /// std::invalid_argument for a size or rate out of range.
  VideoFile(const QString& path, int width, int height, double framesPerSecond);
  ~VideoFile();
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;

  /// Encodes one frame; a picture of another size is scaled to the video's. Throws
  /// WriteError.
  void add(const QImage& picture);
  /// Flushes the encoder, writes the container's index and renames the file into place.
  /// Throws WriteError (then nothing is left at the path but what was there before).
  void finish();

  int width() const;
  int height() const;
  int frameCount() const;

 private:
  struct Encoder;
  std::unique_ptr<Encoder> encoder_;
};

}  // namespace volpost::app
