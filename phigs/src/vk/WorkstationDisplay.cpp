#include "phigs/vk/WorkstationDisplay.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace phigs::vk {

namespace {

ContextSettings forType(WorkstationType type, const ContextSettings& settings) {
    return type == WorkstationType::Window ? WindowWorkstation::contextSettings(settings) : settings;
}

}  // namespace

WorkstationDisplay::WorkstationDisplay(Workstation& workstation, const ContextSettings& context,
                                       DisplaySettings settings)
    : workstation_(workstation),
      ownContext_(std::make_unique<Context>(forType(workstation.type(), context))),
      context_(ownContext_.get()) {
    open(std::move(settings));
}

WorkstationDisplay::WorkstationDisplay(Workstation& workstation, Context& context, DisplaySettings settings)
    : workstation_(workstation), context_(&context) {
    open(std::move(settings));
}

WorkstationDisplay::~WorkstationDisplay() {
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
    switch (workstation_.type()) {
        case WorkstationType::OffscreenImage:
            offscreen_ = std::make_unique<OffscreenWorkstation>(*context_, width, height);
            break;
        case WorkstationType::Hardcopy:
            if (settings.file.empty())
                throw std::invalid_argument("WorkstationDisplay: hardcopy workstation " +
                                            std::to_string(workstation_.id()) + " needs a file");
            hardcopy_ = std::make_unique<HardcopyWorkstation>(*context_, width, height, settings.file);
            break;
        case WorkstationType::Window:
            window_ = std::make_unique<WindowWorkstation>(*context_, width, height, settings.title);
            break;
        case WorkstationType::PdfFile:
        case WorkstationType::SvgFile:
        case WorkstationType::EpsFile:
            throw std::invalid_argument("WorkstationDisplay: workstation " +
                                        std::to_string(workstation_.id()) +
                                        " is a vector hardcopy: draw it with hardcopy::VectorWorkstation");
    }
}

bool WorkstationDisplay::update() {
    const DrawList* shown = &workstation_.display();
    if (!echo_.empty()) {
        // A copy with the echoed items highlighted: highlighting is a draw record flag, so the
        // renderer re-uploads only those records.
        echoed_ = *shown;
        for (DrawItem& item : echoed_.items)
            if (std::find(echo_.begin(), echo_.end(), item.source.path) != echo_.end())
                item.highlighted = true;
        shown = &echoed_;
    }
    const DrawList& picture = *shown;
    if (offscreen_) {
        image_ = offscreen_->draw(picture);
        return true;
    }
    if (hardcopy_) {
        hardcopy_->update(picture);
        image_ = *hardcopy_->lastImage();
        return true;
    }
    return window_->draw(picture, readBack_ ? &image_ : nullptr);
}

Renderer& WorkstationDisplay::renderer() {
    if (offscreen_) return offscreen_->renderer();
    if (hardcopy_) return hardcopy_->renderer();
    return window_->renderer();
}

std::uint32_t WorkstationDisplay::width() const {
    if (offscreen_) return offscreen_->width();
    if (hardcopy_) return hardcopy_->width();
    return window_->extent().width;
}

std::uint32_t WorkstationDisplay::height() const {
    if (offscreen_) return offscreen_->height();
    if (hardcopy_) return hardcopy_->height();
    return window_->extent().height;
}

WorkstationMapping WorkstationDisplay::mapping() {
    return WorkstationMapping(workstation_.display(), width(), height());
}

}  // namespace phigs::vk
