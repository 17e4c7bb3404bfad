#include "core/io/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include "core/common/error.h"
#include "testsupport.h"

namespace metrofit {
namespace {

TEST(FileIo, AtomicWriteReplacesAndLeavesNoTemporaries) {
  test::TempDir dir;
  const std::string path = dir.file("out.json");
  writeFileAtomic(path, "first");
  writeFileAtomic(path, "second, longer content");
  EXPECT_EQ(readFile(path), "second, longer content");
  EXPECT_EQ(test::listFolder(dir.path()), (std::vector<std::string>{"out.json"}));
}

TEST(FileIo, AtomicWriteIntoMissingFolderFailsCleanly) {
  test::TempDir dir;
  try {
    writeFileAtomic(dir.file("no/such/out.json"), "x");
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(test::listFolder(dir.path()).empty());
  EXPECT_THROW(writeFileAtomic(dir.path().string(), "x"), FileError);  // a folder
  EXPECT_THROW(writeFileAtomic("", "x"), FileError);
}

TEST(FileIo, KilledWriterLeavesOldOrNewFileNeverAHalfOne) {
  // A child process rewrites the file in a loop and is killed with SIGKILL at varying moments;
  // afterwards the file must be exactly one of the complete versions.
  test::TempDir dir;
  const std::string path = dir.file("project.metrofit");
  const std::string a(200000, 'a'), b(300000, 'b');
  writeFileAtomic(path, a);
  for (int round = 0; round < 8; ++round) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      for (int i = 0;; ++i) writeFileAtomic(path, (i % 2) ? a : b);
    }
    ::usleep(2000 + 3000 * round);
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    const std::string now = readFile(path);
    EXPECT_TRUE(now == a || now == b) << "round " << round << ": size " << now.size();
  }
}

TEST(FileIo, SpecialFilesAreWrittenInPlaceNotReplaced) {
  // Regression: `--out /dev/null` once renamed a temporary file over /dev/null.
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  ASSERT_TRUE(S_ISCHR(before.st_mode));
  writeFileAtomic("/dev/null", "discarded");
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/null is no longer a character device";
  EXPECT_EQ(before.st_rdev, after.st_rdev);
  // A FIFO with a reader gets the content.
  test::TempDir dir;
  const std::string fifo = dir.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    writeFileAtomic(fifo, "through the pipe");
    ::_exit(0);
  }
  EXPECT_EQ(readFile(fifo), "through the pipe");
  int status = 0;
  ::waitpid(pid, &status, 0);
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(test::listFolder(dir.path()), (std::vector<std::string>{"pipe"}));
}

TEST(FileIo, ReadFileErrors) {
  test::TempDir dir;
  EXPECT_THROW((void)readFile(dir.file("missing")), FileError);
  EXPECT_THROW((void)readFile(dir.path().string()), FileError);
  test::writeText(dir.file("big"), std::string(2048, 'x'));
  try {
    (void)readFile(dir.file("big"), 1024);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than"), std::string::npos);
  }
}

TEST(FileIo, Paths) {
  EXPECT_EQ(parentFolder("a/b/c.csv"), "a/b");
  EXPECT_EQ(parentFolder("c.csv"), ".");
  EXPECT_EQ(parentFolder("/c.csv"), "/");
  EXPECT_EQ(joinPath("a/b", "data/x.csv"), "a/b/data/x.csv");
  EXPECT_EQ(joinPath("a/b/", "x.csv"), "a/b/x.csv");
  EXPECT_EQ(joinPath(".", "x.csv"), "x.csv");
  EXPECT_EQ(joinPath("a", "/abs/x.csv"), "/abs/x.csv");
}

}  // namespace
}  // namespace metrofit
