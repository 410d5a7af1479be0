#pragma once

#include "phigs/vk/Context.h"

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>

namespace phigs::vk {

/// What the renderer sent to the GPU and created, per frame or in total (tests count uploads).
struct RenderStats {
    std::uint64_t uploads = 0;        ///< buffer writes
    std::uint64_t uploadedBytes = 0;  ///< bytes written to GPU buffers
    std::uint64_t buffersCreated = 0;
    std::uint64_t buffersDestroyed = 0;
    std::uint64_t pipelinesCreated = 0;
    std::uint64_t drawCalls = 0;
    void add(const RenderStats& o) {
        uploads += o.uploads, uploadedBytes += o.uploadedBytes, buffersCreated += o.buffersCreated;
        buffersDestroyed += o.buffersDestroyed, pipelinesCreated += o.pipelinesCreated,
            drawCalls += o.drawCalls;
    }
};

/// A host-visible, persistently mapped Vulkan buffer; every write is counted in a RenderStats.
class GpuBuffer {
public:
    GpuBuffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage, RenderStats& stats);
    ~GpuBuffer();
    GpuBuffer(const GpuBuffer&) = delete;
    GpuBuffer& operator=(const GpuBuffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    /// Copies `bytes` bytes to `offset`; throws when the range does not fit.
    void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);

private:
    Context& context_;
    RenderStats& stats_;
    VkDeviceSize size_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    void* mapped_ = nullptr;
};

}  // namespace phigs::vk
