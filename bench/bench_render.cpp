// bench_render: frame time of the toolkit renderer on lavapipe for a scene of shaded triangles
// plus iso-lines, against a minimal baseline that draws the same vertex data with one pipeline
// per topology and no toolkit around it; and the frame after editing one structure (one mesh).
// Usage: bench_render [--triangles N] [--width W] [--height H] [--frames F]. Ends with one JSON object.
#include "SceneMeshes.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/GpuBuffer.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/Renderer.h"
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
        VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        VkSubpassDescription sub{};
        sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        sub.colorAttachmentCount = 1;
        sub.pColorAttachments = &colourRef;
        sub.pDepthStencilAttachment = &depthRef;
        VkSubpassDependency dep{};
        dep.srcSubpass = VK_SUBPASS_EXTERNAL;
        dep.srcStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
        dep.dstStageMask =
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
        dep.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
        VkRenderPassCreateInfo rp{};
        rp.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
        rp.attachmentCount = 2;
        rp.pAttachments = a;
        rp.subpassCount = 1;
        rp.pSubpasses = &sub;
        rp.dependencyCount = 1;
        rp.pDependencies = &dep;
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

    void upload(const std::vector<std::shared_ptr<MeshData>>& scene) {
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

    void draw(const glm::mat4& worldToClip, VkExtent2D extent) {
        context.submitAndWait([&](VkCommandBuffer cmd) {
            VkClearValue clears[2]{};
            clears[0].color = {{0.1f, 0.1f, 0.1f, 1.0f}};
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
        });
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

}  // namespace

int main(int argc, char** argv) {
    long triangles = 1000000;
    std::uint32_t width = 1280, height = 1024;
    int frames = 5;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string arg = argv[i];
        if (arg == "--triangles")
            triangles = std::atol(argv[i + 1]);
        else if (arg == "--width")
            width = std::uint32_t(std::atoi(argv[i + 1]));
        else if (arg == "--height")
            height = std::uint32_t(std::atoi(argv[i + 1]));
        else if (arg == "--frames")
            frames = std::max(1, std::atoi(argv[i + 1]));
    }
    try {
        vk::ContextSettings settings;
        settings.device = vk::DevicePreference::Lavapipe;
        settings.validation = false;
        vk::Context context(vk::ContextSettings::fromEnvironment(settings));

        // A grid of spheres, 100 x 50 quads each (10,000 triangles), with 8 iso-lines each way.
        const int slices = 100, stacks = 50;
        const long perMesh = 2L * slices * stacks;
        const int count = int(std::max(1L, triangles / perMesh));
        const int side = int(std::ceil(std::sqrt(double(count))));
        std::vector<std::shared_ptr<MeshData>> meshes;
        DrawList list;
        list.views.push_back(DrawView{});
        list.hiddenSurfaceRemoval = true;
        Light ambient;
        Light key;
        key.type = LightType::Directional;
        key.direction = {-1, -1, -2};
        list.lightSets.push_back({ambient, key});
        long isoSegments = 0;
        for (int k = 0; k < count; ++k) {
            const float r = 0.5f / float(side);
            auto m = render_test::sphere(
                {(float(k % side) + 0.5f) / float(side), (float(k / side) + 0.5f) / float(side), 0.5f},
                r * 0.95f, slices, stacks, 8);
            for (const auto& line : m->isoLines) isoSegments += long(line.size()) - 1;
            meshes.push_back(m);
            DrawMesh d;
            d.mesh = m;
            d.interior.style = InteriorStyle::Solid;
            d.interior.colour = {0.8f, 0.8f, 0.8f};
            d.interior.shading = ShadingMethod::Normal;
            d.interior.reflectance = ReflectanceModel::Specular;
            d.interior.properties = {0.2f, 0.7f, 0.5f, glm::vec3(1.0f), 20.0f, 0.0f};
            d.isoLineStyle.colour = {1, 1, 0};
            DrawItem item;
            item.primitive = d;
            item.lightSet = 0;
            item.source.path = {{k + 1, 1, 0}};
            list.items.push_back(item);
        }
        const long totalTriangles = long(count) * perMesh;
        std::printf("scene: %d meshes, %ld triangles, %ld iso-line segments, %ux%u, lavapipe: %s\n", count,
                    totalTriangles, isoSegments, width, height, context.isLavapipe() ? "yes" : "no");

        vk::OffscreenTarget target(context, width, height);
        const VkExtent2D extent{width, height};
        vk::Renderer renderer(context, vk::OffscreenTarget::kColorFormat,
                              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        {
            VkImageView views[2] = {target.colorView(), target.depthView()};
            VkFramebufferCreateInfo fb{};
            fb.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
            fb.renderPass = renderer.renderPass();
            fb.attachmentCount = 2;
            fb.pAttachments = views;
            fb.width = width;
            fb.height = height;
            fb.layers = 1;
            vk::check(vkCreateFramebuffer(context.device(), &fb, nullptr, &framebuffer),
                      "vkCreateFramebuffer");
        }
        auto toolkitFrame = [&]() {
            const auto t0 = Clock::now();
            renderer.prepare(list, extent);
            context.submitAndWait([&](VkCommandBuffer cmd) { renderer.record(cmd, framebuffer, extent); });
            return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        };
        const double firstFrame = toolkitFrame();

        // Toolkit and baseline frames alternate, so the load of other processes hits both alike.
        Baseline base(context, target);
        base.upload(meshes);
        const WorkstationMapping mapping(list, width, height);
        const glm::mat4 worldToClip(mapping.npcToClip);
        base.draw(worldToClip, extent);
        std::vector<double> toolkit, baseline, toolkitCpu, baselineCpu;
        std::uint64_t unchangedUploads = 0;
        for (int f = 0; f < frames; ++f) {
            double c0 = cpuMs();
            toolkit.push_back(toolkitFrame());
            toolkitCpu.push_back(cpuMs() - c0);
            unchangedUploads += renderer.lastFrame().uploads;
            c0 = cpuMs();
            const auto t0 = Clock::now();
            base.draw(worldToClip, extent);
            baseline.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
            baselineCpu.push_back(cpuMs() - c0);
        }

        // Edit one structure: its mesh is replaced (a new tessellation), the rest stays.
        std::vector<double> edited;
        std::uint64_t editUploadedBytes = 0;
        for (int f = 0; f < frames; ++f) {
            auto& d = std::get<DrawMesh>(list.items[0].primitive);
            auto m = std::make_shared<MeshData>(*d.mesh);
            for (auto& p : m->positions) p.z += 0.001f;
            d.mesh = m;
            edited.push_back(toolkitFrame());
            editUploadedBytes = renderer.lastFrame().uploadedBytes;
        }
        vkDestroyFramebuffer(context.device(), framebuffer, nullptr);

        const double toolkitMs = median(toolkit), baselineMs = median(baseline), editMs = median(edited);
        std::printf("first frame (uploads everything): %.1f ms\n", firstFrame);
        std::printf("toolkit frame, unchanged: %.1f ms (median of %d), uploads %llu\n", toolkitMs, frames,
                    (unsigned long long)unchangedUploads);
        std::printf("baseline frame: %.1f ms; ratio %.3f (target <= 1.25)\n", baselineMs,
                    toolkitMs / baselineMs);
        const double toolkitCpuMs = median(toolkitCpu), baselineCpuMs = median(baselineCpu);
        std::printf("CPU time per frame (all threads): toolkit %.1f ms, baseline %.1f ms; ratio %.3f\n",
                    toolkitCpuMs, baselineCpuMs, toolkitCpuMs / baselineCpuMs);
        std::printf("frame after editing one structure: %.1f ms, %llu bytes uploaded\n", editMs,
                    (unsigned long long)editUploadedBytes);
        std::printf(
            "{\"triangles\": %ld, \"iso_line_segments\": %ld, \"width_px\": %u, \"height_px\": %u, "
            "\"first_frame_ms\": %.2f, \"toolkit_frame_ms\": %.2f, \"baseline_frame_ms\": %.2f, "
            "\"toolkit_over_baseline\": %.3f, \"toolkit_cpu_ms\": %.2f, \"baseline_cpu_ms\": %.2f, "
            "\"toolkit_over_baseline_cpu\": %.3f, \"edit_one_structure_frame_ms\": %.2f, "
            "\"edit_uploaded_bytes\": %llu, \"unchanged_frame_uploads\": %llu}\n",
            totalTriangles, isoSegments, width, height, firstFrame, toolkitMs, baselineMs,
            toolkitMs / baselineMs, toolkitCpuMs, baselineCpuMs, toolkitCpuMs / baselineCpuMs, editMs,
            (unsigned long long)editUploadedBytes, (unsigned long long)unchangedUploads);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_render: %s\n", e.what());
        return 1;
    }
    return 0;
}
