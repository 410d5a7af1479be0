#pragma once

#include "phigs/image/Image.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/HardcopyTarget.h"
#include "phigs/vk/ImageTarget.h"
#include "phigs/vk/Renderer.h"
#include "phigs/vk/WindowSurface.h"
#include "phigs/vk/WindowTarget.h"
#include "phigs/ws/Workstation.h"
#include "phigs/ws/WorkstationOutput.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phigs::vk {

/// How a WorkstationDisplay shows its workstation.
struct DisplaySettings {
    std::uint32_t width = 0, height = 0;  ///< the surface in pixels; 0: the type's display size
    /// window: the window to draw in (phigs/window's GlfwWindow), which outlives the display;
    /// required for that type. Its drawable decides the size (width and height are unused).
    WindowSurface* window = nullptr;
    /// hardcopy: the PNG file (required for that type); offscreen: a PNG written at every
    /// presentation and on close (optional)
    std::filesystem::path file;
    bool readBack = false;  ///< window: copy every presented picture into image()
    /// Draw the devices' echoes (choice panels, valuator sliders, pick echo) as the standard's
    /// workstation does (WorkstationOutput::drawsDeviceEchoes); off for a program that posts
    /// its own (buildChoicePanel).
    bool deviceEchoes = false;
};

/// The workstation's output (WorkstationOutput) through the Vulkan backend, on the target its
/// type asks for (offscreen image, a window's surface, PNG hardcopy); it attaches itself to the
/// workstation, and update() presents ws.shownPicture() with the target's one Renderer, whose
/// caches make an unchanged picture upload nothing.
class WorkstationDisplay : public WorkstationOutput {
public:
    /// With a context of its own, made from `context` (window types add the surface extensions).
    WorkstationDisplay(Workstation& workstation, const ContextSettings& context,
                       DisplaySettings settings = {});
    /// Sharing a context (for a window, made from WindowTarget::contextSettings()).
    WorkstationDisplay(Workstation& workstation, Context& context, DisplaySettings settings = {});
    /// Sharing a context it keeps alive (the outputs vk::registerOutputs makes).
    WorkstationDisplay(Workstation& workstation, std::shared_ptr<Context> context,
                       DisplaySettings settings = {});
    ~WorkstationDisplay() override;
    WorkstationDisplay(const WorkstationDisplay&) = delete;
    WorkstationDisplay& operator=(const WorkstationDisplay&) = delete;

    /// Draws what the workstation shows now (Workstation::present). False when a window had
    /// nothing to show it on (minimised).
    bool update() { return workstation_.present(); }
    /// Draws `picture` with the echoes last handed over (showEcho) on top.
    bool present(const DrawList& picture) override;
    DrawableSize drawableSize() const override { return {width(), height()}; }
    /// Keeps the echo state the next present draws (appendEchoes).
    void showEcho(const EchoState& echo) override { echo_ = echo; }
    bool drawsDeviceEchoes() const override { return deviceEchoes_; }
    /// The echo state it draws now (a test reads what the picture shows from it).
    const EchoState& echo() const { return echo_; }
    /// CLOSE WORKSTATION: the files (an offscreen PNG, the hardcopy) get `picture`.
    void close(const DrawList& picture) override;
    /// Frees an offscreen image's colour, depth and readback images and image() until the next
    /// present makes them again (a script that draws only for its snapshots holds them only then).
    void releaseImages();
    /// Draws what the workstation shows now and returns the picture (a window reads the
    /// presented image back), for snapshots.
    const Image& capture();
    /// Pick echo: the items with these paths (Workstation::lastPickEcho) are drawn
    /// highlighted until the echo is set again (empty: none).
    void setEcho(std::vector<std::vector<DrawPathLevel>> paths) { workstation_.setEcho(std::move(paths)); }
    /// The last picture (offscreen and hardcopy; a window only with `readBack`).
    const Image& image() const { return image_; }

    Workstation& workstation() { return workstation_; }
    Context& context() { return *context_; }
    Renderer& renderer();
    /// The surface in pixels (a window's current extent).
    std::uint32_t width() const;
    std::uint32_t height() const;
    /// The workstation transformation of the current picture on this surface.
    WorkstationMapping mapping();
    /// The window target (null for other types).
    WindowTarget* window() { return window_.get(); }
    /// The display showing `workstation` (its output); throws std::logic_error naming the
    /// workstation when its output is none or another kind.
    static WorkstationDisplay& of(Workstation& workstation);

private:
    void open(DisplaySettings settings);
    /// `picture` with the echoes drawn over it (the picture itself when there are none).
    const DrawList& withEcho(const DrawList& picture);

    Workstation& workstation_;
    std::unique_ptr<Context> ownContext_;
    std::shared_ptr<Context> sharedContext_;
    Context* context_ = nullptr;
    std::unique_ptr<ImageTarget> offscreen_;
    std::unique_ptr<HardcopyTarget> hardcopy_;
    std::unique_ptr<WindowTarget> window_;
    bool readBack_ = false;
    bool deviceEchoes_ = false;
    std::filesystem::path offscreenFile_;
    Image image_;
    EchoState echo_;
    DrawList echoed_;  ///< the last picture with echoes
};

}  // namespace phigs::vk
