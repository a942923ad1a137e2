// SPDX-License-Identifier: MIT
// File > Open Recent: the last models opened (kept in the settings), newest first; files
// that are gone are left out of the menu.
#pragma once

#include <QObject>
#include <QStringList>

#include <functional>

class QMenu;

namespace volpost::app {

class RecentFiles : public QObject {
  Q_OBJECT

 public:
  static constexpr int kMaxFiles = 10;
  /// Fills `menu` (each time it opens); choosing an entry calls `open` with its path.
  RecentFiles(QMenu& menu, std::function<void(const QString&)> open, QObject* parent);

  /// A model that opened: first in the list (and its folder the Open dialog's start).
  static void add(const QString& path);
  static QStringList paths();

 private:
  void fill();

  QMenu& menu_;
  std::function<void(const QString&)> open_;
};

}  // namespace volpost::app
