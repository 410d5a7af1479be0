#pragma once

#include <vulkan/vulkan.h>

#include <string_view>

namespace phigs::vk {

/// A VkShaderModule made from a shader embedded at build time (`shaders/<name>`), destroyed with it.
class ShaderModule {
public:
    ShaderModule(VkDevice device, std::string_view name);
    ~ShaderModule();
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;

    VkShaderModule handle() const { return module_; }

private:
    VkDevice device_;
    VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace phigs::vk
