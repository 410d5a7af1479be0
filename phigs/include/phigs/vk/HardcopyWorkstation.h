#pragma once

#include "phigs/traverse/DrawList.h"
#include "phigs/vk/OffscreenWorkstation.h"

#include <filesystem>
#include <optional>

namespace phigs::vk {

/// The PNG hardcopy workstation type: an offscreen workstation that writes its picture to a file
/// on every update and once more on close (the last list drawn).
class HardcopyWorkstation {
public:
    HardcopyWorkstation(Context& context, std::uint32_t width, std::uint32_t height,
                        std::filesystem::path file);
    ~HardcopyWorkstation();
    HardcopyWorkstation(const HardcopyWorkstation&) = delete;
    HardcopyWorkstation& operator=(const HardcopyWorkstation&) = delete;

    /// Draws the list and writes the file.
    void update(const DrawList& list);
    /// Writes the file from the last list (if any) and stops accepting updates.
    void close();
    const std::filesystem::path& file() const { return file_; }

private:
    OffscreenWorkstation workstation_;
    std::filesystem::path file_;
    std::optional<DrawList> last_;
    bool closed_ = false;
};

}  // namespace phigs::vk
