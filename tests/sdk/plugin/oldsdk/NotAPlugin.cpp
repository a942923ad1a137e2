// SPDX-License-Identifier: MIT
// A shared library in a plugin folder that is not a Qt plugin at all.
extern "C" int volpostNotAPlugin() { return 42; }
