// SPDX-License-Identifier: MIT
#include "ProbePanel.hpp"

#include "../core/Legend.hpp"
#include "../core/Measure.hpp"
#include "../core/ProbeTable.hpp"
#include "../core/SceneState.hpp"
#include "../core/SetMembership.hpp"
#include "../core/VolumeSpecs.hpp"
#include "host/AtomicFile.hpp"

#include <QApplication>
#include <QClipboard>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace volpost::app {

namespace {

// On screen: the chosen significant digits; the item's tooltip, Copy and CSV: every digit.
QString number(double v) { return QString::fromStdString(displayNumber(v)); }

QTableWidgetItem* readOnly(const QString& text) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(item->flags() & ~Qt::ItemIsEditable);
  return item;
}

QTableWidgetItem* readOnlyNumber(double v) {
  QTableWidgetItem* item = readOnly(number(v));
  item->setToolTip(QString::fromStdString(exactNumber(v)));
  return item;
}

}  // namespace

ProbePanel::ProbePanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  auto* hint = new QLabel("View > Probe (I), then click the model; or type a point:", this);
  hint->setWordWrap(true);
  layout->addWidget(hint);
  auto* typedRow = new QHBoxLayout;
  typed_ = new QLineEdit(this);
  typed_->setObjectName("probeTyped");
  typed_->setPlaceholderText("X, Y, Z  or  node ID  or  element ID");
  auto* add = new QPushButton("Add", this);
  typedRow->addWidget(typed_);
  typedRow->addWidget(add);
  layout->addLayout(typedRow);
  connect(add, &QPushButton::clicked, this, &ProbePanel::addTyped);
  connect(typed_, &QLineEdit::returnPressed, this, &ProbePanel::addTyped);

  auto* split = new QSplitter(Qt::Vertical, this);
  picks_ = new QTableWidget(0, 6, split);
  picks_->setObjectName("probePicks");
  picks_->setSelectionBehavior(QAbstractItemView::SelectRows);
  picks_->verticalHeader()->setVisible(false);
  picks_->horizontalHeader()->setStretchLastSection(true);
  auto* lower = new QWidget(split);
  auto* lowerLayout = new QVBoxLayout(lower);
  lowerLayout->setContentsMargins(0, 0, 0, 0);
  where_ = new QLabel(lower);
  where_->setWordWrap(true);
  where_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  details_ = new QTableWidget(0, 2, lower);
  details_->setObjectName("probeDetails");
  details_->setHorizontalHeaderLabels({"quantity", "value"});
  details_->verticalHeader()->setVisible(false);
  details_->horizontalHeader()->setStretchLastSection(true);
  measure_ = new QLabel(lower);
  measure_->setObjectName("probeMeasure");
  measure_->setWordWrap(true);
  measure_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  measure_->setToolTip("Select two probed points for their distance, three for the angle at the second");
  lowerLayout->addWidget(measure_);
  lowerLayout->addWidget(where_);
  lowerLayout->addWidget(details_);
  layout->addWidget(split, 1);
  connect(picks_, &QTableWidget::itemSelectionChanged, this, &ProbePanel::fillDetails);

  auto* buttons = new QHBoxLayout;
  const auto button = [&](const QString& text, auto slot) {
    auto* b = new QPushButton(text, this);
    buttons->addWidget(b);
    connect(b, &QPushButton::clicked, this, slot);
  };
  digits_ = new QSpinBox(this);
  digits_->setObjectName("probeDigits");
  digits_->setRange(2, 17);
  digits_->setValue(displayDigits());
  digits_->setPrefix("digits: ");
  digits_->setToolTip("Significant digits shown here and in tooltips; Copy and CSV give every digit");
  connect(digits_, &QSpinBox::valueChanged, this, [this](int n) {
    setDisplayDigits(n);
    QSettings("volpost", "volpost").setValue("view/digits", n);
    fillPicks();
  });
  buttons->addWidget(digits_);
  button("Copy", &ProbePanel::copyAll);
  button("Export CSV...", &ProbePanel::exportCsv);
  button("Remove", &ProbePanel::removeSelected);
  // Plot Over Steps: two or more selected probes, else all of them (one is always selected
  // to show its details).
  button("Plot Over Steps", [this] {
    std::vector<std::size_t> rows;
    for (const QModelIndex& index : picks_->selectionModel()->selectedRows()) rows.push_back(std::size_t(index.row()));
    if (rows.size() < 2) rows.clear();
    if (rows.empty())
      for (std::size_t i = 0; i < results_.size(); ++i) rows.push_back(i);
    std::sort(rows.begin(), rows.end());
    emit historyRequested(rows);
  });
  button("Clear", [this] { emit pointsChanged({}); });
  layout->addLayout(buttons);
}

void ProbePanel::showProbes(std::shared_ptr<const ModelSession> session, const std::vector<glm::dvec3>& points,
                            std::size_t step, const std::string& quantityKey) {
  session_ = std::move(session);
  quantityKey_ = quantityKey;
  results_.clear();
  try {
    if (session_)
      for (const glm::dvec3& p : points) results_.push_back(probeAt(*session_, p, step));
  } catch (const std::exception& e) {  // a lazy read of a damaged file
    results_.clear();
    emit message(QString("Probe: %1").arg(e.what()));
  }
  fillPicks();
}

QString ProbePanel::withUnits(const Quantity& q) const {
  const auto units = units_.find(q.field);
  const QString written = quantityUnits(q, units != units_.end() ? QString::fromStdString(units->second) : QString());
  return QString::fromStdString(q.key()) + (written.isEmpty() ? QString() : " [" + written + "]");
}

void ProbePanel::fillPicks() {
  const int selected = picks_->currentRow();
  const QSignalBlocker block(picks_);
  picks_->setRowCount(int(results_.size()));
  QString valueHeader = quantityKey_.empty() ? QString("value") : QString::fromStdString(quantityKey_);
  if (session_ && !quantityKey_.empty()) try {
      valueHeader = withUnits(session_->findQuantity(quantityKey_));
    } catch (const std::exception&) {
      // a quantity of another model: its key as it is
    }
  picks_->setHorizontalHeaderLabels({"#", "x", "y", "z", "element", valueHeader});
  for (int row = 0; row < int(results_.size()); ++row) {
    const ProbeResult& r = results_[std::size_t(row)];
    const auto value = r.inside() && !quantityKey_.empty() ? r.value(quantityKey_) : std::nullopt;
    picks_->setItem(row, 0, readOnly(QString::number(row + 1)));
    for (int c = 0; c < 3; ++c) picks_->setItem(row, 1 + c, readOnlyNumber(r.point[c]));
    picks_->setItem(row, 4, readOnly(r.inside() ? QString::number(r.cellId) : QString("outside")));
    picks_->setItem(row, 5, value ? readOnlyNumber(*value) : readOnly(QString()));
  }
  picks_->resizeColumnsToContents();
  if (!results_.empty()) picks_->selectRow(selected >= 0 && selected < int(results_.size()) ? selected : int(results_.size()) - 1);
  fillDetails();
}

// Two selected points: their distance; three: also the angle at the second.
void ProbePanel::showMeasure() {
  std::vector<int> rows;
  for (const QModelIndex& index : picks_->selectionModel()->selectedRows())
    if (index.row() < int(results_.size())) rows.push_back(index.row());
  std::sort(rows.begin(), rows.end());
  if (rows.size() < 2 || rows.size() > 3) {
    measure_->clear();
    emit measured({});
    return;
  }
  emit measured(std::vector<std::size_t>(rows.begin(), rows.end()));
  const auto point = [&](std::size_t i) { return results_[std::size_t(rows[i])].point; };
  const auto number = [](double v) { return QString::fromStdString(displayNumber(v)); };
  const glm::dvec3 d = point(1) - point(0);
  QString text = QString("Distance %1 to %2: %3 (dx %4, dy %5, dz %6)")
                     .arg(rows[0] + 1)
                     .arg(rows[1] + 1)
                     .arg(number(distanceBetween(point(0), point(1))), number(d.x), number(d.y), number(d.z));
  if (rows.size() == 3) {
    text +=
        QString("; %1 to %2: %3").arg(rows[1] + 1).arg(rows[2] + 1).arg(number(distanceBetween(point(1), point(2))));
    const auto angle = angleAt(point(0), point(1), point(2));
    text += angle ? QString("; angle at %1: %2 degrees").arg(rows[1] + 1).arg(number(*angle))
                  : QString("; no angle: two points coincide");
  }
  if (deformed_) text += " (deformed coordinates, as drawn)";
  measure_->setText(text);
}

// The selected pick: where it is, and every quantity at full precision.
void ProbePanel::fillDetails() {
  showMeasure();
  const int row = picks_->currentRow();
  details_->setRowCount(0);
  if (row < 0 || row >= int(results_.size())) {
    where_->setText(results_.empty() ? "No points probed." : QString());
    return;
  }
  const ProbeResult& r = results_[std::size_t(row)];
  if (!r.inside()) {
    where_->setText(QString("Point %1 is outside the mesh.").arg(row + 1));
    return;
  }
  QStringList nodes;
  for (std::int64_t id : r.nodeIds) nodes << QString::number(id);
  where_->setText(QString("Point %1: %7element %2 (%3)%4; nodes %5. Values %6.")
                      .arg(row + 1)
                      .arg(r.cellId)
                      .arg(QString::fromStdString(std::string(cellTypeName(r.cellType))))
                      .arg(r.nodeId ? QString(", at node %1").arg(*r.nodeId) : QString())
                      .arg(nodes.join(' '))
                      .arg(describe(r.method))
                      .arg(r.gridPosition.empty() ? QString() : QString::fromStdString(r.gridPositionText()) + "; "));
  // The sets holding the element (and the node it sits on): what Abaqus's Query says too.
  if (session_) {
    if (setsOf_.expired() || setsOf_.lock() != session_) {
      setsOf_ = session_;
      sets_ = modelSets(session_->model());
    }
    const std::string cellSets = setNameList(setsHolding(sets_, SetKind::Cells, r.cell));
    const std::string nodeSets =
        r.nodeId ? setNameList(setsHolding(sets_, SetKind::Nodes, r.nearestNode)) : std::string();
    if (!cellSets.empty())
      where_->setText(where_->text() + QString(" Element sets: %1.").arg(QString::fromStdString(cellSets)));
    if (!nodeSets.empty())
      where_->setText(where_->text() + QString(" Node sets: %1.").arg(QString::fromStdString(nodeSets)));
  }
  for (const ProbedField& f : r.fields)
    for (const ProbedQuantity& q : f.quantities) {
      const int at = details_->rowCount();
      details_->insertRow(at);
      details_->setItem(at, 0,
                        readOnly(withUnits(q.quantity) + (f.location == FieldLocation::Cell ? " (element)" : "")));
      details_->setItem(at, 1, readOnlyNumber(q.value));
    }
  details_->resizeColumnsToContents();
}

std::vector<glm::dvec3> ProbePanel::points() const {
  std::vector<glm::dvec3> p;
  for (const ProbeResult& r : results_) p.push_back(r.point);
  return p;
}

void ProbePanel::addTyped() {
  std::optional<glm::dvec3> p = parsePoint(typed_->text());
  if (!p && session_) {  // "node 5484", "element 15600": the node, the element's centre
    try {
      if (const auto found = probeById(*session_, typed_->text().toStdString(), 0)) p = found->point;
    } catch (const std::invalid_argument& e) {
      emit message(QString::fromStdString(e.what()));
      return;
    }
  }
  if (!p) {
    emit message(QString("'%1' is not a point: type X, Y, Z, node ID or element ID").arg(typed_->text()));
    return;
  }
  if (results_.size() >= kMaxProbes) {
    emit message(QString("At most %1 probed points").arg(kMaxProbes));
    return;
  }
  std::vector<glm::dvec3> all = points();
  all.push_back(*p);
  typed_->clear();
  typed_->clearFocus();  // the next shortcut letter goes to the window, not into the field
  emit pointsChanged(all);
}

void ProbePanel::removeSelected() {
  std::vector<glm::dvec3> all = points();
  std::vector<int> rows;
  for (const QModelIndex& index : picks_->selectionModel()->selectedRows()) rows.push_back(index.row());
  std::sort(rows.rbegin(), rows.rend());
  for (int row : rows)
    if (row >= 0 && row < int(all.size())) all.erase(all.begin() + row);
  emit pointsChanged(all);
}

std::string ProbePanel::table(char separator) const {
  return session_ ? probeTable(results_, allQuantityKeys(*session_), separator) : std::string();
}

void ProbePanel::copyAll() {
  if (results_.empty()) return;
  QApplication::clipboard()->setText(QString::fromStdString(table('\t')));
  emit message(QString("Copied %1 probed point(s), every quantity, to the clipboard").arg(results_.size()));
}

void ProbePanel::exportCsv() {
  if (results_.empty()) {
    emit message("No points probed to export");
    return;
  }
  QSettings settings("volpost", "volpost");
  const QString path = QFileDialog::getSaveFileName(this, "Export probed points", settings.value("files/lastDir").toString(),
                                                    "CSV (*.csv)");
  if (path.isEmpty()) return;
  try {
    writeFileAtomically(path.toStdString(), table(','));
    emit message(QString("Wrote %1").arg(path));
  } catch (const std::exception& e) {
    emit message(QString("Could not write %1: %2").arg(path, e.what()));
  }
}

}  // namespace volpost::app
