// SPDX-License-Identifier: MIT
// Long work behind a progress dialog, alone (offscreen): the value, an error and a cancel
// come back on the GUI thread; the dialog shows the stage and is gone by then.
#include "gui/WorkWithProgress.hpp"

#include <QApplication>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QWidget>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

using namespace volpost;
using namespace volpost::app;

class WorkWithProgressTest : public QObject {
  Q_OBJECT

 private slots:
  void theValueComesBackOnTheGuiThreadWithTheDialogGone() {
    QWidget parent;
    std::optional<WorkOutcome<int>> got;
    const auto gui = QThread::currentThread();
    QThread* worker = nullptr;
    runWithProgress<int>(
        parent, "Adding", 0,
        [&worker](const Progress& p) {
          worker = QThread::currentThread();
          p.report(0.5);
          return 42;
        },
        [&](WorkOutcome<int> o) {
          QCOMPARE(QThread::currentThread(), gui);
          got = std::move(o);
        });
    QTRY_VERIFY_WITH_TIMEOUT(got.has_value(), 10000);
    QCOMPARE(got->value.value_or(0), 42);
    QVERIFY(!got->cancelled && got->error.isEmpty());
    QVERIFY(worker && worker != gui);
    QTRY_VERIFY(parent.findChildren<QProgressDialog*>().isEmpty());
  }

  void anErrorComesBackInItsOwnWords() {
    QWidget parent;
    std::optional<WorkOutcome<int>> got;
    runWithProgress<int>(
        parent, "Reading", 0, [](const Progress&) -> int { throw std::runtime_error("bar.vtu: line 7: no cells"); },
        [&](WorkOutcome<int> o) { got = std::move(o); });
    QTRY_VERIFY_WITH_TIMEOUT(got.has_value(), 10000);
    QVERIFY(!got->value && !got->cancelled);
    QCOMPARE(got->error, QString("bar.vtu: line 7: no cells"));
  }

  void theDialogShowsTheStageAndCancelStopsTheWork() {
    QWidget parent;
    parent.show();
    std::optional<WorkOutcome<int>> got;
    std::atomic<bool> running{true};
    runWithProgress<int>(
        parent, "Reading big.frd", 0,
        [&running](const Progress& given) {
          Progress p = given;
          p.setStage("reading the nodes");
          const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
          while (std::chrono::steady_clock::now() < until) {  // until cancelled, or a bounded wait
            p.report(0.25);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
          }
          running = false;
          return 1;
        },
        [&](WorkOutcome<int> o) { got = std::move(o); });
    QProgressDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = parent.findChild<QProgressDialog*>()) != nullptr);
    QTRY_COMPARE(dialog->labelText(), QString("Reading big.frd: reading the nodes..."));
    QTRY_COMPARE(dialog->value(), 25);
    auto* cancel = dialog->findChild<QPushButton*>();
    QVERIFY(cancel);
    QCOMPARE(cancel->text(), QString("Cancel"));
    QTest::mouseClick(cancel, Qt::LeftButton);  // as the user does
    QTRY_VERIFY_WITH_TIMEOUT(got.has_value(), 10000);
    QVERIFY(got->cancelled);
    QVERIFY(!got->value);
    QVERIFY2(running, "the work stopped at Cancel, not at its own end");
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  WorkWithProgressTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "WorkWithProgressTest.moc"
