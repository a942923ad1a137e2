// SPDX-License-Identifier: MIT
#include "ExportToFile.hpp"

#include <QFileDialog>
#include <QSettings>

#include <exception>

namespace volpost::app {

std::optional<QString> exportToChosenFile(QWidget* parent, const QString& title, const QString& filter,
                                          const std::function<void(const QString&)>& write) {
  QSettings settings("volpost", "volpost");
  const QString path = QFileDialog::getSaveFileName(parent, title, settings.value("files/lastDir").toString(), filter);
  if (path.isEmpty()) return std::nullopt;
  try {
    write(path);
    return "Wrote " + path;
  } catch (const std::exception& e) {
    return QString("Could not write %1: %2").arg(path, e.what());
  }
}

}  // namespace volpost::app
