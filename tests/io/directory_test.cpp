#include "io/directory.h"
#include "temp_dir.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace aurorawall::io;
using aurorawall::common::InputError;
using aurorawall::io::test::TempDir;
namespace fs = std::filesystem;

namespace {

// The message of the InputError that ensureWritableDirectory throws, or "" if none.
std::string errorFor(const std::string& dir)
{
    try {
        ensureWritableDirectory(dir, "--out");
    } catch (const aurorawall::common::InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(EnsureWritableDirectory, AcceptsAnExistingWritableFolderAndLeavesItEmpty)
{
    TempDir dir;
    EXPECT_NO_THROW(ensureWritableDirectory(dir.path().string(), "--out"));
    EXPECT_TRUE(dir.entries().empty()); // the probe file is gone
}

TEST(EnsureWritableDirectory, CreatesMissingFoldersWithTheirParents)
{
    TempDir dir;
    const std::string nested = dir.file("a/b/c");
    EXPECT_NO_THROW(ensureWritableDirectory(nested, "--out"));
    EXPECT_TRUE(fs::is_directory(nested));
    EXPECT_TRUE(fs::is_empty(nested));
}

TEST(EnsureWritableDirectory, ProcFolderGivesOneLineNamingOptionPathAndReason)
{
    const std::string message = errorFor("/proc/aw_io_test/x");
    EXPECT_EQ(message.rfind("--out /proc/aw_io_test/x: cannot create directory (", 0), 0u) << message;
    EXPECT_EQ(message.back(), ')') << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(EnsureWritableDirectory, ParentThatIsARegularFileIsRejected)
{
    TempDir dir;
    std::ofstream(dir.file("plain")) << "not a folder";
    const std::string message = errorFor(dir.file("plain/out"));
    EXPECT_EQ(message, "--out " + dir.file("plain/out") + ": cannot create directory (Not a directory)");
}

TEST(EnsureWritableDirectory, PathThatIsARegularFileIsRejected)
{
    TempDir dir;
    std::ofstream(dir.file("plain")) << "not a folder";
    const std::string message = errorFor(dir.file("plain"));
    EXPECT_EQ(message.rfind("--out " + dir.file("plain") + ": ", 0), 0u) << message;
}

TEST(EnsureWritableDirectory, ReadOnlyFolderIsRejected)
{
    TempDir dir;
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    if (::access(dir.path().c_str(), W_OK) == 0)
        GTEST_SKIP() << "this user may write into read-only folders (root)";
    const std::string message = errorFor(dir.path().string());
    EXPECT_EQ(message, "--out " + dir.path().string() + ": directory is not writable (Permission denied)");
}

// An output file's path may be nothing yet or a regular file; a folder, a device or a pipe is refused
// before anything is written, naming the option and the path.
TEST(EnsureWritableFile, OnlyNothingOrARegularFileIsWritable)
{
    TempDir dir;
    EXPECT_NO_THROW(ensureWritableFile(dir.file("new.png"), "--gather"));
    std::ofstream(dir.file("old.png")) << "an older image";
    EXPECT_NO_THROW(ensureWritableFile(dir.file("old.png"), "--gather"));
    const auto message = [](const std::string& path) {
        try {
            ensureWritableFile(path, "--gather");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    fs::create_directory(dir.file("folder.png"));
    EXPECT_EQ(message(dir.file("folder.png")), "--gather " + dir.file("folder.png") + ": is a folder, not a file");
    ASSERT_EQ(::mkfifo(dir.file("pipe.png").c_str(), 0600), 0);
    EXPECT_EQ(message(dir.file("pipe.png")), "--gather " + dir.file("pipe.png") + ": exists and is not a file");
}
