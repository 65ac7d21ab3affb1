#include "io/atomic_file.h"
#include "io/exr.h"
#include "io/png.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <unistd.h>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;
namespace fs = std::filesystem;

namespace {

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream file(path, std::ios::binary);
    file << text;
    if (!file.flush())
        throw std::runtime_error(path + ": write failed");
}

std::string readText(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// Random values compress badly, so the files are larger than the size limit below.
Image noise(int width, int height)
{
    Image image(width, height);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(0.0f, 2.0f);
    for (float& v : image.rgba)
        v = value(random);
    return image;
}

// While alive, the process may not write files past `bytes` (writes fail with EFBIG instead of SIGXFSZ).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &old_);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }

private:
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

} // namespace

TEST(AtomicFile, TemporaryIsHiddenInTheSameFolder)
{
    EXPECT_EQ(temporaryPathFor("out/wall.exr"), "out/.wall.exr.tmp-" + std::to_string(::getpid()));
    EXPECT_EQ(temporaryPathFor("wall.exr"), ".wall.exr.tmp-" + std::to_string(::getpid()));
}

TEST(AtomicFile, CompleteWriteAppearsUnderTheFinalNameOnly)
{
    TempDir dir;
    const std::string path = dir.file("a.txt");
    writeFileAtomically(path, [](const std::string& temporary) { writeText(temporary, "complete"); });
    EXPECT_EQ(readText(path), "complete");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, FailureMidWriteLeavesNoFinalFileAndNoTemporary)
{
    TempDir dir;
    const std::string path = dir.file("a.txt");
    EXPECT_THROW(writeFileAtomically(path,
                                     [](const std::string& temporary) {
                                         writeText(temporary, "half of it");
                                         throw std::runtime_error("simulated crash of the writer");
                                     }),
                 std::runtime_error);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, FailedRewriteKeepsTheOlderFile)
{
    TempDir dir;
    const std::string path = dir.file("a.txt");
    writeText(path, "old");
    EXPECT_THROW(writeFileAtomically(path,
                                     [](const std::string& temporary) {
                                         writeText(temporary, "ne");
                                         throw std::runtime_error("simulated failure");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(readText(path), "old");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, ExrAndPngIntoAMissingFolderThrowAndCreateNothing)
{
    TempDir dir;
    const Image image(4, 4);
    EXPECT_THROW(writeExr(dir.file("missing/wall.exr"), image), std::runtime_error);
    EXPECT_THROW(writePng(dir.file("missing/wall.png"), image, ToneMap{}), std::runtime_error);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ExrAndPngIntoProcThrowAndCreateNothing)
{
    // /proc refuses new files even to root.
    const Image image(4, 4);
    EXPECT_THROW(writeExr("/proc/aw_io_test.exr", image), std::runtime_error);
    EXPECT_THROW(writePng("/proc/aw_io_test.png", image, ToneMap{}), std::runtime_error);
    EXPECT_FALSE(fs::exists("/proc/aw_io_test.exr"));
    EXPECT_FALSE(fs::exists("/proc/aw_io_test.png"));
}

TEST(AtomicFile, ExrAndPngIntoAReadOnlyFolderThrowAndCreateNothing)
{
    TempDir dir;
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    if (::access(dir.path().c_str(), W_OK) == 0)
        GTEST_SKIP() << "this user may write into read-only folders (root)";
    const Image image(4, 4);
    EXPECT_THROW(writeExr(dir.file("wall.exr"), image), std::runtime_error);
    EXPECT_THROW(writePng(dir.file("wall.png"), image, ToneMap{}), std::runtime_error);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ExrAndPngFailingMidWriteLeaveNoFinalFileAndNoTemporary)
{
    TempDir dir;
    const Image image = noise(256, 256); // several hundred kB in either format
    {
        FileSizeLimit limit(16 * 1024);
        EXPECT_THROW(writeExr(dir.file("wall.exr"), image), std::runtime_error);
        EXPECT_THROW(writePng(dir.file("wall.png"), image, ToneMap{}), std::runtime_error);
    }
    EXPECT_TRUE(dir.entries().empty());
    // The same writes succeed without the limit.
    writeExr(dir.file("wall.exr"), image);
    writePng(dir.file("wall.png"), image, ToneMap{});
    EXPECT_GT(fs::file_size(dir.file("wall.exr")), 16u * 1024u);
    EXPECT_GT(fs::file_size(dir.file("wall.png")), 16u * 1024u);
    EXPECT_EQ(dir.entries().size(), 2u);
}
