// SPDX-License-Identifier: MIT
// The Probe panel: the points probed (clicked in the view or typed), each with its
// element and the shown quantity, every quantity of the selected one at full precision,
// and Copy / Export CSV / Remove / Clear. The points live in the scene (state files keep
// them); the panel shows what the model holds there.
#pragma once

#include "../core/Probe.hpp"

#include <volpost/core/EntitySet.hpp>

#include <QWidget>

#include <map>
#include <memory>
#include <vector>

class QLabel;
class QLineEdit;
class QSpinBox;
class QPushButton;
class QTableWidget;

namespace volpost::app {

class ProbePanel : public QWidget {
  Q_OBJECT

 public:
  explicit ProbePanel(QWidget* parent = nullptr);

  /// What to probe: the model, the points, the step and the quantity shown (its column).
  /// The points are on the deformed shape (measures say so).
  void setDeformed(bool deformed) { deformed_ = deformed; }
  /// Units by field name (View > Legend Text and Numbers), written after each quantity.
  void setUnits(std::map<std::string, std::string> units) { units_ = std::move(units); }
  void showProbes(std::shared_ptr<const ModelSession> session, const std::vector<glm::dvec3>& points, std::size_t step,
                  const std::string& quantityKey);
  const std::vector<ProbeResult>& results() const { return results_; }
  /// The table of every pick and quantity (as `volpost probe --csv` writes it).
  std::string table(char separator) const;

 signals:
  /// The user added, removed or cleared points: the scene should hold these now.
  void pointsChanged(const std::vector<glm::dvec3>& points);
  /// Plot Over Steps: the shown quantity against the steps at these probes (row numbers).
  void historyRequested(const std::vector<std::size_t>& rows);
  /// The selected probes measured (two or three rows; none when fewer or more are selected):
  /// the scene draws the measure in the picture.
  void measured(const std::vector<std::size_t>& rows);
  void message(const QString& text);

 private:
  void addTyped();
  void fillPicks();
  void fillDetails();
  void showMeasure();
  void removeSelected();
  void copyAll();
  void exportCsv();
  std::vector<glm::dvec3> points() const;

  std::shared_ptr<const ModelSession> session_;
  /// The model's sets, made once per session (a region field's groups scan the field).
  std::weak_ptr<const ModelSession> setsOf_;  // weak: a freed session's address may come again
  std::vector<EntitySet> sets_;
  QLabel* measure_ = nullptr;
  bool deformed_ = false;
  std::vector<ProbeResult> results_;
  std::string quantityKey_;
  std::map<std::string, std::string> units_;
  /// "S.mises [MPa]": the quantity and its units, when the field has some.
  QString withUnits(const Quantity& q) const;
  QSpinBox* digits_ = nullptr;
  QLineEdit* typed_ = nullptr;
  QTableWidget* picks_ = nullptr;
  QTableWidget* details_ = nullptr;
  QLabel* where_ = nullptr;
};

}  // namespace volpost::app
