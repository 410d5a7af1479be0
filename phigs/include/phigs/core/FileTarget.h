#pragma once

// Files written by replacing them: the new contents go to a temporary file renamed over the old.

#include <filesystem>
#include <string>

namespace phigs {

/// The file a write to `path` must replace: a symbolic link followed to the file it names (a
/// dangling one too), so that the link stays a link and its target gets the contents.
std::filesystem::path replacedFile(std::filesystem::path path);

/// Why the file at `path` cannot be replaced by a rename (empty when it can): an existing device,
/// FIFO, socket or directory would be swapped for a regular file.
std::string notReplaceable(const std::filesystem::path& path);

}  // namespace phigs
