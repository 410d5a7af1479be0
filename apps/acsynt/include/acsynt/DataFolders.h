#pragma once

#include <filesystem>
#include <vector>

namespace acsynt {

/// The folders holding the shipped models, curves and demo session, in search order: the
/// installed one (share/acsynt/data, found relative to the running program) where it exists,
/// then the source tree's (a build tree's program).
std::vector<std::filesystem::path> dataFolders();

}  // namespace acsynt
