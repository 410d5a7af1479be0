#include "acsynt/DataFolders.h"

#include <system_error>

namespace acsynt {

std::vector<std::filesystem::path> dataFolders() {
    std::vector<std::filesystem::path> folders;
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        // An installed program's data lies where the install rules put it, relative to its folder.
        const std::filesystem::path installed =
            (program.parent_path() / ACSYNT_DATA_INSTALL_DIR).lexically_normal();
        if (std::filesystem::is_directory(installed, error)) folders.push_back(installed);
    }
    folders.emplace_back(ACSYNT_DATA_DIR);
    return folders;
}

}  // namespace acsynt
