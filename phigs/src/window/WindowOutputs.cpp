#include "phigs/window/WindowOutputs.h"

#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace phigs {

namespace {

/// A window the output opened itself, the display drawing in it and the window's input source.
class OwnWindowOutput : public WorkstationOutput {
public:
    OwnWindowOutput(Workstation& ws, const OutputConnection& connection, const vk::ContextSettings& context)
        : workstation_(ws) {
        const glm::dvec2 size = ws.description().displaySize;
        const std::uint32_t width = connection.width ? connection.width : std::uint32_t(std::lround(size.x));
        const std::uint32_t height =
            connection.height ? connection.height : std::uint32_t(std::lround(size.y));
        window_ = std::make_unique<GlfwWindow>(width, height, "PHIGS workstation " + std::to_string(ws.id()),
                                               connection.identifier);
        vk::DisplaySettings settings;
        settings.window = window_.get();
        settings.deviceEchoes = true;
        display_ = std::make_unique<vk::WorkstationDisplay>(ws, context, settings);
    }
    ~OwnWindowOutput() override {
        input_.reset();    // its callbacks leave the window first
        display_.reset();  // the display (its surface) before the window
        window_.reset();
    }
    bool present(const DrawList& picture) override {
        window_->pollEvents();
        return display_->present(picture);
    }
    void showEcho(const EchoState& echo) override { display_->showEcho(echo); }
    /// The workstation's own window: nothing else draws the devices' echoes there.
    bool drawsDeviceEchoes() const override { return display_->drawsDeviceEchoes(); }
    DrawableSize drawableSize() const override { return display_->drawableSize(); }
    bool followsDrawable() const override { return true; }
    /// Made when first asked for: a program that reads no input keeps no queue of actions. While
    /// the program waits for input, a resized or exposed window is repainted (the workstation
    /// keeps its picture) and the wait goes on.
    GlfwInputSource& input() {
        if (!input_) {
            input_ = std::make_unique<GlfwInputSource>(*window_);
            input_->setDamageHandler([this] { workstation_.present(); });
        }
        return *input_;
    }

private:
    Workstation& workstation_;
    std::unique_ptr<GlfwWindow> window_;
    std::unique_ptr<vk::WorkstationDisplay> display_;
    std::unique_ptr<GlfwInputSource> input_;
};

}  // namespace

InputSource* ownWindowInputSource(WorkstationOutput* output) {
    auto* own = dynamic_cast<OwnWindowOutput*>(output);
    return own ? &own->input() : nullptr;
}

void registerWindowOutputs(OutputRegistry& registry, const vk::ContextSettings& context) {
    const OutputFactory* given = registry.find(WorkstationType::Window);
    OutputFactory program = given ? *given : OutputFactory{};
    registry.add(
        WorkstationType::Window,
        [program, context](Workstation& ws,
                           const OutputConnection& connection) -> std::unique_ptr<WorkstationOutput> {
            if (program && connection.settings.has_value()) return program(ws, connection);
            try {
                return std::make_unique<OwnWindowOutput>(ws, connection, context);
            } catch (const std::invalid_argument& e) {  // a second display, a bad size
                throw ConnectionRefused(e.what());
            }
        });
}

}  // namespace phigs
