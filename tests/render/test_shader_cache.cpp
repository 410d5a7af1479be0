// The disk cache of specialised shaders: what is stored comes back for the same inputs only, and
// a file that is damaged in any way (a byte changed, cut short, lengthened, another input's) is a
// miss, never an error or a crash.
#include "phigs/vk/ShaderCache.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

namespace test_shader_cache {

using phigs::vk::ShaderCache;

namespace {

std::vector<std::uint32_t> randomWords(std::mt19937& rng, std::size_t lo, std::size_t hi) {
    std::vector<std::uint32_t> words(std::uniform_int_distribution<std::size_t>(lo, hi)(rng));
    for (auto& w : words) w = std::uint32_t(rng());
    return words;
}

ShaderCache::Pair randomPair(std::mt19937& rng) {
    ShaderCache::Pair pair{randomWords(rng, 5, 200), randomWords(rng, 5, 200)};
    pair.vertex[0] = pair.fragment[0] = 0x07230203;  // SPIR-V's magic number
    return pair;
}

std::filesystem::path freshFolder(const char* name) {
    const auto folder = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / name;
    std::filesystem::remove_all(folder);
    return folder;
}

std::vector<char> bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const std::filesystem::path& file, const std::vector<char>& bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace

TEST_CASE("shader cache: a stored pair comes back for its inputs and tag only", "[shader_cache]") {
    std::mt19937 rng(20);
    const ShaderCache cache(freshFolder("shader_cache_round_trip"));
    for (int round = 0; round < 50; ++round) {
        const auto input = randomWords(rng, 0, 300);
        const auto pair = randomPair(rng);
        REQUIRE_FALSE(cache.load(input, "tag").has_value());
        cache.store(input, "tag", pair);
        const auto back = cache.load(input, "tag");
        REQUIRE(back.has_value());
        CHECK(back->vertex == pair.vertex);
        CHECK(back->fragment == pair.fragment);
        CHECK_FALSE(cache.load(input, "another tag").has_value());
        auto other = input;
        if (other.empty())
            other.push_back(1);
        else
            other[std::uniform_int_distribution<std::size_t>(0, other.size() - 1)(rng)] ^= 1u << (rng() % 32);
        CHECK_FALSE(cache.load(other, "tag").has_value());
    }
    // No temporary file is left behind.
    for (const auto& entry : std::filesystem::directory_iterator(cache.folder()))
        CHECK(entry.path().extension() == ".spv2");
}

TEST_CASE("shader cache: a damaged file is a miss", "[shader_cache]") {
    std::mt19937 rng(21);
    const ShaderCache cache(freshFolder("shader_cache_damage"));
    for (int round = 0; round < 100; ++round) {
        const auto input = randomWords(rng, 1, 50);
        const auto pair = randomPair(rng);
        cache.store(input, "tag", pair);
        const auto file = cache.fileFor(input, "tag");
        const std::vector<char> good = bytesOf(file);
        REQUIRE(good.size() > 44);
        std::vector<char> bad = good;
        switch (round % 4) {
            case 0:  // one byte changed, anywhere
                bad[std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng)] ^=
                    char(1 + rng() % 255);
                break;
            case 1:  // cut short
                bad.resize(std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng));
                break;
            case 2:  // longer than its header says
                bad.insert(bad.end(), 1 + rng() % 8, char(rng()));
                break;
            default: {  // another input's file under this name
                const auto input2 = randomWords(rng, 1, 50);
                cache.store(input2, "tag", randomPair(rng));
                bad = bytesOf(cache.fileFor(input2, "tag"));
            }
        }
        write(file, bad);
        CHECK_FALSE(cache.load(input, "tag").has_value());
        write(file, good);
        CHECK(cache.load(input, "tag").has_value());
    }
}

TEST_CASE("shader cache: modules that are not SPIR-V are a miss", "[shader_cache]") {
    std::mt19937 rng(22);
    const ShaderCache cache(freshFolder("shader_cache_not_spirv"));
    const auto input = randomWords(rng, 1, 50);
    auto pair = randomPair(rng);
    pair.fragment[0] = 0x12345678;
    cache.store(input, "tag", pair);
    CHECK_FALSE(cache.load(input, "tag").has_value());
}

TEST_CASE("shader cache: off stores and finds nothing, the environment chooses the folder",
          "[shader_cache]") {
    std::mt19937 rng(23);
    const ShaderCache off;
    const auto input = randomWords(rng, 1, 50);
    off.store(input, "tag", randomPair(rng));
    CHECK_FALSE(off.enabled());
    CHECK_FALSE(off.load(input, "tag").has_value());

    const char* saved = std::getenv("PHIGS_SHADER_CACHE");
    const std::string savedValue = saved ? saved : "";
    setenv("PHIGS_SHADER_CACHE", "off", 1);
    CHECK_FALSE(ShaderCache::fromEnvironment().enabled());
    setenv("PHIGS_SHADER_CACHE", "0", 1);
    CHECK_FALSE(ShaderCache::fromEnvironment().enabled());
    setenv("PHIGS_SHADER_CACHE", "/some/folder", 1);
    CHECK(ShaderCache::fromEnvironment().folder() == "/some/folder");
    unsetenv("PHIGS_SHADER_CACHE");
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const std::string xdgValue = xdg ? xdg : "";
    setenv("XDG_CACHE_HOME", "/xdg", 1);
    CHECK(ShaderCache::fromEnvironment().folder() == "/xdg/phigs/spirv");
    if (xdg)
        setenv("XDG_CACHE_HOME", xdgValue.c_str(), 1);
    else
        unsetenv("XDG_CACHE_HOME");
    setenv("PHIGS_SHADER_CACHE", saved ? savedValue.c_str() : "off", 1);
}

}  // namespace test_shader_cache
