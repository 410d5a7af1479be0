#include "phigs/vk/HardcopyTarget.h"

#include <stdexcept>

namespace phigs::vk {

HardcopyTarget::HardcopyTarget(Context& context, std::uint32_t width, std::uint32_t height,
                               std::filesystem::path file)
    : target_(context, width, height), file_(std::move(file)) {
}

HardcopyTarget::~HardcopyTarget() {
    try {
        close();
    } catch (...) {
        // A destructor must not throw; close() explicitly to see write errors.
    }
}

void HardcopyTarget::update(const DrawList& list) {
    if (closed_) throw std::logic_error("HardcopyTarget::update: " + file_.string() + " is closed");
    // The last picture's room is reused; a first draw that fails leaves no picture for close().
    if (image_)
        target_.draw(list, *image_);
    else
        image_ = target_.draw(list);
    if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
    writePng(*image_, file_);
}

void HardcopyTarget::close() {
    if (closed_) return;
    closed_ = true;
    if (image_) writePng(*image_, file_);
}

}  // namespace phigs::vk
