#pragma once

// Specialises the renderer's SPIR-V on the CPU before the driver sees it (see the .cpp).

#include <cstdint>
#include <span>
#include <vector>

namespace phigs::vk {

/// One specialisation constant of shaders/scene.glsl: its constant_id and value (bools as 0 or 1).
struct SpecialisationValue {
    std::uint32_t id = 0;
    std::int32_t value = 0;
};

/// A vertex and fragment shader pair, specialised.
struct SpecialisedStages {
    std::vector<std::uint32_t> vertex;
    std::vector<std::uint32_t> fragment;
    /// The vertex inputs the specialised vertex shader still reads: the pipeline declares only
    /// these attributes (an unread one draws a validation warning).
    std::vector<std::uint32_t> vertexInputLocations;
};

/// Freezes the specialisation constants of a vertex and fragment shader pair into the SPIR-V,
/// removes the code they make dead, the fragment inputs nothing reads any more and the vertex
/// outputs that fed only those. Throws std::runtime_error naming the stage if SPIRV-Tools fails.
SpecialisedStages specialiseStages(std::span<const std::uint32_t> vertex,
                                   std::span<const std::uint32_t> fragment,
                                   std::span<const SpecialisationValue> values);

}  // namespace phigs::vk
