#pragma once

// The C++ mirror of the data shaders/scene.glsl reads (std140 frame block, std430 draw array).

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace phigs::vk::gpu {

/// Views a frame may use: each takes a run of the run buffer (its view alone). The workstation
/// types' view tables hold 32; a larger table is allowed up to this.
inline constexpr int kMaxViews = 1024;
inline constexpr int kMaxLights = 64;
inline constexpr int kMaxLightSets = 16;
inline constexpr int kMaxCues = 16;
inline constexpr int kMaxClipPlanes = 64;  ///< model clipping half spaces of all items together
/// Lit runs of a frame (a light set of up to 4 lights premultiplied by a material, seen from a
/// view); draws beyond them light the general way.
inline constexpr int kMaxLitRuns = 256;
/// The run buffer: one run per view (the view alone), then the lit runs.
inline constexpr int kMaxRuns = kMaxViews + kMaxLitRuns;

/// The draw record's flags: the shaders test Hatch, Pattern and PatternInModelUnits; the others
/// decide the pipeline's specialisation (shaders/scene.glsl) and are kept for inspection.
enum Flag : int {
    VertexColours = 1,
    Lit = 2,
    DistinguishBack = 4,
    Highlight = 8,
    Hatch = 16,
    Pattern = 32,
    OffsetNpc = 64,
    Triangles = 128,
    PatternInModelUnits = 256,
};
enum Shade : int { Flat = 1, Gouraud = 2, Phong = 4 };

struct View {
    glm::mat4 worldToClip{1.0f};
    glm::mat4 worldToNpc{1.0f};
    glm::vec4 eye{0, 0, 1, 0};
    glm::vec4 clip{0, 1, 0, 0};
    // The NPC rectangle the scissor keeps and a marker's position must lie in (ViewClipRectangle):
    // lo x, lo y, hi x, hi y.
    glm::vec4 clipXY{0, 0, 1, 1};
};

struct Light {
    glm::vec4 colour{0.0f};
    glm::vec4 position{0.0f};
    glm::vec4 direction{0.0f};
    glm::vec4 attenuation{0.0f};
};

/// A light of a draw's light set with the draw's reflectance folded in (in a LitRun): an
/// ambient light's ambient term, or another light's diffuse and specular terms, so the shaders
/// only multiply by the base colour.
struct LitLight {
    glm::vec4 diffuse{0.0f};   ///< ambient light: ambient coefficient x colour; else diffuse x colour
    glm::vec4 specular{0.0f};  ///< specular x colour x specular colour, exponent
    glm::vec4 position{0.0f};
    glm::vec4 direction{0.0f};
    glm::vec4 attenuation{0.0f};
};

struct DepthCue {
    glm::vec4 planes{0.0f};
    glm::vec4 colour{0.0f};
};

struct Frame {
    Light lights[kMaxLights];
    glm::ivec4 lightSets[kMaxLightSets];
    DepthCue cues[kMaxCues];
    glm::vec4 pixelScale{0.0f};
    glm::vec4 highlight{0.0f};
    glm::vec4 clipPlanes[kMaxClipPlanes];  ///< world: keep where dot(xyz, p) + w >= 0
};

/// What the vertex shader and the discard tests read per draw (colours and reflectance travel as
/// push constants, Renderer::Command::Push).
struct DrawParams {
    glm::mat4 model{1.0f};
    glm::mat4 normalMatrix{1.0f};
    glm::ivec4 indices{0};
    glm::ivec4 style{0};
    /// line width, first model clip plane, clip plane count, PATTERN interiors: where the draw's
    /// pattern record starts in the pattern buffer (world to cell column, to cell row, and the
    /// first cell, columns and rows)
    glm::vec4 misc{0.0f};
};
static_assert(sizeof(DrawParams) == 176);
/// What a draw reads at its dynamic offset of the run buffer: its view, and for a
/// PREMULTIPLIED_LIGHTS draw its light set's lights with the material folded in.
struct LitRun {
    View view;
    LitLight lights[4];
};
static_assert(sizeof(LitRun) == 496);

}  // namespace phigs::vk::gpu
