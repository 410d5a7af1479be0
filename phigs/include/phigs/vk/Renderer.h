#pragma once

#include "phigs/render/ItemGeometry.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/GpuBuffer.h"

#include <vulkan/vulkan.h>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

namespace phigs {
struct WorkstationMapping;
}

namespace phigs::vk {

namespace gpu {
struct DrawParams;
struct LitRun;
}  // namespace gpu

/// Draws a phigs::DrawList into any framebuffer of its render pass: offscreen images, window
/// swapchains and hardcopies share it. prepare() compiles the list (GPU buffers reused while the
/// input is unchanged, only changes uploaded); record() records the frame's commands.
class Renderer {
public:
    Renderer(Context& context, VkFormat colourFormat, VkImageLayout finalLayout);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    VkRenderPass renderPass() const { return renderPass_; }
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    /// Compiles a draw list for a framebuffer of `extent`: describes changed items, uploads what
    /// changed, frees what is no longer drawn. The previous frame must have finished on the GPU.
    /// Throws std::invalid_argument naming the item when it refers to a missing view, light set
    /// or depth cue.
    void prepare(const DrawList& list, VkExtent2D extent);
    /// Records the render pass of the last prepared list into `cmd`.
    void record(VkCommandBuffer cmd, VkFramebuffer framebuffer, VkExtent2D extent) const;

    /// The colour highlighted primitives are mixed toward, and how far (0..1).
    void setHighlight(glm::vec3 colour, float amount);

    const RenderStats& lastFrame() const { return frame_; }
    const RenderStats& total() const { return total_; }

private:
    struct CachedGeometry {
        std::unique_ptr<GpuBuffer> vertices;
        std::vector<render::GeometryPart> parts;
        std::uint64_t lastUsed = 0;
    };
    struct CachedMesh {
        std::weak_ptr<const MeshData> data;
        std::unique_ptr<GpuBuffer> vertices;
        std::unique_ptr<GpuBuffer> indices;
        render::MeshIndices counts;
        bool hasNormals = false, hasColours = false;
        bool facetNormals = false;  ///< the normals are each facet's given one (MeshData::normalsPerFacet)
        /// Each triangle's facet edges with its plane (render::meshSidedEdges), made when a
        /// HOLLOW side first needs them, and their indices (0, 1, 2, ...).
        std::unique_ptr<GpuBuffer> sidedVertices, sidedIndices;
        std::uint32_t sidedCount = 0;
        std::uint64_t lastUsed = 0;
    };
    struct Command {
        std::uint64_t pipeline = 0;
        VkBuffer vertices = VK_NULL_HANDLE;
        VkBuffer indices = VK_NULL_HANDLE;
        std::uint32_t first = 0, count = 0;
        /// The push constants (shaders/scene.glsl): the draw record's and the frame block's
        /// indices, and what the fragment shader reads per draw (faster there than a buffer).
        struct Push {
            std::uint32_t drawIndex = 0;
            std::int32_t firstLight = 0, depthCue = -1;
            std::int32_t unused = 0;  ///< keeps the colours 16-byte aligned
            glm::vec4 colour{0.0f};
            glm::vec4 backColour{0.0f};
            glm::vec4 reflectance{0.0f};     ///< ambient, diffuse, specular, exponent
            glm::vec4 specularColour{0.0f};  ///< rgb, reflectance model
            glm::vec4 backReflectance{0.0f};
            glm::vec4 backSpecularColour{0.0f};
        } push;
        static_assert(offsetof(Push, colour) == 16, "shaders/scene.glsl reads the colours from byte 16");
        float lineWidth = 1.0f;
        VkRect2D scissor{};
        /// Its run's dynamic offset in the run buffer (its view's, or its lit run's), and its view:
        /// a draw that is not PREMULTIPLIED_LIGHTS reads only the view, which every run of that
        /// view holds.
        std::uint32_t runOffset = 0;
        int view = 0;
    };

    struct FramePlan;  ///< what every item's draws read of the frame (Renderer.cpp)
    struct ItemPlan;   ///< what one item's draws share
    struct PartDraw;   ///< one part with its buffers and interior styles
    struct DrawLook;   ///< a draw's shader flags, shading and pattern
    /// Adds item `index`'s draws: its mesh's parts, or its own geometry's (described once, cached).
    void prepareItem(FramePlan& frame, std::size_t index);
    /// The item's own geometry for this framebuffer, described when first drawn, uploaded, cached.
    CachedGeometry& itemGeometry(const DrawItem& item, const glm::dmat4& worldToPixels, double pixelsPerNpc);
    /// A part's draws: one per side filled in its own style (interiors), else one.
    void addPart(FramePlan& frame, const ItemPlan& plan, const PartDraw& part);
    /// One draw of a part: its draw record, push constants, pipeline and command.
    void addDraw(FramePlan& frame, const ItemPlan& plan, const PartDraw& part, bool backSide, int cull);
    /// The flags and shading of a part's draw, its interior's colours and reflectances on one side
    /// into push (and a pattern's record into d).
    DrawLook drawLook(const FramePlan& frame, const ItemPlan& plan, const PartDraw& part, bool backSide,
                      gpu::DrawParams& d, Command::Push& push);
    /// The pipeline key of a part's draw (and a sided edge draw's viewer into push).
    std::uint64_t pipelineKey(const FramePlan& frame, const ItemPlan& plan, const PartDraw& part,
                              const DrawLook& look, int cull, Command::Push& push) const;
    VkPipeline pipeline(std::uint64_t key);
    void createDescriptors();
    /// Writes the frame block; firstLights[s] is where light set s starts in its light array.
    void uploadFrame(const DrawList& list, VkExtent2D extent, const std::vector<int>& firstLights);
    void uploadDraws();
    /// Points descriptor `binding` of the set at `buffer` (its first `range` bytes).
    void bindBuffer(std::uint32_t binding, VkDescriptorType type, const GpuBuffer& buffer,
                    VkDeviceSize range) const;
    /// A PATTERN interior item's record for pattern `patternIndex` (its map to cells) into the
    /// pattern buffer and `d` (the pattern's cells join it once a frame); false when it has no
    /// drawable pattern and draws solid.
    bool patternDraw(const DrawList& list, const DrawItem& item, int patternIndex, gpu::DrawParams& d);
    void uploadPatterns();
    /// The runs of the list's views (run v: view v alone), the first of a frame.
    void addViewRuns(const DrawList& list, const WorkstationMapping& mapping);
    /// The index of the lit run of view `viewIndex` and light set `lightSet` with this reflectance
    /// (ambient, diffuse, specular, exponent), specular colour and colour (white when it varies
    /// per fragment) folded in, added once a frame; -1 when the buffer is full (the draw then
    /// lights the general way).
    int premultipliedLights(const DrawList& list, int viewIndex, int lightSet, glm::vec4 reflectance,
                            glm::vec4 specularColour, glm::vec3 colour);
    void uploadLitRuns();
    /// Where item `index`'s model clipping planes sit in the frame block (first, count); equal
    /// plane sets share one run.
    glm::vec2 clipPlaneRange(const DrawItem& item, std::size_t index);
    CachedMesh& compileMesh(const std::shared_ptr<const MeshData>& mesh);
    /// Makes the mesh's sided edge buffers once (CachedMesh::sidedVertices).
    void compileSidedEdges(CachedMesh& cached);
    /// Hands a mesh's parts to `addPart` (part, interior, mesh normals, vertex and index buffers):
    /// its HOLLOW sides' outlines, filled interior, iso-lines and edges.
    template <typename AddPart>
    void addMeshParts(const DrawMesh& mesh, CachedMesh& cached, const AddPart& addPart);
    void release();

    Context& context_;
    VkFormat colourFormat_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::map<std::uint64_t, VkPipeline> pipelines_;
    float maxLineWidth_ = 1.0f;

    std::unique_ptr<GpuBuffer> frameBuffer_;
    std::vector<unsigned char> lastFrameBytes_;
    std::unique_ptr<GpuBuffer> drawBuffer_;
    std::vector<unsigned char> drawBytes_;      // what this frame wants
    std::vector<unsigned char> lastDrawBytes_;  // what the draw buffer holds
    std::unique_ptr<GpuBuffer> patternBuffer_;
    std::vector<glm::vec4> patternCells_, lastPatternCells_;  // this frame's records and cells, the buffer's
    std::map<const DrawPattern*, int> patternFirst_;          // this frame's patterns' first cells
    /// What a run holds: a view, and a light set premultiplied by a material (light set -1: the
    /// view alone).
    struct LitKey {
        int viewIndex = 0, lightSet = 0;
        glm::vec4 reflectance{0.0f};
        glm::vec3 specularColour{0.0f};
        glm::vec3 colour{0.0f};
        bool operator==(const LitKey&) const = default;
    };
    std::unique_ptr<GpuBuffer> litBuffer_;
    std::size_t litStride_ = 0;                           // bytes from one run to the next
    std::vector<unsigned char> litBytes_, lastLitBytes_;  // this frame's runs, the buffer's
    std::vector<LitKey> litKeys_;                         // this frame's

    std::unordered_map<std::uint64_t, CachedGeometry> geometry_;
    std::unordered_map<const MeshData*, CachedMesh> meshes_;
    std::vector<Command> commands_;
    std::vector<std::pair<std::vector<glm::dvec4>, int>> clipPlaneSets_;  ///< this frame's, with first index
    std::vector<glm::vec4> clipPlanes_;
    glm::vec4 highlight_{1.0f, 1.0f, 0.0f, 0.6f};
    glm::vec3 background_{0.0f};
    bool depthTest_ = false;
    std::uint64_t frameNumber_ = 0;
    RenderStats frame_, total_;
};

}  // namespace phigs::vk
