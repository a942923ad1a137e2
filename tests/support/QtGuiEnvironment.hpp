// SPDX-License-Identifier: MIT
// A QGuiApplication on Qt's offscreen platform for the whole test binary: pictures with a
// legend need fonts, which Qt serves only with an application object.
#pragma once

#include <QGuiApplication>

#include <gtest/gtest.h>

#include <memory>

namespace volpost::test {

class QtGuiEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "volpost_tests";
    static char* argv[] = {name, nullptr};
    app_ = std::make_unique<QGuiApplication>(argc, argv);
  }
  void TearDown() override { app_.reset(); }

 private:
  std::unique_ptr<QGuiApplication> app_;
};

// One per binary that includes this header.
inline ::testing::Environment* const kQtGuiEnvironment = ::testing::AddGlobalTestEnvironment(new QtGuiEnvironment);

}  // namespace volpost::test
