// Instance: opens the Vulkan loader through volk, optionally with the validation
// layer (synchronization validation on), records validation messages, and lists
// adapters in the order hush prefers them.
#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "objects.hpp"
#include "vk_check.hpp"

namespace hush::rhi {
namespace detail {

InstanceImpl::~InstanceImpl() {
    if (messenger != VK_NULL_HANDLE && destroyMessenger) destroyMessenger(instance, messenger, nullptr);
    if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
    // The loader stays open: volk's global function pointers may still be used by
    // another instance, and unloading libvulkan buys nothing.
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* impl = static_cast<InstanceImpl*>(user);
    std::string text = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "[vulkan error] " : "[vulkan warning] ";
    text += data && data->pMessage ? data->pMessage : "(no message)";
    std::function<void(const std::string&)> callback;
    {
        std::lock_guard lock(impl->messageMutex);
        impl->messages.push_back(text);
        callback = impl->onMessage;
    }
    if (callback) callback(text);
    else std::cerr << text << '\n';
    return VK_FALSE;   // never abort the call: the caller decides what a message means
}

bool envFlag(const char* name) {
    const char* value = std::getenv(name);
    return value && *value && std::strcmp(value, "0") != 0;
}

// The validation layer's own extension list (VK_EXT_validation_features lives there).
bool layerHasExtension(const char* layer, const char* extension) {
    uint32_t count = 0;
    if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
    std::vector<VkExtensionProperties> props(count);
    vkEnumerateInstanceExtensionProperties(layer, &count, props.data());
    return std::any_of(props.begin(), props.end(),
                       [&](const VkExtensionProperties& p) { return std::strcmp(p.extensionName, extension) == 0; });
}

bool hasLayer(const char* layer) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> props(count);
    vkEnumerateInstanceLayerProperties(&count, props.data());
    return std::any_of(props.begin(), props.end(),
                       [&](const VkLayerProperties& p) { return std::strcmp(p.layerName, layer) == 0; });
}

int preference(AdapterType type) {
    switch (type) {
    case AdapterType::DiscreteGpu: return 0;
    case AdapterType::IntegratedGpu: return 1;
    case AdapterType::VirtualGpu: return 2;
    case AdapterType::Other: return 3;
    case AdapterType::Cpu: return 4;
    }
    return 5;
}

} // namespace

// Opens the loader named by desc, HUSH_VULKAN_LOADER or libvulkan.so.1 and points volk at it.
void* openLoader(const std::string& requested) {
    std::string name = requested;
    if (name.empty()) {
        const char* env = std::getenv("HUSH_VULKAN_LOADER");
        name = env && *env ? env : "libvulkan.so.1";
    }
    void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* why = dlerror();
        fail(ErrorKind::NoLoader,
             "could not open the Vulkan loader '" + name + "' (" + (why ? why : "unknown reason") +
                 "). Install it (Debian: apt-get install libvulkan1 mesa-vulkan-drivers) or set "
                 "HUSH_VULKAN_LOADER to its path.");
    }
    auto getProc = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(handle, "vkGetInstanceProcAddr"));
    if (!getProc)
        fail(ErrorKind::NoLoader, "'" + name + "' is not a Vulkan loader: it has no vkGetInstanceProcAddr.");
    volkInitializeCustom(getProc);
    return handle;
}

std::vector<AdapterRecord> enumerateAdapterRecords(VkInstance instance);

} // namespace detail

using namespace detail;

Instance Instance::create(const InstanceDesc& desc) {
    auto impl = std::make_shared<InstanceImpl>();
    impl->loader = openLoader(desc.loaderLibrary);
    impl->validation = desc.validation || (desc.validationFromEnvironment && envFlag("HUSH_VALIDATION"));
    impl->onMessage = desc.onValidationMessage;

    uint32_t version = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion) vkEnumerateInstanceVersion(&version);
    if (version < VK_API_VERSION_1_3)
        fail(ErrorKind::Unsupported, "the Vulkan loader supports API " + std::to_string(VK_API_VERSION_MAJOR(version)) +
                                         "." + std::to_string(VK_API_VERSION_MINOR(version)) +
                                         "; hush needs Vulkan 1.3. Update libvulkan1.");

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = onDebugMessage;
    messengerInfo.pUserData = impl.get();

    const void* next = nullptr;
    if (impl->validation) {
        if (!hasLayer(kValidationLayer))
            fail(ErrorKind::Unsupported, "validation was requested but the layer VK_LAYER_KHRONOS_validation is not "
                                         "installed (Debian: apt-get install vulkan-validationlayers).");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        if (layerHasExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            features.pNext = &messengerInfo;   // also catches messages from vkCreateInstance itself
            next = &features;
        } else {
            next = &messengerInfo;
        }
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = desc.applicationName.c_str();
    app.pEngineName = "hush";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = next;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result = vkCreateInstance(&info, nullptr, &impl->instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        fail(ErrorKind::NoDriver, "the Vulkan loader found no driver (ICD) that supports Vulkan 1.3. Install one "
                                  "(Debian: apt-get install mesa-vulkan-drivers for the CPU driver lavapipe) or check "
                                  "VK_ICD_FILENAMES / VK_DRIVER_FILES.");
    checkVk(result, "vkCreateInstance");
    volkLoadInstanceOnly(impl->instance);

    if (impl->validation) {
        checkVk(vkCreateDebugUtilsMessengerEXT(impl->instance, &messengerInfo, nullptr, &impl->messenger),
                "vkCreateDebugUtilsMessengerEXT");
        impl->destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(impl->instance, "vkDestroyDebugUtilsMessengerEXT"));
    }

    impl->adapters = enumerateAdapterRecords(impl->instance);
    std::stable_sort(impl->adapters.begin(), impl->adapters.end(), [](const auto& a, const auto& b) {
        return preference(a.info.type) < preference(b.info.type);
    });
    return Instance(std::move(impl));
}

std::vector<Adapter> Instance::enumerateAdapters() const {
    auto* impl = checked(impl_, "Instance");
    std::vector<Adapter> out;
    for (uint32_t i = 0; i < impl->adapters.size(); ++i) out.emplace_back(impl_, i);
    return out;
}

Adapter Instance::requestAdapter(const AdapterRequest& request) const {
    auto* impl = checked(impl_, "Instance");
    std::string wanted = request.nameContains;
    if (wanted.empty() && request.nameFromEnvironment) {
        const char* env = std::getenv("HUSH_ADAPTER");
        if (env) wanted = env;
    }
    if (impl->adapters.empty())
        fail(ErrorKind::NoAdapter, "Vulkan reports no adapter (physical device). Install a driver (Debian: "
                                   "apt-get install mesa-vulkan-drivers for the CPU driver lavapipe).");
    auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return s;
    };
    std::string available;
    for (uint32_t i = 0; i < impl->adapters.size(); ++i) {
        const auto& record = impl->adapters[i];
        if (record.computeQueueFamily == ~0u) continue;
        if (wanted.empty() || lower(record.info.name).find(lower(wanted)) != std::string::npos) return Adapter(impl_, i);
    }
    for (const auto& record : impl->adapters) {
        if (!available.empty()) available += ", ";
        available += "'" + record.info.name + "'";
    }
    fail(ErrorKind::NoAdapter, wanted.empty()
                                   ? "no adapter has a compute queue; available: " + available
                                   : "no adapter name contains '" + wanted + "' (from " +
                                         (request.nameContains.empty() ? "HUSH_ADAPTER" : "the request") +
                                         "); available: " + available);
}

bool Instance::validationEnabled() const { return checked(impl_, "Instance")->validation; }

std::vector<std::string> Instance::validationMessages() const {
    auto* impl = checked(impl_, "Instance");
    std::lock_guard lock(impl->messageMutex);
    return impl->messages;
}

size_t Instance::validationMessageCount() const {
    auto* impl = checked(impl_, "Instance");
    std::lock_guard lock(impl->messageMutex);
    return impl->messages.size();
}

void Instance::clearValidationMessages() const {
    auto* impl = checked(impl_, "Instance");
    std::lock_guard lock(impl->messageMutex);
    impl->messages.clear();
}

} // namespace hush::rhi
