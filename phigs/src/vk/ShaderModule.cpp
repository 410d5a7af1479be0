#include "phigs/vk/ShaderModule.h"

#include "phigs/vk/Context.h"
#include "shaders/Spirv.h"

namespace phigs::vk {

ShaderModule::ShaderModule(VkDevice device, std::string_view name) : device_(device) {
    const auto words = shaders::spirv(name);
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    check(vkCreateShaderModule(device_, &info, nullptr, &module_), "vkCreateShaderModule");
}

ShaderModule::~ShaderModule() {
    vkDestroyShaderModule(device_, module_, nullptr);
}

}  // namespace phigs::vk
