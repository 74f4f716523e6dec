#pragma once
//! The Vulkan back end. Its implementation is the only place that includes vulkan.h.

#include <memory>

#include "device.h"

namespace meshquilt::engine {

//! Opens the best Vulkan 1.1+ device with a compute queue: a discrete GPU first, then an
//! integrated GPU, a virtual GPU, and finally a CPU implementation such as lavapipe.
//! \throw DeviceError when there is no loader, no driver or no suitable device, or when device
//! creation fails (the message names the failing call), and always in a build without Vulkan.
std::unique_ptr<Device> open_vulkan_device();

}  // namespace meshquilt::engine
