// Built instead of vulkan_device.cpp when MESHQUILT_VULKAN=OFF.
#include "core/error.h"
#include "vulkan_device.h"

namespace meshquilt::engine {

std::unique_ptr<Device> open_vulkan_device() {
  throw DeviceError("vulkan: this build has no Vulkan back end (configured with MESHQUILT_VULKAN=OFF)");
}

}  // namespace meshquilt::engine
