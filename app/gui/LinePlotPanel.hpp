// SPDX-License-Identifier: MIT
// View > Plot Over Line: quantities along a segment typed or taken from the last two
// probed points, drawn as a chart (the same as `volpost plot`), exportable as CSV and PNG.
// The quantities are those checked in the panel's list, or the shown one when none is.
#pragma once

#include "../core/LineSampling.hpp"

#include <QWidget>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class QLineEdit;
class QListWidget;
class QSpinBox;

namespace volpost::app {

class Scene;

class LinePlotPanel : public QWidget {
  Q_OBJECT

 public:
  using SceneGetter = std::function<const Scene&()>;
  /// Shows (or, with nullopt, hides) the sampled line in the view.
  using LineShower = std::function<void(std::optional<std::array<glm::dvec3, 2>>)>;
  LinePlotPanel(SceneGetter scene, LineShower showLine, QWidget* parent = nullptr);

  /// Another model: its quantities listed, the old curves, ends and line gone.
  void modelChanged();
  /// The scene's line (a state file's) in the fields, plotted when it is set.
  void followScene();

  /// Samples the line typed in the panel; false (with a message) when it cannot.
  bool plot();
  /// The ends from the last two probed points of the scene.
  bool useLastProbes();
  const std::optional<LineSamples>& samples() const { return samples_; }
  void setEnds(const glm::dvec3& from, const glm::dvec3& to);
  /// Checks the quantities (written forms, "S.mises") to plot, unchecks the others; an
  /// empty list plots the shown quantity. Unknown keys are left out.
  void setQuantities(const std::vector<std::string>& keys);

 signals:
  void message(const QString& text);

 private:
  /// Lists the model's quantities (when the model changed), keeping what was checked.
  void refreshQuantities();
  std::vector<std::string> checkedQuantities() const;
  void exportCsv();
  void exportPicture();
  /// Asks where (a save dialog), then writes; a failure is said in the status bar.
  void exportTo(const QString& title, const QString& filter, const std::function<void(const QString&)>& write);

  SceneGetter scene_;
  LineShower showLine_;
  QLineEdit* from_ = nullptr;
  QLineEdit* to_ = nullptr;
  QSpinBox* count_ = nullptr;
  QListWidget* quantities_ = nullptr;
  std::string listedModel_;  ///< the model whose quantities are listed (address and path)
  QWidget* chart_ = nullptr;
  std::optional<LineSamples> samples_;
};

}  // namespace volpost::app
