#include "phigs/core/FileTarget.h"

#include <system_error>

namespace phigs {

std::filesystem::path replacedFile(std::filesystem::path path) {
    std::error_code ec;
    // 40 links, as the kernel allows before ELOOP.
    for (int hop = 0; hop < 40 && std::filesystem::is_symlink(path, ec); ++hop) {
        const std::filesystem::path next = std::filesystem::read_symlink(path, ec);
        if (ec) break;
        path = next.is_absolute() ? next : path.parent_path() / next;
    }
    return path;
}

std::string notReplaceable(const std::filesystem::path& path) {
    std::error_code ec;
    switch (std::filesystem::status(path, ec).type()) {
        case std::filesystem::file_type::not_found:
        case std::filesystem::file_type::regular:
            return {};
        case std::filesystem::file_type::directory:
            return "is a directory";
        default:
            return "is not a regular file (a device, FIFO or socket)";
    }
}

}  // namespace phigs
