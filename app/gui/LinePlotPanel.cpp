// SPDX-License-Identifier: MIT
#include "LinePlotPanel.hpp"

#include "../core/LinePlot.hpp"
#include "../core/PictureFile.hpp"
#include "../core/ProbeTable.hpp"
#include "../core/Scene.hpp"
#include "../core/VolumeSpecs.hpp"
#include "ExportToFile.hpp"

#include "host/AtomicFile.hpp"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace volpost::app {
namespace {

// The chart, repainted from the panel's samples at whatever size the dock has.
class ChartWidget : public QWidget {
 public:
  ChartWidget(const std::optional<LineSamples>& samples, QWidget* parent) : QWidget(parent), samples_(samples) {
    setMinimumSize(240, 160);
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    if (samples_) paintLinePlot(painter, rect(), *samples_);
    else painter.drawText(rect(), Qt::AlignCenter, "Type two points (or take the last two probes) and Plot");
  }

 private:
  const std::optional<LineSamples>& samples_;
};

QString pointText(const glm::dvec3& p) {
  return QString("%1, %2, %3").arg(QString::fromStdString(exactNumber(p.x)), QString::fromStdString(exactNumber(p.y)),
                                   QString::fromStdString(exactNumber(p.z)));
}

}  // namespace

LinePlotPanel::LinePlotPanel(SceneGetter scene, LineShower showLine, QWidget* parent)
    : QWidget(parent), scene_(std::move(scene)), showLine_(std::move(showLine)) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  from_ = new QLineEdit(this);
  from_->setObjectName("lineFrom");
  from_->setPlaceholderText("X, Y, Z");
  to_ = new QLineEdit(this);
  to_->setObjectName("lineTo");
  to_->setPlaceholderText("X, Y, Z");
  count_ = new QSpinBox(this);
  count_->setObjectName("lineSamples");
  count_->setRange(2, int(kMaxLineSamples));
  count_->setValue(200);
  form->addRow("From", from_);
  form->addRow("To", to_);
  form->addRow("Samples", count_);
  quantities_ = new QListWidget(this);
  quantities_->setObjectName("lineQuantities");
  quantities_->setToolTip("Check the quantities to plot together; none checked: the shown one");
  quantities_->setMaximumHeight(90);
  form->addRow("Quantities", quantities_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  const auto button = [&](const QString& text, const char* name, auto slot) {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    connect(b, &QPushButton::clicked, this, slot);
    buttons->addWidget(b);
  };
  button("Plot", "linePlot", [this] { plot(); });
  button("Last Two Probes", "lineFromProbes", [this] {
    if (useLastProbes()) plot();
  });
  button("CSV...", "lineCsv", [this] { exportCsv(); });
  button("PNG...", "linePng", [this] { exportPicture(); });
  layout->addLayout(buttons);
  chart_ = new ChartWidget(samples_, this);
  chart_->setObjectName("lineChart");
  layout->addWidget(chart_, 1);
  for (QLineEdit* e : {from_, to_}) connect(e, &QLineEdit::returnPressed, this, [this] { plot(); });
}

void LinePlotPanel::modelChanged() {
  samples_.reset();
  from_->clear();
  to_->clear();
  refreshQuantities();  // the new model's, none checked
  for (int i = 0; i < quantities_->count(); ++i) quantities_->item(i)->setCheckState(Qt::Unchecked);
  chart_->update();
}

void LinePlotPanel::followScene() {
  const auto& line = scene_().plotLine();
  if (!line) return;
  setEnds((*line)[0], (*line)[1]);
  plot();
}

void LinePlotPanel::setEnds(const glm::dvec3& from, const glm::dvec3& to) {
  from_->setText(pointText(from));
  to_->setText(pointText(to));
}

void LinePlotPanel::refreshQuantities() {
  const Scene& scene = scene_();
  // Which model is listed: its address and path (a new model may reuse an address).
  const ModelSession* session = scene.baseSession();
  const std::string listed = session ? std::to_string(reinterpret_cast<std::uintptr_t>(session)) + " " +
                                           session->model().sourcePath
                                     : std::string();
  if (listed == listedModel_) return;
  const std::vector<std::string> checked = checkedQuantities();
  quantities_->clear();
  listedModel_ = listed;
  if (!session) return;
  for (const Quantity& q : session->quantities()) {
    auto* item = new QListWidgetItem(QString::fromStdString(q.displayName() + "  (" + q.key() + ")"), quantities_);
    item->setData(Qt::UserRole, QString::fromStdString(q.key()));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(std::find(checked.begin(), checked.end(), q.key()) != checked.end() ? Qt::Checked : Qt::Unchecked);
  }
}

std::vector<std::string> LinePlotPanel::checkedQuantities() const {
  std::vector<std::string> keys;
  for (int i = 0; i < quantities_->count(); ++i)
    if (quantities_->item(i)->checkState() == Qt::Checked)
      keys.push_back(quantities_->item(i)->data(Qt::UserRole).toString().toStdString());
  return keys;
}

void LinePlotPanel::setQuantities(const std::vector<std::string>& keys) {
  refreshQuantities();
  for (int i = 0; i < quantities_->count(); ++i) {
    const std::string key = quantities_->item(i)->data(Qt::UserRole).toString().toStdString();
    quantities_->item(i)->setCheckState(std::find(keys.begin(), keys.end(), key) != keys.end() ? Qt::Checked : Qt::Unchecked);
  }
}

bool LinePlotPanel::useLastProbes() {
  const auto& probes = scene_().probes();
  if (probes.size() < 2) {
    emit message("Plot Over Line: probe two points first (View > Probe), or type the ends");
    return false;
  }
  setEnds(probes[probes.size() - 2], probes.back());
  return true;
}

bool LinePlotPanel::plot() {
  const Scene& scene = scene_();
  const auto a = parsePoint(from_->text());
  const auto b = parsePoint(to_->text());
  if (!a || !b) {
    emit message(QString("Plot Over Line: '%1' and '%2' must both be X, Y, Z").arg(from_->text(), to_->text()));
    return false;
  }
  refreshQuantities();
  std::vector<std::string> keys = checkedQuantities();
  if (keys.empty() && scene.view()) keys.push_back(scene.view()->quantity.key());
  if (!scene.session() || keys.empty()) {
    emit message("Plot Over Line: choose a result to plot first (or check quantities in the panel)");
    return false;
  }
  try {
    samples_ = sampleLine(*scene.session(), *a, *b, std::size_t(count_->value()), keys, scene.step());
  } catch (const std::exception& e) {
    emit message(QString("Plot Over Line: %1").arg(e.what()));
    return false;
  }
  showLine_(std::array<glm::dvec3, 2>{*a, *b});  // the sampled line, drawn in the view
  std::size_t outside = 0;
  for (const ProbeResult& r : samples_->points) outside += !r.inside();
  emit message(outside ? QString("Plot Over Line: %1 of %2 samples lie outside the mesh (gaps)").arg(outside).arg(samples_->points.size())
                       : QString("Plot Over Line: %1 samples").arg(samples_->points.size()));
  chart_->update();
  return true;
}

void LinePlotPanel::exportCsv() {
  exportTo("Export the line's samples", "CSV (*.csv)",
           [this](const QString& path) { writeFileAtomically(path.toStdString(), lineTable(*samples_)); });
}

void LinePlotPanel::exportPicture() {
  exportTo("Save the chart", "PNG image (*.png)",
           [this](const QString& path) { savePicture(linePlotImage(*samples_, 800, 500), path); });
}

void LinePlotPanel::exportTo(const QString& title, const QString& filter, const std::function<void(const QString&)>& write) {
  if (!samples_ && !plot()) return;
  if (const auto said = exportToChosenFile(this, title, filter, write)) emit message(*said);
}

}  // namespace volpost::app
