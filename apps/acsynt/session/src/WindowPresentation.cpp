#include "acsynt/session/WindowPresentation.h"

#ifdef ACSYNT_HAVE_WINDOW

namespace acsynt {

WindowPresentation::WindowPresentation(Session& session, phigs::GlfwWindow& window,
                                       phigs::vk::WorkstationDisplay& display)
    : session_(session), window_(window), display_(display) {
    session_.setShowNow([this] { present(); });
}

bool WindowPresentation::step(std::chrono::milliseconds timeout) {
    if (window_.shouldClose()) return false;
    const bool going = session_.step(timeout);
    present();
    return going && !window_.shouldClose();
}

void WindowPresentation::present() {
    const VkExtent2D size = window_.drawableSize();
    if (size.width > 0 && size.height > 0)  // minimised: keep the layout until it comes back
        session_.resize(int(size.width), int(size.height));
    session_.picture();
    const std::uint64_t picture = session_.workstation().regenerations();
    if (picture == shownPicture_ && window_.damage() == shownDamage_) return;
    shownDamage_ = window_.damage();
    if (display_.update()) {
        shownPicture_ = picture;
        ++frames_;
    }
}

}  // namespace acsynt

#endif
