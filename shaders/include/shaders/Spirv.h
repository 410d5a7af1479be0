#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace shaders {

/// The SPIR-V words of the shader compiled from shaders/<name> (e.g. "smoke.vert"); throws
/// std::invalid_argument for a name that was not embedded.
std::span<const uint32_t> spirv(std::string_view name);

}  // namespace shaders
