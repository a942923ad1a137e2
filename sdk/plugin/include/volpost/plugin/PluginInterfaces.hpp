// SPDX-License-Identifier: MIT
// The Qt plugin interfaces of volpost. Each IID carries the version of its own interface
// (VOLPOST_*_INTERFACE_VERSION): a plugin built against another version of the interface it
// implements does not cast to it, and the host refuses it from its metadata before loading
// it (see PluginManager); a change of one interface leaves plugins of the others alone.
#pragma once

#include <volpost/core/MeshReader.hpp>
#include <volpost/core/Model.hpp>
#include <volpost/core/Quantity.hpp>
#include <volpost/core/SampleView.hpp>
#include <volpost/core/TransferFunction.hpp>
#include <volpost/core/TransferFunction2D.hpp>
#include <volpost/core/Version.hpp>

#include <QtPlugin>
#include <QList>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

class QWidget;

namespace volpost {

class Renderer;

/// Provides mesh readers. The readers live as long as the plugin instance.
class ReaderPlugin {
 public:
  virtual ~ReaderPlugin() = default;
  virtual QList<const MeshReader*> readers() const = 0;
};

/// Provides renderers (they draw into a RenderContext; see volpost/render/Renderer.hpp).
/// A volume renderer says what it draws, which settings it takes and its words for a menu
/// itself (VolumeRenderer::traits()).
class RendererPlugin {
 public:
  virtual ~RendererPlugin() = default;
  /// The names the command line and state files use ("raycast"), in menu order.
  virtual QStringList rendererNames() const = 0;
  /// A new renderer; the caller initializes it with a current GL context.
  virtual std::unique_ptr<Renderer> createRenderer(const QString& name) const = 0;
};

/// What a panel may ask of the host window.
class PanelHost {
 public:
  virtual ~PanelHost() = default;
  virtual const Model* model() const = 0;
  virtual std::optional<Quantity> activeQuantity() const = 0;
  virtual std::size_t activeStep() const = 0;
  virtual void requestRender() = 0;
  /// The volume view's transfer function (the host's default for the active result until
  /// a panel sets one).
  virtual TransferFunction transferFunction() const = 0;
  /// Applies a transfer function: the volume view and its legend follow. Cheap to call
  /// often: slow tables are rebuilt off the GUI thread and rapid changes coalesce.
  virtual void setTransferFunction(const TransferFunction& tf) = 0;
  /// Values of the active result at the active step (one per node or cell), for histograms
  /// and snapping, in the type that holds them (a seismic cube's samples as stored); empty
  /// when none is shown. Valid until the panel's next hostChanged(): a panel copies what it
  /// keeps longer.
  virtual SampleView activeValues() const = 0;
  /// Diagonal of the model's bounding box (model length units): the scale for opacity.
  virtual double modelSize() const = 0;
  /// What the renderer's last transfer-function change cost (tables and upload), ms; 0 if
  /// none yet.
  virtual double lastTransferFunctionMs() const = 0;
  /// The volume view's 2D transfer function (value x gradient magnitude), for regular grids;
  /// nullopt while the 1D one is used.
  virtual std::optional<TransferFunction2D> transferFunction2D() const = 0;
  /// Draws a grid's volume with `tf` instead of the 1D function (nullopt: the 1D one
  /// again). Returns false, having told the user why, where the model cannot take it.
  virtual bool setTransferFunction2D(const std::optional<TransferFunction2D>& tf) = 0;
};

/// Provides a dock panel (e.g. the transfer-function editor). Only real editors ship widgets.
class PanelPlugin {
 public:
  virtual ~PanelPlugin() = default;
  virtual QString panelTitle() const = 0;
  virtual QWidget* createPanel(PanelHost& host, QWidget* parent) = 0;
  /// Called by the host when the model, quantity or step changed.
  virtual void hostChanged() {}
};

}  // namespace volpost

#define VOLPOST_IID_TEXT(x) #x
#define VOLPOST_IID(name, version) "org.volpost." name "/" VOLPOST_IID_TEXT(version)
#define VOLPOST_READER_PLUGIN_IID VOLPOST_IID("ReaderPlugin", VOLPOST_READER_INTERFACE_VERSION)
#define VOLPOST_RENDERER_PLUGIN_IID VOLPOST_IID("RendererPlugin", VOLPOST_RENDERER_INTERFACE_VERSION)
#define VOLPOST_PANEL_PLUGIN_IID VOLPOST_IID("PanelPlugin", VOLPOST_PANEL_INTERFACE_VERSION)

Q_DECLARE_INTERFACE(volpost::ReaderPlugin, VOLPOST_READER_PLUGIN_IID)
Q_DECLARE_INTERFACE(volpost::RendererPlugin, VOLPOST_RENDERER_PLUGIN_IID)
Q_DECLARE_INTERFACE(volpost::PanelPlugin, VOLPOST_PANEL_PLUGIN_IID)
