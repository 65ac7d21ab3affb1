#include "io/table_cache.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace aurorawall::io;
using aurorawall::io::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::vector<char> table(char seed)
{
    std::vector<char> bytes(1000);
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = static_cast<char>(seed + 7 * i);
    return bytes;
}

// Calls cachedTable and counts how often it had to build.
struct Counted {
    int builds = 0;
    CachedTable get(const std::string& directory, const std::string& key, char seed = 1)
    {
        return cachedTable(directory, "test", key, [&] {
            ++builds;
            return table(seed);
        });
    }
};

std::vector<char> readBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<char>& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(TableCache, BuildsOnceThenReadsTheSameBytes)
{
    TempDir dir;
    const std::string folder = dir.file("cache");
    Counted c;
    const CachedTable first = c.get(folder, "key A");
    EXPECT_EQ(first.outcome, "built, cached");
    EXPECT_EQ(first.bytes, table(1));
    const CachedTable second = c.get(folder, "key A");
    EXPECT_EQ(second.outcome, "read from cache");
    EXPECT_EQ(second.bytes, table(1));
    EXPECT_EQ(c.builds, 1);
    EXPECT_TRUE(fs::exists(cachedTablePath(folder, "test", "key A")));
    EXPECT_EQ(fs::directory_iterator(folder)->path().filename().string().rfind("test-", 0), 0u);
}

TEST(TableCache, AChangedKeyRebuilds)
{
    TempDir dir;
    Counted c;
    c.get(dir.path().string(), "key A");
    EXPECT_NE(cachedTablePath(dir.path().string(), "test", "key A"), cachedTablePath(dir.path().string(), "test", "key B"));
    const CachedTable other = c.get(dir.path().string(), "key B", 2);
    EXPECT_EQ(other.outcome, "built, cached");
    EXPECT_EQ(other.bytes, table(2));
    EXPECT_EQ(c.builds, 2);
}

// A file under the key's name that holds another key (a hash collision) is not this table.
TEST(TableCache, AFileOfAnotherKeyIsNotRead)
{
    TempDir dir;
    const std::string folder = dir.path().string();
    Counted c;
    c.get(folder, "key A");
    fs::copy_file(cachedTablePath(folder, "test", "key A"), cachedTablePath(folder, "test", "key B"));
    const CachedTable b = c.get(folder, "key B", 2);
    EXPECT_EQ(b.outcome, "built, cached");
    EXPECT_EQ(b.bytes, table(2));
}

// Every single flipped byte (key, table, sizes, checksum, magic) and every truncation is detected,
// reported and rebuilt; the rebuilt file is good again.
TEST(TableCache, CorruptFilesAreDetectedAndRebuilt)
{
    TempDir dir;
    const std::string folder = dir.path().string();
    Counted c;
    c.get(folder, "key A");
    const std::string path = cachedTablePath(folder, "test", "key A");
    const std::vector<char> good = readBytes(path);
    ASSERT_GT(good.size(), 1000u);
    int detected = 0, cases = 0;
    for (std::size_t at = 0; at < good.size(); at += (at < 40 || at > good.size() - 20) ? 1 : 37) {
        std::vector<char> bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x10);
        writeBytes(path, bad);
        ++cases;
        const CachedTable t = c.get(folder, "key A");
        detected += t.outcome == "cache corrupt, rebuilt" && t.bytes == table(1);
        EXPECT_EQ(readBytes(path), good) << "flipped byte " << at;
    }
    for (std::size_t size : {std::size_t(0), std::size_t(5), std::size_t(30), good.size() / 2, good.size() - 1}) {
        writeBytes(path, std::vector<char>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(size)));
        ++cases;
        const CachedTable t = c.get(folder, "key A");
        detected += t.outcome == "cache corrupt, rebuilt" && t.bytes == table(1);
        EXPECT_EQ(readBytes(path), good) << "truncated to " << size;
    }
    std::vector<char> longer = good;
    longer.push_back('x');
    writeBytes(path, longer);
    ++cases;
    detected += c.get(folder, "key A").outcome == "cache corrupt, rebuilt";
    EXPECT_EQ(detected, cases);
    EXPECT_EQ(c.get(folder, "key A").outcome, "read from cache");
}

// Each rebuild of the executable is a new key: the folder keeps only the newest 8 files of a name.
TEST(TableCache, KeepsTheNewestEightFilesOfAName)
{
    TempDir dir;
    const std::string folder = dir.path().string();
    Counted c;
    cachedTable(folder, "other", "key 0", [] { return table(3); });
    for (int k = 0; k < 12; ++k) {
        const auto path = cachedTablePath(folder, "test", "key " + std::to_string(k));
        c.get(folder, "key " + std::to_string(k));
        // Older write times than the ones that follow, whatever the file system's clock resolution.
        fs::last_write_time(path, fs::file_time_type::clock::now() - std::chrono::hours(12 - k));
    }
    int tests = 0, locks = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const std::string file = entry.path().filename().string();
        tests += file.rfind("test-", 0) == 0 && entry.path().extension() == ".table";
        locks += file.rfind("test-", 0) == 0 && entry.path().extension() == ".lock";
    }
    EXPECT_EQ(tests, 8);
    EXPECT_EQ(locks, 8); // the build locks of the removed files went with them
    EXPECT_TRUE(fs::exists(cachedTablePath(folder, "other", "key 0")));
    EXPECT_TRUE(fs::exists(cachedTablePath(folder, "test", "key 11")));
    EXPECT_TRUE(fs::exists(cachedTablePath(folder, "test", "key 4")));
    EXPECT_FALSE(fs::exists(cachedTablePath(folder, "test", "key 3")));
    EXPECT_FALSE(fs::exists(cachedTablePath(folder, "test", "key 3") + ".lock"));
}

// Ranks are processes: of several that want the same missing table at once (a build that takes
// 300 ms, so that they overlap), one builds it while the others wait and then read it. Every one
// ends with the table, none sees a partial file, and the file left is good.
TEST(TableCache, ProcessesWantingTheSameTableBuildItOnce)
{
    TempDir dir;
    const std::string folder = dir.path().string();
    std::vector<pid_t> children;
    for (int k = 0; k < 6; ++k) {
        const pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            const CachedTable t = cachedTable(folder, "test", "key A", [] {
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
                return table(1);
            });
            if (t.bytes != table(1))
                ::_exit(1);
            if (t.outcome == "built, cached")
                ::_exit(10);
            ::_exit(t.outcome == "read from cache, built by another process" || t.outcome == "read from cache" ? 0 : 1);
        }
        children.push_back(pid);
    }
    int builds = 0;
    for (const pid_t pid : children) {
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_NE(WEXITSTATUS(status), 1);
        builds += WEXITSTATUS(status) == 10;
    }
    EXPECT_EQ(builds, 1);
    Counted c;
    EXPECT_EQ(c.get(folder, "key A").outcome, "read from cache");
    EXPECT_EQ(c.builds, 0);
    EXPECT_EQ(dir.entries().size(), 2u); // the table and its build lock; no temporary left behind
}

TEST(TableCache, NoFolderMeansNoCache)
{
    Counted c;
    const CachedTable t = c.get("", "key A");
    EXPECT_EQ(t.bytes, table(1));
    EXPECT_EQ(t.outcome.rfind("built, not cached", 0), 0u);
}

// A file where the folder should be: the table is still built, the failure reported.
TEST(TableCache, AFolderThatCannotBeMadeIsReported)
{
    TempDir dir;
    writeBytes(dir.file("plain"), {'x'});
    Counted c;
    const CachedTable t = c.get(dir.file("plain") + "/cache", "key A");
    EXPECT_EQ(t.bytes, table(1));
    EXPECT_EQ(t.outcome.rfind("built, not cached (", 0), 0u) << t.outcome;
}

TEST(TableCache, FolderFollowsXdgThenHome)
{
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const std::string savedXdg = xdg ? xdg : "";
    ::setenv("XDG_CACHE_HOME", "/x/cache", 1);
    EXPECT_EQ(defaultCacheDirectory(), "/x/cache/aurorawall");
    ::unsetenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    if (home && *home) {
        EXPECT_EQ(defaultCacheDirectory(), std::string(home) + "/.cache/aurorawall");
    }
    if (xdg)
        ::setenv("XDG_CACHE_HOME", savedXdg.c_str(), 1);
}

// FNV-1a 64 test vectors (Fowler, Noll & Vo): "" and "a".
TEST(TableCache, Fnv1aMatchesItsPublishedVectors)
{
    EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ull);
    EXPECT_EQ(executableDigest().size(), 16u);
}

} // namespace
