// SPDX-License-Identifier: MIT
// Output files are complete or not there: a failed write (file-size limit standing in for
// a full disk, a missing folder, a folder as target) throws naming the file and leaves the
// previous file intact and no temporary file behind; a link planted next to the target
// is never followed.
#include "host/AtomicFile.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace volpost;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("volpost_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t entries() const { return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
  fs::path dir_;
};

}  // namespace

TEST_F(AtomicFileTest, WritesAndReplaces) {
  const fs::path out = dir_ / "a.txt";
  writeFileAtomically(out.string(), "first");
  writeFileAtomically(out.string(), "second");
  EXPECT_EQ(contents(out), "second");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AFailedWriteKeepsThePreviousFile) {
  const fs::path out = dir_ / "b.txt";
  writeFileAtomically(out.string(), "the user's old file");
  // A file-size limit makes write() fail with EFBIG, as a full disk fails with ENOSPC.
  struct rlimit old {};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = old;
  small.rlim_cur = 1000;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeFileAtomically(out.string(), std::string(100000, 'x'));
  } catch (const WriteError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previousHandler);
  EXPECT_NE(message.find(out.string()), std::string::npos) << message;
  EXPECT_EQ(contents(out), "the user's old file");
  EXPECT_EQ(entries(), 1u) << "no temporary file left behind";
}

TEST_F(AtomicFileTest, MissingFolderAndFolderTargetsAreRefusedByName) {
  const fs::path missing = dir_ / "no" / "such" / "c.txt";
  try {
    writeFileAtomically(missing.string(), "x");
    FAIL() << "no exception";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeFileAtomically(dir_.string(), "x"), WriteError);
  EXPECT_THROW(writeFileAtomically("/proc/version", "x"), WriteError);
}

TEST_F(AtomicFileTest, LinksPlantedNextToTheTargetAreNotFollowed) {
  const fs::path victim = dir_ / "victim.txt";
  writeFileAtomically(victim.string(), "precious");
  const fs::path out = dir_ / "d.vtu";
  fs::create_symlink(victim, dir_ / "d.vtu.part");  // the name older versions wrote through
  writeFileAtomically(out.string(), "output");
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_EQ(contents(out), "output");
}

TEST_F(AtomicFileTest, AReplacedFileKeepsItsPermissions) {
  const fs::path out = dir_ / "private.png";
  writeFileAtomically(out.string(), "first");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write);
  writeFileAtomically(out.string(), "second");  // it became 0644 (umask's mode for a new file)
  EXPECT_EQ(fs::status(out).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(contents(out), "second");
}

TEST_F(AtomicFileTest, ALinkAtTheTargetIsWrittenThrough) {
  // As the shell's '>' and cp do: the link stays and the file it points to is replaced.
  fs::create_directories(dir_ / "real");
  const fs::path file = dir_ / "real" / "picture.png", link = dir_ / "picture.png";
  writeFileAtomically(file.string(), "old");
  fs::create_symlink(file, link);
  writeFileAtomically(link.string(), "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(contents(file), "new");
  EXPECT_EQ(entries(), 2u) << "the link and the folder, no temporary";
}

TEST_F(AtomicFileTest, AnInterruptedWriteLeavesNoTemporary) {
  // A video export killed with Ctrl+C or kill left its hidden ".name.XXXXXX" beside the target.
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const fs::path out = dir_ / "movie.mp4";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      AtomicFile file(out.string());
      file.write("half a video");
      std::raise(signal);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "the signal still ends the process";
    EXPECT_EQ(entries(), 0u) << "signal " << signal << " left a temporary";
  }
}
