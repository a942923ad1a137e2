// SPDX-License-Identifier: MIT
#include "WorkWithProgress.hpp"

#include <QFutureWatcher>
#include <QProgressDialog>
#include <QTimer>
#include <QWidget>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <mutex>

namespace volpost::app::detail {
namespace {

// What the worker reports and the dialog reads, shared between the two threads.
struct Shared {
  std::atomic<int> percent{0};
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  QString stage;
};

}  // namespace

void runWithProgress(QWidget& parent, const QString& label, int delayMs, std::function<void(const Progress&)> work,
                     std::function<void()> done) {
  auto shared = std::make_shared<Shared>();
  auto* dialog = new QProgressDialog(label + "...", "Cancel", 0, 100, &parent);
  dialog->setWindowModality(Qt::WindowModal);
  dialog->setMinimumDuration(delayMs);
  QObject::connect(dialog, &QProgressDialog::canceled, dialog, [shared] { shared->cancel = true; });
  auto* timer = new QTimer(dialog);
  QObject::connect(timer, &QTimer::timeout, dialog, [dialog, shared, label] {
    QString stage;
    {
      const std::lock_guard lock(shared->mutex);
      stage = shared->stage;
    }
    if (!stage.isEmpty()) dialog->setLabelText(QString("%1: %2...").arg(label, stage));
    dialog->setValue(shared->percent);
  });
  timer->start(50);
  auto* watcher = new QFutureWatcher<void>(&parent);
  QObject::connect(watcher, &QFutureWatcher<void>::finished, &parent, [watcher, dialog, timer, done = std::move(done)] {
    watcher->deleteLater();
    // The dialog goes now, not when control is back in the main loop: a message box that
    // `done` opens runs its own loop, in which the timer would show the dialog again.
    timer->stop();
    dialog->reset();
    dialog->hide();
    dialog->deleteLater();
    done();
  });
  watcher->setFuture(QtConcurrent::run([shared, work = std::move(work)] {
    work(Progress([shared](double fraction, const std::string& stage) {
      shared->percent = int(fraction * 100.0);
      const std::lock_guard lock(shared->mutex);
      shared->stage = QString::fromStdString(stage);
      return !shared->cancel;
    }));
  }));
}

}  // namespace volpost::app::detail
