// SPDX-License-Identifier: MIT
// The 2D transfer function's editor driven by mouse and keyboard on a virtual display: the
// joint histogram of a grid whose gradient is known, widgets added by double-click and by
// button, moved and reshaped by their handles, deleted by key; the switch sends the function
// to the host live, files round-trip, a broken one is refused naming it.
#include "Tf2dEditorPanel.hpp"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace volpost;
using namespace volpost::tfeditor;

namespace {

// A 20 x 10 x 8 grid of unit spacing whose value is 0.5 x + (z > 3 ? 4 : 0): gradient 0.5
// everywhere but across the step in z (two layers of points by central differences).
class GridHost : public PanelHost {
 public:
  GridHost() {
    data.sourcePath = "layers";
    RegularGrid g;
    g.dims = {20, 10, 8};
    data.grid = g;
    for (std::size_t k = 0; k < 8; ++k)
      for (std::size_t j = 0; j < 10; ++j)
        for (std::size_t i = 0; i < 20; ++i) values.push_back(0.5 * double(i) + (k > 3 ? 4.0 : 0.0));
  }
  const Model* model() const override { return &data; }
  std::optional<Quantity> activeQuantity() const override {
    Quantity q;
    q.field = "amplitude";
    return q;
  }
  std::size_t activeStep() const override { return 0; }
  void requestRender() override {}
  TransferFunction transferFunction() const override { return {}; }
  void setTransferFunction(const TransferFunction&) override {}
  SampleView activeValues() const override { return values; }
  double modelSize() const override { return 10.0; }
  double lastTransferFunctionMs() const override { return 0.0; }
  std::optional<TransferFunction2D> transferFunction2D() const override { return tf2d; }
  bool setTransferFunction2D(const std::optional<TransferFunction2D>& f) override {
    tf2d = f;
    ++received;
    return true;
  }

  Model data;
  std::vector<double> values;
  std::optional<TransferFunction2D> tf2d;
  int received = 0;
};

}  // namespace

class Tf2dEditorTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<GridHost> host_;
  std::unique_ptr<Tf2dEditorPanel> panel_;

 private slots:
  void init() {
    host_ = std::make_unique<GridHost>();
    panel_ = std::make_unique<Tf2dEditorPanel>(*host_);
    panel_->resize(420, 360);
    panel_->show();
    QVERIFY(QTest::qWaitForWindowExposed(panel_.get()));
  }
  void cleanup() {
    panel_.reset();
    host_.reset();
  }

  void theHistogramSpansTheValuesAndGradients() {
    const JointHistogram h = JointHistogram::ofGrid(*host_->data.grid, host_->values);
    QCOMPARE(h.valueLow, 0.0);
    QCOMPARE(h.valueHigh, 13.5);
    // Most points have gradient 0.5; the 2 x 200 next to the step much more (central
    // differences across it: 2 per unit), so the top of the axis is that.
    std::uint32_t atHalf = 0, total = 0;
    for (int g = 0; g < h.gradientBins; ++g)
      for (int v = 0; v < h.valueBins; ++v) {
        total += h.count(v, g);
        if (std::abs((g + 0.5) / h.gradientBins * h.gradientHigh - 0.5) < h.gradientHigh / h.gradientBins) atHalf += h.count(v, g);
      }
    QCOMPARE(total, 1600u);
    QCOMPARE(atHalf, 1200u);
    QVERIFY(std::abs(h.gradientHigh - std::sqrt(0.25 + 4.0)) < 1e-6);
    QVERIFY(panel_->isEnabled());
  }

  void doubleClickAddsDragMovesHandlesReshapeDeleteRemoves() {
    Tf2dCanvas& canvas = panel_->canvas();
    const QPoint at = canvas.toScreen(6.0, 0.5).toPoint();
    QTest::mouseDClick(&canvas, Qt::LeftButton, {}, at);
    QCOMPARE(canvas.widgets().size(), std::size_t(1));
    QCOMPARE(canvas.selected(), 0);
    const TfWidget2D added = canvas.widgets()[0];
    QVERIFY(std::abs(added.value - 6.0) < 0.1);
    QVERIFY(added.gradientLow <= 0.5 && added.gradientHigh >= 0.5);
    // Drag its body right by a value of about 2.
    const QPoint to = canvas.toScreen(8.0, 0.5).toPoint();
    QTest::mousePress(&canvas, Qt::LeftButton, {}, at);
    QTest::mouseMove(&canvas, to);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, to);
    QVERIFY2(std::abs(canvas.widgets()[0].value - 8.0) < 0.15, "moved with the mouse");
    QVERIFY(std::abs(canvas.widgets()[0].width - added.width) < 1e-9);
    // Its width handle to value 10: width 2 x (10 - 8).
    const QPoint handle = canvas.widthHandle(canvas.widgets()[0]).toPoint();
    QTest::mousePress(&canvas, Qt::LeftButton, {}, handle);
    const QPoint wide(canvas.toScreen(10.0, 0.0).toPoint().x(), handle.y());
    QTest::mouseMove(&canvas, wide);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, wide);
    QVERIFY2(std::abs(canvas.widgets()[0].width - 4.0) < 0.2, "widened by the handle");
    // Its top handle up to gradient 1.5.
    const QPoint top = canvas.topHandle(canvas.widgets()[0]).toPoint();
    QTest::mousePress(&canvas, Qt::LeftButton, {}, top);
    const QPoint higher(top.x(), canvas.toScreen(0.0, 1.5).toPoint().y());
    QTest::mouseMove(&canvas, higher);
    QTest::mouseRelease(&canvas, Qt::LeftButton, {}, higher);
    QVERIFY2(std::abs(canvas.widgets()[0].gradientHigh - 1.5) < 0.05, "raised by the handle");
    canvas.setFocus();
    QTest::keyClick(&canvas, Qt::Key_Delete);
    QVERIFY(canvas.widgets().empty());
    QCOMPARE(host_->received, 0);  // the switch is off: nothing was sent
  }

  void theSwitchSendsLiveAndTheSelectionEdits() {
    panel_->findChild<QPushButton*>("tf2dAddTriangle")->click();
    QCOMPARE(panel_->canvas().widgets().size(), std::size_t(1));
    QCOMPARE(panel_->canvas().widgets()[0].shape, TfWidget2D::Shape::Triangle);
    panel_->findChild<QCheckBox*>("tf2dUse")->setChecked(true);
    QVERIFY(host_->tf2d.has_value());
    QCOMPARE(host_->tf2d->widgets().size(), std::size_t(1));
    // Opacity 0.3 over a tenth of the model (1 unit): extinction -ln(0.7).
    panel_->findChild<QDoubleSpinBox*>("tf2dOpacity")->setValue(0.3);
    panel_->flush();
    QVERIFY(std::abs(host_->tf2d->widgets()[0].extinction + std::log(0.7)) < 1e-9);
    panel_->findChild<QPushButton*>("tf2dAddRectangle")->click();
    panel_->flush();
    QCOMPARE(host_->tf2d->widgets().size(), std::size_t(2));
    panel_->findChild<QCheckBox*>("tf2dUse")->setChecked(false);
    QVERIFY(!host_->tf2d);
  }

  void filesRoundTripAndABrokenOneIsRefused() {
    QTemporaryDir dir;
    panel_->findChild<QPushButton*>("tf2dAddRectangle")->click();
    panel_->findChild<QPushButton*>("tf2dAddTriangle")->click();
    const std::vector<TfWidget2D> made = panel_->canvas().widgets();
    QString error;
    QVERIFY2(panel_->saveFile(dir.filePath("f.json"), &error), qPrintable(error));
    panel_->canvas().setWidgets({});
    QVERIFY2(panel_->loadFile(dir.filePath("f.json"), &error), qPrintable(error));
    QCOMPARE(panel_->canvas().widgets().size(), made.size());
    QVERIFY(panel_->canvas().widgets() == made);
    QFile broken(dir.filePath("broken.json"));
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write("{\"format\":\"volpost-tf2d\",\"version\":2,\"widgets\":[]}");
    broken.close();
    QVERIFY(!panel_->loadFile(dir.filePath("broken.json"), &error));
    QVERIFY2(error.contains("broken.json") && error.contains("version"), qPrintable(error));
    QVERIFY(panel_->canvas().widgets() == made);  // kept
  }

  void aHostWithoutAGridDisablesTheEditor() {
    QVERIFY(panel_->canvas().hasHistogram());
    host_->data.grid.reset();
    panel_->hostChanged();
    QVERIFY(!panel_->isEnabled());
    // The last cube's histogram goes with it (it stayed behind a mesh).
    QVERIFY(!panel_->canvas().hasHistogram());
  }
};

int runTf2dEditorTests(int argc, char** argv) {
  Tf2dEditorTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "Tf2dEditorTest.moc"
