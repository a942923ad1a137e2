// SPDX-License-Identifier: MIT
// The History dock: a quantity against the steps at probed points (Probe panel > Plot Over
// Steps), as a chart, with Copy, CSV and picture export.
#pragma once

#include "../core/History.hpp"

#include <QWidget>

#include <optional>

class QLabel;

namespace volpost::app {

class HistoryPanel : public QWidget {
  Q_OBJECT

 public:
  explicit HistoryPanel(QWidget* parent = nullptr);
  void show(History history);
  const std::optional<History>& history() const { return history_; }

 signals:
  void message(const QString& text);

 private:
  void exportTo(const QString& title, const QString& filter, const std::function<void(const QString&)>& write);

  std::optional<History> history_;
  QWidget* chart_ = nullptr;
  QLabel* title_ = nullptr;
};

}  // namespace volpost::app
