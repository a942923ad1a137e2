// SPDX-License-Identifier: MIT
#include <volpost/core/Version.hpp>
#include <volpost/plugin/PluginManager.hpp>

#include <gtest/gtest.h>

#include <set>

using namespace volpost;

TEST(PluginManager, LoadsTheBundledReaderPlugin) {
  PluginManager plugins;
  plugins.loadFrom({VOLPOST_PLUGIN_DIR});
  bool found = false;
  for (const PluginRecord& r : plugins.records())
    if (r.id == "meshio") {
      found = true;
      EXPECT_TRUE(r.loaded) << r.error.toStdString();
      EXPECT_EQ(r.sdkVersion.toStdString(), VOLPOST_SDK_VERSION);
      EXPECT_TRUE(r.provides.contains("reader"));
    }
  EXPECT_TRUE(found);
  std::set<std::string> formats;
  for (const MeshReader* r : plugins.readers().readers()) formats.insert(r->formatName());
  EXPECT_EQ(formats, (std::set<std::string>{"VTK XML unstructured grid", "VTK legacy", "Gmsh mesh",
                                            "Abaqus/CalculiX input deck", "CalculiX results", "Exodus II",
                                            "Tecgraf neutral file", "SEG-Y seismic volume", "VTK XML image data", "NRRD raw volume"}));
}

TEST(PluginManager, RefusesOtherSdkVersionsAndNonPluginsWithReasons) {
  PluginManager plugins;
  plugins.loadFrom({REFUSED_PLUGIN_DIR});
  ASSERT_EQ(plugins.records().size(), 3u);
  for (const PluginRecord& r : plugins.records()) {
    EXPECT_FALSE(r.loaded);
    if (r.path.contains("oldsdk"))
      EXPECT_NE(r.error.toStdString().find("built against volpost SDK 0.9"), std::string::npos) << r.error.toStdString();
    else if (r.path.contains("oldreader"))  // this SDK, another reader interface: refused for that alone
      EXPECT_NE(r.error.toStdString().find("implements the reader interface version 7; this volpost provides version " +
                                           std::to_string(VOLPOST_READER_INTERFACE_VERSION)),
                std::string::npos)
          << r.error.toStdString();
    else
      EXPECT_NE(r.error.toStdString().find("not a Qt plugin"), std::string::npos) << r.error.toStdString();
  }
  EXPECT_TRUE(plugins.readers().readers().empty());
}

TEST(PluginManager, SameIdTwiceIsRefusedTheSecondTime) {
  PluginManager plugins;
  plugins.loadFrom({VOLPOST_PLUGIN_DIR, VOLPOST_PLUGIN_DIR});
  int loaded = 0, refused = 0;
  for (const PluginRecord& r : plugins.records())
    if (r.id == "meshio") (r.loaded ? loaded : refused)++;
  EXPECT_EQ(loaded, 1);
  EXPECT_EQ(refused, 1);
}

TEST(PluginManager, MissingFoldersAreIgnored) {
  PluginManager plugins;
  plugins.loadFrom({"/no/such/folder"});
  EXPECT_TRUE(plugins.records().empty());
}
