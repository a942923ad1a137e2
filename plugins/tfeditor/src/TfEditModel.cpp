// SPDX-License-Identifier: MIT
#include "TfEditModel.hpp"

#include <algorithm>
#include <cmath>

namespace volpost::tfeditor {
namespace {

class SnapshotCommand : public QUndoCommand {
 public:
  SnapshotCommand(TfEditModel& model, std::vector<EditPoint> before, std::vector<EditPoint> after, const QString& text,
                  int mergeKey)
      : QUndoCommand(text), model_(model), before_(std::move(before)), after_(std::move(after)), mergeKey_(mergeKey) {}
  void undo() override { model_.applySnapshot(before_); }
  void redo() override { model_.applySnapshot(after_); }
  int id() const override { return mergeKey_ > 0 ? mergeKey_ : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = static_cast<const SnapshotCommand*>(other);
    after_ = o->after_;
    return true;
  }

 private:
  TfEditModel& model_;
  std::vector<EditPoint> before_, after_;
  int mergeKey_;
};

void sortByValue(std::vector<EditPoint>& p) {
  std::stable_sort(p.begin(), p.end(), [](const EditPoint& a, const EditPoint& b) { return a.value < b.value; });
}

glm::dvec3 rgb(const QColor& c) { return {c.redF(), c.greenF(), c.blueF()}; }

}  // namespace

TfEditModel::TfEditModel(QObject* parent) : QObject(parent) { undo_.setUndoLimit(500); }

int TfEditModel::indexOf(int id) const {
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (points_[i].id == id) return int(i);
  return -1;
}

void TfEditModel::setReferenceLength(double length) {
  if (!(length > 0.0) || !std::isfinite(length) || length == referenceLength_) return;
  // Keep the physics (extinction) and show it over the new length.
  const TransferFunction tf = toTransferFunction();
  referenceLength_ = length;
  std::vector<EditPoint> p = points_;
  for (std::size_t i = 0; i < p.size(); ++i)
    p[i].opacity = std::min(extinctionToOpacity(tf.points()[i].extinction, length), 0.9999);
  points_ = std::move(p);
  emit changed();
}

void TfEditModel::applySnapshot(const std::vector<EditPoint>& points) {
  points_ = points;
  std::set<int> kept;
  for (int id : selection_)
    if (indexOf(id) >= 0) kept.insert(id);
  const bool selectionLost = kept != selection_;
  selection_ = std::move(kept);
  emit changed();
  if (selectionLost) emit selectionChanged();
}

void TfEditModel::record(std::vector<EditPoint> after, const QString& what, int mergeKey) {
  sortByValue(after);
  for (auto& p : after) {
    p.opacity = std::clamp(p.opacity, 0.0, 0.9999);
    if (!std::isfinite(p.value)) p.value = 0.0;
  }
  if (after == points_) return;
  undo_.push(new SnapshotCommand(*this, points_, std::move(after), what, mergeKey));
}

int TfEditModel::addPoint(double value, double opacity, std::optional<QColor> color) {
  std::vector<EditPoint> after = points_;
  const int id = nextId_++;
  after.push_back({id, value, opacity, color.value_or(colorAt(value))});
  record(std::move(after), "Add point", 0);
  setSelection({id});
  return id;
}

void TfEditModel::movePoints(const std::vector<EditPoint>& moved, const QString& what, int mergeKey) {
  std::vector<EditPoint> after = points_;
  for (const EditPoint& m : moved)
    for (auto& p : after)
      if (p.id == m.id) {
        p.value = m.value;
        p.opacity = m.opacity;
      }
  record(std::move(after), what, mergeKey);
}

void TfEditModel::setColor(int id, const QColor& color) {
  std::vector<EditPoint> after = points_;
  for (auto& p : after)
    if (p.id == id) p.color = color;
  record(std::move(after), "Point color", 0);
}

void TfEditModel::removePoints(const std::set<int>& ids) {
  std::vector<EditPoint> after;
  for (const auto& p : points_)
    if (!ids.count(p.id)) after.push_back(p);
  record(std::move(after), ids.size() == 1 ? "Delete point" : "Delete points", 0);
}

void TfEditModel::replaceAll(std::vector<EditPoint> points, const QString& what, int mergeKey) {
  for (auto& p : points)
    if (p.id == 0) p.id = nextId_++;
  record(std::move(points), what, mergeKey);
}

void TfEditModel::load(const TransferFunction& tf, const QString& what, bool resetHistory) {
  std::vector<EditPoint> p;
  for (const ControlPoint& c : tf.points())
    p.push_back({nextId_++, c.value, std::min(extinctionToOpacity(c.extinction, referenceLength_), 0.9999),
                 QColor::fromRgbF(float(c.color.r), float(c.color.g), float(c.color.b))});
  if (resetHistory) {
    undo_.clear();
    selection_.clear();
    applySnapshot(p);
    emit selectionChanged();
  } else {
    record(std::move(p), what, 0);
  }
}

TransferFunction TfEditModel::toTransferFunction() const {
  std::vector<ControlPoint> c;
  for (const auto& p : points_) c.push_back({p.value, rgb(p.color), opacityToExtinction(p.opacity, referenceLength_)});
  return TransferFunction(std::move(c));
}

QColor TfEditModel::colorAt(double value) const {
  if (points_.empty()) return Qt::white;
  const glm::dvec3 c = toTransferFunction().color(value);
  return QColor::fromRgbF(float(c.r), float(c.g), float(c.b));
}

double TfEditModel::opacityAt(double value) const {
  if (points_.empty()) return 0.0;
  return extinctionToOpacity(toTransferFunction().extinction(value), referenceLength_);
}

void TfEditModel::setSelection(std::set<int> ids) {
  if (ids == selection_) return;
  selection_ = std::move(ids);
  emit selectionChanged();
}

}  // namespace volpost::tfeditor
