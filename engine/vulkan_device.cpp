#include "vulkan_device.h"

#include <dlfcn.h>
#include <link.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"

namespace meshquilt::engine {
namespace {

// The file names of the shared objects loaded into this process now.
std::set<std::string> loaded_objects() {
  std::set<std::string> names;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        if (info->dlpi_name && *info->dlpi_name) static_cast<std::set<std::string>*>(out)->insert(info->dlpi_name);
        return 0;
      },
      &names);
  return names;
}

// The loader unloads an ICD (lavapipe, and LLVM with it) when the last instance goes. Its state
// then lies in unmapped globals, so LeakSanitizer reports it as leaked on some machines, and a
// later device pays to load it again: the objects the instance brought in stay for the process.
void keep_loaded_since(const std::set<std::string>& before) {
  for (const std::string& name : loaded_objects())
    if (!before.count(name)) dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
}

const char* result_name(VkResult result) {
  switch (result) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_INCOMPLETE: return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_FRAGMENTED_POOL: return "VK_ERROR_FRAGMENTED_POOL";
    case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult error";
  }
}

//! Every Vulkan call goes through here: a failure becomes a DeviceError naming the call.
void check(VkResult result, const char* call) {
  if (result != VK_SUCCESS)
    throw DeviceError(std::string("vulkan: ") + call + " failed: " + result_name(result) + " (" +
                      std::to_string(static_cast<int>(result)) + ")");
}

// Lower is better: a discrete GPU first, lavapipe (a CPU device) last among the usable ones.
int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

class VulkanDevice;

class VulkanBuffer final : public Buffer {
 public:
  VulkanBuffer(VkDevice device, VkBuffer buffer, VkDeviceMemory memory, void* mapped, std::size_t bytes)
      : device_(device), buffer_(buffer), memory_(memory), mapped_(mapped), size_(bytes) {}
  ~VulkanBuffer() override {
    vkUnmapMemory(device_, memory_);
    vkDestroyBuffer(device_, buffer_, nullptr);
    vkFreeMemory(device_, memory_, nullptr);
  }
  std::size_t size() const override { return size_; }
  void* data() override { return mapped_; }
  VkBuffer handle() const { return buffer_; }

 private:
  VkDevice device_;
  VkBuffer buffer_;
  VkDeviceMemory memory_;
  void* mapped_;
  std::size_t size_;
};

class VulkanKernel final : public Kernel {
 public:
  explicit VulkanKernel(VkDevice device) : device_(device) {}
  ~VulkanKernel() override {
    if (pipeline) vkDestroyPipeline(device_, pipeline, nullptr);
    if (pipeline_layout) vkDestroyPipelineLayout(device_, pipeline_layout, nullptr);
    if (descriptor_pool) vkDestroyDescriptorPool(device_, descriptor_pool, nullptr);
    if (set_layout) vkDestroyDescriptorSetLayout(device_, set_layout, nullptr);
    if (module) vkDestroyShaderModule(device_, module, nullptr);
  }
  std::string_view name() const override { return name_; }

  std::string name_;
  std::uint32_t binding_count = 0;
  std::uint32_t push_constant_bytes = 0;
  std::uint32_t workgroup_size = 0;
  VkShaderModule module = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;

 private:
  VkDevice device_;
};

class VulkanDevice final : public Device {
 public:
  VulkanDevice() {
    try {
      create();
    } catch (...) {
      destroy();
      throw;
    }
  }
  ~VulkanDevice() override { destroy(); }

  Backend backend() const override { return Backend::vulkan; }
  std::string name() const override { return properties_.deviceName; }
  bool software_rasterizer() const override { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  std::size_t max_binding_bytes() const override { return properties_.limits.maxStorageBufferRange; }
  // gallivm's LP_MAX_TGSI_LOOP_ITERATIONS: one counter for every loop of a shader invocation.
  std::uint32_t max_loop_iterations() const override {
    const bool llvmpipe = properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU &&
                          std::strncmp(properties_.deviceName, "llvmpipe", 8) == 0;
    return llvmpipe ? 65535u : 0u;
  }

  std::unique_ptr<Buffer> create_buffer(std::size_t bytes) override {
    if (bytes > max_binding_bytes())
      throw DeviceError("vulkan: buffer of " + std::to_string(bytes) + " bytes exceeds the storage-buffer range (" +
                        std::to_string(max_binding_bytes()) + " bytes) of " + name());
    // Vulkan has no zero-sized buffers; keep the size the caller asked for.
    const VkDeviceSize allocated = std::max<VkDeviceSize>(16, (bytes + 15) / 16 * 16);
    VkBufferCreateInfo buffer_info{};
    buffer_info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    buffer_info.size = allocated;
    buffer_info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    buffer_info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device_, &buffer_info, nullptr, &buffer), "vkCreateBuffer");

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer, &requirements);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkResult result = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    // A small device-local, host-visible heap (a discrete GPU without resizable BAR) can run
    // out; the next memory type in order of preference is then tried.
    std::vector<std::uint32_t> types;
    try {
      types = memory_types(requirements.memoryTypeBits);
    } catch (...) {
      vkDestroyBuffer(device_, buffer, nullptr);
      throw;
    }
    for (std::uint32_t type : types) {
      VkMemoryAllocateInfo allocate_info{};
      allocate_info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
      allocate_info.allocationSize = requirements.size;
      allocate_info.memoryTypeIndex = type;
      result = vkAllocateMemory(device_, &allocate_info, nullptr, &memory);
      if (result != VK_ERROR_OUT_OF_DEVICE_MEMORY) break;
    }
    if (result != VK_SUCCESS) {
      vkDestroyBuffer(device_, buffer, nullptr);
      check(result, "vkAllocateMemory");
    }
    void* mapped = nullptr;
    result = vkBindBufferMemory(device_, buffer, memory, 0);
    if (result == VK_SUCCESS) result = vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped);
    if (result != VK_SUCCESS) {
      vkDestroyBuffer(device_, buffer, nullptr);
      vkFreeMemory(device_, memory, nullptr);
      check(result, "vkBindBufferMemory/vkMapMemory");
    }
    return std::make_unique<VulkanBuffer>(device_, buffer, memory, mapped, bytes);
  }

  Kernel& kernel(const KernelSpec& spec) override {
    const std::string key(spec.name);
    if (auto found = kernels_.find(key); found != kernels_.end()) return *found->second;
    if (spec.spirv.empty()) throw DeviceError("vulkan: kernel '" + key + "' has no SPIR-V");
    if (spec.binding_count > 16 || spec.push_constant_bytes > 128 || spec.push_constant_bytes % 4 != 0 ||
        spec.workgroup_size == 0 || spec.workgroup_size > properties_.limits.maxComputeWorkGroupSize[0])
      throw DeviceError("vulkan: kernel '" + key + "' has an invalid spec (bindings, push constants or workgroup size)");

    auto kernel = std::make_unique<VulkanKernel>(device_);
    kernel->name_ = key;
    kernel->binding_count = spec.binding_count;
    kernel->push_constant_bytes = spec.push_constant_bytes;
    kernel->workgroup_size = spec.workgroup_size;

    VkShaderModuleCreateInfo module_info{};

    module_info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    module_info.codeSize = spec.spirv.size() * sizeof(std::uint32_t);
    module_info.pCode = spec.spirv.data();
    check(vkCreateShaderModule(device_, &module_info, nullptr, &kernel->module), "vkCreateShaderModule");

    std::vector<VkDescriptorSetLayoutBinding> bindings(spec.binding_count);
    for (std::uint32_t i = 0; i < spec.binding_count; ++i) {
      bindings[i].binding = i;
      bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[i].descriptorCount = 1;
      bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo set_info{};
    set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    set_info.bindingCount = spec.binding_count;
    set_info.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device_, &set_info, nullptr, &kernel->set_layout),
          "vkCreateDescriptorSetLayout");

    // One set per kernel, reset before each dispatch: dispatches are synchronous.
    VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max<std::uint32_t>(1, spec.binding_count)};
    VkDescriptorPoolCreateInfo pool_info{};
    pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &pool_size;
    check(vkCreateDescriptorPool(device_, &pool_info, nullptr, &kernel->descriptor_pool), "vkCreateDescriptorPool");

    VkPushConstantRange push_range{VK_SHADER_STAGE_COMPUTE_BIT, 0, spec.push_constant_bytes};
    VkPipelineLayoutCreateInfo layout_info{};
    layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &kernel->set_layout;
    layout_info.pushConstantRangeCount = spec.push_constant_bytes > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &push_range;
    check(vkCreatePipelineLayout(device_, &layout_info, nullptr, &kernel->pipeline_layout), "vkCreatePipelineLayout");

    VkComputePipelineCreateInfo pipeline_info{};

    pipeline_info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipeline_info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = kernel->module;
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = kernel->pipeline_layout;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &kernel->pipeline),
          "vkCreateComputePipelines");

    Kernel& result = *kernel;
    kernels_.emplace(key, std::move(kernel));
    return result;
  }

  DispatchTiming dispatch(Kernel& kernel_base, std::span<Buffer* const> bindings,
                          std::span<const std::byte> push_constants, std::uint32_t invocations) override {
    auto& kernel = static_cast<VulkanKernel&>(kernel_base);
    if (bindings.size() != kernel.binding_count)
      throw DeviceError("vulkan: kernel '" + kernel.name_ + "' needs " + std::to_string(kernel.binding_count) +
                        " bindings, got " + std::to_string(bindings.size()));
    if (push_constants.size() != kernel.push_constant_bytes)
      throw DeviceError("vulkan: kernel '" + kernel.name_ + "' needs " + std::to_string(kernel.push_constant_bytes) +
                        " push-constant bytes, got " + std::to_string(push_constants.size()));
    DispatchTiming timing;
    if (invocations == 0) return timing;
    std::lock_guard lock(mutex_);
    const auto start = std::chrono::steady_clock::now();

    check(vkResetDescriptorPool(device_, kernel.descriptor_pool, 0), "vkResetDescriptorPool");
    VkDescriptorSetAllocateInfo set_allocate{};
    set_allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    set_allocate.descriptorPool = kernel.descriptor_pool;
    set_allocate.descriptorSetCount = 1;
    set_allocate.pSetLayouts = &kernel.set_layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(device_, &set_allocate, &set), "vkAllocateDescriptorSets");
    std::vector<VkDescriptorBufferInfo> buffer_infos(bindings.size());
    std::vector<VkWriteDescriptorSet> writes(bindings.size());
    for (std::size_t i = 0; i < bindings.size(); ++i) {
      buffer_infos[i] = {static_cast<VulkanBuffer*>(bindings[i])->handle(), 0, VK_WHOLE_SIZE};
      writes[i] = {};
      writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      writes[i].dstSet = set;
      writes[i].dstBinding = static_cast<std::uint32_t>(i);
      writes[i].descriptorCount = 1;
      writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[i].pBufferInfo = &buffer_infos[i];
    }
    vkUpdateDescriptorSets(device_, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);

    // Large grids spill into y; shaders rebuild the linear index (see KernelSpec).
    const std::uint32_t groups = (invocations + kernel.workgroup_size - 1) / kernel.workgroup_size;
    const std::uint32_t max_x = properties_.limits.maxComputeWorkGroupCount[0];
    const std::uint32_t groups_x = std::min(groups, max_x);
    const std::uint32_t groups_y = (groups + groups_x - 1) / groups_x;
    if (groups_y > properties_.limits.maxComputeWorkGroupCount[1])
      throw DeviceError("vulkan: kernel '" + kernel.name_ + "': " + std::to_string(invocations) +
                        " invocations exceed the device's workgroup-count limits");

    check(vkResetCommandBuffer(command_buffer_, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(command_buffer_, &begin), "vkBeginCommandBuffer");
    if (query_pool_) {
      vkCmdResetQueryPool(command_buffer_, query_pool_, 0, 2);
      vkCmdWriteTimestamp(command_buffer_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, query_pool_, 0);
    }
    vkCmdBindPipeline(command_buffer_, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline);
    vkCmdBindDescriptorSets(command_buffer_, VK_PIPELINE_BIND_POINT_COMPUTE, kernel.pipeline_layout, 0, 1, &set, 0,
                            nullptr);
    if (!push_constants.empty())
      vkCmdPushConstants(command_buffer_, kernel.pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                         static_cast<std::uint32_t>(push_constants.size()), push_constants.data());
    vkCmdDispatch(command_buffer_, groups_x, groups_y, 1);
    // Host writes before submit are made visible by the submit itself; the kernel's writes need
    // this barrier before the fence makes them available to the host.
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(command_buffer_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
    if (query_pool_)
      vkCmdWriteTimestamp(command_buffer_, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, query_pool_, 1);
    check(vkEndCommandBuffer(command_buffer_), "vkEndCommandBuffer");

    check(vkResetFences(device_, 1, &fence_), "vkResetFences");
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &command_buffer_;
    check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit");
    check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");

    timing.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (query_pool_) {
      std::uint64_t stamps[2] = {0, 0};
      check(vkGetQueryPoolResults(device_, query_pool_, 0, 2, sizeof(stamps), stamps, sizeof(std::uint64_t),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
      const std::uint64_t mask =
          timestamp_bits_ >= 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << timestamp_bits_) - 1);
      const std::uint64_t ticks = (stamps[1] - stamps[0]) & mask;
      timing.device_seconds = static_cast<double>(ticks) * properties_.limits.timestampPeriod * 1e-9;
    }
    record(timing, invocations);
    return timing;
  }

 private:
  void create() {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "meshquilt";
    app.pEngineName = "meshquilt";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo instance_info{};
    instance_info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    instance_info.pApplicationInfo = &app;
    const std::set<std::string> before = loaded_objects();
    check(vkCreateInstance(&instance_info, nullptr, &instance_), "vkCreateInstance");

    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    if (count > 0) check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
    keep_loaded_since(before);

    int best_rank = 1 << 30;
    for (VkPhysicalDevice candidate : devices) {
      VkPhysicalDeviceProperties properties;
      vkGetPhysicalDeviceProperties(candidate, &properties);
      if (properties.apiVersion < VK_API_VERSION_1_1) continue;
      std::uint32_t family_count = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, nullptr);
      std::vector<VkQueueFamilyProperties> families(family_count);
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, families.data());
      for (std::uint32_t f = 0; f < family_count; ++f) {
        if (!(families[f].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[f].queueCount == 0) continue;
        const int rank = type_rank(properties.deviceType);
        if (rank < best_rank) {
          best_rank = rank;
          physical_ = candidate;
          properties_ = properties;
          family_ = f;
          timestamp_bits_ = families[f].timestampValidBits;
        }
        break;
      }
    }
    if (!physical_)
      throw DeviceError("vulkan: no Vulkan 1.1 device with a compute queue among " + std::to_string(count) +
                        " device(s)");

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{};
    queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue_info.queueFamilyIndex = family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{};
    device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    check(vkCreateDevice(physical_, &device_info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, family_, 0, &queue_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_properties_);

    VkCommandPoolCreateInfo pool_info{};

    pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = family_;
    check(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo command_info{};
    command_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    command_info.commandPool = command_pool_;
    command_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    command_info.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device_, &command_info, &command_buffer_), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence_info{};
    fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(device_, &fence_info, nullptr, &fence_), "vkCreateFence");

    if (timestamp_bits_ > 0 && properties_.limits.timestampComputeAndGraphics) {
      VkQueryPoolCreateInfo query_info{};
      query_info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
      query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
      query_info.queryCount = 2;
      check(vkCreateQueryPool(device_, &query_info, nullptr, &query_pool_), "vkCreateQueryPool");
    }
  }

  void destroy() {
    kernels_.clear();
    if (device_) {
      vkDeviceWaitIdle(device_);
      if (query_pool_) vkDestroyQueryPool(device_, query_pool_, nullptr);
      if (fence_) vkDestroyFence(device_, fence_, nullptr);
      if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
      vkDestroyDevice(device_, nullptr);
      device_ = VK_NULL_HANDLE;
    }
    if (instance_) {
      vkDestroyInstance(instance_, nullptr);
      instance_ = VK_NULL_HANDLE;
    }
  }

  // Host-visible and coherent is required (buffers stay mapped, no flushes); device-local on
  // top of that is preferred (resizable BAR on discrete GPUs, everything on lavapipe).
  std::vector<std::uint32_t> memory_types(std::uint32_t allowed) const {
    const VkMemoryPropertyFlags required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    std::vector<std::uint32_t> preferred, others;
    for (std::uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
      const VkMemoryPropertyFlags flags = memory_properties_.memoryTypes[i].propertyFlags;
      if (!(allowed & (1u << i)) || (flags & required) != required) continue;
      (flags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT ? preferred : others).push_back(i);
    }
    preferred.insert(preferred.end(), others.begin(), others.end());
    if (preferred.empty())
      throw DeviceError(std::string("vulkan: no host-visible coherent memory type for storage buffers on ") +
                        properties_.deviceName);
    return preferred;
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  std::uint32_t family_ = 0;
  std::uint32_t timestamp_bits_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkQueryPool query_pool_ = VK_NULL_HANDLE;
  std::map<std::string, std::unique_ptr<VulkanKernel>, std::less<>> kernels_;
  std::mutex mutex_;
};

}  // namespace

std::unique_ptr<Device> open_vulkan_device() { return std::make_unique<VulkanDevice>(); }

}  // namespace meshquilt::engine
