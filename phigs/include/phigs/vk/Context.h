#pragma once

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace phigs::vk {

/// Which physical device a Context picks.
enum class DevicePreference {
    Lavapipe,  ///< Mesa's CPU rasteriser only (tests, headless runs on any machine)
    Hardware,  ///< a discrete or integrated GPU when there is one, else lavapipe
};

/// What to create a Context with.
struct ContextSettings {
    DevicePreference device = DevicePreference::Lavapipe;
    bool validation = true;  ///< enable VK_LAYER_KHRONOS_validation and collect its messages
    std::vector<const char*> instanceExtensions;  ///< e.g. the window system's surface extensions
    std::vector<const char*> deviceExtensions;    ///< e.g. VK_KHR_swapchain for a window
    /// Also receives every validation message and outlives the Context, so the messages of the
    /// shutdown itself (objects still alive when the device is destroyed) can be checked.
    std::vector<std::string>* messageLog = nullptr;
    /// Also prints every validation message to stderr as it arrives (an interactive program run
    /// with PHIGS_VK_VALIDATION=1; tests collect them instead and fail on any).
    bool printMessages = false;
    /// Reads PHIGS_VK_DEVICE=lavapipe|hardware and PHIGS_VK_VALIDATION=0|1 over the defaults.
    static ContextSettings fromEnvironment(ContextSettings defaults);
    static ContextSettings fromEnvironment();
};

/// The Vulkan instance, the chosen physical device, one logical device with a graphics queue and
/// a command pool, and the validation messages seen so far.
class Context {
public:
    explicit Context(const ContextSettings& settings = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }
    VkCommandPool commandPool() const { return commandPool_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    /// The largest image the device draws into: maxImageDimension2D within the framebuffer limits.
    VkExtent2D largestDrawable() const {
        const VkPhysicalDeviceLimits& l = properties_.limits;
        return {std::min(l.maxImageDimension2D, l.maxFramebufferWidth),
                std::min(l.maxImageDimension2D, l.maxFramebufferHeight)};
    }
    /// True when the chosen device is Mesa lavapipe.
    bool isLavapipe() const { return lavapipe_; }

    /// Index of a memory type allowed by typeBits that has all the wanted property flags; throws
    /// when there is none.
    std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted) const;

    /// Records commands with `record` into a one-time command buffer, submits it and waits.
    template <class Record>
    void submitAndWait(Record&& record) {
        VkCommandBuffer cmd = beginOneTime();
        record(cmd);
        endOneTimeAndWait(cmd);
    }

    /// Validation-layer messages (warnings and errors) received so far, oldest first.
    std::vector<std::string> validationMessages() const;
    void clearValidationMessages();

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                         void* self);
    VkCommandBuffer beginOneTime();
    void endOneTimeAndWait(VkCommandBuffer cmd);
    void selectPhysicalDevice(DevicePreference preference);
    void release();

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    bool lavapipe_ = false;
    mutable std::mutex messagesMutex_;
    std::vector<std::string> messages_;
    std::vector<std::string>* messageLog_ = nullptr;
    bool printMessages_ = false;
};

/// Throws std::runtime_error naming `what` when result is not VK_SUCCESS.
void check(VkResult result, const char* what);

}  // namespace phigs::vk
