// SPDX-License-Identifier: MIT
// View > Plot Over Line: the shown quantity along a segment typed or taken from the last
// two probed points, drawn as a chart (the same as `volpost plot`), exportable as CSV and
// PNG.
#pragma once

#include "../core/LineSampling.hpp"

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QLineEdit;
class QSpinBox;

namespace volpost::app {

class Scene;

class LinePlotPanel : public QWidget {
  Q_OBJECT

 public:
  using SceneGetter = std::function<const Scene&()>;
  LinePlotPanel(SceneGetter scene, QWidget* parent = nullptr);

  /// Samples the line typed in the panel; false (with a message) when it cannot.
  bool plot();
  /// The ends from the last two probed points of the scene.
  bool useLastProbes();
  const std::optional<LineSamples>& samples() const { return samples_; }
  void setEnds(const glm::dvec3& from, const glm::dvec3& to);

 signals:
  void message(const QString& text);

 private:
  void exportCsv();
  void exportPicture();
  /// Asks where (a save dialog), then writes; a failure is said in the status bar.
  void exportTo(const QString& title, const QString& filter, const std::function<void(const QString&)>& write);

  SceneGetter scene_;
  QLineEdit* from_ = nullptr;
  QLineEdit* to_ = nullptr;
  QSpinBox* count_ = nullptr;
  QWidget* chart_ = nullptr;
  std::optional<LineSamples> samples_;
};

}  // namespace volpost::app
