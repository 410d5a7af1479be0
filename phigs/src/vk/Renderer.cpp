#include "phigs/vk/Renderer.h"

#include "GpuLayout.h"
#include "ShaderSpecialisation.h"
#include "phigs/render/MeshEdges.h"
#include "phigs/render/PatternMapping.h"
#include "phigs/traverse/ViewClipRectangle.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "shaders/Spirv.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string>

namespace phigs::vk {
namespace {

// Pipeline keys: topology, face culling and depth test are the only fixed-function differences.
constexpr int kLines = 1;
constexpr int kDepth = 2;
constexpr int kCullShift = 2;  // CullMode in bits 2..3
constexpr int kMayDiscard = 16;
constexpr int kShadeShift = 5;        // per-fragment shading (0, Flat or Phong) in bits 5..7
constexpr int kReflectanceShift = 8;  // fixed reflectance model (0: read per draw) in bits 8..10
constexpr int kSignatureShift = 11;   // light set signature + 1 (0: read at run time) in bits 11..26
// Inputs a pipeline's draws do not need, so the varyings can be dropped (lavapipe's triangle
// setup cost grows with every varying).
constexpr std::uint64_t kNoDepthCue = 1ull << 27;
constexpr std::uint64_t kNoVertexColours = 1ull << 28;
constexpr std::uint64_t kNoWorldPosition = 1ull << 29;
// Features a pipeline's draws all have, so the shaders test nothing per vertex or fragment
// (lavapipe runs both sides of every branch that is not constant).
constexpr std::uint64_t kVertexLighting = 1ull << 30;
constexpr std::uint64_t kHighlighted = 1ull << 31;
constexpr std::uint64_t kDistinguishBack = 1ull << 32;
constexpr int kOffsetShift = 33;  // screen offsets: 0 none, 1 pixels (markers), 2 NPC (annotation text)
// PHIGS PLUS transparency: blended over what is behind, without writing depth.
constexpr std::uint64_t kTransparent = 1ull << 35;
// PATTERN interiors: the colour is the pattern cell under the fragment.
constexpr std::uint64_t kPatterned = 1ull << 36;
// The light set's lights come with the draw's reflectance folded in (a lit run, binding 3).
constexpr std::uint64_t kPremultipliedLights = 1ull << 37;
// The draws' modelling transformation is the identity (no matrix read per vertex).
constexpr std::uint64_t kIdentityModel = 1ull << 38;
// The rendering colour model less one (0 RGB .. 3 HLS) in bits 39..40, where it changes the
// picture: interpolated vertex colours, Gouraud or depth cueing.
constexpr int kColourModelShift = 39;
// A mesh's facet edges of one HOLLOW side, the front (bit 41) or the back (bit 42): the vertex
// shader drops those whose triangle shows the other.
constexpr std::uint64_t kSidedFront = 1ull << 41;
constexpr std::uint64_t kSidedBack = 1ull << 42;
// Flat shading lights with the vertices' normal, each facet's given normal alike at its vertices.
constexpr std::uint64_t kFlatFacetNormals = 1ull << 43;

// The subpass self-dependency of binningFlush: attachment writes, then later tests and writes.
constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags kAttachmentAccess =
    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
// lavapipe bins a render pass's draws into one scene, held whole, before it rasterises them; a
// barrier makes it rasterise what it holds, so one every this many vertices bounds the scene.
constexpr std::uint64_t kVerticesPerScene = 30000;

/// Makes lavapipe rasterise the draws binned so far (a barrier flushes its scene).
void binningFlush(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = kAttachmentAccess;
    barrier.dstAccessMask = kAttachmentAccess;
    vkCmdPipelineBarrier(cmd, kAttachmentStages, kAttachmentStages, VK_DEPENDENCY_BY_REGION_BIT, 1, &barrier,
                         0, nullptr, 0, nullptr);
}

VkShaderModule createShader(VkDevice device, const std::vector<std::uint32_t>& words) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = words.size() * sizeof(std::uint32_t);
    info.pCode = words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
    return module;
}

glm::mat4 toFloat(const glm::dmat4& m) {
    return glm::mat4(m);
}

/// A PHIGS light as the shaders read it (its colour's w is its type).
gpu::Light gpuLight(const Light& light) {
    gpu::Light g;
    g.colour = glm::vec4(light.colour, float(int(light.type)));
    g.position = glm::vec4(glm::vec3(light.position), 1.0f);
    const glm::dvec3 direction =
        glm::length(light.direction) > 0.0 ? glm::normalize(light.direction) : glm::dvec3(0, 0, -1);
    g.direction = glm::vec4(glm::vec3(direction), light.concentration);
    g.attenuation = glm::vec4(light.attenuation, std::cos(light.spreadAngle), 0.0f);
    return g;
}

std::string itemName(std::size_t index) {
    return "draw item " + std::to_string(index);
}

int shadeOf(ShadingMethod method) {
    switch (method) {
        case ShadingMethod::Colour:
        case ShadingMethod::DotProduct:
            return gpu::Gouraud;
        case ShadingMethod::Normal:
            return gpu::Phong;
        case ShadingMethod::None:
            break;
    }
    return gpu::Flat;
}

}  // namespace

Renderer::Renderer(Context& context, VkFormat colourFormat, VkImageLayout finalLayout)
    : context_(context), colourFormat_(colourFormat) {
    VkDevice device = context_.device();
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context_.physicalDevice(), &features);
    maxLineWidth_ = features.wideLines ? context_.properties().limits.lineWidthRange[1] : 1.0f;
    try {
        VkAttachmentDescription attachments[2]{};
        attachments[0].format = colourFormat;
        attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
        attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        attachments[0].finalLayout = finalLayout;
        attachments[1].format = kDepthFormat;
        attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
        attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription subpass{};
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        subpass.colorAttachmentCount = 1;
        subpass.pColorAttachments = &colourRef;
        subpass.pDepthStencilAttachment = &depthRef;
        VkSubpassDependency dependencies[3]{};
        // Wait for the previous use of the attachments (an acquired swapchain image, or last frame).
        dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
        dependencies[0].dstSubpass = 0;
        dependencies[0].srcStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
        dependencies[0].dstStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
        dependencies[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
        // The readback copy (offscreen) waits for the colour writes.
        dependencies[1].srcSubpass = 0;
        dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
        dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
        dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        // Within the pass, attachment writes before later ones: the barrier record() places to
        // hand lavapipe's binned draws to its rasteriser (binningFlush).
        dependencies[2].srcSubpass = dependencies[2].dstSubpass = 0;
        dependencies[2].srcStageMask = kAttachmentStages;
        dependencies[2].dstStageMask = kAttachmentStages;
        dependencies[2].srcAccessMask = kAttachmentAccess;
        dependencies[2].dstAccessMask = kAttachmentAccess;
        dependencies[2].dependencyFlags = VK_DEPENDENCY_BY_REGION_BIT;
        VkRenderPassCreateInfo rpInfo{};
        rpInfo.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
        rpInfo.attachmentCount = 2;
        rpInfo.pAttachments = attachments;
        rpInfo.subpassCount = 1;
        rpInfo.pSubpasses = &subpass;
        rpInfo.dependencyCount = 3;
        rpInfo.pDependencies = dependencies;
        check(vkCreateRenderPass(device, &rpInfo, nullptr, &renderPass_), "vkCreateRenderPass");

        createDescriptors();
    } catch (...) {
        release();
        throw;
    }
}

Renderer::~Renderer() {
    release();
}

void Renderer::release() {
    VkDevice device = context_.device();
    vkDeviceWaitIdle(device);
    geometry_.clear();
    meshes_.clear();
    drawBuffer_.reset();
    patternBuffer_.reset();
    litBuffer_.reset();
    frameBuffer_.reset();
    for (auto& [key, p] : pipelines_) vkDestroyPipeline(device, p, nullptr);
    pipelines_.clear();
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    pool_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
    renderPass_ = VK_NULL_HANDLE;
}

void Renderer::createDescriptors() {
    VkDevice device = context_.device();
    VkDescriptorSetLayoutBinding bindings[4]{};
    bindings[0].binding = 0;
    bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    bindings[0].descriptorCount = 1;
    bindings[0].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    bindings[1].binding = 1;
    bindings[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[1].descriptorCount = 1;
    bindings[1].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    bindings[2].binding = 2;
    bindings[2].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[2].descriptorCount = 1;
    bindings[2].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    bindings[3].binding = 3;
    bindings[3].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    bindings[3].descriptorCount = 1;
    bindings[3].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.bindingCount = 4;
    setInfo.pBindings = bindings;
    check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");

    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                              sizeof(Command::Push)};
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_), "vkCreatePipelineLayout");

    VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                     {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1}};
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 3;
    poolInfo.pPoolSizes = sizes;
    check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &setLayout_;
    check(vkAllocateDescriptorSets(device, &alloc, &set_), "vkAllocateDescriptorSets");
    const std::size_t align =
        std::max<std::size_t>(1, context_.properties().limits.minUniformBufferOffsetAlignment);
    litStride_ = (sizeof(gpu::LitRun) + align - 1) / align * align;
}

namespace {

/// The shaders of shaders/scene.glsl specialised for a pipeline key (its constants 0..17).
SpecialisedStages stagesFor(std::uint64_t key) {
    auto flag = [&](std::uint64_t bit) { return (key & bit) ? 1 : 0; };
    const SpecialisationValue constants[] = {
        {0, flag(kMayDiscard)},
        {1, std::int32_t((key >> kShadeShift) & 7)},
        {2, std::int32_t((key >> kSignatureShift) & 0xffff) - 1},
        {3, std::int32_t((key >> kReflectanceShift) & 7)},
        {4, 1 - flag(kNoDepthCue)},
        {5, 1 - flag(kNoVertexColours)},
        {6, 1 - flag(kNoWorldPosition)},
        {7, flag(kVertexLighting)},
        {8, flag(kHighlighted)},
        {9, flag(kDistinguishBack)},
        {10, 1 - flag(kLines)},
        {11, std::int32_t((key >> kOffsetShift) & 3)},
        {12, flag(kPatterned)},
        {13, flag(kPremultipliedLights)},
        {14, flag(kIdentityModel)},
        {15, std::int32_t((key >> kColourModelShift) & 3) + 1},
        {16, flag(kSidedFront) - flag(kSidedBack)},
        {17, flag(kFlatFacetNormals)},
    };
    return specialiseStages(shaders::spirv("prim.vert"), shaders::spirv("prim.frag"), constants);
}

/// Face culling, winding and depth bias of a pipeline key.
VkPipelineRasterizationStateCreateInfo rasterStateFor(std::uint64_t key) {
    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    const int culled = (key >> kCullShift) & 3;  // CullMode bits: 1 back, 2 front, 3 both
    raster.cullMode = culled == 3                           ? VK_CULL_MODE_FRONT_AND_BACK
                      : culled == int(CullMode::BackFaces)  ? VK_CULL_MODE_BACK_BIT
                      : culled == int(CullMode::FrontFaces) ? VK_CULL_MODE_FRONT_BIT
                                                            : VK_CULL_MODE_NONE;
    // Vulkan's winding test already allows for the framebuffer's downward y, so counter-clockwise
    // in NPC (x right, y up) is counter-clockwise here too.
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    // Surfaces are pushed back a little so iso-lines and edges at the same depth win the test.
    raster.depthBiasEnable = (key & kDepth) && !(key & kLines);
    raster.depthBiasConstantFactor = 2.0f;
    raster.depthBiasSlopeFactor = 1.5f;
    return raster;
}

/// The colour attachment's blending of a pipeline key: none, or a transparent surface's.
VkPipelineColorBlendAttachmentState blendFor(std::uint64_t key) {
    VkPipelineColorBlendAttachmentState blend{};
    if (key & kTransparent) {
        // Colour: source over destination by the surface's opacity; the picture's alpha stays
        // opaque (PNG files and swapchains show the colour, not a see-through image).
        blend.blendEnable = VK_TRUE;
        blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        blend.colorBlendOp = VK_BLEND_OP_ADD;
        blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        blend.alphaBlendOp = VK_BLEND_OP_ADD;
    }
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                           VK_COLOR_COMPONENT_A_BIT;
    return blend;
}

/// A shader stage running `module`'s main.
VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits which, VkShaderModule module) {
    VkPipelineShaderStageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage = which;
    info.module = module;
    info.pName = "main";
    return info;
}

}  // namespace

VkPipeline Renderer::pipeline(std::uint64_t key) {
    if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
    const bool lines = key & kLines;
    const bool depth = key & kDepth;
    const SpecialisedStages code = stagesFor(key);
    VkDevice device = context_.device();
    struct Modules {
        VkDevice device;
        VkShaderModule vertex = VK_NULL_HANDLE, fragment = VK_NULL_HANDLE;
        ~Modules() {
            if (vertex) vkDestroyShaderModule(device, vertex, nullptr);
            if (fragment) vkDestroyShaderModule(device, fragment, nullptr);
        }
    } modules{device};
    modules.vertex = createShader(device, code.vertex);
    modules.fragment = createShader(device, code.fragment);
    const VkPipelineShaderStageCreateInfo stages[2] = {stage(VK_SHADER_STAGE_VERTEX_BIT, modules.vertex),
                                                       stage(VK_SHADER_STAGE_FRAGMENT_BIT, modules.fragment)};

    VkVertexInputBindingDescription binding{0, sizeof(render::RenderVertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription allAttributes[5] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(render::RenderVertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(render::RenderVertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(render::RenderVertex, colour)},
        {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(render::RenderVertex, offset)},
        {4, 0, VK_FORMAT_R32_SFLOAT, offsetof(render::RenderVertex, pattern)},
    };
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (std::uint32_t location : code.vertexInputLocations) attributes.push_back(allAttributes[location]);
    VkPipelineVertexInputStateCreateInfo vertexInput{};
    vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = std::uint32_t(attributes.size());
    vertexInput.pVertexAttributeDescriptions = attributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = lines ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewportState{};
    viewportState.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewportState.viewportCount = 1;
    viewportState.scissorCount = 1;
    const VkPipelineRasterizationStateCreateInfo raster = rasterStateFor(key);
    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depthState{};
    depthState.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    depthState.depthTestEnable = depth;
    depthState.depthWriteEnable = depth && !(key & kTransparent);
    depthState.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    const VkPipelineColorBlendAttachmentState blendAttachment = blendFor(key);
    VkPipelineColorBlendStateCreateInfo blend{};
    blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    VkDynamicState dynamics[3] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                  VK_DYNAMIC_STATE_LINE_WIDTH};
    VkPipelineDynamicStateCreateInfo dynamic{};
    dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dynamic.dynamicStateCount = 3;
    dynamic.pDynamicStates = dynamics;

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewportState;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depthState;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout_;
    info.renderPass = renderPass_;
    VkPipeline p = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(context_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p),
          "vkCreateGraphicsPipelines");
    pipelines_[key] = p;
    ++frame_.pipelinesCreated;
    return p;
}

void Renderer::setHighlight(glm::vec3 colour, float amount) {
    highlight_ = glm::vec4(colour, std::clamp(amount, 0.0f, 1.0f));
}

Renderer::CachedMesh& Renderer::compileMesh(const std::shared_ptr<const MeshData>& mesh) {
    auto it = meshes_.find(mesh.get());
    // A different mesh may reuse a freed address: the weak pointer tells them apart.
    if (it != meshes_.end() && it->second.data.lock() == mesh) {
        it->second.lastUsed = frameNumber_;
        return it->second;
    }
    CachedMesh cached;
    cached.data = mesh;
    cached.lastUsed = frameNumber_;
    cached.hasNormals = mesh->normals.size() == mesh->positions.size() && !mesh->positions.empty();
    cached.facetNormals = cached.hasNormals && mesh->normalsPerFacet;
    cached.hasColours = mesh->colours.size() == mesh->positions.size() && !mesh->positions.empty();
    const auto vertices = render::meshVertices(*mesh);
    cached.counts = render::meshIndices(*mesh);
    if (!vertices.empty() && !cached.counts.indices.empty()) {
        const VkDeviceSize vbytes = vertices.size() * sizeof(render::RenderVertex);
        cached.vertices =
            std::make_unique<GpuBuffer>(context_, vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, frame_);
        cached.vertices->write(vertices.data(), vbytes);
        const VkDeviceSize ibytes = cached.counts.indices.size() * sizeof(std::uint32_t);
        cached.indices =
            std::make_unique<GpuBuffer>(context_, ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, frame_);
        cached.indices->write(cached.counts.indices.data(), ibytes);
    }
    cached.counts.indices.clear();
    cached.counts.indices.shrink_to_fit();
    return meshes_[mesh.get()] = std::move(cached);
}

void Renderer::compileSidedEdges(CachedMesh& cached) {
    if (cached.sidedVertices) return;
    const auto data = cached.data.lock();
    const std::vector<render::RenderVertex> vertices = render::meshSidedEdges(*data);
    if (vertices.empty()) return;
    std::vector<std::uint32_t> indices(vertices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = std::uint32_t(i);
    const VkDeviceSize vbytes = vertices.size() * sizeof(render::RenderVertex);
    cached.sidedVertices =
        std::make_unique<GpuBuffer>(context_, vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, frame_);
    cached.sidedVertices->write(vertices.data(), vbytes);
    const VkDeviceSize ibytes = indices.size() * sizeof(std::uint32_t);
    cached.sidedIndices =
        std::make_unique<GpuBuffer>(context_, ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, frame_);
    cached.sidedIndices->write(indices.data(), ibytes);
    cached.sidedCount = std::uint32_t(indices.size());
}

template <typename AddPart>
void Renderer::addMeshParts(const DrawMesh& mesh, CachedMesh& cached, const AddPart& addPart) {
    const InteriorStyleSet& s = mesh.interior;
    const VkBuffer vertices = cached.vertices->handle(), indices = cached.indices->handle();
    // HOLLOW sides outline their facets: all alike in one colour, else each side's facet edges
    // only while their triangle shows that side (the vertex shader decides).
    glm::vec3 colour;
    const bool alike = render::hollowOutline(s, 0, colour);
    const bool sided =
        !alike && (render::hollowOutline(s, 1, colour) || render::hollowOutline(s, -1, colour));
    if (sided) compileSidedEdges(cached);
    render::GeometryPart part;
    part.vertexNormals = cached.hasNormals;
    part.facetNormals = cached.facetNormals;
    part.lines = true;
    part.role = render::PartRole::Edge;
    if (alike && cached.counts.edgeCount) {
        part.colour = colour;
        part.first = cached.counts.triangleCount + cached.counts.isoLineCount;
        part.count = cached.counts.edgeCount;
        addPart(part, nullptr, false, vertices, indices);
    }
    for (const int side : {1, -1}) {
        if (!sided || !cached.sidedCount || !render::hollowOutline(s, side, colour)) continue;
        part.colour = colour;
        part.side = side;
        part.first = 0;
        part.count = cached.sidedCount;
        addPart(part, nullptr, false, cached.sidedVertices->handle(), cached.sidedIndices->handle());
    }
    part.side = 0;
    if ((s.fillsFrontFaces() || s.fillsBackFaces()) && cached.counts.triangleCount) {
        part.lines = false;
        part.role = render::PartRole::Interior;
        part.colour = s.colour;
        part.vertexColours = cached.hasColours;
        part.first = 0;
        part.count = cached.counts.triangleCount;
        addPart(part, &s, cached.hasNormals, vertices, indices);
    }
    if (cached.counts.isoLineCount) {
        render::GeometryPart iso;
        iso.lines = true;
        iso.role = render::PartRole::IsoLine;
        iso.colour = mesh.isoLineStyle->colour;
        iso.lineType = mesh.isoLineStyle->type;
        iso.lineWidth = mesh.isoLineStyle->width;
        iso.first = cached.counts.triangleCount;
        iso.count = cached.counts.isoLineCount;
        iso.patternInModelUnits = true;
        addPart(iso, nullptr, false, vertices, indices);
    }
    // The edge flag draws the facets' edges and the visible trimming curves, which follow them.
    if (mesh.edges->visible && cached.counts.edgeCount + cached.counts.trimEdgeCount) {
        render::GeometryPart edge;
        edge.lines = true;
        edge.role = render::PartRole::Edge;
        edge.colour = mesh.edges->colour;
        edge.lineWidth = mesh.edges->width;
        edge.first = cached.counts.triangleCount + cached.counts.isoLineCount;
        edge.count = cached.counts.edgeCount + cached.counts.trimEdgeCount;
        addPart(edge, nullptr, false, vertices, indices);
    }
}

/// What prepare() works out once a frame for every item: the list and its mapping to the
/// framebuffer, each view's kind, each light set's shape and first light, and the draw records.
struct Renderer::FramePlan {
    FramePlan(const DrawList& drawList, const WorkstationMapping& workstationMapping, VkExtent2D extent)
        : list(drawList), mapping(workstationMapping) {
        npcToPixels =
            glm::dmat4(glm::dvec4(0.5 * extent.width, 0, 0, 0), glm::dvec4(0, 0.5 * extent.height, 0, 0),
                       glm::dvec4(0, 0, 1, 0), glm::dvec4(0.5 * extent.width, 0.5 * extent.height, 0, 1)) *
            mapping.npcToClip;
        for (const DrawView& v : list.views) perspective.push_back(viewerOf(v).w != 0.0);
        int nextLight = 0;
        for (const auto& set : list.lightSets) {
            firstLights.push_back(nextLight);
            nextLight += int(set.size());
            int signature = set.size() <= 4 ? int(set.size()) : -1;
            for (std::size_t j = 0; signature >= 0 && j < set.size(); ++j)
                signature |= (int(set[j].type) & 7) << (3 + 3 * j);
            signatures.push_back(signature);
        }
    }

    const DrawList& list;
    const WorkstationMapping& mapping;
    glm::dmat4 npcToPixels{1.0};
    /// By view: a perspective view's viewer is a point (viewerOf), so V varies over a surface.
    std::vector<char> perspective;
    /// Each light set's shape for the shader: count | type << (3 + 3 j), or -1 beyond 4 lights.
    std::vector<int> signatures;
    /// Each light set's first light in the frame block's light array: the sets packed in order
    /// (uploadFrame packs them so).
    std::vector<int> firstLights;
    std::vector<gpu::DrawParams> draws;
    const DrawView defaultView{};
};

/// What one item's draws share: its view, scissor, depth cueing and clipping, and the draw
/// record's view, light set, depth cue, highlighting and (meshes) model transformation.
struct Renderer::ItemPlan {
    ItemPlan(const DrawItem& drawItem, const DrawView& drawView) : item(drawItem), view(drawView) {}

    const DrawItem& item;
    const DrawView& view;
    bool perspectiveView = false, cued = false, clipsDepth = false;
    VkRect2D scissor{};
    glm::vec2 modelClip{0.0f};
    gpu::DrawParams base;
};

/// One part to draw with the buffers it reads (indices: a mesh's; none for an item's own
/// geometry) and, for an area, its interior styles.
struct Renderer::PartDraw {
    const render::GeometryPart& part;
    const InteriorStyleSet* interior;
    bool meshNormals;
    VkBuffer vertices, indices;
};

/// A draw's shader flags, per-fragment shading and whether it reads a pattern.
struct Renderer::DrawLook {
    int flags = 0;
    int shade = gpu::Flat;
    bool patterned = false;
};

namespace {

/// Throws std::invalid_argument where item `index` names a view, light set or depth cue the list
/// lacks.
void checkItemTables(const DrawList& list, std::size_t index) {
    const DrawItem& item = list.items[index];
    if (item.viewIndex() < 0 ||
        (item.viewIndex() >= int(list.views.size()) && !(list.views.empty() && item.viewIndex() == 0)))
        throw std::invalid_argument("Renderer: " + itemName(index) + " uses view " +
                                    std::to_string(item.viewIndex()) + " but the list has " +
                                    std::to_string(list.views.size()));
    if (item.lightSet() >= int(list.lightSets.size()) || item.lightSet() >= gpu::kMaxLightSets)
        throw std::invalid_argument("Renderer: " + itemName(index) + " uses light set " +
                                    std::to_string(item.lightSet()) + " but the list has " +
                                    std::to_string(list.lightSets.size()));
    if (item.depthCue() >= int(list.depthCues.size()) || item.depthCue() >= gpu::kMaxCues)
        throw std::invalid_argument("Renderer: " + itemName(index) + " uses depth cue " +
                                    std::to_string(item.depthCue()) + " but the list has " +
                                    std::to_string(list.depthCues.size()));
}

}  // namespace

void Renderer::prepare(const DrawList& list, VkExtent2D extent) {
    ++frameNumber_;
    frame_ = {};
    commands_.clear();
    drawBytes_.clear();
    patternCells_.clear();
    patternFirst_.clear();
    clipPlanes_.clear();
    clipPlaneSets_.clear();
    litBytes_.clear();
    litKeys_.clear();
    depthTest_ = list.hiddenSurfaceRemoval;
    background_ = list.background;
    if (list.views.size() > std::size_t(gpu::kMaxViews))
        throw std::invalid_argument("Renderer: " + std::to_string(list.views.size()) + " views, at most " +
                                    std::to_string(gpu::kMaxViews) + " are supported");
    const WorkstationMapping mapping(list, extent.width, extent.height);
    addViewRuns(list, mapping);
    FramePlan frame(list, mapping, extent);
    for (std::size_t i = 0; i < list.items.size(); ++i) prepareItem(frame, i);

    // Free what this frame no longer draws (the previous frame has finished with it).
    std::erase_if(geometry_, [&](const auto& entry) { return entry.second.lastUsed != frameNumber_; });
    std::erase_if(meshes_, [&](const auto& entry) { return entry.second.lastUsed != frameNumber_; });

    drawBytes_.resize(frame.draws.size() * sizeof(gpu::DrawParams));
    if (!frame.draws.empty()) std::memcpy(drawBytes_.data(), frame.draws.data(), drawBytes_.size());
    uploadFrame(list, extent, frame.firstLights);
    uploadDraws();
    uploadPatterns();
    uploadLitRuns();
    // With hidden-surface removal, transparent draws come after every opaque one (in traversal
    // order among themselves), so what lies behind them is there to show through.
    if (depthTest_)
        std::stable_partition(commands_.begin(), commands_.end(),
                              [](const Command& c) { return !(c.pipeline & kTransparent); });
    frame_.drawCalls = commands_.size();
    total_.add(frame_);
}

void Renderer::prepareItem(FramePlan& frame, std::size_t index) {
    const DrawList& list = frame.list;
    const DrawItem& item = list.items[index];
    checkItemTables(list, index);
    const DrawView& view = list.views.empty() ? frame.defaultView : list.views[item.viewIndex()];
    ItemPlan plan(item, view);
    plan.perspectiveView = !list.views.empty() && frame.perspective[std::size_t(item.viewIndex())];
    const ViewClipRectangle kept(view, list.windowMin, list.windowMax);
    const PixelRect r = frame.mapping.scissor(kept.min, kept.max);
    plan.scissor = {{r.x, r.y}, {r.width, r.height}};
    if (plan.scissor.extent.width == 0 || plan.scissor.extent.height == 0) return;
    plan.cued = item.depthCue() >= 0 && list.depthCues[std::size_t(item.depthCue())].enabled;
    plan.clipsDepth = (view.clipBack && view.clipMin.z > 0.0) || (view.clipFront && view.clipMax.z < 1.0);
    plan.modelClip = clipPlaneRange(item, index);
    plan.base.indices = glm::ivec4(item.viewIndex(), item.lightSet(), item.depthCue(),
                                   item.highlighted() ? gpu::Highlight : 0);

    if (const auto* mesh = primitiveIf<DrawMesh>(item.primitive)) {
        if (!mesh->mesh) return;
        CachedMesh& cached = compileMesh(mesh->mesh);
        if (!cached.vertices) return;
        plan.base.model = toFloat(item.modelTransform().get());
        plan.base.normalMatrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(plan.base.model))));
        addMeshParts(*mesh, cached,
                     [&](const render::GeometryPart& part, const InteriorStyleSet* interior, bool meshNormals,
                         VkBuffer vertices, VkBuffer indices) {
                         addPart(frame, plan, {part, interior, meshNormals, vertices, indices});
                     });
        return;
    }
    const glm::dmat4 worldToPixels = frame.npcToPixels * view.mapping * view.orientation;
    const CachedGeometry& cached = itemGeometry(item, worldToPixels, frame.mapping.pixelsPerNpc);
    if (!cached.vertices) return;
    const InteriorStyleSet* interior = nullptr;
    if (const auto* fill = primitiveIf<DrawFillArea>(item.primitive)) interior = &fill->interior.get();
    const glm::dmat4 worldToNpc = view.mapping * view.orientation;
    for (const auto& part : cached.parts)
        if (part.side == 0 || render::sideShown(part.sidePlane, worldToNpc) == part.side)
            addPart(frame, plan,
                    {part, interior, part.vertexNormals, cached.vertices->handle(), VK_NULL_HANDLE});
}

Renderer::CachedGeometry& Renderer::itemGeometry(const DrawItem& item, const glm::dmat4& worldToPixels,
                                                 double pixelsPerNpc) {
    const std::uint64_t key = render::geometryKey(item, worldToPixels, pixelsPerNpc);
    auto it = geometry_.find(key);
    if (it == geometry_.end()) {
        render::ItemGeometry g = render::describeItem(item, worldToPixels, pixelsPerNpc);
        CachedGeometry cached;
        if (!g.vertices.empty()) {
            const VkDeviceSize bytes = g.vertices.size() * sizeof(render::RenderVertex);
            cached.vertices =
                std::make_unique<GpuBuffer>(context_, bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, frame_);
            cached.vertices->write(g.vertices.data(), bytes);
        }
        cached.parts = std::move(g.parts);
        it = geometry_.emplace(key, std::move(cached)).first;
    }
    it->second.lastUsed = frameNumber_;
    return it->second;
}

void Renderer::addPart(FramePlan& frame, const ItemPlan& plan, const PartDraw& p) {
    // Each side's faces by its own style: the sides not filled (culled, or HOLLOW / EMPTY) are
    // culled, and a distinguished back of another style, index or shading is a second draw.
    if (!p.interior || p.part.lines) return addDraw(frame, plan, p, false, 0);
    const bool front = p.interior->fillsFrontFaces(), back = p.interior->fillsBackFaces();
    const int cullFront = int(CullMode::FrontFaces), cullBack = int(CullMode::BackFaces);
    if (front && back && p.interior->sidesDiffer()) {
        addDraw(frame, plan, p, false, cullBack);
        addDraw(frame, plan, p, true, cullFront);
    } else if (front || back) {
        addDraw(frame, plan, p, !front, (front ? 0 : cullFront) | (back ? 0 : cullBack));
    }
}

void Renderer::addDraw(FramePlan& frame, const ItemPlan& plan, const PartDraw& p, bool backSide, int cull) {
    const render::GeometryPart& part = p.part;
    gpu::DrawParams d = plan.base;
    if (!p.indices) d.model = glm::mat4(1.0f), d.normalMatrix = glm::mat4(1.0f);
    Command c;
    c.push.colour = glm::vec4(part.colour, 1.0f);
    c.push.backColour = c.push.colour;
    const DrawLook look = drawLook(frame, plan, p, backSide, d, c.push);
    d.indices.w = look.flags;
    d.style = glm::ivec4(int(part.role), p.interior ? p.interior->styleIndexOf(backSide) : 0,
                         int(part.lineType), look.shade);
    d.misc = glm::vec4(part.lineWidth, plan.modelClip.x, plan.modelClip.y, d.misc.w);
    c.pipeline = pipelineKey(frame, plan, p, look, cull, c.push);
    if (d.model == glm::mat4(1.0f)) c.pipeline |= kIdentityModel;
    c.vertices = p.vertices;
    c.indices = p.indices;
    c.first = part.first;
    c.count = part.count;
    c.push.drawIndex = static_cast<std::uint32_t>(frame.draws.size());
    c.view = plan.item.viewIndex();
    c.runOffset = std::uint32_t(std::size_t(plan.item.viewIndex()) * litStride_);
    const int lightSet = plan.item.lightSet();
    c.push.firstLight = lightSet >= 0 ? frame.firstLights[std::size_t(lightSet)] : 0;
    if ((look.flags & gpu::Lit) && !(look.flags & gpu::DistinguishBack) &&
        ((c.pipeline >> kSignatureShift) & 0xffff) && ((c.pipeline >> kReflectanceShift) & 7)) {
        // A uniform colour is folded in too (shaders/scene.glsl, litPremultiplied).
        const bool uniformColour = !part.vertexColours && !look.patterned;
        const int run = premultipliedLights(frame.list, plan.item.viewIndex(), lightSet, c.push.reflectance,
                                            c.push.specularColour,
                                            uniformColour ? glm::vec3(c.push.colour) : glm::vec3(1.0f));
        if (run >= 0) {
            c.pipeline |= kPremultipliedLights;
            c.runOffset = std::uint32_t(std::size_t(run) * litStride_);
        }
    }
    c.push.depthCue = plan.item.depthCue();
    c.lineWidth = std::clamp(part.lineWidth, 1.0f, maxLineWidth_);
    c.scissor = plan.scissor;
    pipeline(c.pipeline);
    frame.draws.push_back(d);
    commands_.push_back(c);
}

Renderer::DrawLook Renderer::drawLook(const FramePlan& frame, const ItemPlan& plan, const PartDraw& p,
                                      bool backSide, gpu::DrawParams& d, Command::Push& push) {
    const render::GeometryPart& part = p.part;
    DrawLook look;
    look.flags = d.indices.w;
    if (part.vertexColours) look.flags |= gpu::VertexColours;
    if (part.offsetInNpc) look.flags |= gpu::OffsetNpc;
    if (part.lines && part.lineType != LineType::Solid) look.flags |= gpu::Pattern;
    if (part.patternInModelUnits) look.flags |= gpu::PatternInModelUnits;
    if (!part.lines) look.flags |= gpu::Triangles;
    if (!p.interior || part.role != render::PartRole::Interior) return look;
    const InteriorStyleSet& s = *p.interior;
    const InteriorStyle style = s.styleOf(backSide);
    if (style == InteriorStyle::Hatch) look.flags |= gpu::Hatch;
    if (style == InteriorStyle::Pattern)
        look.patterned = patternDraw(frame.list, plan.item, s.styleIndexOf(backSide), d);
    const ReflectanceModel backModel = s.distinguishBackFaces ? s.back.reflectance : s.reflectance;
    if ((s.reflectance != ReflectanceModel::None || backModel != ReflectanceModel::None) &&
        plan.item.lightSet() >= 0)
        look.flags |= gpu::Lit;
    if (s.distinguishBackFaces) {
        look.flags |= gpu::DistinguishBack;
        push.backColour = glm::vec4(s.backColour, 1.0f);
    }
    look.shade = p.meshNormals ? shadeOf(s.shadingOf(backSide)) : gpu::Flat;
    auto reflect = [&](const Reflectance& r, ReflectanceModel model, glm::vec4& k, glm::vec4& sc) {
        k = glm::vec4(r.ambient, r.diffuse, r.specular, r.specularExponent);
        sc = glm::vec4(r.specularColour, float(int(model)));
    };
    reflect(s.properties, s.reflectance, push.reflectance, push.specularColour);
    const Reflectance& back = s.distinguishBackFaces ? s.backProperties : s.properties;
    reflect(back, backModel, push.backReflectance, push.backSpecularColour);
    // The colours' alpha is the opacity the fragment shader writes.
    push.colour.w = 1.0f - std::clamp(s.properties.transparency, 0.0f, 1.0f);
    push.backColour.w = 1.0f - std::clamp(back.transparency, 0.0f, 1.0f);
    return look;
}

std::uint64_t Renderer::pipelineKey(const FramePlan& frame, const ItemPlan& plan, const PartDraw& p,
                                    const DrawLook& look, int cull, Command::Push& push) const {
    const render::GeometryPart& part = p.part;
    std::uint64_t key = (part.lines ? kLines : 0) | (depthTest_ ? kDepth : 0);
    key |= std::uint64_t(cull) << kCullShift;
    if ((look.flags & (gpu::Hatch | gpu::Pattern)) || plan.clipsDepth || plan.modelClip.y > 0)
        key |= kMayDiscard;
    if (look.patterned) key |= kPatterned;
    bool fragmentNeedsWorld = plan.modelClip.y > 0 || look.patterned;
    if (look.flags & gpu::Lit) {
        // A model both sides share is fixed (0: each side's is read per draw); a fixed light
        // set shape lets the shader unroll.
        const InteriorStyleSet& s = *p.interior;
        const ReflectanceModel backModel = s.distinguishBackFaces ? s.back.reflectance : s.reflectance;
        key |= std::uint64_t(backModel == s.reflectance ? int(s.reflectance) : 0) << kReflectanceShift;
        const int signature = frame.signatures[std::size_t(plan.item.lightSet())];
        key |= std::uint64_t(signature + 1) << kSignatureShift;
        if (look.shade == gpu::Gouraud) {
            key |= kVertexLighting;
        } else {
            if (look.shade == gpu::Flat && part.facetNormals) key |= kFlatFacetNormals;
            key |= std::uint64_t(look.shade) << kShadeShift;
            bool local = signature < 0 || look.shade == gpu::Flat || plan.perspectiveView;
            for (int j = 0; signature >= 0 && j < (signature & 7); ++j)
                local = local || ((signature >> (3 + 3 * j)) & 7) >= int(LightType::Positional);
            fragmentNeedsWorld = fragmentNeedsWorld || local;
        }
    }
    if (part.lines && part.side != 0 && p.indices) {
        // A mesh's facet edges of one side (render::meshSidedEdges): the viewer in modelling
        // coordinates rides where lines read no reflectance.
        key |= part.side > 0 ? kSidedFront : kSidedBack;
        push.backReflectance = glm::vec4(
            render::meshViewer(plan.view.mapping * plan.view.orientation * plan.item.modelTransform().get()));
    }
    if (!plan.cued) key |= kNoDepthCue;
    if (p.interior && part.role == render::PartRole::Interior &&
        (plan.cued || part.vertexColours || (key & kVertexLighting)))
        key |= std::uint64_t(int(p.interior->renderingModel) - 1) << kColourModelShift;
    if (!part.vertexColours) key |= kNoVertexColours;
    if (!fragmentNeedsWorld) key |= kNoWorldPosition;
    if (look.flags & gpu::Highlight) key |= kHighlighted;
    if (look.flags & gpu::DistinguishBack) key |= kDistinguishBack;
    if (push.colour.w < 1.0f || push.backColour.w < 1.0f) key |= kTransparent;
    const int offsets = part.offsetInNpc ? 2 : part.role == render::PartRole::Marker ? 1 : 0;
    key |= std::uint64_t(offsets) << kOffsetShift;
    return key;
}

bool Renderer::patternDraw(const DrawList& list, const DrawItem& item, int patternIndex, gpu::DrawParams& d) {
    // No pattern defined at all, or a pattern box with no area on the primitive: drawn solid.
    const DrawPattern* pattern = render::findPattern(list, patternIndex);
    if (!pattern || pattern->columns < 1 || pattern->rows < 1 ||
        pattern->colours.size() != std::size_t(pattern->columns) * std::size_t(pattern->rows))
        return false;
    const std::optional<render::PatternMap> map = render::itemPatternMap(item, *pattern);
    if (!map) return false;
    auto [at, added] = patternFirst_.try_emplace(pattern, 0);
    if (added) {
        at->second = int(patternCells_.size());
        for (const glm::vec3& colour : pattern->colours) patternCells_.push_back(glm::vec4(colour, 1.0f));
    }
    d.misc.w = float(patternCells_.size());
    patternCells_.push_back(glm::vec4(map->u));
    patternCells_.push_back(glm::vec4(map->v));
    patternCells_.push_back(
        glm::vec4(float(at->second), float(pattern->columns), float(pattern->rows), 0.0f));
    return true;
}

void Renderer::addViewRuns(const DrawList& list, const WorkstationMapping& mapping) {
    const DrawView defaultView;
    const std::size_t viewCount = std::max<std::size_t>(1, list.views.size());
    litBytes_.assign(viewCount * litStride_, 0);
    for (std::size_t v = 0; v < viewCount; ++v) {
        const DrawView& view = list.views.empty() ? defaultView : list.views[v];
        const glm::dmat4 worldToNpc = view.mapping * view.orientation;
        gpu::LitRun run;
        run.view.worldToNpc = toFloat(worldToNpc);
        run.view.worldToClip = toFloat(mapping.npcToClip * worldToNpc);
        run.view.eye = glm::vec4(viewerOf(view));
        run.view.clip = glm::vec4(float(view.clipMin.z), float(view.clipMax.z), view.clipBack ? 1.0f : 0.0f,
                                  view.clipFront ? 1.0f : 0.0f);
        // What the scissor keeps, where a marker's position must lie.
        const ViewClipRectangle kept(view, list.windowMin, list.windowMax);
        run.view.clipXY = glm::vec4(glm::vec2(kept.min), glm::vec2(kept.max));
        std::memcpy(&litBytes_[v * litStride_], &run, sizeof run);
        litKeys_.push_back(LitKey{int(v), -1, glm::vec4(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)});
    }
}

int Renderer::premultipliedLights(const DrawList& list, int viewIndex, int lightSet, glm::vec4 reflectance,
                                  glm::vec4 specularColour, glm::vec3 colour) {
    const LitKey key{viewIndex, lightSet, reflectance, glm::vec3(specularColour), colour};
    if (const auto it = std::find(litKeys_.begin(), litKeys_.end(), key); it != litKeys_.end())
        return int(it - litKeys_.begin());
    const auto& lights = list.lightSets[std::size_t(lightSet)];
    if (litKeys_.size() >= std::size_t(gpu::kMaxRuns) || lights.size() > 4) return -1;
    gpu::LitRun run;
    // The view as its own run holds it (addViewRuns).
    std::memcpy(&run.view, &litBytes_[std::size_t(viewIndex) * litStride_], sizeof run.view);
    const glm::vec3 specular = reflectance.z * glm::vec3(specularColour);
    for (std::size_t j = 0; j < lights.size(); ++j) {
        const gpu::Light g = gpuLight(lights[j]);
        gpu::LitLight& lit = run.lights[j];
        const glm::vec3 lightColour(g.colour);
        const bool ambient = lights[j].type == LightType::Ambient;
        lit.diffuse = glm::vec4((ambient ? reflectance.x : reflectance.y) * lightColour * colour, 0.0f);
        lit.specular =
            glm::vec4(ambient ? glm::vec3(0.0f) : specular * lightColour, std::max(reflectance.w, 0.0f));
        lit.position = g.position;
        lit.direction = g.direction;
        lit.attenuation = g.attenuation;
    }
    litBytes_.resize((litKeys_.size() + 1) * litStride_);
    std::memcpy(&litBytes_[litKeys_.size() * litStride_], &run, sizeof run);
    litKeys_.push_back(key);
    return int(litKeys_.size()) - 1;
}

void Renderer::uploadLitRuns() {
    const std::size_t bytes = litStride_ * std::size_t(gpu::kMaxRuns);
    if (!litBuffer_) {
        litBuffer_ = std::make_unique<GpuBuffer>(context_, bytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, frame_);
        lastLitBytes_.clear();
        bindBuffer(3, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, *litBuffer_, sizeof(gpu::LitRun));
    }
    // The runs a frame uses are a prefix of what the buffer holds when nothing changed.
    const bool same = litBytes_.size() <= lastLitBytes_.size() &&
                      std::equal(litBytes_.begin(), litBytes_.end(), lastLitBytes_.begin());
    if (!same) {
        litBuffer_->write(litBytes_.data(), litBytes_.size());
        lastLitBytes_ = litBytes_;
    }
}

void Renderer::bindBuffer(std::uint32_t binding, VkDescriptorType type, const GpuBuffer& buffer,
                          VkDeviceSize range) const {
    VkDescriptorBufferInfo info{buffer.handle(), 0, range};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set_;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

void Renderer::uploadPatterns() {
    if (patternCells_.empty()) patternCells_.push_back(glm::vec4(0.0f));  // the binding is never empty
    const std::size_t bytes = patternCells_.size() * sizeof(glm::vec4);
    if (!patternBuffer_ || patternBuffer_->size() < bytes) {
        patternBuffer_.reset();
        patternBuffer_ = std::make_unique<GpuBuffer>(context_, bytes + bytes / 2,
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frame_);
        lastPatternCells_.clear();
        bindBuffer(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, *patternBuffer_, VK_WHOLE_SIZE);
    }
    if (patternCells_ != lastPatternCells_) {
        patternBuffer_->write(patternCells_.data(), bytes);
        lastPatternCells_ = patternCells_;
    }
}

glm::vec2 Renderer::clipPlaneRange(const DrawItem& item, std::size_t index) {
    if (item.modelClipPlanes().empty()) return glm::vec2(0.0f);
    for (const auto& [planes, first] : clipPlaneSets_)
        if (planes == item.modelClipPlanes()) return glm::vec2(float(first), float(planes.size()));
    const int first = int(clipPlanes_.size());
    if (clipPlanes_.size() + item.modelClipPlanes().size() > std::size_t(gpu::kMaxClipPlanes))
        throw std::invalid_argument("Renderer: " + itemName(index) + " brings the model clipping planes to " +
                                    std::to_string(clipPlanes_.size() + item.modelClipPlanes().size()) +
                                    ", at most " + std::to_string(gpu::kMaxClipPlanes) + " distinct ones");
    for (const glm::dvec4& plane : item.modelClipPlanes()) clipPlanes_.push_back(glm::vec4(plane));
    clipPlaneSets_.emplace_back(item.modelClipPlanes(), first);
    return glm::vec2(float(first), float(item.modelClipPlanes().size()));
}

void Renderer::uploadFrame(const DrawList& list, VkExtent2D extent, const std::vector<int>& firstLights) {
    const WorkstationMapping mapping(list, extent.width, extent.height);
    gpu::Frame f{};
    for (std::size_t s = 0; s < list.lightSets.size() && s < std::size_t(gpu::kMaxLightSets); ++s) {
        const int first = firstLights[s];
        int next = first;
        for (const Light& light : list.lightSets[s]) {
            if (next >= gpu::kMaxLights)
                throw std::invalid_argument("Renderer: more than " + std::to_string(gpu::kMaxLights) +
                                            " lights in the light sets");
            f.lights[next++] = gpuLight(light);
        }
        f.lightSets[s] = glm::ivec4(first, next - first, 0, 0);
    }
    for (std::size_t c = 0; c < list.depthCues.size() && c < std::size_t(gpu::kMaxCues); ++c) {
        const DepthCue& cue = list.depthCues[c];
        f.cues[c].planes =
            glm::vec4(float(cue.frontPlane), float(cue.backPlane), cue.frontScale, cue.backScale);
        f.cues[c].colour = glm::vec4(cue.colour, cue.enabled ? 1.0f : 0.0f);
    }
    f.pixelScale =
        glm::vec4(2.0f / float(extent.width), -2.0f / float(extent.height), float(mapping.pixelsPerNpc), 0);
    f.highlight = highlight_;
    std::copy(clipPlanes_.begin(), clipPlanes_.end(), f.clipPlanes);

    const auto* bytes = reinterpret_cast<const unsigned char*>(&f);
    const bool created = !frameBuffer_;
    if (created)
        frameBuffer_ =
            std::make_unique<GpuBuffer>(context_, sizeof f, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, frame_);
    if (created || std::memcmp(lastFrameBytes_.data(), bytes, sizeof f) != 0) {
        frameBuffer_->write(bytes, sizeof f);
        lastFrameBytes_.assign(bytes, bytes + sizeof f);
    }
    if (created) {
        bindBuffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, *frameBuffer_, sizeof f);
    }
}

void Renderer::uploadDraws() {
    const std::size_t needed = std::max<std::size_t>(drawBytes_.size(), sizeof(gpu::DrawParams));
    if (!drawBuffer_ || drawBuffer_->size() < needed) {
        drawBuffer_.reset();
        drawBuffer_ = std::make_unique<GpuBuffer>(context_, needed + needed / 2,
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frame_);
        lastDrawBytes_.clear();
        bindBuffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, *drawBuffer_, VK_WHOLE_SIZE);
    }
    // Only the runs of draw records that differ from what the buffer holds are written.
    constexpr std::size_t record = sizeof(gpu::DrawParams);
    const std::size_t count = drawBytes_.size() / record;
    std::size_t i = 0;
    while (i < count) {
        auto same = [&](std::size_t k) {
            return (k + 1) * record <= lastDrawBytes_.size() &&
                   std::memcmp(&drawBytes_[k * record], &lastDrawBytes_[k * record], record) == 0;
        };
        if (same(i)) {
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        while (j < count && !same(j)) ++j;
        drawBuffer_->write(&drawBytes_[i * record], (j - i) * record, i * record);
        i = j;
    }
    lastDrawBytes_ = drawBytes_;
}

void Renderer::record(VkCommandBuffer cmd, VkFramebuffer framebuffer, VkExtent2D extent) const {
    VkClearValue clears[2]{};
    clears[0].color = {{background_.x, background_.y, background_.z, 1.0f}};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = renderPass_;
    begin.framebuffer = framebuffer;
    begin.renderArea = {{0, 0}, extent};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    // The run is the set's one dynamic offset: rebound only where a draw needs another (run 0
    // is view 0 alone).
    std::uint32_t runOffset = 0;
    int runView = 0;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 1, &runOffset);
    std::uint64_t bound = ~0ull;
    VkBuffer boundVertices = VK_NULL_HANDLE, boundIndices = VK_NULL_HANDLE;
    VkRect2D scissor{};
    float lineWidth = 0.0f;
    bool first = true;
    const bool flushScenes = context_.isLavapipe();
    std::uint64_t binned = 0;
    for (const Command& c : commands_) {
        if (flushScenes && binned >= kVerticesPerScene) {
            binningFlush(cmd);
            binned = 0;
        }
        binned += c.count;
        if (c.pipeline != bound) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.at(c.pipeline));
            bound = c.pipeline;
        }
        if (c.vertices != boundVertices) {
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(cmd, 0, 1, &c.vertices, &offset);
            boundVertices = c.vertices;
        }
        // Only changes: each dynamic state change costs lavapipe a rasteriser state rebuild.
        if (first || std::memcmp(&c.scissor, &scissor, sizeof scissor) != 0) {
            vkCmdSetScissor(cmd, 0, 1, &c.scissor);
            scissor = c.scissor;
        }
        if (first || c.lineWidth != lineWidth) {
            vkCmdSetLineWidth(cmd, c.lineWidth);
            lineWidth = c.lineWidth;
        }
        if ((c.pipeline & kPremultipliedLights) ? c.runOffset != runOffset : c.view != runView) {
            runOffset = c.runOffset;
            runView = c.view;
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 1,
                                    &runOffset);
        }
        first = false;
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof c.push, &c.push);
        if (c.indices) {
            if (c.indices != boundIndices) {
                vkCmdBindIndexBuffer(cmd, c.indices, 0, VK_INDEX_TYPE_UINT32);
                boundIndices = c.indices;
            }
            vkCmdDrawIndexed(cmd, c.count, 1, c.first, 0, 0);
        } else {
            vkCmdDraw(cmd, c.count, 1, c.first, 0);
        }
    }
    vkCmdEndRenderPass(cmd);
}

}  // namespace phigs::vk
