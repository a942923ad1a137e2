// SPDX-License-Identifier: MIT
#include "RecentFiles.hpp"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace volpost::app {

RecentFiles::RecentFiles(QMenu& menu, std::function<void(const QString&)> open, QObject* parent)
    : QObject(parent), menu_(menu), open_(std::move(open)) {
  connect(&menu_, &QMenu::aboutToShow, this, &RecentFiles::fill);
  fill();
}

void RecentFiles::add(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QSettings settings("volpost", "volpost");
  QStringList list = settings.value("files/recent").toStringList();
  list.removeAll(absolute);
  list.prepend(absolute);
  while (list.size() > kMaxFiles) list.removeLast();
  settings.setValue("files/recent", list);
  settings.setValue("files/lastDir", QFileInfo(absolute).absolutePath());
}

QStringList RecentFiles::paths() { return QSettings("volpost", "volpost").value("files/recent").toStringList(); }

void RecentFiles::fill() {
  menu_.clear();
  int number = 0;
  for (const QString& path : paths()) {
    if (!QFileInfo(path).isFile()) continue;
    ++number;
    // "&1 wheel.vtu  (/home/...)": the name first, the folder to tell twins apart.
    const QString label = QString("&%1 %2  (%3)")
                              .arg(number % 10)
                              .arg(QFileInfo(path).fileName(), QDir::toNativeSeparators(QFileInfo(path).absolutePath()));
    QAction* action = menu_.addAction(label);
    action->setData(path);
    connect(action, &QAction::triggered, this, [this, path] { open_(path); });
  }
  if (number == 0) menu_.addAction("No recent models")->setEnabled(false);
  menu_.setEnabled(true);
}

}  // namespace volpost::app
