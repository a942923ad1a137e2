// SPDX-License-Identifier: MIT
#include "SetsPanel.hpp"

#include "../core/Scene.hpp"
#include "../core/SetColors.hpp"

#include <volpost/core/EntitySet.hpp>

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QPixmap>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cctype>

namespace volpost::app {
namespace {

constexpr int kNameRole = Qt::UserRole;
constexpr int kCountRole = Qt::UserRole + 1;  // the set's size in the whole model
constexpr int kPlaceRole = Qt::UserRole + 2;  // an element set's place among them (its color)

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void erase(std::vector<std::string>& names, const std::string& name) {
  names.erase(std::remove(names.begin(), names.end(), name), names.end());
}

// A set's name as the scene's choice spells it: the choice matches names regardless of
// case, the boxes compare them as written.
bool drawnByChoice(const SetVisibility& v, const std::string& name) {
  const auto has = [&](const std::vector<std::string>& names) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& n) {
      return std::equal(n.begin(), n.end(), name.begin(), name.end(), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
      });
    });
  };
  return (v.shown.empty() || has(v.shown)) && !has(v.hidden);
}

QString count(std::size_t n) { return QLocale().toString(qulonglong(n)); }

}  // namespace

SetsPanel::SetsPanel(const Scene& scene, ChangeScene change, QWidget* parent)
    : QWidget(parent), scene_(scene), change_(std::move(change)) {
  auto* layout = new QVBoxLayout(this);
  tree_ = new QTreeWidget(this);
  tree_->setObjectName("setsTree");
  tree_->setColumnCount(2);
  tree_->setHeaderLabels({"Set", "Count"});
  tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  // The name takes the room the count leaves (a narrow dock cut names to "N...").
  tree_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  tree_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  tree_->header()->setStretchLastSection(false);
  tree_->setRootIsDecorated(true);
  layout->addWidget(tree_);
  auto* buttons = new QHBoxLayout;
  showOnly_ = new QPushButton("Show &Only", this);
  showOnly_->setObjectName("setsShowOnly");
  showOnly_->setToolTip("Draw the selected element sets alone (a double click: that set alone)");
  showAll_ = new QPushButton("Show &All", this);
  showAll_->setObjectName("setsShowAll");
  showAll_->setToolTip("Draw every element again");
  mark_ = new QPushButton("&Mark", this);
  mark_->setObjectName("setsMark");
  mark_->setCheckable(true);
  mark_->setToolTip(
      "Mark the chosen set's nodes in the picture (an element set: its elements' nodes); "
      "while on, the mark follows the set you choose");
  buttons->addWidget(showOnly_);
  buttons->addWidget(showAll_);
  buttons->addWidget(mark_);
  numbers_ = new QCheckBox("&Numbers", this);
  numbers_->setObjectName("setsNumbers");
  numbers_->setToolTip(
      "Write the marked set's numbers in the picture: its node ids, or an element set's "
      "element ids at their centres (at most 300)");
  buttons->addWidget(numbers_);
  colors_ = new QCheckBox("&Colors", this);
  colors_->setObjectName("setsColors");
  colors_->setToolTip(
      "Color each element set plainly in a color of its own (shown beside its name) instead of "
      "by the result; an element in several sets takes the smallest one's color");
  buttons->addWidget(colors_);
  buttons->addStretch();
  layout->addLayout(buttons);
  auto* more = new QHBoxLayout;
  history_ = new QPushButton("Plot Over &Steps", this);
  history_->setObjectName("setsHistory");
  history_->setToolTip(
      "The shown result's largest and smallest values over the chosen set against the steps (a node set: "
      "its nodes; an element set: its elements, or their nodes for a result at the nodes)");
  more->addWidget(history_);
  more->addStretch();
  layout->addLayout(more);
  drawn_ = new QLabel(this);
  drawn_->setObjectName("setsDrawn");
  drawn_->setWordWrap(true);
  layout->addWidget(drawn_);

  connect(tree_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    if (column == 0) boxToggled(item);
  });
  connect(tree_, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
    if (!(item->flags() & Qt::ItemIsUserCheckable)) return;
    SetVisibility v = scene_.setVisibility();
    v.shown = {item->data(0, kNameRole).toString().toStdString()};
    v.hidden.clear();
    apply(v);
  });
  connect(showOnly_, &QPushButton::clicked, this, [this] { showOnlySelected(); });
  connect(showAll_, &QPushButton::clicked, this, [this] {
    SetVisibility v = scene_.setVisibility();
    v.shown.clear();
    v.hidden.clear();
    apply(v);
  });
  connect(mark_, &QPushButton::clicked, this, [this](bool on) { markCurrent(on); });
  connect(history_, &QPushButton::clicked, this, [this] {
    QTreeWidgetItem* item = tree_->currentItem();
    const QVariant name = item ? item->data(0, kNameRole) : QVariant();
    if (!name.isValid()) {
      drawn_->setText("Choose a set to plot its extremes over the steps");
      return;
    }
    emit historyRequested(name.toString());
  });
  connect(numbers_, &QCheckBox::toggled, this, [this](bool on) {
    if (following_) return;
    SetVisibility v = scene_.setVisibility();
    v.numbers = on && !v.marked.empty();
    apply(v);
  });
  connect(colors_, &QCheckBox::toggled, this, [this](bool on) {
    if (following_) return;
    SetVisibility v = scene_.setVisibility();
    v.colors = on;
    apply(v);
  });
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this] {
    if (!following_ && mark_->isChecked()) markCurrent(true);  // the mark follows the chosen set
  });
  followScene();
}

void SetsPanel::listSets() {
  const QSignalBlocker block(tree_);
  tree_->clear();
  const ModelSession* base = scene_.baseSession();
  listed_ = base;
  listedPath_ = base ? base->model().sourcePath : std::string();
  if (!base) return;
  const std::vector<EntitySet> sets = modelSets(base->model());
  if (sets.empty()) {
    auto* none = new QTreeWidgetItem(tree_, {"This model defines no sets"});
    none->setFlags(Qt::ItemIsEnabled);
    return;
  }
  QTreeWidgetItem* groups[2] = {nullptr, nullptr};  // element sets first: they have boxes
  for (const SetKind kind : {SetKind::Cells, SetKind::Nodes})
    for (const EntitySet& s : sets)
      if (s.kind == kind) addSet(groups, s);
  if (groups[0])
    for (int i = 0; i < groups[0]->childCount(); ++i) groups[0]->child(i)->setData(0, kPlaceRole, i);
  for (QTreeWidgetItem* g : groups)
    if (g) g->setText(1, count(std::size_t(g->childCount())));
}

void SetsPanel::addSet(QTreeWidgetItem* (&groups)[2], const EntitySet& s) {
  const int g = s.kind == SetKind::Cells ? 0 : 1;
  if (!groups[g]) {
    groups[g] = new QTreeWidgetItem(tree_, {g == 0 ? "Element sets" : "Node sets"});
    groups[g]->setFlags(Qt::ItemIsEnabled);
    groups[g]->setExpanded(true);
  }
  auto* item = new QTreeWidgetItem(groups[g], {QString::fromStdString(s.name), count(s.members.size())});
  item->setData(0, kNameRole, QString::fromStdString(s.name));
  item->setData(0, kCountRole, qulonglong(s.members.size()));
  item->setTextAlignment(1, Qt::AlignRight | Qt::AlignVCenter);
  const QString what = QString("%1 (%2): ").arg(QString::fromStdString(s.name), QString::fromStdString(s.origin));
  if (g == 0) {
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
    item->setToolTip(0, what + "its box draws or hides its " + count(s.members.size()) + " elements");
  } else {
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    item->setToolTip(0, what + count(s.members.size()) + " nodes (the Probe panel takes \"node ID\" to query one)");
  }
}

void SetsPanel::followScene() {
  following_ = true;
  // Another model (compared by its file too: a new session may take a freed one's address).
  const ModelSession* base = scene_.baseSession();
  if (base != listed_ || (base && base->model().sourcePath != listedPath_)) listSets();
  const SetVisibility& v = scene_.setVisibility();
  {
    const QSignalBlocker block(tree_);
    for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
      QTreeWidgetItem* item = *it;
      const QVariant name = item->data(0, kNameRole);
      if (!v.marked.empty() && name.isValid() &&
          name.toString().compare(QString::fromStdString(v.marked), Qt::CaseInsensitive) == 0)
        tree_->setCurrentItem(item);  // the marked set is the chosen one
      if (!(item->flags() & Qt::ItemIsUserCheckable)) continue;
      const bool drawn = drawnByChoice(v, name.toString().toStdString());
      item->setCheckState(0, drawn ? Qt::Checked : Qt::Unchecked);
    }
  }
  showDrawnCounts();
  const auto session = scene_.session();
  const bool hasElementSets = !tree_->findItems("Element sets", Qt::MatchExactly, 0).isEmpty();
  showOnly_->setEnabled(hasElementSets);
  showAll_->setEnabled(v.active());
  mark_->setEnabled(listed_ && tree_->topLevelItemCount() > 0 && tree_->topLevelItem(0)->childCount() > 0);
  mark_->setChecked(!v.marked.empty());
  numbers_->setEnabled(!v.marked.empty());
  numbers_->setChecked(v.numbers);
  colors_->setEnabled(hasElementSets);
  history_->setEnabled(listed_ && scene_.view().has_value() && tree_->topLevelItemCount() > 0 &&
                       tree_->topLevelItem(0)->childCount() > 0);
  colors_->setChecked(v.colors);
  showSetColors(v.colors);
  if (!base || !session) drawn_->clear();
  else {
    QString text = !v.active() ? QString("Every element drawn (%1)").arg(count(base->model().cellCount()))
                               : QString("Drawn: %1 of the %2 elements")
                                     .arg(count(session->model().cellCount()), count(base->model().cellCount()));
    if (!v.marked.empty()) {
      const Scene::MarkedSet& m = scene_.markedSet();
      text += QString("; %1 marked (%2 nodes)").arg(QString::fromStdString(v.marked), count(m.nodeCount));
      if (v.numbers && m.numbers.empty() && m.numbered > 0)
        text += QString(", too many to number (%1; at most %2)").arg(count(m.numbered)).arg(Scene::kMaxNumbers);
    }
    drawn_->setText(text);
  }
  following_ = false;
}

// An element set partly drawn (another set hidden, a threshold) says how much: "6,622 / 32,482".
void SetsPanel::showDrawnCounts() {
  const auto part = scene_.sharedSession();
  if (!part) return;
  if (drawnOf_.expired() || drawnOf_.lock() != part) {  // counted once per drawn part
    drawnOf_ = part;
    drawnCounts_.clear();
    if (part.get() != scene_.baseSession())
      for (const EntitySet& s : modelSets(part->model()))
        if (s.kind == SetKind::Cells) drawnCounts_[s.name] = s.members.size();
  }
  const bool whole = part.get() == scene_.baseSession();
  for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
    QTreeWidgetItem* item = *it;
    if (!(item->flags() & Qt::ItemIsUserCheckable)) continue;
    const std::size_t total = item->data(0, kCountRole).toULongLong();
    const auto drawn = drawnCounts_.find(item->data(0, kNameRole).toString().toStdString());
    const std::size_t shown = whole ? total : drawn == drawnCounts_.end() ? 0 : drawn->second;
    item->setText(1, shown == total ? count(total) : count(shown) + " / " + count(total));
  }
}

// Each element set's color beside its name while the sets color the model (SetColors.hpp).
void SetsPanel::showSetColors(bool on) {
  const QSignalBlocker block(tree_);
  const int side = tree_->fontMetrics().height() * 3 / 4;
  for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
    QTreeWidgetItem* item = *it;
    const QVariant place = item->data(0, kPlaceRole);
    if (!place.isValid()) continue;
    if (!on) {
      item->setIcon(0, QIcon());
      continue;
    }
    const glm::dvec3 rgb = setPaletteColor(std::size_t(place.toInt()));
    QPixmap swatch(side, side);
    swatch.fill(QColor::fromRgbF(float(rgb.r), float(rgb.g), float(rgb.b)));
    item->setIcon(0, QIcon(swatch));
  }
}

void SetsPanel::boxToggled(QTreeWidgetItem* item) {
  if (!(item->flags() & Qt::ItemIsUserCheckable)) return;
  const std::string name = item->data(0, kNameRole).toString().toStdString();
  SetVisibility v = scene_.setVisibility();
  const bool on = item->checkState(0) == Qt::Checked;
  erase(v.hidden, name);
  if (v.shown.empty()) {  // every element but the hidden sets'
    if (!on) v.hidden.push_back(name);
  } else if (on) {  // the shown sets alone: one more
    v.shown.push_back(name);
  } else if (v.shown.size() > 1 || !contains(v.shown, name)) {
    erase(v.shown, name);
  } else {
    v.hidden.push_back(name);  // the last shown set: refused, as nothing would be left
  }
  apply(v);
}

void SetsPanel::markCurrent(bool on) {
  SetVisibility v = scene_.setVisibility();
  QTreeWidgetItem* item = tree_->currentItem();
  const QVariant name = item ? item->data(0, kNameRole) : QVariant();
  if (on && !name.isValid()) {
    drawn_->setText("Choose a set to mark it");
    mark_->setChecked(false);
    return;
  }
  v.marked = on ? name.toString().toStdString() : std::string();
  if (!on) v.numbers = false;
  apply(v);
}

void SetsPanel::showOnlySelected() {
  SetVisibility v = scene_.setVisibility();
  v.shown.clear();
  v.hidden.clear();
  for (QTreeWidgetItem* item : tree_->selectedItems())
    if (item->flags() & Qt::ItemIsUserCheckable) v.shown.push_back(item->data(0, kNameRole).toString().toStdString());
  if (v.shown.empty()) {
    drawn_->setText("Select one or more element sets to show them alone");
    return;
  }
  apply(v);
}

void SetsPanel::apply(const SetVisibility& v) {
  change_([&v](Scene& s) { s.setSetVisibility(v); });
  followScene();  // refused or not, the boxes show what the scene holds
}

}  // namespace volpost::app
