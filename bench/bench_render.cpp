// bench_render: a frame through the whole toolkit on lavapipe (structure store -> traversal ->
// offscreen workstation -> Renderer -> picture read back), for a grid of shaded bicubic
// surfaces with iso-lines, against a raw Vulkan draw of the same vertex data (one pipeline per
// topology, push constants only, the same readback); the uploads of an unchanged frame; and the
// frame after editing one structure, with what it uploaded.
// Usage: bench_render [--triangles N] [--width W] [--height H] [--frames F]. Ends with one JSON object.
#include "phigs/Phigs.h"
#include "phigs/image/Image.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/GpuBuffer.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/Renderer.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "shaders/Spirv.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

using namespace phigs;

namespace {

using Clock = std::chrono::steady_clock;

VkShaderModule shader(VkDevice device, const char* name) {
    const auto words = shaders::spirv(name);
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    VkShaderModule m = VK_NULL_HANDLE;
    vk::check(vkCreateShaderModule(device, &info, nullptr, &m), "vkCreateShaderModule");
    return m;
}

/// The baseline: one render pass, a triangle pipeline and a line pipeline, push constants only.
struct Baseline {
    struct Push {
        glm::mat4 worldToClip;
        glm::vec4 colour;
        glm::vec4 material;
        glm::vec4 toLight;
    };
    struct Mesh {
        std::unique_ptr<vk::GpuBuffer> vertices, indices;
        std::uint32_t triangleCount = 0, isoLineCount = 0;
    };

    vk::Context& context;
    VkRenderPass pass = VK_NULL_HANDLE;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline triangles = VK_NULL_HANDLE, lines = VK_NULL_HANDLE;
    vk::RenderStats stats;
    std::vector<Mesh> meshes;
    Image picture;

    Baseline(vk::Context& c, vk::OffscreenTarget& target) : context(c) {
        VkDevice device = c.device();
        VkAttachmentDescription a[2]{};
        a[0].format = vk::OffscreenTarget::kColorFormat;
        a[0].samples = VK_SAMPLE_COUNT_1_BIT;
        a[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        a[1] = a[0];
        a[1].format = vk::Renderer::kDepthFormat;
        a[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        a[0].initialLayout = a[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription sub{};
        sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        sub.colorAttachmentCount = 1;
        sub.pColorAttachments = &colourRef;
        sub.pDepthStencilAttachment = &depthRef;
        VkSubpassDependency dep[2]{};
        dep[0].srcSubpass = VK_SUBPASS_EXTERNAL;
        dep[0].srcStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
        dep[0].dstStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
        dep[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        dep[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
        // The readback copy waits for the colour writes, as in the toolkit's render pass.
        dep[1].srcSubpass = 0;
        dep[1].dstSubpass = VK_SUBPASS_EXTERNAL;
        dep[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
        dep[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
        dep[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        dep[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        VkRenderPassCreateInfo rp{};
        rp.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
        rp.attachmentCount = 2;
        rp.pAttachments = a;
        rp.subpassCount = 1;
        rp.pSubpasses = &sub;
        rp.dependencyCount = 2;
        rp.pDependencies = dep;
        vk::check(vkCreateRenderPass(device, &rp, nullptr, &pass), "vkCreateRenderPass");
        VkImageView views[2] = {target.colorView(), target.depthView()};
        VkFramebufferCreateInfo fb{};
        fb.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
        fb.renderPass = pass;
        fb.attachmentCount = 2;
        fb.pAttachments = views;
        fb.width = target.width();
        fb.height = target.height();
        fb.layers = 1;
        vk::check(vkCreateFramebuffer(device, &fb, nullptr, &framebuffer), "vkCreateFramebuffer");
        VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
        VkPipelineLayoutCreateInfo li{};
        li.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
        li.pushConstantRangeCount = 1;
        li.pPushConstantRanges = &range;
        vk::check(vkCreatePipelineLayout(device, &li, nullptr, &layout), "vkCreatePipelineLayout");
        triangles = pipeline(false, target);
        lines = pipeline(true, target);
    }

    VkPipeline pipeline(bool lineList, vk::OffscreenTarget& target) {
        VkDevice device = context.device();
        VkShaderModule vert = shader(device, "baseline.vert");
        VkShaderModule frag = shader(device, lineList ? "baseline_line.frag" : "baseline.frag");
        VkPipelineShaderStageCreateInfo stages[2]{};
        for (int i = 0; i < 2; ++i) {
            stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
            stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
            stages[i].module = i == 0 ? vert : frag;
            stages[i].pName = "main";
        }
        VkVertexInputBindingDescription binding{0, sizeof(render::RenderVertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attrs[2] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(render::RenderVertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(render::RenderVertex, normal)}};
        VkPipelineVertexInputStateCreateInfo vi{};
        vi.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &binding;
        vi.vertexAttributeDescriptionCount = 2;
        vi.pVertexAttributeDescriptions = attrs;
        VkPipelineInputAssemblyStateCreateInfo ia{};
        ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
        ia.topology = lineList ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        VkViewport viewport{0, 0, float(target.width()), float(target.height()), 0, 1};
        VkRect2D scissor{{0, 0}, {target.width(), target.height()}};
        VkPipelineViewportStateCreateInfo vp{};
        vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
        vp.viewportCount = 1;
        vp.pViewports = &viewport;
        vp.scissorCount = 1;
        vp.pScissors = &scissor;
        VkPipelineRasterizationStateCreateInfo rs{};
        rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
        rs.polygonMode = VK_POLYGON_MODE_FILL;
        rs.cullMode = VK_CULL_MODE_NONE;
        rs.lineWidth = 1.0f;
        rs.depthBiasEnable = !lineList;
        rs.depthBiasConstantFactor = 2.0f;
        rs.depthBiasSlopeFactor = 1.5f;
        VkPipelineMultisampleStateCreateInfo ms{};
        ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
        ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        VkPipelineDepthStencilStateCreateInfo ds{};
        ds.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
        ds.depthTestEnable = VK_TRUE;
        ds.depthWriteEnable = VK_TRUE;
        ds.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
        VkPipelineColorBlendAttachmentState ba{};
        ba.colorWriteMask = 0xF;
        VkPipelineColorBlendStateCreateInfo cb{};
        cb.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
        cb.attachmentCount = 1;
        cb.pAttachments = &ba;
        VkGraphicsPipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
        info.stageCount = 2;
        info.pStages = stages;
        info.pVertexInputState = &vi;
        info.pInputAssemblyState = &ia;
        info.pViewportState = &vp;
        info.pRasterizationState = &rs;
        info.pMultisampleState = &ms;
        info.pDepthStencilState = &ds;
        info.pColorBlendState = &cb;
        info.layout = layout;
        info.renderPass = pass;
        VkPipeline p = VK_NULL_HANDLE;
        vk::check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &p),
                  "vkCreateGraphicsPipelines");
        vkDestroyShaderModule(device, vert, nullptr);
        vkDestroyShaderModule(device, frag, nullptr);
        return p;
    }

    void upload(const std::vector<std::shared_ptr<const MeshData>>& scene) {
        for (const auto& m : scene) {
            const auto v = render::meshVertices(*m);
            const auto idx = render::meshIndices(*m);
            Mesh g;
            g.vertices = std::make_unique<vk::GpuBuffer>(context, v.size() * sizeof v[0],
                                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, stats);
            g.vertices->write(v.data(), v.size() * sizeof v[0]);
            g.indices = std::make_unique<vk::GpuBuffer>(context, idx.indices.size() * 4,
                                                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT, stats);
            g.indices->write(idx.indices.data(), idx.indices.size() * 4);
            g.triangleCount = idx.triangleCount;
            g.isoLineCount = idx.isoLineCount;
            meshes.push_back(std::move(g));
        }
    }

    /// One frame: the same two passes over every mesh, then the same readback the offscreen
    /// workstation does (its picture has to reach the host).
    void draw(const glm::mat4& worldToClip, vk::OffscreenTarget& target) {
        const VkExtent2D extent{target.width(), target.height()};
        context.submitAndWait([&](VkCommandBuffer cmd) {
            VkClearValue clears[2]{};
            clears[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
            clears[1].depthStencil = {1.0f, 0};
            VkRenderPassBeginInfo begin{};
            begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
            begin.renderPass = pass;
            begin.framebuffer = framebuffer;
            begin.renderArea = {{0, 0}, extent};
            begin.clearValueCount = 2;
            begin.pClearValues = clears;
            vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
            for (int pass2 = 0; pass2 < 2; ++pass2) {
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass2 == 0 ? triangles : lines);
                const Push push{
                    worldToClip, pass2 == 0 ? glm::vec4(0.8f, 0.8f, 0.8f, 1) : glm::vec4(1, 1, 0, 1),
                    glm::vec4(0.2f, 0.7f, 0.5f, 20.0f), glm::vec4(glm::normalize(glm::vec3(1, 1, 2)), 0.0f)};
                vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof push, &push);
                for (const Mesh& m : meshes) {
                    const VkDeviceSize offset = 0;
                    VkBuffer vb = m.vertices->handle();
                    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
                    vkCmdBindIndexBuffer(cmd, m.indices->handle(), 0, VK_INDEX_TYPE_UINT32);
                    if (pass2 == 0)
                        vkCmdDrawIndexed(cmd, m.triangleCount, 1, 0, 0, 0);
                    else
                        vkCmdDrawIndexed(cmd, m.isoLineCount, 1, m.triangleCount, 0, 0);
                }
            }
            vkCmdEndRenderPass(cmd);
            target.recordReadback(cmd);
        });
        picture = target.readbackPixels();
    }

    ~Baseline() {
        VkDevice device = context.device();
        vkDeviceWaitIdle(device);
        meshes.clear();
        vkDestroyPipeline(device, triangles, nullptr);
        vkDestroyPipeline(device, lines, nullptr);
        vkDestroyPipelineLayout(device, layout, nullptr);
        vkDestroyFramebuffer(device, framebuffer, nullptr);
        vkDestroyRenderPass(device, pass, nullptr);
    }
};

// Process CPU time (all threads: lavapipe's queue and rasteriser threads included), in ms: on a
// shared machine it measures the work done, where wall time also measures the neighbours.
double cpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// The scene's layout: `count` surfaces of `slices` x `stacks` quads on a square grid.
struct Scene {
    int count = 1, side = 1;
    int slices = 100, stacks = 50, isoLines = 7;  // iso-lines each way
    static constexpr int kRoot = 1, kFirstLeaf = 100;
};

/// Leaf k's surface: a bicubic Bezier dome over its grid cell, raised by `lift`.
NurbsSurfaceElement dome(const Scene& scene, int k, double lift) {
    const double cell = 1.0 / scene.side;
    const double x0 = (k % scene.side + 0.025) * cell, y0 = (k / scene.side + 0.025) * cell;
    const double size = 0.95 * cell;
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
            points.push_back(
                {x0 + size * i / 3.0, y0 + size * j / 3.0, 0.4 + lift + (inner ? 0.6 * size : 0.0)});
        }
    const std::vector<double> knots = {0, 0, 0, 0, 1, 1, 1, 1};
    return NurbsSurfaceElement{geom::Surface(3, 3, knots, knots, 4, 4, points), {}};
}

/// The root holds the attributes (solid, Phong, specular, lit, iso-lines, a fixed tessellation)
/// and executes one leaf structure per surface.
void buildStore(StructureStore& store, const Scene& scene) {
    store.openStructure(Scene::kRoot);
    store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
    store.insert(IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Normal)});
    store.insert(IndexAttribute{ElementType::InteriorReflectanceEquation, int(ReflectanceModel::Specular)});
    AreaPropertiesAttribute properties;
    properties.ambient = 0.2, properties.diffuse = 0.7, properties.specular = 0.5;
    properties.specularExponent = 20;
    store.insert(properties);
    store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0.8, 0.8, 0.8})});
    store.insert(ColourAttribute{ElementType::PolylineColour, Colour::fromRgb({1.0, 1.0, 0.0})});
    store.insert(LightSourceStateAttribute{{1, 2}, {}});
    store.insert(ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, double(scene.slices),
                                        double(scene.stacks)});
    store.insert(SurfaceCharacteristicsAttribute{3, 0, scene.isoLines, scene.isoLines});
    for (int k = 0; k < scene.count; ++k) store.insert(executeStructure(Scene::kFirstLeaf + k));
    store.closeStructure();
    for (int k = 0; k < scene.count; ++k) {
        store.openStructure(Scene::kFirstLeaf + k);
        store.insert(dome(scene, k, 0.0));
        store.closeStructure();
    }
}

void setUpWorkstation(Workstation& ws) {
    ws.setHlhsrMode(1);
    Light ambient;
    ws.setLightSourceRepresentation(1, ambient);
    Light key;
    key.type = LightType::Directional;
    key.direction = {-1, -1, -2};
    ws.setLightSourceRepresentation(2, key);
}

/// The bytes of a mesh's vertex and index buffers (what uploading it costs).
std::uint64_t meshBytes(const MeshData& mesh) {
    return render::meshVertices(mesh).size() * sizeof(render::RenderVertex) +
           render::meshIndices(mesh).indices.size() * sizeof(std::uint32_t);
}

struct Timing {
    std::vector<double> wall, cpu;
    template <class Frame>
    void measure(Frame&& frame) {
        const double c0 = cpuMs();
        const auto t0 = Clock::now();
        frame();
        wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        cpu.push_back(cpuMs() - c0);
    }
};

struct Options {
    long triangles = 1000000;
    std::uint32_t width = 1280, height = 1024;
    int frames = 5;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string arg = argv[i];
        if (arg == "--triangles")
            o.triangles = std::atol(argv[i + 1]);
        else if (arg == "--width")
            o.width = std::uint32_t(std::atoi(argv[i + 1]));
        else if (arg == "--height")
            o.height = std::uint32_t(std::atoi(argv[i + 1]));
        else if (arg == "--frames")
            o.frames = std::max(1, std::atoi(argv[i + 1]));
    }
    return o;
}

/// The meshes of a picture, in item order.
std::vector<std::shared_ptr<const MeshData>> meshesOf(const DrawList& picture) {
    std::vector<std::shared_ptr<const MeshData>> meshes;
    for (const DrawItem& item : picture.items)
        if (const auto* m = primitiveIf<DrawMesh>(item.primitive); m && m->mesh) meshes.push_back(m->mesh);
    return meshes;
}

/// What the frames uploaded.
struct Uploads {
    std::uint64_t unchanged = 0, unchangedBytes = 0;  ///< over all unchanged frames
    std::uint64_t edit = 0, editBytes = 0;            ///< the last edited frame
    std::uint64_t editStructureBytes = 0;             ///< the edited structure's mesh buffers
};

void report(const Options& o, long triangles, long isoSegments, const Timing& first, const Timing& toolkit,
            const Timing& raw, const Timing& edited, const Uploads& u) {
    const double toolkitMs = median(toolkit.wall), rawMs = median(raw.wall);
    const double toolkitCpu = median(toolkit.cpu), rawCpu = median(raw.cpu);
    const bool onlyThat = u.editBytes == u.editStructureBytes;
    std::printf("first frame (traversal, tessellation, every upload): %.1f ms\n", first.wall[0]);
    std::printf(
        "frame through the store, unchanged: %.1f ms wall, %.1f ms CPU (median of %d); "
        "%llu uploads, %llu bytes\n",
        toolkitMs, toolkitCpu, o.frames, (unsigned long long)u.unchanged,
        (unsigned long long)u.unchangedBytes);
    std::printf(
        "raw draw of the same buffers: %.1f ms wall, %.1f ms CPU; ratio wall %.3f, CPU %.3f "
        "(target <= 1.05)\n",
        rawMs, rawCpu, toolkitMs / rawMs, toolkitCpu / rawCpu);
    std::printf(
        "frame after editing one structure: %.1f ms, %llu uploads, %llu bytes (that structure's "
        "buffers: %llu bytes)\n",
        median(edited.wall), (unsigned long long)u.edit, (unsigned long long)u.editBytes,
        (unsigned long long)u.editStructureBytes);
    std::printf(
        "{\"triangles\": %ld, \"iso_line_segments\": %ld, \"width_px\": %u, \"height_px\": %u, "
        "\"frames\": %d, \"first_frame_ms\": %.2f, \"store_frame_ms\": %.2f, \"raw_frame_ms\": %.2f, "
        "\"store_frame_over_raw\": %.3f, \"store_frame_cpu_ms\": %.2f, \"raw_frame_cpu_ms\": %.2f, "
        "\"store_frame_over_raw_cpu\": %.3f, \"unchanged_frame_uploads\": %llu, "
        "\"unchanged_frame_uploaded_bytes\": %llu, \"edit_one_structure_frame_ms\": %.2f, "
        "\"edit_one_structure_frame_cpu_ms\": %.2f, \"edit_uploads\": %llu, \"edit_uploaded_bytes\": %llu, "
        "\"edit_structure_buffer_bytes\": %llu, \"edit_uploads_only_that_structure\": %s}\n",
        triangles, isoSegments, o.width, o.height, o.frames, first.wall[0], toolkitMs, rawMs,
        toolkitMs / rawMs, toolkitCpu, rawCpu, toolkitCpu / rawCpu, (unsigned long long)u.unchanged,
        (unsigned long long)u.unchangedBytes, median(edited.wall), median(edited.cpu),
        (unsigned long long)u.edit, (unsigned long long)u.editBytes, (unsigned long long)u.editStructureBytes,
        onlyThat ? "true" : "false");
}

int run(const Options& o) {
    Scene scene;
    const long perMesh = 2L * scene.slices * scene.stacks;
    scene.count = int(std::max(1L, o.triangles / perMesh));
    scene.side = int(std::ceil(std::sqrt(double(scene.count))));

    vk::ContextSettings settings;
    settings.device = vk::DevicePreference::Lavapipe;
    settings.validation = false;
    vk::Context context(vk::ContextSettings::fromEnvironment(settings));
    Phigs phigs;
    phigs.open();
    buildStore(phigs.store(), scene);
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    setUpWorkstation(ws);
    vk::DisplaySettings display;
    display.width = o.width, display.height = o.height;
    vk::WorkstationDisplay output(ws, context, display);
    ws.postStructure(Scene::kRoot, 0.5);

    Timing first;
    first.measure([&] { output.update(); });
    const DrawList& picture = ws.shownPicture();
    const auto meshes = meshesOf(picture);
    long triangles = 0, isoSegments = 0;
    for (const auto& m : meshes) {
        triangles += long(m->triangles.size() / 3);
        for (const auto& line : m->isoLines) isoSegments += long(line.size()) - 1;
    }
    std::printf(
        "scene: %d structures, %zu meshes, %ld triangles, %ld iso-line segments, %ux%u, lavapipe: %s\n",
        scene.count, meshes.size(), triangles, isoSegments, o.width, o.height,
        context.isLavapipe() ? "yes" : "no");

    // Toolkit and raw frames alternate, so the load of other processes hits both alike.
    vk::OffscreenTarget rawTarget(context, o.width, o.height);
    Baseline base(context, rawTarget);
    base.upload(meshes);
    const glm::mat4 worldToClip(output.mapping().npcToClip);
    base.draw(worldToClip, rawTarget);
    Timing toolkit, raw;
    std::uint64_t unchangedUploads = 0, unchangedBytes = 0;
    for (int f = 0; f < o.frames; ++f) {
        toolkit.measure([&] { output.update(); });
        unchangedUploads += output.renderer().lastFrame().uploads;
        unchangedBytes += output.renderer().lastFrame().uploadedBytes;
        raw.measure([&] { base.draw(worldToClip, rawTarget); });
    }

    // Edit one structure through the store: leaf 0's surface replaced by a raised copy.
    Timing edited;
    std::uint64_t editBytes = 0, editExpected = 0, editUploads = 0;
    for (int f = 0; f < o.frames; ++f) {
        StructureStore& store = phigs.store();
        store.openStructure(Scene::kFirstLeaf);
        store.setEditMode(EditMode::Replace);
        store.setElementPointer(1);
        store.insert(dome(scene, 0, 0.001 * (f + 1)));
        store.setEditMode(EditMode::Insert);
        store.closeStructure();
        edited.measure([&] { output.update(); });
        editBytes = output.renderer().lastFrame().uploadedBytes;
        editUploads = output.renderer().lastFrame().uploads;
        editExpected = meshBytes(*meshesOf(ws.shownPicture()).front());
    }
    report(o, triangles, isoSegments, first, toolkit, raw, edited,
           Uploads{unchangedUploads, unchangedBytes, editUploads, editBytes, editExpected});
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_render: %s\n", e.what());
        return 1;
    }
}
