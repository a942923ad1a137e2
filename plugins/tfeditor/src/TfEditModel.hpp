// SPDX-License-Identifier: MIT
// What the transfer-function editor edits: control points as an analyst thinks of them
// (value, opacity of a slab of a stated reference length, color), with undo/redo. Every
// edit is one undoable snapshot; a drag merges into one step. The renderer's
// TransferFunction (extinction per length) is derived from it.
#pragma once

#include <volpost/core/TransferFunction.hpp>

#include <QColor>
#include <QObject>
#include <QUndoStack>

#include <optional>
#include <set>
#include <vector>

namespace volpost::tfeditor {

struct EditPoint {
  int id = 0;             ///< stable identity (selection survives reordering)
  double value = 0.0;     ///< scalar value, field units
  double opacity = 0.0;   ///< opacity of a slab of the reference length, 0..1
  QColor color = Qt::white;
  bool operator==(const EditPoint&) const = default;
};

class TfEditModel : public QObject {
  Q_OBJECT

 public:
  explicit TfEditModel(QObject* parent = nullptr);

  /// Sorted by value.
  const std::vector<EditPoint>& points() const { return points_; }
  int indexOf(int id) const;
  /// Opacity is measured over this length (model units); changing it keeps the extinction.
  double referenceLength() const { return referenceLength_; }
  void setReferenceLength(double length);

  // Edits, each undoable. `mergeKey` > 0 merges consecutive edits with the same key into
  // one undo step (a drag, a window/level gesture).
  int addPoint(double value, double opacity, std::optional<QColor> color = std::nullopt);
  void movePoints(const std::vector<EditPoint>& moved, const QString& what, int mergeKey = 0);
  void setColor(int id, const QColor& color);
  void removePoints(const std::set<int>& ids);
  void replaceAll(std::vector<EditPoint> points, const QString& what, int mergeKey = 0);

  /// Loads a renderer TF (opacity from extinction over the reference length). Not undoable
  /// when `resetHistory` (a new field); otherwise one undo step.
  void load(const TransferFunction& tf, const QString& what, bool resetHistory);
  TransferFunction toTransferFunction() const;
  /// Color of the function at a value (for new points and the color bar).
  QColor colorAt(double value) const;
  double opacityAt(double value) const;

  QUndoStack* undoStack() { return &undo_; }
  const std::set<int>& selection() const { return selection_; }
  void setSelection(std::set<int> ids);

  /// Used by the undo commands: sets the points without recording.
  void applySnapshot(const std::vector<EditPoint>& points);

 signals:
  void changed();
  void selectionChanged();

 private:
  void record(std::vector<EditPoint> after, const QString& what, int mergeKey);
  std::vector<EditPoint> points_;
  std::set<int> selection_;
  double referenceLength_ = 1.0;
  int nextId_ = 1;
  QUndoStack undo_;
};

}  // namespace volpost::tfeditor
