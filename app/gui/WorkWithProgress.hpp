// SPDX-License-Identifier: MIT
// Long work from the window (reading a model, tracing streamlines): it runs on a worker
// thread while a window-modal progress dialog, shown after a short delay, gives its
// fraction and stage and a Cancel button; the window stays responsive, and the result
// comes back on the GUI thread with the dialog already gone.
#pragma once

#include <volpost/core/Progress.hpp>

#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <string>

class QWidget;

namespace volpost::app {

/// How the work ended: a value, cancelled by the user, or an error in a user's words.
template <typename Value>
struct WorkOutcome {
  std::optional<Value> value;
  bool cancelled = false;
  QString error;
};

namespace detail {
/// The untyped core: `work` gets a Progress wired to the dialog (it throws Cancelled after
/// Cancel) and runs on a worker thread; `done` runs on the GUI thread afterwards.
void runWithProgress(QWidget& parent, const QString& label, int delayMs, std::function<void(const Progress&)> work,
                     std::function<void()> done);
}  // namespace detail

/// Runs `work(progress)` on a worker thread behind a progress dialog over `parent` that
/// reads "`label`: stage..." (shown after `delayMs`), then `done(outcome)` on the GUI thread.
/// Cancelled and std::exception from `work` become the outcome's `cancelled` and `error`.
template <typename Value>
void runWithProgress(QWidget& parent, const QString& label, int delayMs, std::function<Value(const Progress&)> work,
                     std::function<void(WorkOutcome<Value>)> done) {
  auto outcome = std::make_shared<WorkOutcome<Value>>();
  detail::runWithProgress(
      parent, label, delayMs,
      [outcome, work = std::move(work)](const Progress& progress) {
        try {
          outcome->value = work(progress);
        } catch (const Cancelled&) {
          outcome->cancelled = true;
        } catch (const std::exception& e) {
          outcome->error = QString::fromStdString(e.what());
        }
      },
      [outcome, done = std::move(done)] { done(std::move(*outcome)); });
}

}  // namespace volpost::app
