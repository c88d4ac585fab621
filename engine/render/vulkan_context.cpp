// SPDX-License-Identifier: MIT
#include <tutti/render/vulkan_context.hpp>

#include <algorithm>
#include <cctype>
#include <optional>
#include <utility>

#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDevice =
    "no Vulkan device found (install mesa-vulkan-drivers for the CPU renderer)";

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data) {
  const char* level =
      (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::string message = std::string("validation ") + level + ": ";
  if (data != nullptr && data->pMessageIdName != nullptr) {
    message += std::string(data->pMessageIdName) + ": ";
  }
  if (data != nullptr && data->pMessage != nullptr) message += data->pMessage;
  static_cast<ValidationLog*>(user_data)->add(std::move(message));
  return VK_FALSE;  // never abort the call that triggered the message
}

VkDebugUtilsMessengerCreateInfoEXT messenger_info(ValidationLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info = vk_struct<VkDebugUtilsMessengerCreateInfoEXT>(
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = on_validation_message;
  info.pUserData = log;
  return info;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
    return std::string(layer.layerName) == name;
  });
}

bool instance_extension_available(const std::string& name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()) != VK_SUCCESS) {
    return false;
  }
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return name == e.extensionName; });
}

bool device_extension_available(VkPhysicalDevice device, const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) != VK_SUCCESS) {
    return false;
  }
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()) !=
      VK_SUCCESS) {
    return false;
  }
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::string(e.extensionName) == name;
  });
}

// The first graphics queue family (that can present, when the options ask for presentation).
std::optional<std::uint32_t> graphics_family(VkInstance instance, VkPhysicalDevice device,
                                             const VulkanContextOptions& options) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
    if (options.can_present && !options.can_present(instance, device, i)) continue;
    return i;
  }
  return std::nullopt;
}

// What a usable device needs, for error messages.
std::string requirements_text(const VulkanContextOptions& options) {
  std::string text = "Vulkan 1.3, a graphics queue";
  if (options.can_present) text += " that can present";
  text += options.swapchain ? ", dynamic rendering or VK_KHR_swapchain" : " or dynamic rendering";
  return text;
}

VulkanDeviceInfo describe(VkInstance instance, VkPhysicalDevice device, std::uint32_t index,
                          const VulkanContextOptions& options) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);
  VulkanDeviceInfo info;
  info.index = index;
  info.name = properties.deviceName;
  info.type = properties.deviceType;
  info.api_version = properties.apiVersion;
  bool dynamic_rendering = false;
  if (properties.apiVersion >= VK_API_VERSION_1_3) {
    VkPhysicalDeviceVulkan13Features features13 = vk_struct<VkPhysicalDeviceVulkan13Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    VkPhysicalDeviceFeatures2 features =
        vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    features.pNext = &features13;
    vkGetPhysicalDeviceFeatures2(device, &features);
    dynamic_rendering = features13.dynamicRendering && features13.synchronization2;
  }
  info.usable =
      dynamic_rendering && graphics_family(instance, device, options).has_value() &&
      (!options.swapchain || device_extension_available(device, VK_KHR_SWAPCHAIN_EXTENSION_NAME));
  return info;
}

Result<std::vector<VkPhysicalDevice>> enumerate_devices(VkInstance instance) {
  std::uint32_t count = 0;
  if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, nullptr); r != VK_SUCCESS) {
    return vk_error("vkEnumeratePhysicalDevices", r);
  }
  std::vector<VkPhysicalDevice> devices(count);
  if (VkResult r = vkEnumeratePhysicalDevices(instance, &count, devices.data());
      r != VK_SUCCESS && r != VK_INCOMPLETE) {
    return vk_error("vkEnumeratePhysicalDevices", r);
  }
  devices.resize(count);
  return devices;
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string describe_all(const std::vector<VulkanDeviceInfo>& infos,
                         const VulkanContextOptions& options) {
  std::string needs = " + dynamic rendering";
  if (options.swapchain) needs += " + VK_KHR_swapchain";
  if (options.can_present) needs += " + presentation";
  std::string out;
  for (const VulkanDeviceInfo& info : infos) {
    if (!out.empty()) out += "; ";
    out += std::to_string(info.index) + ": " + info.name + " (" + device_type_name(info.type) +
           (info.usable ? "" : ", unusable: needs Vulkan 1.3" + needs) + ")";
  }
  return out;
}

// Index into `infos` of the device `selector` names (see the header for the rules).
Result<std::size_t> select_device(const std::vector<VulkanDeviceInfo>& infos,
                                  const VulkanContextOptions& options) {
  const std::string& selector = options.device;
  if (infos.empty()) return Error{kNoDevice, ErrorCode::environment};
  const bool by_index =
      !selector.empty() && std::all_of(selector.begin(), selector.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
      });
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < infos.size(); ++i) {
    const VulkanDeviceInfo& info = infos[i];
    bool matches = true;
    if (by_index) {
      matches = selector.size() < 10 && std::stoul(selector) == info.index;
    } else if (!selector.empty()) {
      matches = lower(info.name).find(lower(selector)) != std::string::npos;
    }
    if (!matches) continue;
    if (!info.usable) {
      if (!selector.empty()) {
        return Error{"Vulkan device " + std::to_string(info.index) + " (" + info.name + ") lacks " +
                     requirements_text(options)};
      }
      continue;
    }
    if (!best || type_rank(info.type) < type_rank(infos[*best].type)) best = i;
    if (!selector.empty()) break;
  }
  if (best) return *best;
  if (selector.empty()) {
    std::string needs = "Vulkan 1.3 with dynamic rendering";
    if (options.swapchain) needs += ", VK_KHR_swapchain";
    if (options.can_present) needs += ", a graphics queue that can present";
    return Error{"no usable Vulkan device (need " + needs + "); found " +
                 describe_all(infos, options), ErrorCode::environment};
  }
  return Error{"no Vulkan device matches \"" + selector +
               "\"; available: " + describe_all(infos, options), ErrorCode::environment};
}

Result<VkInstance> create_instance(const VulkanContextOptions& options, ValidationLog* log) {
  std::uint32_t loader_version = VK_API_VERSION_1_0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS ||
      loader_version < VK_API_VERSION_1_3) {
    return Error{"the Vulkan loader is older than 1.3 (install libvulkan1 >= 1.3)",
                 ErrorCode::environment};
  }
  VkApplicationInfo app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = options.application_name.c_str();
  app.pEngineName = "tutti";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  VkDebugUtilsMessengerCreateInfoEXT debug_info = messenger_info(log);
  VkInstanceCreateInfo info =
      vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  const VkValidationFeatureEnableEXT enabled_features[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  auto features = vk_struct<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enabled_features;
  info.pApplicationInfo = &app;
  if (options.validation) {
    if (!layer_available(kValidationLayer)) {
      return Error{std::string(kValidationLayer) +
                   " is not installed (install vulkan-validationlayers)"};
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    info.pNext = &debug_info;  // also reports on vkCreateInstance / vkDestroyInstance
    if (options.synchronization_validation) {
      extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
      features.pNext = info.pNext;
      info.pNext = &features;
    }
  }
  for (const std::string& name : options.instance_extensions) {
    if (!instance_extension_available(name)) {
      return Error{"the Vulkan instance extension " + name +
                       " is not available (a window needs the loader's surface extensions)",
                   ErrorCode::environment};
    }
    if (std::none_of(extensions.begin(), extensions.end(),
                     [&](const char* enabled) { return name == enabled; })) {
      extensions.push_back(name.c_str());
    }
  }
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) {
    return Error{kNoDevice, ErrorCode::environment};  // no ICD at all
  }
  if (r != VK_SUCCESS) return vk_error("vkCreateInstance", r);
  return instance;
}

}  // namespace

void ValidationLog::add(std::string message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::size_t ValidationLog::size() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices() {
  VulkanContextOptions options;
  ValidationLog unused;
  Result<VkInstance> instance = create_instance(options, &unused);
  if (!instance) return instance.error();
  Result<std::vector<VkPhysicalDevice>> devices = enumerate_devices(*instance);
  std::vector<VulkanDeviceInfo> infos;
  if (devices) {
    for (std::size_t i = 0; i < devices->size(); ++i) {
      infos.push_back(describe(*instance, (*devices)[i], static_cast<std::uint32_t>(i), options));
    }
  }
  vkDestroyInstance(*instance, nullptr);
  if (!devices) return devices.error();
  return infos;
}

Result<std::unique_ptr<VulkanContext>> VulkanContext::create(const VulkanContextOptions& options) {
  std::unique_ptr<VulkanContext> context(new VulkanContext());
  context->validation_ = options.validation;

  Result<VkInstance> instance = create_instance(options, context->log_.get());
  if (!instance) return instance.error();
  context->instance_ = *instance;

  if (options.validation) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(context->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create_messenger == nullptr) {
      return Error{"vkGetInstanceProcAddr: vkCreateDebugUtilsMessengerEXT not found"};
    }
    VkDebugUtilsMessengerCreateInfoEXT info = messenger_info(context->log_.get());
    if (VkResult r = create_messenger(context->instance_, &info, nullptr, &context->messenger_);
        r != VK_SUCCESS) {
      return vk_error("vkCreateDebugUtilsMessengerEXT", r);
    }
  }

  Result<std::vector<VkPhysicalDevice>> devices = enumerate_devices(context->instance_);
  if (!devices) return devices.error();
  std::vector<VulkanDeviceInfo> infos;
  for (std::size_t i = 0; i < devices->size(); ++i) {
    infos.push_back(
        describe(context->instance_, (*devices)[i], static_cast<std::uint32_t>(i), options));
  }
  Result<std::size_t> chosen = select_device(infos, options);
  if (!chosen) return chosen.error();
  context->physical_device_ = (*devices)[*chosen];
  context->device_info_ = infos[*chosen];
  context->graphics_queue_family_ =
      *graphics_family(context->instance_, context->physical_device_, options);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info =
      vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue_info.queueFamilyIndex = context->graphics_queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkPhysicalDeviceVulkan13Features features13 = vk_struct<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  features13.dynamicRendering = VK_TRUE;
  features13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features =
      vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  features.pNext = &features13;
  VkDeviceCreateInfo device_info =
      vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  device_info.pNext = &features;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  const char* const swapchain_extension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
  if (options.swapchain) {
    device_info.enabledExtensionCount = 1;
    device_info.ppEnabledExtensionNames = &swapchain_extension;
  }
  context->swapchain_ = options.swapchain;
  if (VkResult r =
          vkCreateDevice(context->physical_device_, &device_info, nullptr, &context->device_);
      r != VK_SUCCESS) {
    return vk_error("vkCreateDevice", r);
  }
  vkGetDeviceQueue(context->device_, context->graphics_queue_family_, 0, &context->graphics_queue_);

  VkCommandPoolCreateInfo pool_info =
      vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = context->graphics_queue_family_;
  if (VkResult r =
          vkCreateCommandPool(context->device_, &pool_info, nullptr, &context->command_pool_);
      r != VK_SUCCESS) {
    return vk_error("vkCreateCommandPool", r);
  }
  return context;
}

VulkanContext::~VulkanContext() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    if (command_pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, command_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy_messenger != nullptr) destroy_messenger(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

Status VulkanContext::wait_idle() const {
  return vk_check("vkDeviceWaitIdle", vkDeviceWaitIdle(device_));
}

Result<VkCommandBuffer> VulkanContext::allocate_command_buffer() const {
  VkCommandBufferAllocateInfo allocate =
      vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  allocate.commandPool = command_pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  if (VkResult r = vkAllocateCommandBuffers(device_, &allocate, &commands); r != VK_SUCCESS) {
    return vk_error("vkAllocateCommandBuffers", r);
  }
  return commands;
}

Result<DeviceHandle<VkFence>> VulkanContext::create_fence(bool signaled) const {
  VkFenceCreateInfo info = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  if (signaled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VkFence fence = VK_NULL_HANDLE;
  if (VkResult r = vkCreateFence(device_, &info, nullptr, &fence); r != VK_SUCCESS) {
    return vk_error("vkCreateFence", r);
  }
  return DeviceHandle<VkFence>(device_, fence, vkDestroyFence);
}

}  // namespace tutti::render
