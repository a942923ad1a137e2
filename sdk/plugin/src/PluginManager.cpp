// SPDX-License-Identifier: MIT
#include <volpost/plugin/PluginManager.hpp>

#include <volpost/core/Version.hpp>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>
#include <QLibrary>
#include <QSettings>

namespace volpost {
namespace {

// Refuses a plugin from its metadata alone, before any of its code runs.
QString checkMetadata(const QJsonObject& meta, PluginRecord& record) {
  const QString iid = meta.value("IID").toString();
  if (!iid.startsWith("org.volpost."))
    return QString("not a volpost plugin (IID \"%1\")").arg(iid);
  const QJsonObject data = meta.value("MetaData").toObject();
  record.id = data.value("id").toString();
  record.name = data.value("name").toString(record.id);
  record.version = data.value("version").toString();
  record.sdkVersion = data.value("sdkVersion").toString();
  record.description = data.value("description").toString();
  if (record.id.isEmpty()) return "its metadata has no \"id\"";
  const QStringList sdk = record.sdkVersion.split('.');
  const int major = sdk.value(0).toInt(), minor = sdk.value(1).toInt();
  if (record.sdkVersion.isEmpty() || major != VOLPOST_SDK_VERSION_MAJOR ||
      minor > VOLPOST_SDK_VERSION_MINOR)
    return QString("built against volpost SDK %1, this volpost has SDK %2; rebuild the plugin "
                   "against this SDK")
        .arg(record.sdkVersion.isEmpty() ? "(unknown)" : record.sdkVersion, VOLPOST_SDK_VERSION);
  // The interface it implements, at its own version.
  struct Interface {
    const char* name;
    const char* words;
    int version;
  };
  const Interface interfaces[] = {{"ReaderPlugin", "reader", VOLPOST_READER_INTERFACE_VERSION},
                                  {"RendererPlugin", "renderer", VOLPOST_RENDERER_INTERFACE_VERSION},
                                  {"PanelPlugin", "panel", VOLPOST_PANEL_INTERFACE_VERSION}};
  const QString kind = iid.section('/', 0, 0).section('.', -1), version = iid.section('/', 1);
  for (const Interface& i : interfaces)
    if (kind == i.name) {
      if (version == QString::number(i.version)) return {};
      return QString(
                 "implements the %1 interface version %2; this volpost provides version %3: rebuild the "
                 "plugin against this SDK")
          .arg(i.words, version.isEmpty() ? QString("(none)") : version)
          .arg(i.version);
    }
  return QString("declares interface %1, which this SDK (%2) does not provide").arg(iid, VOLPOST_SDK_VERSION);
}

}  // namespace

PluginManager::PluginManager() = default;

PluginManager::~PluginManager() {
  // Readers and renderers live in the plugins: drop every pointer before unloading.
  readers_ = ReaderRegistry();
  instances_.clear();
  loaders_.clear();  // QPluginLoader keeps the libraries loaded until process exit
}

QStringList PluginManager::userPaths() {
  return QSettings("volpost", "volpost").value("plugins/userPaths").toStringList();
}

void PluginManager::setUserPaths(const QStringList& paths) {
  QSettings("volpost", "volpost").setValue("plugins/userPaths", paths);
}

QStringList PluginManager::defaultSearchPaths() {
  QStringList dirs;
  dirs << QDir(QCoreApplication::applicationDirPath()).absoluteFilePath("../lib/volpost/plugins");
  for (const QString& d : qEnvironmentVariable("VOLPOST_PLUGIN_PATH").split(':', Qt::SkipEmptyParts))
    dirs << d;
  dirs << userPaths();
  return dirs;
}

void PluginManager::loadFrom(const QStringList& folders) {
  for (const QString& folder : folders) {
    const QDir dir(folder);
    if (!dir.exists()) continue;
    for (const QFileInfo& file : dir.entryInfoList(QDir::Files, QDir::Name))
      if (QLibrary::isLibrary(file.fileName())) tryLoad(file.absoluteFilePath());
  }
}

void PluginManager::tryLoad(const QString& path) {
  PluginRecord record;
  record.path = path;
  auto loader = std::make_unique<QPluginLoader>(path);
  const QJsonObject meta = loader->metaData();
  if (meta.isEmpty()) {
    record.error = "not a Qt plugin: " + loader->errorString();
  } else {
    record.error = checkMetadata(meta, record);
  }
  for (const PluginRecord& other : records_)
    if (record.error.isEmpty() && other.loaded && other.id == record.id)
      record.error = QString("another plugin with id \"%1\" is already loaded from %2").arg(record.id, other.path);
  if (record.error.isEmpty()) {
    QObject* instance = loader->instance();
    if (!instance) {
      record.error = "failed to load: " + loader->errorString();
    } else {
      if (auto* r = qobject_cast<ReaderPlugin*>(instance)) {
        record.provides << "reader";
        for (const MeshReader* reader : r->readers()) readers_.add(reader);
      }
      if (qobject_cast<RendererPlugin*>(instance)) record.provides << "renderer";
      if (qobject_cast<PanelPlugin*>(instance)) record.provides << "panel";
      if (record.provides.isEmpty()) {
        record.error = "implements no volpost interface of SDK " VOLPOST_SDK_VERSION;
        loader->unload();
      } else {
        record.loaded = true;
        instances_.push_back(instance);
        loaders_.push_back(std::move(loader));
      }
    }
  }
  records_.push_back(std::move(record));
}

std::vector<RendererPlugin*> PluginManager::rendererPlugins() const {
  std::vector<RendererPlugin*> out;
  for (QObject* o : instances_)
    if (auto* p = qobject_cast<RendererPlugin*>(o)) out.push_back(p);
  return out;
}

std::vector<PanelPlugin*> PluginManager::panelPlugins() const {
  std::vector<PanelPlugin*> out;
  for (QObject* o : instances_)
    if (auto* p = qobject_cast<PanelPlugin*>(o)) out.push_back(p);
  return out;
}

}  // namespace volpost
