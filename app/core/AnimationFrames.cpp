// SPDX-License-Identifier: MIT
#include "AnimationFrames.hpp"

#include "PictureFile.hpp"

#include <QFileInfo>

#include <algorithm>

namespace volpost::app {

QString framePath(const QString& path, std::size_t index, std::size_t count) {
  const int digits = std::max(3, int(QString::number(qulonglong(std::max<std::size_t>(count, 1))).size()));
  const QString number = QString("_%1").arg(qulonglong(index + 1), digits, 10, QChar('0'));
  // Only the file name's last suffix: a dot in a folder name stays where it is.
  const QString suffix = QFileInfo(path).suffix();
  if (suffix.isEmpty()) return path + number;
  return path.left(path.size() - suffix.size() - 1) + number + "." + suffix;
}

AnimationOutput::AnimationOutput(QString path, std::size_t count, double framesPerSecond)
    : path_(std::move(path)), count_(count), framesPerSecond_(framesPerSecond) {}

QString AnimationOutput::add(const QImage& picture) {
  if (isVideo()) {
    // The video's size is the first frame's; later frames of another size are scaled.
    if (!video_) video_ = std::make_unique<VideoFile>(path_, picture.width(), picture.height(), framesPerSecond_);
    video_->add(picture);
    ++added_;
    return path_;
  }
  const QString path = framePath(path_, added_, count_);
  savePicture(picture, path);
  ++added_;
  return path;
}

QString AnimationOutput::finish() {
  if (video_) {
    video_->finish();
    video_.reset();
    return path_;
  }
  return framePath(path_, 0, count_);
}

}  // namespace volpost::app
