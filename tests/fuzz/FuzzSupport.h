#pragma once
// Shared by the libFuzzer targets: the input as text, a scratch directory of this process for
// the files a target must write, and a check that turns a broken property into a crash.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// A directory of this process under the system temporary directory, removed at exit.
struct ScratchDirectory {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("phigs-fuzz-" + std::to_string(getpid()));
    ScratchDirectory() { std::filesystem::create_directories(path); }
    ~ScratchDirectory() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

/// The scratch directory, emptied on every call so that one input never sees the files of the
/// one before.
inline const std::filesystem::path& scratch() {
    static const ScratchDirectory dir;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path))
        std::filesystem::remove_all(entry);
    return dir.path;
}

/// A property every accepted input must have (a round trip, a promise of the API): its failure
/// is a finding, so it aborts and libFuzzer keeps the input.
inline void check(bool holds, const char* what) {
    if (holds) return;
    std::fprintf(stderr, "fuzz: property broken: %s\n", what);
    std::abort();
}

}  // namespace fuzz
