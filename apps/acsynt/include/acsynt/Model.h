#pragma once

#include "acsynt/AircraftDescription.h"
#include "acsynt/Component.h"

#include <filesystem>
#include <string>
#include <vector>

namespace acsynt {

/// An aircraft: its lofted components and the description they came from (kept for FILE →
/// SAVE MODEL; a reduced model's surfaces no longer follow it).
struct Model {
    std::string name;
    std::string sourceFile;  ///< where it was read from; empty for a built or copied model
    AircraftDescription description;
    std::vector<Component> components;

    /// The component of that name, or null.
    const Component* find(const std::string& componentName) const;
    Component* find(const std::string& componentName);
    /// Patches of all components together.
    std::size_t patchCount() const;
};

/// Lofts every component of a description (a mirrored component adds its mirror image right
/// after it). A component that cannot be lofted throws ModelFileError naming fileName and the
/// component's line; no partial model is returned.
Model buildModel(const AircraftDescription& description, const std::string& fileName = "<model>");

/// readAircraftDescription, then buildModel: the whole model or a ModelFileError.
Model loadModel(const std::filesystem::path& path);

}  // namespace acsynt
