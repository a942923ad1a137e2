// SPDX-License-Identifier: MIT
// The transfer-function editor driven like a user (mouse and keyboard under Xvfb): add,
// drag, delete a point, undo, numeric entry, presets, files. Checks the resulting
// function, what the host received, and the iso-detection table built from it.
#include "TfEditorPanel.hpp"

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <cmath>

using namespace volpost;
using namespace volpost::tfeditor;

namespace {

// A host with a result of values 0..100 and a 10-unit model.
class FakeHost : public PanelHost {
 public:
  FakeHost() {
    for (int i = 0; i <= 1000; ++i) values.push_back(i * 0.1);
    tf = TransferFunction({{0.0, {0, 0, 1}, 0.0}, {100.0, {1, 0, 0}, opacityToExtinction(0.5, 1.0)}});
  }
  const Model* model() const override { return nullptr; }
  std::optional<Quantity> activeQuantity() const override {
    Quantity q;
    q.field = "T";
    return q;
  }
  std::size_t activeStep() const override { return 0; }
  void requestRender() override {}
  TransferFunction transferFunction() const override { return tf; }
  void setTransferFunction(const TransferFunction& f) override {
    tf = f;
    ++received;
  }
  SampleView activeValues() const override { return values; }
  double modelSize() const override { return 10.0; }
  double lastTransferFunctionMs() const override { return 0.0; }
  std::optional<TransferFunction2D> transferFunction2D() const override { return tf2d; }
  bool setTransferFunction2D(const std::optional<TransferFunction2D>& f) override {
    tf2d = f;
    ++received2d;
    return true;
  }

  std::vector<double> values;
  TransferFunction tf;
  std::optional<TransferFunction2D> tf2d;
  int received = 0, received2d = 0;
};

}  // namespace

class TfEditorTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<FakeHost> host_;
  std::unique_ptr<TfEditorPanel> panel_;

  QPoint at(double value, double opacity) const { return panel_->curve().toPixel(value, opacity).toPoint(); }

 private slots:
  void init() {
    QSettings("volpost", "volpost").remove("tfeditor");  // no state from an earlier run
    host_ = std::make_unique<FakeHost>();
    panel_ = std::make_unique<TfEditorPanel>(*host_);
    panel_->resize(420, 480);
    panel_->show();
    QVERIFY(QTest::qWaitForWindowExposed(panel_.get()));

    panel_->curve().setView(0.0, 100.0);
  }
  void cleanup() { panel_.reset(); }

  // A large model's histogram comes from a subsample that still holds its extremes: the
  // view spans the exact smallest and largest value even where the stride skips them.
  void aLargeModelsHistogramKeepsItsExtremes() {
    std::vector<double> values(3 * TfCurveWidget::kMaxHistogramValues + 7);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = double(i % 1000);
    values[5] = -1234.5;   // not on the stride
    values[values.size() - 2] = 98765.25;
    values[11] = std::nan("");
    panel_->curve().setData(values);
    // The data's own range, as the legend shows it: no padding beyond it (0..0.99997 showed
    // as -0.02..1.02).
    const auto [lo, hi] = panel_->curve().view();
    QCOMPARE(lo, -1234.5);
    QCOMPARE(hi, 98765.25);
  }

  // The histogram and range follow other values only: a change the host shows with the same
  // values (a color map, the volume switched on) keeps the user's zoom and costs no pass
  // over a large model's values; new values (another step, result or file) reset the view.
  void theHistogramIsRebuiltForOtherValuesOnly() {
    panel_->hostChanged();
    panel_->curve().setView(20.0, 30.0);
    panel_->hostChanged();
    QCOMPARE(panel_->curve().view(), std::make_pair(20.0, 30.0));
    host_->values = std::vector<double>{500.0, 700.0, 900.0};
    panel_->hostChanged();
    const auto [lo, hi] = panel_->curve().view();
    QVERIFY2(lo <= 500.0 && hi >= 900.0, "the view shows the new values");
  }

  // A function the host gets from elsewhere (a state file opened in the window) is what
  // the panel shows and edits; the panel's own edits, sent or still waiting, are not undone
  // by it, and an edit sent does not reload the panel (its undo history stays).
  void aFunctionSetByTheHostIsWhatThePanelEdits() {
    panel_->hostChanged();
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(40.0, 0.2));
    panel_->flush();
    panel_->hostChanged();  // the host answers every change it shows
    QCOMPARE(int(panel_->model().points().size()), 3);
    QVERIFY(panel_->model().undoStack()->canUndo());
    host_->tf = TransferFunction({{10.0, {0, 1, 0}, 0.0}, {15.0, {1, 0.5, 0}, 2.0}, {20.0, {1, 0, 0}, 0.0},
                                  {90.0, {1, 0, 0}, 0.0}});
    panel_->hostChanged();
    QCOMPARE(int(panel_->model().points().size()), 4);
    QCOMPARE(panel_->model().points()[1].value, 15.0);
    panel_->flush();  // nothing waiting: the host keeps its function
    QCOMPARE(host_->tf.points()[1].extinction, 2.0);
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(60.0, 0.3));  // waits to be sent
    panel_->hostChanged();
    QCOMPARE(int(panel_->model().points().size()), 5);
    panel_->flush();
    QCOMPARE(int(host_->tf.points().size()), 5);
  }

  void startsFromTheHostsFunctionWithOpacityOverATenthOfTheModel() {
    QCOMPARE(panel_->model().referenceLength(), 1.0);
    QCOMPARE(int(panel_->model().points().size()), 2);
    QVERIFY(std::abs(panel_->model().points()[1].opacity - 0.5) < 1e-12);
  }

  void clickAddsAPointAndTheHostAndIsoTableFollow() {
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(40.0, 0.2));
    const auto& p = panel_->model().points();
    QCOMPARE(int(p.size()), 3);
    QVERIFY(std::abs(p[1].value - 40.0) < 0.5);       // within a pixel of the click
    QVERIFY(std::abs(p[1].opacity - 0.2) < 0.02);
    panel_->flush();
    QCOMPARE(int(host_->tf.points().size()), 3);
    const double added = host_->tf.points()[1].value;
    // The iso-detection table: a segment from just below to just above the new point
    // crosses it first; one that stays below crosses nothing.
    const optics::IsoDetectionTable* iso = panel_->isoTable();
    QVERIFY(iso);
    const auto [crossed, next] = iso->at(added - 2.0, added + 2.0);
    QVERIFY2(std::abs(crossed - added) < 0.5, qPrintable(QString::number(crossed)));
    QCOMPARE(next, -1.0);
    QCOMPARE(iso->at(added - 6.0, added - 3.0).first, -1.0);
  }

  void dragMovesThePointAndOneUndoBringsItBack() {
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(40.0, 0.2));
    const double before = panel_->model().points()[1].value;
    QTest::mousePress(&panel_->curve(), Qt::LeftButton, {}, at(before, 0.2));
    for (double v = before; v <= 60.0; v += 5.0) QTest::mouseMove(&panel_->curve(), at(v, 0.2));
    QTest::mouseRelease(&panel_->curve(), Qt::LeftButton, {}, at(60.0, 0.2));
    QVERIFY(std::abs(panel_->model().points()[1].value - 60.0) < 0.5);
    panel_->curve().setFocus();
    QTest::keyClick(&panel_->curve(), Qt::Key_Z, Qt::ControlModifier);  // the whole drag is one step
    QVERIFY(std::abs(panel_->model().points()[1].value - before) < 1e-12);
    QTest::keyClick(&panel_->curve(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(std::abs(panel_->model().points()[1].value - 60.0) < 0.5);
  }

  void shiftDragSnapsToDataValues() {
    host_->values = {10.0, 33.3, 70.0};
    panel_->hostChanged();
    panel_->curve().setView(0.0, 100.0);
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(50.0, 0.2));
    QTest::mousePress(&panel_->curve(), Qt::LeftButton, {}, at(50.0, 0.2));
    QTest::mouseMove(&panel_->curve(), at(36.0, 0.2));
    QTest::mouseMove(&panel_->curve(), at(35.0, 0.2));
    QMouseEvent move(QEvent::MouseMove, QPointF(at(35.0, 0.2)), panel_->curve().mapToGlobal(QPointF(at(35.0, 0.2))),
                     Qt::NoButton, Qt::LeftButton, Qt::ShiftModifier);
    QApplication::sendEvent(&panel_->curve(), &move);
    QTest::mouseRelease(&panel_->curve(), Qt::LeftButton, Qt::ShiftModifier, at(35.0, 0.2));
    bool snapped = false;
    for (const auto& p : panel_->model().points()) snapped = snapped || p.value == 33.3;
    QVERIFY(snapped);
  }

  void deleteKeyAndRightClickRemovePointsAndUndoRestoresThem() {
    QTest::mouseClick(&panel_->curve(), Qt::LeftButton, {}, at(40.0, 0.2));
    QCOMPARE(int(panel_->model().points().size()), 3);
    QTest::keyClick(&panel_->curve(), Qt::Key_Delete);
    QCOMPARE(int(panel_->model().points().size()), 2);
    QTest::mouseClick(&panel_->curve(), Qt::RightButton, {}, at(100.0, 0.5));
    QCOMPARE(int(panel_->model().points().size()), 1);
    QTest::keyClick(&panel_->curve(), Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(&panel_->curve(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(int(panel_->model().points().size()), 3);
    panel_->flush();
    QCOMPARE(int(host_->tf.points().size()), 3);
  }

  void keyboardSelectsMovesAndEntersExactValues() {
    panel_->curve().setFocus();
    QTest::keyClick(&panel_->curve(), Qt::Key_PageDown);  // first point
    QCOMPARE(int(panel_->model().selection().size()), 1);
    QTest::keyClick(&panel_->curve(), Qt::Key_PageDown);  // second point (value 100)
    const int id = *panel_->model().selection().begin();
    QTest::keyClick(&panel_->curve(), Qt::Key_Left);      // 1% of the view to the left
    QVERIFY(std::abs(panel_->model().points()[std::size_t(panel_->model().indexOf(id))].value - 99.0) < 1e-9);
    auto* value = panel_->findChild<QLineEdit*>("tfValue");
    auto* opacity = panel_->findChild<QLineEdit*>("tfOpacity");
    value->setFocus();
    value->selectAll();
    QTest::keyClicks(value, "87.125");
    opacity->setText("0.003");
    QTest::keyClick(value, Qt::Key_Return);
    const auto& p = panel_->model().points()[std::size_t(panel_->model().indexOf(id))];
    QCOMPARE(p.value, 87.125);
    QCOMPARE(p.opacity, 0.003);
    opacity->setText("1.5");  // refused with a message, nothing changes
    QTest::keyClick(opacity, Qt::Key_Return);
    QCOMPARE(panel_->model().points()[std::size_t(panel_->model().indexOf(id))].opacity, 0.003);
    panel_->flush();
    QVERIFY(std::abs(host_->tf.points().back().extinction - opacityToExtinction(0.003, 1.0)) < 1e-15);
  }

  void opacityShapesKeepTheColorsAndThePeak() {
    const auto before = panel_->model().points();
    double peak = 0.0;
    for (const auto& p : before) peak = std::max(peak, p.opacity);
    panel_->applyOpacityShape("falling");
    const auto& after = panel_->model().points();
    QCOMPARE(after.size(), before.size());
    for (std::size_t i = 0; i < after.size(); ++i) QCOMPARE(after[i].color, before[i].color);
    QVERIFY(std::abs(after.front().opacity - peak) < 1e-12);
    QVERIFY(std::abs(after.back().opacity - 0.1 * peak) < 1e-12);
    panel_->applyOpacityShape("rising");
    QVERIFY(std::abs(panel_->model().points().back().opacity - peak) < 1e-12);
    // The Undo button keeps its word (the panel does not change width); the step is in its tooltip.
    QToolButton* undoButton = nullptr;
    for (auto* b : panel_->findChildren<QToolButton*>())
      if (b->defaultAction() && b->defaultAction()->text() == "Undo") undoButton = b;
    QVERIFY(undoButton);
    QCOMPARE(undoButton->text(), QString("Undo"));
    QVERIFY2(undoButton->defaultAction()->toolTip().contains("Opacity rising"), qPrintable(undoButton->defaultAction()->toolTip()));
    panel_->model().undoStack()->undo();  // one undo step each
    QVERIFY(std::abs(panel_->model().points().front().opacity - peak) < 1e-12);
    panel_->model().undoStack()->undo();
    QCOMPARE(panel_->model().points(), before);
  }

  void presetsRecolorAndFilesRoundTrip() {
    panel_->applyPreset("grayscale");
    const auto& p = panel_->model().points();
    QCOMPARE(p.front().color, QColor::fromRgbF(0, 0, 0));
    QVERIFY(p.back().color.redF() > 0.99f);
    QTemporaryDir dir;
    const QString file = dir.filePath("tf.json");
    QString error;
    QVERIFY(panel_->saveFile(file, &error));
    panel_->model().load(TransferFunction({{5.0, {1, 1, 1}, 0.0}}), "other", false);
    QVERIFY(panel_->loadFile(file, &error));
    QCOMPARE(int(panel_->model().points().size()), 2);
    QFile bad(dir.filePath("bad.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{\"format\": \"volpost-tf\", \"points\": [{\"value\": 1, \"extinction\": -3}]}");
    bad.close();
    QVERIFY(!panel_->loadFile(dir.filePath("bad.json"), &error));
    QVERIFY2(error.contains("bad.json"), qPrintable(error));
    QCOMPARE(int(panel_->model().points().size()), 2);  // what the user had stays
    QVERIFY(!panel_->importParaView(dir.filePath("missing.json"), &error));
  }

  void windowLevelMovesTheWholeFunction() {
    QTest::mousePress(&panel_->curve(), Qt::MiddleButton, {}, at(50.0, 0.1));
    QTest::mouseMove(&panel_->curve(), at(60.0, 0.1));
    QTest::mouseRelease(&panel_->curve(), Qt::MiddleButton, {}, at(60.0, 0.1));
    const auto& p = panel_->model().points();
    QVERIFY(std::abs(p.front().value - 10.0) < 0.5);
    QVERIFY(std::abs(p.back().value - 110.0) < 0.5);
  }

  void twoHundredFiftyFivePointsEditAndCutLikeTwo() {
    // The seed tried 255 segments; the editor puts no limit on the points.
    std::vector<ControlPoint> many;
    for (int i = 0; i <= 255; ++i) many.push_back({i * 100.0 / 255.0, {i / 255.0, 0.5, 1.0 - i / 255.0}, 0.01 * (i % 7)});
    panel_->model().load(TransferFunction(many), "many", false);
    QCOMPARE(int(panel_->model().points().size()), 256);
    QVERIFY(!panel_->grab().isNull());  // paints
    QTest::keyClick(&panel_->curve(), Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(int(panel_->model().selection().size()), 256);
    QTest::keyClick(&panel_->curve(), Qt::Key_Right);  // moves them all at once
    panel_->flush();
    QCOMPARE(int(host_->tf.points().size()), 256);
    QVERIFY(std::abs(host_->tf.points().front().value - 1.0) < 1e-9);
    const optics::IsoDetectionTable* iso = panel_->isoTable();
    QVERIFY(iso);
    // Points as dense as the table's texels: where the entry cannot tell, the cut is searched;
    // where it can, it is the moved point.
    const double first = host_->tf.points()[10].value;
    const std::optional<double> cut = iso->cut(first - 0.1, first + 0.2);
    QVERIFY(!cut || std::abs(*cut - first) < 1e-4);
    QVERIFY(std::abs(iso->at(first - 0.1, first + 0.2).first - first) < 0.5);
  }

  void resizesDownToItsMinimumWithoutLosingTheCurve() {
    panel_->resize(panel_->minimumSizeHint());
    QTest::qWait(20);
    QVERIFY(panel_->curve().width() >= 150);
    QVERIFY(panel_->curve().height() >= 100);
  }
};

int runTf2dEditorTests(int argc, char** argv);  // Tf2dEditorTest.cpp

int main(int argc, char** argv) {
  QStandardPaths::setTestModeEnabled(true);  // settings go to a test location
  QApplication app(argc, argv);
  TfEditorTest test;
  const int oneD = QTest::qExec(&test, argc, argv);
  return oneD | runTf2dEditorTests(argc, argv);
}

#include "TfEditorTest.moc"
