#include "acsynt/session/OffscreenPictures.h"

#include "phigs/vk/Context.h"
#include "phigs/vk/OffscreenWorkstation.h"

#include <algorithm>

namespace acsynt {

OffscreenPictures::OffscreenPictures(int width, int height) : width_(width), height_(height) {
    phigs::vk::ContextSettings defaults;
    defaults.device = phigs::vk::DevicePreference::Lavapipe;
    defaults.validation = false;
    context_ = std::make_unique<phigs::vk::Context>(phigs::vk::ContextSettings::fromEnvironment(defaults));
    workstation_ = std::make_unique<phigs::vk::OffscreenWorkstation>(*context_, width, height);
}

OffscreenPictures::~OffscreenPictures() = default;

phigs::DrawList OffscreenPictures::forRenderer(const phigs::DrawList& picture, int width, int height) {
    phigs::DrawList list = picture;
    const double unit = std::min(width, height);
    list.viewportMin /= unit;
    list.viewportMax /= unit;
    list.viewportMin.z = picture.viewportMin.z;
    list.viewportMax.z = picture.viewportMax.z;
    return list;
}

phigs::Image OffscreenPictures::draw(const phigs::DrawList& picture) {
    return workstation_->draw(forRenderer(picture, width_, height_));
}

void OffscreenPictures::writePng(const phigs::DrawList& picture, const std::filesystem::path& file) {
    phigs::writePng(draw(picture), file);
}

}  // namespace acsynt
