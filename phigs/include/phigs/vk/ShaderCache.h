#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace phigs::vk {

/// A folder of specialised SPIR-V shader pairs, one file per input, so that a later process skips
/// the optimiser: each file names its inputs by two hashes and carries a checksum; one that does
/// not match, is cut short or is not SPIR-V is a miss, never an error.
class ShaderCache {
public:
    /// A vertex and fragment module pair.
    struct Pair {
        std::vector<std::uint32_t> vertex, fragment;
    };

    /// Off: every look-up misses and nothing is written.
    ShaderCache() = default;
    /// Files in `folder` (made when the first is stored).
    explicit ShaderCache(std::filesystem::path folder) : folder_(std::move(folder)) {}
    /// `PHIGS_SHADER_CACHE`: a folder, or `off` (also `0` or empty); unset, `$XDG_CACHE_HOME/phigs/spirv`
    /// or `$HOME/.cache/phigs/spirv`; off when neither is set.
    static ShaderCache fromEnvironment();

    /// Whether look-ups can hit and stores write.
    bool enabled() const { return !folder_.empty(); }
    /// The folder, empty when off.
    const std::filesystem::path& folder() const { return folder_; }

    /// The pair stored for these inputs (`tag` names what made it: the optimiser's version and
    /// settings), or nothing.
    std::optional<Pair> load(std::span<const std::uint32_t> input, std::string_view tag) const;
    /// Stores a pair (through a temporary file, renamed: readers never see half a file); failures
    /// to write are ignored, as the cache only saves time.
    void store(std::span<const std::uint32_t> input, std::string_view tag, const Pair& pair) const;
    /// The file a pair for these inputs lives in.
    std::filesystem::path fileFor(std::span<const std::uint32_t> input, std::string_view tag) const;

private:
    std::filesystem::path folder_;
};

}  // namespace phigs::vk
