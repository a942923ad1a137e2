// SPDX-License-Identifier: MIT
#include "HistoryPanel.hpp"

#include "../core/PictureFile.hpp"
#include "ExportToFile.hpp"

#include "host/AtomicFile.hpp"

#include <QApplication>
#include <QClipboard>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

namespace volpost::app {
namespace {

// The chart, repainted from the panel's history at whatever size the dock has.
class HistoryChart : public QWidget {
 public:
  HistoryChart(const std::optional<History>& history, QWidget* parent) : QWidget(parent), history_(history) {
    setMinimumSize(240, 160);
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    if (history_) paintChart(painter, rect(), historyChart(*history_));
    else painter.drawText(rect(), Qt::AlignCenter, "Probe points, then Plot Over Steps in the Probe panel");
  }

 private:
  const std::optional<History>& history_;
};

}  // namespace

HistoryPanel::HistoryPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  title_ = new QLabel(this);
  title_->setObjectName("historyTitle");
  title_->setWordWrap(true);
  layout->addWidget(title_);
  chart_ = new HistoryChart(history_, this);
  chart_->setObjectName("historyChart");
  layout->addWidget(chart_, 1);
  auto* buttons = new QHBoxLayout;
  const auto button = [&](const QString& text, const char* name, auto slot) {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    connect(b, &QPushButton::clicked, this, slot);
    buttons->addWidget(b);
  };
  button("Copy", "historyCopy", [this] {
    if (history_) QApplication::clipboard()->setText(QString::fromStdString(historyTable(*history_)));
  });
  button("CSV...", "historyCsv", [this] {
    exportTo("Export the history", "CSV (*.csv)",
             [this](const QString& path) { writeFileAtomically(path.toStdString(), historyTable(*history_)); });
  });
  button("Picture...", "historyPicture", [this] {
    exportTo("Save the chart", "PNG image (*.png)",
             [this](const QString& path) { savePicture(chartImage(historyChart(*history_), 800, 500), path); });
  });
  buttons->addStretch(1);
  layout->addLayout(buttons);
}

void HistoryPanel::show(History history) {
  history_ = std::move(history);
  QString places;
  for (const History::Curve& c : history_->curves)
    places += (places.isEmpty() ? "" : ", ") + QString::fromStdString(c.place);
  title_->setText(QString("%1 over %2 steps at %3")
                      .arg(QString::fromStdString(history_->curves.front().quantityName))
                      .arg(history_->times.size())
                      .arg(places));
  chart_->update();
}

void HistoryPanel::exportTo(const QString& title, const QString& filter,
                            const std::function<void(const QString&)>& write) {
  if (!history_) return;
  if (const auto said = exportToChosenFile(this, title, filter, write)) emit message(*said);
}

}  // namespace volpost::app
