// The cache on disk of derived data (core/derived_cache.h) through its use
// for the coast field (ocean/coast/coast_cache.h): a field read back is the
// solved one bit for bit; an entry cut short, changed or of other inputs
// is never read as one; a cache that is off or cannot be written changes
// nothing but the time; the folder's bound removes the oldest entries.
#include "core/derived_cache.h"
#include "ocean/coast/coast_cache.h"

#include "swell/coast_field.h"
#include "swell/scene/waves.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using swell::CoastField;
using swell::DepthGrid;
using swell::WaveSet;

// A beach of one slope across a 48 x 40 grid, two waves: a field that
// solves in milliseconds and has shoaling, breaking and dry land in it.
DepthGrid derivedCacheBeach(float shift_m = 0.0f)
{
    DepthGrid g;
    g.cell_m = 4.0;
    g.size = {48, 40};
    g.outsideDepth_m = 20.0;
    g.depth_m.resize(std::size_t(g.size.x) * std::size_t(g.size.y));
    for (int j = 0; j < g.size.y; ++j)
        for (int i = 0; i < g.size.x; ++i)
            g.depth_m[std::size_t(j) * std::size_t(g.size.x) + std::size_t(i)] = 20.0f - 0.12f * float(i) * 4.0f + shift_m;
    return g;
}

WaveSet derivedCacheWaves()
{
    WaveSet set;
    set.depth_m = 20.0;
    set.waves.push_back(swell::Wave{{1.0, 0.3}, 40.0, 0.4, 0.5, 0.0});
    set.waves.push_back(swell::Wave{{1.0, -0.2}, 25.0, 0.2, 0.5, 1.0});
    return set;
}

bool sameField(const CoastField& a, const CoastField& b)
{
    if (a.waveCount() != b.waveCount() || a.reach().vertical_m != b.reach().vertical_m
        || a.reach().horizontal_m != b.reach().horizontal_m || a.common().size() != b.common().size()
        || std::memcmp(a.common().data(), b.common().data(), a.common().size_bytes()) != 0)
        return false;
    for (std::size_t w = 0; w < 2; ++w)
        if (a.layerOf(w) != b.layerOf(w))
            return false;
    for (std::size_t l = 0; l < a.waveCount(); ++l)
        if (a.layer(l).size() != b.layer(l).size()
            || std::memcmp(a.layer(l).data(), b.layer(l).data(), a.layer(l).size_bytes()) != 0)
            return false;
    return true;
}

// Each test its own folder, named in the environment the cache reads.
class DerivedCache : public ::testing::Test {
protected:
    void SetUp() override
    {
        folder_ = fs::temp_directory_path() / ("swell-derived-cache-test-" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        ::setenv("SWELL_CACHE_DIR", folder_.c_str(), 1);
    }
    void TearDown() override
    {
        ::unsetenv("SWELL_CACHE_DIR");
        ::unsetenv("SWELL_CACHE_MAX_MB");
        fs::remove_all(folder_);
    }
    std::vector<fs::path> entries() const
    {
        std::vector<fs::path> found;
        std::error_code ec;
        for (const fs::directory_entry& e : fs::directory_iterator(folder_, ec))
            found.push_back(e.path());
        return found;
    }
    fs::path folder_;
};

TEST_F(DerivedCache, AFieldReadBackIsTheSolvedOneBitForBit)
{
    const CoastField solved(derivedCacheWaves(), derivedCacheBeach());
    const std::uint64_t hits = swell::detail::derivedCacheHits();
    const auto first = swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
    EXPECT_EQ(swell::detail::derivedCacheHits(), hits) << "a cold cache read an entry";
    ASSERT_EQ(entries().size(), 1u);
    const auto second = swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
    EXPECT_EQ(swell::detail::derivedCacheHits(), hits + 1) << "the kept entry was not read";
    EXPECT_TRUE(sameField(*first, solved));
    EXPECT_TRUE(sameField(*second, solved)) << "the field read back is not the solved one";
    EXPECT_EQ(second->depth().depth_m, derivedCacheBeach().depth_m);
    // Its readings too, at a point in the surf.
    const glm::dvec2 p{101.3, 77.7};
    EXPECT_EQ(second->commonAt(p).breaking, solved.commonAt(p).breaking);
}

TEST_F(DerivedCache, OtherInputsAreNeverReadAsTheKeptOnes)
{
    swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
    const std::uint64_t hits = swell::detail::derivedCacheHits();
    // The floor 1 cm deeper everywhere, then one wave's phase changed.
    const auto deeper = swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach(0.01f));
    WaveSet turned = derivedCacheWaves();
    turned.waves[1].phase_rad += 1e-9;
    const auto shifted = swell::coast::solvedOrCachedField(turned, derivedCacheBeach());
    EXPECT_EQ(swell::detail::derivedCacheHits(), hits);
    EXPECT_TRUE(sameField(*deeper, CoastField(derivedCacheWaves(), derivedCacheBeach(0.01f))));
    EXPECT_TRUE(sameField(*shifted, CoastField(turned, derivedCacheBeach())));
    EXPECT_EQ(entries().size(), 3u);
}

TEST_F(DerivedCache, AnEntryCutShortOrChangedIsSolvedAgainAndReplaced)
{
    const CoastField solved(derivedCacheWaves(), derivedCacheBeach());
    swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries().front();
    const auto size = fs::file_size(entry);
    for (const bool cut : {false, true}) {
        SCOPED_TRACE(cut ? "cut short" : "one byte changed");
        if (cut) {
            fs::resize_file(entry, size / 2);
        } else {
            std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(std::streamoff(size * 3 / 4));
            f.put('\x5a');
        }
        const std::uint64_t hits = swell::detail::derivedCacheHits();
        const auto again = swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
        EXPECT_EQ(swell::detail::derivedCacheHits(), hits) << "a damaged entry was read";
        EXPECT_TRUE(sameField(*again, solved));
        // Replaced by a sound one, which the next reads.
        EXPECT_EQ(fs::file_size(entry), size);
        const auto read = swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach());
        EXPECT_EQ(swell::detail::derivedCacheHits(), hits + 1);
        EXPECT_TRUE(sameField(*read, solved));
    }
}

TEST_F(DerivedCache, OffOrUnwritableItOnlySolves)
{
    const CoastField solved(derivedCacheWaves(), derivedCacheBeach());
    const std::uint64_t hits = swell::detail::derivedCacheHits();
    ::setenv("SWELL_CACHE_DIR", "", 1);
    EXPECT_TRUE(sameField(*swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach()), solved));
    EXPECT_FALSE(fs::exists(folder_));
    // A folder under a plain file can be neither made nor written.
    fs::create_directories(folder_);
    std::ofstream(folder_ / "plain") << "x";
    ::setenv("SWELL_CACHE_DIR", (folder_ / "plain" / "cache").c_str(), 1);
    for (int i = 0; i < 2; ++i)
        EXPECT_TRUE(sameField(*swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach()), solved));
    EXPECT_EQ(swell::detail::derivedCacheHits(), hits);
    EXPECT_EQ(entries().size(), 1u); // the plain file alone
}

TEST_F(DerivedCache, TheBoundRemovesTheLeastRecentlyUsedFirst)
{
    auto solve = [](float shift_m) { swell::coast::solvedOrCachedField(derivedCacheWaves(), derivedCacheBeach(shift_m)); };
    solve(0.1f);
    ASSERT_EQ(entries().size(), 1u);
    // A bound of three and a half entries: the fourth takes the folder past
    // it, and the least recently used go until it holds three quarters of it.
    const double entry_mb = double(fs::file_size(entries().front())) / (1024.0 * 1024.0);
    ::setenv("SWELL_CACHE_MAX_MB", std::to_string(3.5 * entry_mb).c_str(), 1);
    solve(0.2f);
    solve(0.3f);
    ASSERT_EQ(entries().size(), 3u);
    // The first read again (renewed): the second and third are the least
    // recently used when a fourth comes.
    std::uint64_t hits = swell::detail::derivedCacheHits();
    solve(0.1f);
    EXPECT_EQ(swell::detail::derivedCacheHits(), ++hits);
    solve(0.4f);
    EXPECT_EQ(entries().size(), 2u);
    solve(0.1f);
    EXPECT_EQ(swell::detail::derivedCacheHits(), ++hits) << "the entry used last but one was removed";
    solve(0.4f);
    EXPECT_EQ(swell::detail::derivedCacheHits(), ++hits) << "the newest entry was removed";
    solve(0.2f);
    EXPECT_EQ(swell::detail::derivedCacheHits(), hits) << "a least recently used entry was kept";
}

} // namespace
