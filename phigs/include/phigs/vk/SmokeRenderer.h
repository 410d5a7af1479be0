#pragma once

#include "phigs/image/Image.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/OffscreenTarget.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace phigs::vk {

/// One flat-coloured triangle in normalized device coordinates (x right, y down, [-1, 1]).
struct SmokeTriangle {
    std::array<glm::vec2, 3> corners{glm::vec2(0.0f, -0.8f), glm::vec2(0.8f, 0.8f), glm::vec2(-0.8f, 0.8f)};
    glm::vec4 color{1.0f, 0.5f, 0.0f, 1.0f};
    glm::vec4 background{0.0f, 0.0f, 0.2f, 1.0f};
};

/// Draws a SmokeTriangle into an offscreen target through a pipeline built from the embedded
/// smoke.vert / smoke.frag shaders and reads the picture back: the whole tool chain in one call.
class SmokeRenderer {
public:
    SmokeRenderer(Context& context, OffscreenTarget& target);
    ~SmokeRenderer();
    SmokeRenderer(const SmokeRenderer&) = delete;
    SmokeRenderer& operator=(const SmokeRenderer&) = delete;

    Image render(const SmokeTriangle& triangle);

private:
    void release();

    Context& context_;
    OffscreenTarget& target_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace phigs::vk
