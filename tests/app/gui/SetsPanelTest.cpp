// SPDX-License-Identifier: MIT
// The Sets panel alone (a plain main window and a scene, no OpenGL): it lists the file's
// sets with their counts, its boxes and buttons set the scene's choice of drawn sets, a
// refused choice leaves boxes and scene as they were, and the boxes follow a state file
// and another model.
#include "gui/SetsPanel.hpp"

#include "core/SetColors.hpp"

#include "support/WindowParts.hpp"

#include <QApplication>
#include <QCheckBox>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QTreeWidget>

#include <cmath>
#include <memory>

using namespace volpost;
using namespace volpost::app;

class SetsPanelTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<QMainWindow> window_;
  std::unique_ptr<Scene> scene_;
  SetsPanel* panel_ = nullptr;

  QTreeWidget* tree() { return panel_->findChild<QTreeWidget*>("setsTree"); }
  QTreeWidgetItem* item(const QString& name) {
    const auto found = tree()->findItems(name, Qt::MatchExactly | Qt::MatchRecursive, 0);
    return found.isEmpty() ? nullptr : found.front();
  }
  // The element sets whose boxes are checked.
  QStringList checked() {
    QStringList out;
    for (QTreeWidgetItemIterator it(tree()); *it; ++it)
      if (((*it)->flags() & Qt::ItemIsUserCheckable) && (*it)->checkState(0) == Qt::Checked) out << (*it)->text(0);
    return out;
  }
  std::size_t drawnCells() { return scene_->session()->model().cellCount(); }
  QString drawnText() { return panel_->findChild<QLabel*>("setsDrawn")->text(); }

 private slots:
  void init() {
    window_ = std::make_unique<QMainWindow>();
    scene_ = std::make_unique<Scene>(VolumeRendererFactory{});
    scene_->setSession(volpost::test::loadTestModel("formats/golden.inp"));
    panel_ = new SetsPanel(*scene_, volpost::test::changingScene(*window_, *scene_), window_.get());
    window_->setCentralWidget(panel_);
  }

  void cleanup() {
    window_.reset();
    scene_.reset();
  }

  void listsTheSetsWithTheirCounts() {
    QVERIFY(item("Element sets"));
    QCOMPARE(item("Element sets")->childCount(), 3);
    QCOMPARE(item("E_HEX")->text(1), QString("1"));
    QVERIFY(item("E_HEX")->toolTip(0).contains("(ELSET)"));
    QCOMPARE(item("NALL")->text(1), QString("37"));
    QVERIFY(!(item("NALL")->flags() & Qt::ItemIsUserCheckable));  // nodes have nothing to hide
    QCOMPARE(checked(), (QStringList{"E_HEX", "E_WEDGE", "E_TET"}));
    QCOMPARE(drawnText(), QString("Every element drawn (3)"));
  }

  void aBoxHidesAndDrawsItsSet() {
    item("E_HEX")->setCheckState(0, Qt::Unchecked);
    QCOMPARE(scene_->setVisibility().hidden, std::vector<std::string>{"E_HEX"});
    QCOMPARE(drawnCells(), std::size_t(2));
    QCOMPARE(drawnText(), QString("Drawn: 2 of the 3 elements"));
    QCOMPARE(item("E_HEX")->text(1), QString("0 / 1"));  // the count says what is drawn of it
    QCOMPARE(item("E_TET")->text(1), QString("1"));
    item("E_HEX")->setCheckState(0, Qt::Checked);
    QVERIFY(!scene_->setVisibility().active());
    QCOMPARE(drawnCells(), std::size_t(3));
  }

  void showOnlyAndShowAll() {
    emit tree()->itemDoubleClicked(item("E_TET"), 0);
    QCOMPARE(scene_->setVisibility().shown, std::vector<std::string>{"E_TET"});
    QCOMPARE(checked(), QStringList{"E_TET"});
    QCOMPARE(drawnCells(), std::size_t(1));
    item("E_WEDGE")->setCheckState(0, Qt::Checked);  // one more set drawn
    QCOMPARE(checked(), (QStringList{"E_WEDGE", "E_TET"}));
    QCOMPARE(drawnCells(), std::size_t(2));
    tree()->clearSelection();
    item("E_HEX")->setSelected(true);
    item("NALL")->setSelected(true);  // a node set is left out of Show Only
    panel_->findChild<QPushButton*>("setsShowOnly")->click();
    QCOMPARE(checked(), QStringList{"E_HEX"});
    panel_->findChild<QPushButton*>("setsShowAll")->click();
    QCOMPARE(checked(), (QStringList{"E_HEX", "E_WEDGE", "E_TET"}));
    QCOMPARE(drawnCells(), std::size_t(3));
  }

  void markDrawsTheChosenSetsNodesAndFollowsTheChoice() {
    QPushButton* mark = panel_->findChild<QPushButton*>("setsMark");
    QVERIFY(mark->isEnabled());
    tree()->setCurrentItem(item("NALL"));
    mark->click();
    QVERIFY(mark->isChecked());
    QCOMPARE(scene_->setVisibility().marked, std::string("NALL"));
    QCOMPARE(scene_->markedSet().nodeCount, std::size_t(37));
    QVERIFY(drawnText().contains("NALL marked (37 nodes)"));
    tree()->setCurrentItem(item("E_TET"));  // the mark follows
    QCOMPARE(scene_->setVisibility().marked, std::string("E_TET"));
    QCOMPARE(scene_->markedSet().nodeCount, std::size_t(10));
    QCheckBox* numbers = panel_->findChild<QCheckBox*>("setsNumbers");
    QVERIFY(numbers->isEnabled());
    numbers->setChecked(true);
    QVERIFY(scene_->setVisibility().numbers);
    QCOMPARE(scene_->markedSet().numbers.size(), std::size_t(1));  // E_TET's element number
    QCOMPARE(scene_->markedSet().numbers[0].id, std::int64_t(103));
    mark->click();
    QVERIFY(!mark->isChecked());
    QVERIFY(!scene_->setVisibility().numbers);
    QVERIFY(!numbers->isChecked() && !numbers->isEnabled());
    QVERIFY(scene_->setVisibility().marked.empty());
    tree()->setCurrentItem(item("E_HEX"));
    QVERIFY2(scene_->setVisibility().marked.empty(), "off, choosing a set marks nothing");
  }

  void aRefusedChoiceChangesNothing() {
    emit tree()->itemDoubleClicked(item("E_TET"), 0);
    item("E_TET")->setCheckState(0, Qt::Unchecked);  // nothing would be left
    QVERIFY(window_->statusBar()->currentMessage().contains("leave no element"));
    QCOMPARE(checked(), QStringList{"E_TET"});
    QCOMPARE(drawnCells(), std::size_t(1));
  }

  void colorsDrawEachSetInItsOwnColorShownBesideIt() {
    QCheckBox* colors = panel_->findChild<QCheckBox*>("setsColors");
    QVERIFY(colors->isEnabled() && !colors->isChecked());
    QVERIFY(item("E_HEX")->icon(0).isNull());
    colors->setChecked(true);
    QVERIFY(scene_->setVisibility().colors);
    QVERIFY(!item("E_WEDGE")->icon(0).isNull());
    const QColor swatch = item("E_WEDGE")->icon(0).pixmap(8, 8).toImage().pixelColor(4, 4);
    const glm::dvec3 rgb = setPaletteColor(1);  // the second element set's color, as drawn
    QVERIFY(std::abs(swatch.redF() - rgb.r) < 0.01 && std::abs(swatch.greenF() - rgb.g) < 0.01);
    QVERIFY(item("NALL")->icon(0).isNull());  // a node set colors nothing
    SceneState state = scene_->state();
    state.sets.colors = false;
    scene_->applyState(state);
    panel_->followScene();
    QVERIFY(!colors->isChecked());  // the box shows the scene's choice
    QVERIFY(item("E_WEDGE")->icon(0).isNull());
  }

  void plotOverStepsAsksForTheChosenSetsExtremes() {
    QPushButton* history = panel_->findChild<QPushButton*>("setsHistory");
    QVERIFY(!history->isEnabled());  // no result shown: nothing to plot
    scene_->setResult("element set", 0);
    panel_->followScene();
    QVERIFY(history->isEnabled());
    QSignalSpy asked(panel_, &SetsPanel::historyRequested);
    tree()->setCurrentItem(item("E_TET"));
    history->click();
    QCOMPARE(asked.count(), 1);
    QCOMPARE(asked.first().first().toString(), QString("E_TET"));
  }

  void theSelectionIsListedAsSets() {
    scene_->setSelection({{101, 103}, {}});
    panel_->followScene();
    QVERIFY(item("selected elements"));
    QCOMPARE(item("selected elements")->text(1), QString("2"));
    item("selected elements")->setCheckState(0, Qt::Unchecked);  // hidden like any set
    QCOMPARE(drawnCells(), std::size_t(1));
    scene_->setSelection({});
    panel_->followScene();
    QVERIFY(!item("selected elements"));
    QCOMPARE(drawnCells(), std::size_t(3));  // the choice that named it forgot it
  }

  void theBoxesFollowAStateAndAnotherModel() {
    SceneState state = scene_->state();
    state.sets.hidden = {"E_WEDGE"};
    scene_->applyState(state);
    panel_->followScene();
    QCOMPARE(checked(), (QStringList{"E_HEX", "E_TET"}));
    scene_->setSession(volpost::test::loadTestModel("bar/bar_tet4.vtu"));
    panel_->followScene();
    QVERIFY(item("This model defines no sets"));
    QVERIFY(!panel_->findChild<QPushButton*>("setsShowOnly")->isEnabled());
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");  // a tree and buttons only: no display needed
  QApplication app(argc, argv);
  SetsPanelTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "SetsPanelTest.moc"
