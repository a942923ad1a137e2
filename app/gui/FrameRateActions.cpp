// SPDX-License-Identifier: MIT
#include "FrameRateActions.hpp"

#include "Viewport.hpp"

#include <QAction>
#include <QFileDialog>
#include <QMenu>
#include <QStatusBar>

namespace volpost::app {

FrameRateActions::FrameRateActions(QWidget& window, Viewport& viewport, QMenu& view, QStatusBar& status)
    : QObject(&window), window_(window), viewport_(viewport), status_(status) {
  show_ = view.addAction("Show &Frame Rate");
  show_->setObjectName("showFrameRateAction");
  show_->setCheckable(true);
  show_->setStatusTip(
      "How long a frame takes to follow the mouse, how many follow a drag each second, and how "
      "long the full picture takes after the last change");
  connect(show_, &QAction::toggled, this, [this](bool on) { viewport_.setShowFrameRate(on); });
  log_ = view.addAction("Log Frame &Times...");
  log_->setObjectName("logFrameTimesAction");
  log_->setCheckable(true);
  log_->setStatusTip("Writes each timed frame to a text file, one line each, until unchecked");
  connect(log_, &QAction::triggered, this, [this](bool on) {
    if (!on) {
      logTo({});
      return;
    }
    const QString path =
        QFileDialog::getSaveFileName(&window_, "Log frame times to", "frame_times.txt", "Text files (*.txt *.log)");
    logTo(path);
  });
}

bool FrameRateActions::logTo(const QString& path) {
  bool ok = true;
  try {
    viewport_.setFrameLog(path);
    if (!path.isEmpty()) status_.showMessage(QString("Frame times are written to %1").arg(path));
  } catch (const std::exception& e) {
    status_.showMessage(QString("Log Frame Times: %1").arg(e.what()));
    ok = false;
  }
  const QSignalBlocker quiet(log_);
  log_->setChecked(!viewport_.frameLogPath().isEmpty());  // the entry says whether a log runs
  return ok;
}

}  // namespace volpost::app
