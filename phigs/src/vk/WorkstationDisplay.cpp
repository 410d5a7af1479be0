#include "phigs/vk/WorkstationDisplay.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace phigs::vk {

namespace {

WindowSurface& windowOf(const Workstation& workstation, const DisplaySettings& settings) {
    if (!settings.window)
        throw std::invalid_argument("WorkstationDisplay: window workstation " +
                                    std::to_string(workstation.id()) +
                                    " needs a window (DisplaySettings::window)");
    return *settings.window;
}

ContextSettings forType(const Workstation& workstation, const ContextSettings& context,
                        const DisplaySettings& settings) {
    if (workstation.type() != WorkstationType::Window) return context;
    return WindowTarget::contextSettings(windowOf(workstation, settings), context);
}

}  // namespace

WorkstationDisplay::WorkstationDisplay(Workstation& workstation, const ContextSettings& context,
                                       DisplaySettings settings)
    : workstation_(workstation),
      ownContext_(std::make_unique<Context>(forType(workstation, context, settings))),
      context_(ownContext_.get()) {
    open(std::move(settings));
}

WorkstationDisplay::WorkstationDisplay(Workstation& workstation, Context& context, DisplaySettings settings)
    : workstation_(workstation), context_(&context) {
    open(std::move(settings));
}

WorkstationDisplay::WorkstationDisplay(Workstation& workstation, std::shared_ptr<Context> context,
                                       DisplaySettings settings)
    : workstation_(workstation), sharedContext_(std::move(context)), context_(sharedContext_.get()) {
    open(std::move(settings));
}

WorkstationDisplay& WorkstationDisplay::of(Workstation& workstation) {
    if (auto* display = dynamic_cast<WorkstationDisplay*>(workstation.output())) return *display;
    throw std::logic_error("workstation " + std::to_string(workstation.id()) +
                           " is not shown by a vk::WorkstationDisplay (opened without vk::registerOutputs?)");
}

WorkstationDisplay::~WorkstationDisplay() {
    // Leaving the workstation (back to its own output) is WorkstationOutput's destructor's part:
    // it runs after this, and knows whether the workstation is still there.
    // The targets go before a context of our own (member order would do it too; said for clarity).
    window_.reset();
    hardcopy_.reset();
    offscreen_.reset();
}

void WorkstationDisplay::open(DisplaySettings settings) {
    const glm::dvec2 display = workstation_.description().displaySize;
    const std::uint32_t width = settings.width ? settings.width : std::uint32_t(std::lround(display.x));
    const std::uint32_t height = settings.height ? settings.height : std::uint32_t(std::lround(display.y));
    readBack_ = settings.readBack;
    deviceEchoes_ = settings.deviceEchoes;
    switch (workstation_.type()) {
        case WorkstationType::OffscreenImage:
            offscreen_ = std::make_unique<ImageTarget>(*context_, width, height);
            offscreenFile_ = settings.file;
            break;
        case WorkstationType::Hardcopy:
            if (settings.file.empty())
                throw std::invalid_argument("WorkstationDisplay: hardcopy workstation " +
                                            std::to_string(workstation_.id()) + " needs a file");
            hardcopy_ = std::make_unique<HardcopyTarget>(*context_, width, height, settings.file);
            break;
        case WorkstationType::Window:
            window_ = std::make_unique<WindowTarget>(*context_, windowOf(workstation_, settings));
            break;
        case WorkstationType::PdfFile:
        case WorkstationType::SvgFile:
        case WorkstationType::EpsFile:
            throw std::invalid_argument("WorkstationDisplay: workstation " +
                                        std::to_string(workstation_.id()) +
                                        " is a vector hardcopy: draw it with hardcopy::VectorWorkstation");
    }
    workstation_.attachOutput(this);
}

const DrawList& WorkstationDisplay::withEcho(const DrawList& picture) {
    if (echo_.empty()) return picture;
    echoed_ = picture;
    appendEchoes(echoed_, echo_, WorkstationMapping(picture, width(), height()));
    return echoed_;
}

bool WorkstationDisplay::present(const DrawList& shown) {
    const DrawList& picture = withEcho(shown);
    if (offscreen_) {
        offscreen_->draw(picture, image_);
        if (!offscreenFile_.empty()) writePng(image_, offscreenFile_);
        return true;
    }
    if (hardcopy_) {
        hardcopy_->update(picture);
        image_ = *hardcopy_->lastImage();
        return true;
    }
    return window_->draw(picture, readBack_ ? &image_ : nullptr);
}

void WorkstationDisplay::close(const DrawList& picture) {
    if (!offscreenFile_.empty()) present(picture);
    if (hardcopy_) {
        present(picture);
        hardcopy_->close();
    }
}

void WorkstationDisplay::releaseImages() {
    if (!offscreen_) return;
    offscreen_->releaseImages();
    image_ = Image{};
}

const Image& WorkstationDisplay::capture() {
    if (!window_ || readBack_) {
        update();
        return image_;
    }
    showEcho(workstation_.echoState());  // the echoes as they are now
    if (!window_->draw(withEcho(workstation_.shownPicture()), &image_))
        throw std::runtime_error("WorkstationDisplay: the window has no picture to capture (minimised)");
    return image_;
}

Renderer& WorkstationDisplay::renderer() {
    if (offscreen_) return offscreen_->renderer();
    if (hardcopy_) return hardcopy_->renderer();
    return window_->renderer();
}

std::uint32_t WorkstationDisplay::width() const {
    if (offscreen_) return offscreen_->width();
    if (hardcopy_) return hardcopy_->width();
    return window_->drawableSize().width;
}

std::uint32_t WorkstationDisplay::height() const {
    if (offscreen_) return offscreen_->height();
    if (hardcopy_) return hardcopy_->height();
    return window_->drawableSize().height;
}

WorkstationMapping WorkstationDisplay::mapping() {
    return WorkstationMapping(workstation_.display(), width(), height());
}

}  // namespace phigs::vk
