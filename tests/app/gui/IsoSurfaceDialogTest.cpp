// SPDX-License-Identifier: MIT
// Results > Iso-surfaces... alone (no display): it offers the quantities given at the
// nodes, proposes one surface at the middle of the shown values, shows the layer's own
// surfaces back, and names the entry it cannot read.
#include "gui/IsoSurfaceDialog.hpp"

#include "support/WindowParts.hpp"

#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QTest>

using namespace volpost;
using namespace volpost::app;

class IsoSurfaceDialogTest : public QObject {
  Q_OBJECT

 private:
  std::shared_ptr<const ModelSession> bar_ = volpost::test::loadTestModel("bar/bar_tet4.vtu");

 private slots:
  void itProposesTheMiddleOfTheShownValues() {
    const ScalarView shown = bar_->evaluate(bar_->findQuantity("S.mises"), 0);
    IsoSurfaceDialog dialog(*bar_, VolumeLayer{}, &shown, nullptr);
    QString bad;
    const auto surfaces = dialog.surfaces(&bad);
    QVERIFY(surfaces);
    QCOMPARE(surfaces->size(), std::size_t(1));
    QVERIFY(std::abs(surfaces->front().value - 0.5 * (shown.range.min + shown.range.max)) <=
            1e-5 * std::abs(shown.range.max));
    QCOMPARE(dialog.quantity(), std::string());  // the shown result
  }

  void itOffersOnlyQuantitiesAtTheNodesAndShowsTheLayersOwn() {
    VolumeLayer volume;
    volume.isoQuantity = "U.magnitude";
    volume.isoSurfaces = {{0.25, {1, 0, 0}, 0.5}, {0.75, {0, 0, 1}, 1.0}};
    IsoSurfaceDialog dialog(*bar_, volume, nullptr, nullptr);
    auto* quantity = dialog.findChild<QComboBox*>("isoQuantity");
    QCOMPARE(dialog.quantity(), std::string("U.magnitude"));
    for (int i = 1; i < quantity->count(); ++i) {
      const std::string key = quantity->itemData(i).toString().toStdString();
      QVERIFY2(bar_->fieldOf(bar_->findQuantity(key)).location() == FieldLocation::Node, key.c_str());
    }
    QString bad;
    const auto surfaces = dialog.surfaces(&bad);
    QVERIFY(surfaces);
    QCOMPARE(surfaces->size(), std::size_t(2));
    QCOMPARE(surfaces->back().value, 0.75);
  }

  void itNamesTheEntryItCannotRead() {
    IsoSurfaceDialog dialog(*bar_, VolumeLayer{}, nullptr, nullptr);
    dialog.findChild<QLineEdit*>("isoValues")->setText("0.5:1,0,0; half");
    QString bad;
    QVERIFY(!dialog.surfaces(&bad));
    QVERIFY2(bad.contains("half"), qPrintable(bad));
    dialog.findChild<QLineEdit*>("isoValues")->setText("");
    QVERIFY(dialog.surfaces(&bad).value().empty());  // empty: none
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // no display needed
  QApplication app(argc, argv);
  IsoSurfaceDialogTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "IsoSurfaceDialogTest.moc"
