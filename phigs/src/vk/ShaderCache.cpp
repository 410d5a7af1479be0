#include "phigs/vk/ShaderCache.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace phigs::vk {
namespace {

constexpr std::uint32_t kMagic = 0x56505350;  // "PSPV"
constexpr std::uint32_t kFormat = 1;
constexpr std::uint32_t kSpirvMagic = 0x07230203;
/// Magic, format, two input hashes (two words each), input length, vertex and fragment lengths,
/// payload checksum (two words).
constexpr std::size_t kHeaderWords = 11;
/// A module larger than this is not one of ours: a miss, not a huge allocation.
constexpr std::uint32_t kMaxModuleWords = 1u << 24;

/// FNV-1a over 64 bits, from `seed`.
struct Fnv {
    std::uint64_t h;
    void add(std::uint32_t w) {
        for (int b = 0; b < 4; ++b) h = (h ^ ((w >> (8 * b)) & 0xff)) * 0x100000001b3ull;
    }
    void add(std::span<const std::uint32_t> words) {
        for (std::uint32_t w : words) add(w);
    }
    void add(std::string_view s) {
        for (char c : s) h = (h ^ std::uint8_t(c)) * 0x100000001b3ull;
        add(std::uint32_t(s.size()));
    }
};

std::array<std::uint64_t, 2> inputHashes(std::span<const std::uint32_t> input, std::string_view tag) {
    Fnv a{0xcbf29ce484222325ull}, b{0x84222325cbf29ce4ull};
    a.add(tag), b.add(tag);
    a.add(input);
    // The second in reverse order: a collision in one is not one in the other.
    for (std::size_t i = input.size(); i-- > 0;) b.add(input[i]);
    return {a.h, b.h};
}

std::uint64_t checksum(std::span<const std::uint32_t> vertex, std::span<const std::uint32_t> fragment) {
    Fnv f{0x9e3779b97f4a7c15ull};
    f.add(vertex), f.add(fragment);
    return f.h;
}

void putHash(std::vector<std::uint32_t>& out, std::uint64_t h) {
    out.push_back(std::uint32_t(h)), out.push_back(std::uint32_t(h >> 32));
}

std::uint64_t getHash(const std::uint32_t* w) {
    return std::uint64_t(w[0]) | std::uint64_t(w[1]) << 32;
}

bool isSpirv(const std::vector<std::uint32_t>& module) {
    return module.size() >= 5 && module[0] == kSpirvMagic;
}

}  // namespace

ShaderCache ShaderCache::fromEnvironment() {
    if (const char* value = std::getenv("PHIGS_SHADER_CACHE")) {
        const std::string_view v = value;
        if (v.empty() || v == "off" || v == "0") return {};
        return ShaderCache(std::filesystem::path(v));
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME");
        xdg && *xdg && std::filesystem::path(xdg).is_absolute())
        return ShaderCache(std::filesystem::path(xdg) / "phigs" / "spirv");
    if (const char* home = std::getenv("HOME"); home && *home)
        return ShaderCache(std::filesystem::path(home) / ".cache" / "phigs" / "spirv");
    return {};
}

std::filesystem::path ShaderCache::fileFor(std::span<const std::uint32_t> input, std::string_view tag) const {
    const auto h = inputHashes(input, tag);
    char name[40];
    std::snprintf(name, sizeof name, "%016llx.spv2", static_cast<unsigned long long>(h[0]));
    return folder_ / name;
}

std::optional<ShaderCache::Pair> ShaderCache::load(std::span<const std::uint32_t> input,
                                                   std::string_view tag) const {
    if (!enabled()) return std::nullopt;
    const std::filesystem::path path = fileFor(input, tag);
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::uint32_t header[kHeaderWords];
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
    const auto h = inputHashes(input, tag);
    if (header[0] != kMagic || header[1] != kFormat || getHash(header + 2) != h[0] ||
        getHash(header + 4) != h[1] || header[6] != std::uint32_t(input.size()) ||
        header[7] > kMaxModuleWords || header[8] > kMaxModuleWords)
        return std::nullopt;
    // The file must hold exactly what its header says before anything is allocated for it.
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error || size != (kHeaderWords + std::uintmax_t(header[7]) + header[8]) * 4) return std::nullopt;
    Pair pair;
    pair.vertex.resize(header[7]);
    pair.fragment.resize(header[8]);
    if (!in.read(reinterpret_cast<char*>(pair.vertex.data()), std::streamsize(pair.vertex.size() * 4)) ||
        !in.read(reinterpret_cast<char*>(pair.fragment.data()), std::streamsize(pair.fragment.size() * 4)))
        return std::nullopt;
    char extra;
    if (in.read(&extra, 1)) return std::nullopt;  // longer than its header says
    if (checksum(pair.vertex, pair.fragment) != getHash(header + 9) || !isSpirv(pair.vertex) ||
        !isSpirv(pair.fragment))
        return std::nullopt;
    return pair;
}

void ShaderCache::store(std::span<const std::uint32_t> input, std::string_view tag, const Pair& pair) const {
    if (!enabled()) return;
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    if (error) return;
    std::vector<std::uint32_t> words = {kMagic, kFormat};
    const auto h = inputHashes(input, tag);
    putHash(words, h[0]), putHash(words, h[1]);
    words.push_back(std::uint32_t(input.size()));
    words.push_back(std::uint32_t(pair.vertex.size())), words.push_back(std::uint32_t(pair.fragment.size()));
    putHash(words, checksum(pair.vertex, pair.fragment));
    words.insert(words.end(), pair.vertex.begin(), pair.vertex.end());
    words.insert(words.end(), pair.fragment.begin(), pair.fragment.end());
    // A name of its own per process and call: writers running at once never share a temporary.
    static std::atomic<unsigned> serial{0};
    const std::filesystem::path target = fileFor(input, tag);
    std::filesystem::path temporary = target;
    temporary += "." + std::to_string(::getpid()) + "." + std::to_string(serial++) + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(words.data()), std::streamsize(words.size() * 4));
        if (!out.flush()) {
            out.close();
            std::filesystem::remove(temporary, error);
            return;
        }
    }
    std::filesystem::rename(temporary, target, error);
    if (error) std::filesystem::remove(temporary, error);
}

}  // namespace phigs::vk
