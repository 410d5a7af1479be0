#pragma once

#include "acsynt/DataFolders.h"
#include "phigs/ws/OutputRegistry.h"
#include "phigs/ws/WorkstationType.h"

#include <filesystem>
#include <functional>
#include <vector>

namespace acsynt {

/// What a session starts from.
struct SessionSettings {
    int width = 1024, height = 768;               ///< screen size in pixels (resize() changes it)
    std::filesystem::path outputDirectory = ".";  ///< snapshots, summary, saved files
    /// Where relative names of files to read are looked up after the working directory.
    std::vector<std::filesystem::path> searchPath = dataFolders();
    /// The workstation type. A window's display surface is its drawable (any shape, one device
    /// unit per pixel); the others' (1024 x 768 device units) is shown on the width x height
    /// pixels, which must then have its 4:3 shape.
    phigs::WorkstationType workstationType = phigs::WorkstationType::OffscreenImage;
    /// End the session after the first input line that fails (a script run's default in the
    /// program; its --keep-going carries on).
    bool stopAtFirstError = false;
    /// FILE > HARDCOPY and `hardcopy` write vector files; false refuses them (the session fuzz
    /// target, where a shaded PDF of a whole model takes too long under the sanitizers).
    bool vectorHardcopies = true;
    /// Adds the outputs of the libraries the program links (vk::registerOutputs) before the
    /// workstation opens, so that OPEN WORKSTATION makes its output; none: the workstation opens
    /// without one (tests attach a vk::WorkstationDisplay; the fuzz targets draw nothing). The
    /// session adds the vector hardcopy outputs itself.
    std::function<void(phigs::OutputRegistry&)> registerOutputs;
    /// The connection the workstation opens on (a window: the vk::WindowSurface* in settings).
    phigs::OutputConnection connection;
};

}  // namespace acsynt
