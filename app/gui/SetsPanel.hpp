// SPDX-License-Identifier: MIT
// View > Panels > Sets (a dock beside the model's description): the element and node sets
// the file defines (ELSET/NSET, physical groups, element blocks, groups of a region field)
// with their counts. An element set's box draws or hides its elements; Show Only draws the
// selected sets alone (a double click: that set alone), Show All every element. The boxes
// always show the scene's choice, after a state file or a refused change too. Mark draws
// the chosen set's nodes in the picture. Colors draws each element set in a plain color
// of its own, shown beside its name.
#pragma once

#include "ChangeScene.hpp"

#include <QWidget>

#include <map>
#include <memory>
#include <string>

class QCheckBox;
class QLabel;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace volpost {
struct EntitySet;
}

namespace volpost::app {

class ModelSession;
class Scene;
struct SetVisibility;

class SetsPanel : public QWidget {
  Q_OBJECT

 public:
  SetsPanel(const Scene& scene, ChangeScene change, QWidget* parent = nullptr);
  /// The list follows the scene's model, the boxes its choice, the count what is drawn.
  void followScene();

 signals:
  /// Plot Over Steps: the shown result's extremes over this set against the steps.
  void historyRequested(const QString& set);

 public:
 private:
  void listSets();
  void addSet(QTreeWidgetItem* (&groups)[2], const EntitySet& s);
  void boxToggled(QTreeWidgetItem* item);
  void showOnlySelected();
  void markCurrent(bool on);
  void showDrawnCounts();
  void showSetColors(bool on);
  void apply(const SetVisibility& v);

  const Scene& scene_;
  ChangeScene change_;
  QTreeWidget* tree_ = nullptr;
  QPushButton* showOnly_ = nullptr;
  QPushButton* showAll_ = nullptr;
  QPushButton* mark_ = nullptr;
  QCheckBox* numbers_ = nullptr;
  QCheckBox* colors_ = nullptr;
  QPushButton* history_ = nullptr;
  QLabel* drawn_ = nullptr;
  const ModelSession* listed_ = nullptr;  // whose sets the tree lists
  std::string listedPath_;
  std::weak_ptr<const ModelSession> drawnOf_;  ///< the drawn part drawnCounts_ counts
  std::map<std::string, std::size_t> drawnCounts_;
  bool following_ = false;
};

}  // namespace volpost::app
