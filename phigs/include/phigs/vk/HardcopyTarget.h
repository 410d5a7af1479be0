#pragma once

#include "phigs/traverse/DrawList.h"
#include "phigs/vk/ImageTarget.h"

#include <filesystem>
#include <optional>

namespace phigs::vk {

/// The PNG hardcopy target: an image target that writes its picture to a file
/// on every update and once more on close (the last picture drawn).
class HardcopyTarget {
public:
    HardcopyTarget(Context& context, std::uint32_t width, std::uint32_t height, std::filesystem::path file);
    ~HardcopyTarget();
    HardcopyTarget(const HardcopyTarget&) = delete;
    HardcopyTarget& operator=(const HardcopyTarget&) = delete;

    /// Draws the list and writes the file.
    void update(const DrawList& list);
    /// Writes the file from the last list (if any) and stops accepting updates.
    void close();
    const std::filesystem::path& file() const { return file_; }
    Renderer& renderer() { return target_.renderer(); }
    std::uint32_t width() const { return target_.width(); }
    std::uint32_t height() const { return target_.height(); }
    /// The picture of the last update.
    const std::optional<Image>& lastImage() const { return image_; }

private:
    ImageTarget target_;
    std::filesystem::path file_;
    std::optional<Image> image_;
    bool closed_ = false;
};

}  // namespace phigs::vk
