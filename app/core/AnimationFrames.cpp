// SPDX-License-Identifier: MIT
#include "AnimationFrames.hpp"

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

}  // namespace volpost::app
