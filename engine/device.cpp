#include "device.h"

#include <cstdlib>
#include <filesystem>

#include "cpu_device.h"
#include "core/error.h"
#include "vulkan_device.h"

namespace meshquilt::engine {

const char* backend_name(Backend backend) {
  switch (backend) {
    case Backend::cpu:
      return "cpu";
    case Backend::vulkan:
      return "vulkan";
  }
  return "unknown";
}

BackendChoice parse_backend_choice(std::string_view text) {
  if (text == "auto") return BackendChoice::automatic;
  if (text == "vulkan") return BackendChoice::vulkan;
  if (text == "cpu") return BackendChoice::cpu;
  throw OptionError("{backend}: unknown back end '" + std::string(text) + "' (expected auto, vulkan or cpu)");
}

void Device::record(const DispatchTiming& timing, std::uint32_t invocations) {
  ++stats_.dispatches;
  stats_.invocations += invocations;
  stats_.wall_seconds += timing.wall_seconds;
}

namespace {

// Whether the machine shows a GPU that a Vulkan driver could use: a DRM render node (Mesa's and
// AMD's drivers), an NVIDIA device or WSL's GPU, or a driver named by the loader's variables.
// Without one only a software device can come up, and creating an instance to find that out
// loads lavapipe and LLVM for nothing (docs/decisions/0018).
bool gpu_may_be_present() {
  if (std::getenv("VK_ICD_FILENAMES") || std::getenv("VK_DRIVER_FILES")) return true;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/dev/dri", error))
    if (entry.path().filename().string().starts_with("renderD")) return true;
  for (const char* node : {"/dev/nvidia0", "/dev/nvidiactl", "/dev/dxg"})
    if (std::filesystem::exists(node, error)) return true;
  return false;
}

}  // namespace

std::unique_ptr<Device> open_device(BackendChoice choice, std::string* note) {
  if (note) note->clear();
  if (choice == BackendChoice::cpu) return open_cpu_device();
  if (choice == BackendChoice::vulkan) return open_vulkan_device();
  // automatic: any failure to bring Vulkan up is a reason to fall back, not to stop.
  if (!gpu_may_be_present()) {
    if (note)
      *note = "no GPU device (/dev/dri/renderD*, /dev/nvidia*, /dev/dxg); using the CPU back end ({backend} vulkan "
              "forces a software Vulkan device)";
    return open_cpu_device();
  }
  try {
    std::unique_ptr<Device> vulkan = open_vulkan_device();
    if (!vulkan->software_rasterizer()) return vulkan;
    if (note)
      *note = "only a software Vulkan device (" + vulkan->name() +
              "); using the faster CPU back end ({backend} vulkan forces it)";
    return open_cpu_device();
  } catch (const DeviceError& error) {
    if (note) *note = std::string("no usable Vulkan device (") + error.what() + "); using the CPU back end";
    return open_cpu_device();
  }
}

}  // namespace meshquilt::engine
