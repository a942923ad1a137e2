// SPDX-License-Identifier: MIT
// For tests of a part of the window alone: a plain main window and a scene stand in for
// the window, changes to the scene go through the same kind of callback, and models come
// from tests/data.
#pragma once

#include "gui/ChangeScene.hpp"

#include "core/ModelSession.hpp"
#include "core/Scene.hpp"

#include "AllReaders.hpp"

#include <QMainWindow>
#include <QStatusBar>

#include <filesystem>
#include <memory>
#include <string>

namespace volpost::test {

/// Runs a change on the scene as the window does: a refusal goes to the status bar (false).
inline app::ChangeScene changingScene(QMainWindow& window, app::Scene& scene) {
  return [&window, &scene](const std::function<void(app::Scene&)>& change) {
    try {
      change(scene);
    } catch (const std::exception& e) {
      window.statusBar()->showMessage(e.what());
      return false;
    }
    return true;
  };
}

/// A model from tests/data ("bar/bar_tet4.vtu").
inline std::shared_ptr<const app::ModelSession> loadTestModel(const std::string& relative) {
  return app::ModelSession::load(meshio::allReadersRegistry(),
                                 (std::filesystem::path(VOLPOST_TEST_DATA) / relative).string());
}

}  // namespace volpost::test
