// SPDX-License-Identifier: MIT
// A panel's Export button: asks for a file (starting in the last folder used), writes it,
// and gives the line the status bar shows ("Wrote ...", "Could not write ...: why").
#pragma once

#include <QString>

#include <functional>
#include <optional>

class QWidget;

namespace volpost::app {

/// nullopt when the user chose no file; else what to say about the write.
std::optional<QString> exportToChosenFile(QWidget* parent, const QString& title, const QString& filter,
                                          const std::function<void(const QString&)>& write);

}  // namespace volpost::app
