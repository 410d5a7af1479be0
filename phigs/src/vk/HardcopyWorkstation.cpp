#include "phigs/vk/HardcopyWorkstation.h"

#include <stdexcept>

namespace phigs::vk {

HardcopyWorkstation::HardcopyWorkstation(Context& context, std::uint32_t width, std::uint32_t height,
                                         std::filesystem::path file)
    : workstation_(context, width, height), file_(std::move(file)) {
}

HardcopyWorkstation::~HardcopyWorkstation() {
    try {
        close();
    } catch (...) {
        // A destructor must not throw; close() explicitly to see write errors.
    }
}

void HardcopyWorkstation::update(const DrawList& list) {
    if (closed_) throw std::logic_error("HardcopyWorkstation::update: " + file_.string() + " is closed");
    image_ = workstation_.draw(list);
    if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
    writePng(*image_, file_);
}

void HardcopyWorkstation::close() {
    if (closed_) return;
    closed_ = true;
    if (image_) writePng(*image_, file_);
}

}  // namespace phigs::vk
