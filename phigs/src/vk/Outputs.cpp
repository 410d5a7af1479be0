#include "phigs/vk/Outputs.h"

#include "phigs/vk/WorkstationDisplay.h"

#include <memory>

namespace phigs::vk {

namespace {

/// The Context the offscreen and hardcopy outputs of one registry share, made at the first open
/// and kept while any of them lives.
class SharedContext {
public:
    explicit SharedContext(ContextSettings settings) : settings_(std::move(settings)) {}
    std::shared_ptr<Context> get() {
        std::shared_ptr<Context> context = context_.lock();
        if (!context) {
            context = std::make_shared<Context>(settings_);
            context_ = context;
        }
        return context;
    }

private:
    ContextSettings settings_;
    std::weak_ptr<Context> context_;
};

DisplaySettings displaySettings(const OutputConnection& connection) {
    DisplaySettings settings;
    settings.width = connection.width;
    settings.height = connection.height;
    settings.file = connection.identifier;
    return settings;
}

}  // namespace

void registerOutputs(OutputRegistry& registry, const ContextSettings& context) {
    auto shared = std::make_shared<SharedContext>(context);
    registry.add(
        WorkstationType::OffscreenImage, [shared](Workstation& ws, const OutputConnection& connection) {
            return std::make_unique<WorkstationDisplay>(ws, shared->get(), displaySettings(connection));
        });
    registry.add(WorkstationType::Hardcopy, [shared](Workstation& ws, const OutputConnection& connection) {
        if (connection.identifier.empty())
            throw ConnectionRefused("a PNG hardcopy needs a file name as its connection identifier");
        return std::make_unique<WorkstationDisplay>(ws, shared->get(), displaySettings(connection));
    });
    registry.add(WorkstationType::Window, [context](Workstation& ws, const OutputConnection& connection) {
        WindowSurface* const* window = std::any_cast<WindowSurface*>(&connection.settings);
        if (!window || !*window)
            throw ConnectionRefused(
                "a window workstation needs the window (a vk::WindowSurface*) in its "
                "connection's settings");
        DisplaySettings settings = displaySettings(connection);
        settings.file.clear();
        settings.window = *window;
        return std::make_unique<WorkstationDisplay>(ws, context, settings);
    });
}

}  // namespace phigs::vk
