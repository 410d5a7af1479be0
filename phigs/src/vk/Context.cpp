#include "phigs/vk/Context.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string_view>

namespace phigs::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasInstanceLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(void* self, PFN_vkDebugUtilsMessengerCallbackEXT callback) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = callback;
    info.pUserData = self;
    return info;
}

}  // namespace

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string("Vulkan: ") + what + " failed with VkResult " +
                                 std::to_string(static_cast<int>(result)));
}

ContextSettings ContextSettings::fromEnvironment() {
    return fromEnvironment(ContextSettings{});
}

ContextSettings ContextSettings::fromEnvironment(ContextSettings defaults) {
    if (const char* device = std::getenv("PHIGS_VK_DEVICE")) {
        const std::string_view value = device;
        if (value == "lavapipe")
            defaults.device = DevicePreference::Lavapipe;
        else if (value == "hardware")
            defaults.device = DevicePreference::Hardware;
        else
            throw std::invalid_argument("PHIGS_VK_DEVICE must be 'lavapipe' or 'hardware', not '" +
                                        std::string(value) + "'");
    }
    if (const char* validation = std::getenv("PHIGS_VK_VALIDATION")) {
        const std::string_view value(validation);
        if (value != "0" && value != "1")  // "off" or "" turning the layer on would surprise
            throw std::invalid_argument("PHIGS_VK_VALIDATION must be '0' or '1', not '" + std::string(value) +
                                        "'");
        defaults.validation = value == "1";
    }
    return defaults;
}

Context::Context(const ContextSettings& settings)
    : messageLog_(settings.messageLog), printMessages_(settings.printMessages) {
    std::vector<const char*> layers;
    std::vector<const char*> extensions = settings.instanceExtensions;
    if (settings.validation) {
        if (!hasInstanceLayer(kValidationLayer))
            throw std::runtime_error(
                "Vulkan validation layer VK_LAYER_KHRONOS_validation is not installed: install the Debian "
                "package 'vulkan-validationlayers' or set PHIGS_VK_VALIDATION=0");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "phigs toolkit";
    app.pEngineName = "phigs";
    app.apiVersion = VK_API_VERSION_1_2;

    // Chained into instance creation so messages from vkCreateInstance itself are caught too.
    const VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(this, &Context::onDebugMessage);
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = settings.validation ? &debugInfo : nullptr;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance");

    try {
        if (settings.validation) {
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            check(create(instance_, &debugInfo, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
        }
        selectPhysicalDevice(settings.device);

        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{};
        queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
        queueInfo.queueFamilyIndex = queueFamily_;
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkPhysicalDeviceFeatures features{};
        VkPhysicalDeviceFeatures available{};
        vkGetPhysicalDeviceFeatures(physicalDevice_, &available);
        features.wideLines = available.wideLines;
        features.largePoints = available.largePoints;
        features.fillModeNonSolid = available.fillModeNonSolid;
        features.depthBiasClamp = available.depthBiasClamp;
        VkDeviceCreateInfo deviceInfo{};
        deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
        deviceInfo.queueCreateInfoCount = 1;
        deviceInfo.pQueueCreateInfos = &queueInfo;
        deviceInfo.enabledExtensionCount = static_cast<std::uint32_t>(settings.deviceExtensions.size());
        deviceInfo.ppEnabledExtensionNames = settings.deviceExtensions.data();
        deviceInfo.pEnabledFeatures = &features;
        check(vkCreateDevice(physicalDevice_, &deviceInfo, nullptr, &device_), "vkCreateDevice");
        vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

        VkCommandPoolCreateInfo poolInfo{};
        poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        poolInfo.queueFamilyIndex = queueFamily_;
        check(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
    } catch (...) {
        release();
        throw;
    }
}

Context::~Context() {
    release();
}

void Context::release() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) {
        vkDestroyInstance(instance_, nullptr);
        instance_ = VK_NULL_HANDLE;
    }
}

void Context::selectPhysicalDevice(DevicePreference preference) {
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices.data());

    struct Candidate {
        VkPhysicalDevice device;
        std::uint32_t family;
        bool lavapipe;
        int rank;
    };
    std::vector<Candidate> candidates;
    std::string seen;
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceDriverProperties driver{};
        driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
        VkPhysicalDeviceProperties2 props{};
        props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
        props.pNext = &driver;
        vkGetPhysicalDeviceProperties2(device, &props);
        seen += std::string(seen.empty() ? "" : ", ") + props.properties.deviceName;

        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
        for (std::uint32_t f = 0; f < familyCount; ++f) {
            if (!(families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
            const bool lavapipe = driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE;
            const int rank = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 3
                             : props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 2
                             : lavapipe                                                              ? 1
                                                                                                     : 0;
            candidates.push_back({device, f, lavapipe, rank});
            break;
        }
    }
    const Candidate* chosen = nullptr;
    for (const Candidate& c : candidates) {
        if (preference == DevicePreference::Lavapipe) {
            if (c.lavapipe) chosen = &c;
        } else if (!chosen || c.rank > chosen->rank) {
            chosen = &c;
        }
        if (preference == DevicePreference::Lavapipe && chosen) break;
    }
    if (!chosen)
        throw std::runtime_error(preference == DevicePreference::Lavapipe
                                     ? "Vulkan: Mesa lavapipe is not available (install the Debian package "
                                       "'mesa-vulkan-drivers'); "
                                       "devices seen: " +
                                           (seen.empty() ? std::string("none") : seen)
                                     : "Vulkan: no device with a graphics queue; devices seen: " +
                                           (seen.empty() ? std::string("none") : seen));
    physicalDevice_ = chosen->device;
    queueFamily_ = chosen->family;
    lavapipe_ = chosen->lavapipe;
    vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
}

std::uint32_t Context::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory);
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    throw std::runtime_error("Vulkan: no memory type with the wanted properties");
}

VkCommandBuffer Context::beginOneTime() {
    VkCommandBufferAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = commandPool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    return cmd;
}

void Context::endOneTimeAndWait(VkCommandBuffer cmd) {
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device_, &fenceInfo, nullptr, &fence), "vkCreateFence");
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    VkResult result = vkQueueSubmit(queue_, 1, &submit, fence);
    if (result == VK_SUCCESS) result = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device_, fence, nullptr);
    vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
    check(result, "vkQueueSubmit / vkWaitForFences");
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                       VkDebugUtilsMessageTypeFlagsEXT,
                                                       const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                       void* self) {
    auto* context = static_cast<Context*>(self);
    std::string text = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: " : "warning: ";
    if (data->pMessageIdName) text += std::string(data->pMessageIdName) + ": ";
    text += data->pMessage ? data->pMessage : "";
    std::lock_guard lock(context->messagesMutex_);
    if (context->messageLog_) context->messageLog_->push_back(text);
    if (context->printMessages_) std::cerr << "Vulkan validation " << text << "\n";
    context->messages_.push_back(std::move(text));
    return VK_FALSE;
}

std::vector<std::string> Context::validationMessages() const {
    std::lock_guard lock(messagesMutex_);
    return messages_;
}

void Context::clearValidationMessages() {
    std::lock_guard lock(messagesMutex_);
    messages_.clear();
}

}  // namespace phigs::vk
