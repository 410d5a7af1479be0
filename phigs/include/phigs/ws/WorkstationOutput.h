#pragma once

#include "phigs/traverse/DrawList.h"
#include "phigs/ws/EchoState.h"

#include <cstdint>

namespace phigs {

class Workstation;

/// A drawable's size in pixels (0 x 0 while a window is minimised).
struct DrawableSize {
    std::uint32_t width = 0, height = 0;
    bool operator==(const DrawableSize&) const = default;
};

/// The one seam between a workstation and what shows it: present a picture, report the
/// drawable's size, show the echoes. The workstation keeps everything else (its state, its
/// input devices, the pick echo applied to the picture it hands over). phigs/vk implements it
/// for the image, hardcopy and window targets (vk::WorkstationDisplay); a test may implement
/// it in memory.
class WorkstationOutput {
public:
    /// Leaves the workstation it shows (Workstation::attachOutput), so either may go first.
    virtual ~WorkstationOutput();
    WorkstationOutput() = default;
    WorkstationOutput(const WorkstationOutput&) = delete;
    WorkstationOutput& operator=(const WorkstationOutput&) = delete;
    /// Shows `picture`; false when nothing could be shown (a minimised window).
    virtual bool present(const DrawList& picture) = 0;
    /// The drawable now, in pixels.
    virtual DrawableSize drawableSize() const = 0;
    /// True when the drawable is the display surface itself (a window the output opened for the
    /// workstation): the workstation's display size then follows it (Workstation::followDrawable).
    /// A program that lays out its own window sets the display size itself.
    virtual bool followsDrawable() const { return false; }
    /// What the echo areas show (handed before each present): an output with an operator draws
    /// it over the picture (appendEchoes); a file has none and ignores it.
    virtual void showEcho(const EchoState& echo) { (void)echo; }
    /// True when the output draws the devices' echoes itself, as a workstation of the standard
    /// does (the workstation's own window): the echo state then carries the choice panels,
    /// valuator sliders and pick echo of the active devices (EchoState). False for a file and
    /// for a program that lays out its own window and posts them as structures.
    virtual bool drawsDeviceEchoes() const { return false; }
    /// The workstation closes; `picture` is what it shows now. A file output writes it (when
    /// it has written nothing yet, or keeps every picture) and completes its file.
    virtual void close(const DrawList& picture) { (void)picture; }

private:
    friend class Workstation;
    Workstation* shown_ = nullptr;  ///< the workstation attached to this output (it keeps this)
};

}  // namespace phigs
