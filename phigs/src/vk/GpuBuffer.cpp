#include "phigs/vk/GpuBuffer.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace phigs::vk {

GpuBuffer::GpuBuffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage, RenderStats& stats)
    : context_(context), stats_(stats), size_(size) {
    if (size == 0) throw std::invalid_argument("GpuBuffer: size must not be zero");
    VkDevice device = context_.device();
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device, &info, nullptr, &buffer_), "vkCreateBuffer");
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(device, buffer_, &req);
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = req.size;
    const VkMemoryPropertyFlags host =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    // Device-local host-visible memory where the device has it (integrated GPUs, lavapipe, ReBAR).
    try {
        alloc.memoryTypeIndex =
            context_.memoryType(req.memoryTypeBits, host | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    } catch (const std::runtime_error&) {
        alloc.memoryTypeIndex = context_.memoryType(req.memoryTypeBits, host);
    }
    VkResult result = vkAllocateMemory(device, &alloc, nullptr, &memory_);
    if (result == VK_SUCCESS) result = vkBindBufferMemory(device, buffer_, memory_, 0);
    if (result == VK_SUCCESS) result = vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_);
    if (result != VK_SUCCESS) {
        if (memory_) vkFreeMemory(device, memory_, nullptr);
        vkDestroyBuffer(device, buffer_, nullptr);
        check(result, "vkAllocateMemory / vkBindBufferMemory / vkMapMemory");
    }
    ++stats_.buffersCreated;
}

GpuBuffer::~GpuBuffer() {
    VkDevice device = context_.device();
    vkUnmapMemory(device, memory_);
    vkDestroyBuffer(device, buffer_, nullptr);
    vkFreeMemory(device, memory_, nullptr);
    ++stats_.buffersDestroyed;
}

void GpuBuffer::write(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
    if (offset + bytes > size_)
        throw std::out_of_range("GpuBuffer::write: " + std::to_string(bytes) + " bytes at " +
                                std::to_string(offset) + " do not fit in " + std::to_string(size_));
    if (bytes == 0) return;
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
    ++stats_.uploads;
    stats_.uploadedBytes += bytes;
}

}  // namespace phigs::vk
