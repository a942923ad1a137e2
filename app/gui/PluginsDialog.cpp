// SPDX-License-Identifier: MIT
#include "PluginsDialog.hpp"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace volpost::app {

PluginsDialog::PluginsDialog(const PluginManager& plugins, QWidget* parent) : QDialog(parent) {
  setWindowTitle("Plugins");
  resize(820, 420);
  auto* layout = new QVBoxLayout(this);
  auto* table = new QTableWidget(int(plugins.records().size()), 6, this);
  table->setObjectName("pluginTable");
  table->setHorizontalHeaderLabels({"Status", "Id", "Version", "SDK", "Provides", "File / reason"});
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->horizontalHeader()->setStretchLastSection(true);
  int row = 0;
  for (const PluginRecord& r : plugins.records()) {
    const QStringList cells = {r.loaded ? "loaded" : "refused", r.id, r.version, r.sdkVersion, r.provides.join(", "),
                               r.loaded ? r.path : r.path + "\n" + r.error};
    for (int c = 0; c < cells.size(); ++c) {
      auto* item = new QTableWidgetItem(cells[c]);
      if (!r.loaded) item->setForeground(QColor(170, 30, 30));
      item->setToolTip(r.loaded ? r.description : r.error);
      table->setItem(row, c, item);
    }
    ++row;
  }
  table->resizeColumnsToContents();
  table->resizeRowsToContents();
  layout->addWidget(new QLabel(QString("Searched: %1").arg(PluginManager::defaultSearchPaths().join("; "))));
  layout->addWidget(table, 1);

  layout->addWidget(new QLabel("Your plugin folders (searched at the next start):"));
  auto* row2 = new QHBoxLayout;
  folders_ = new QListWidget(this);
  folders_->addItems(PluginManager::userPaths());
  row2->addWidget(folders_, 1);
  auto* buttons = new QVBoxLayout;
  auto* add = new QPushButton("Add...", this);
  auto* remove = new QPushButton("Remove", this);
  buttons->addWidget(add);
  buttons->addWidget(remove);
  buttons->addStretch();
  row2->addLayout(buttons);
  layout->addLayout(row2);
  connect(add, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, "Plugin folder");
    if (!dir.isEmpty()) {
      folders_->addItem(dir);
      saveFolders();
    }
  });
  connect(remove, &QPushButton::clicked, this, [this] {
    delete folders_->currentItem();
    saveFolders();
  });
  auto* box = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
  layout->addWidget(box);
}

void PluginsDialog::saveFolders() {
  QStringList paths;
  for (int i = 0; i < folders_->count(); ++i) paths << folders_->item(i)->text();
  PluginManager::setUserPaths(paths);
}

}  // namespace volpost::app
