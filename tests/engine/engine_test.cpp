// The engine on both back ends: device selection, buffers, kernel registration and dispatch
// (checked through the probe kernel against its formula computed here).
#include <dirent.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "device.h"
#include "core/error.h"
#include "probe.h"
#include "probe_layout.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

using engine::Backend;
using engine::BackendChoice;

class EngineTest : public test::BackendTest {
 protected:
  // A fresh device per test: some tests read its counters from zero.
  void SetUp() override {
    std::string why;
    device_ = test::open_backend(GetParam(), &why);
    MESHQUILT_REQUIRE_DEVICE(device_, why);
  }

  std::vector<std::uint32_t> run_probe(std::uint32_t invocations, std::uint32_t input_count, std::uint32_t multiplier,
                                       std::size_t output_slack = 0) {
    auto input = device_->create_buffer(input_count * sizeof(std::uint32_t));
    for (std::uint32_t i = 0; i < input_count; ++i) input->as<std::uint32_t>()[i] = 1000003u * i + 7u;
    auto output = device_->create_buffer((invocations + output_slack) * sizeof(std::uint32_t));
    std::memset(output->data(), 0xAB, output->size());
    kernels::probe_layout::ProbeParams params{invocations, input_count, multiplier, 0};
    engine::Buffer* bindings[] = {input.get(), output.get()};
    engine::Kernel& kernel = device_->kernel(probe_kernel());
    const engine::DispatchTiming timing =
        device_->dispatch(kernel, bindings, std::as_bytes(std::span(&params, 1)), invocations);
    if (invocations > 0) {
      EXPECT_GT(timing.wall_seconds, 0.0);
    }
    auto values = output->as<std::uint32_t>();
    return {values.begin(), values.end()};
  }

  std::unique_ptr<engine::Device> device_;
};

TEST(Engine, ParsesBackendChoices) {
  EXPECT_EQ(engine::parse_backend_choice("auto"), BackendChoice::automatic);
  EXPECT_EQ(engine::parse_backend_choice("vulkan"), BackendChoice::vulkan);
  EXPECT_EQ(engine::parse_backend_choice("cpu"), BackendChoice::cpu);
  try {
    engine::parse_backend_choice("cuda");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.kind(), ErrorKind::invalid_option);
    EXPECT_NE(std::string(error.what()).find("cuda"), std::string::npos);
  }
  EXPECT_STREQ(engine::backend_name(Backend::cpu), "cpu");
  EXPECT_STREQ(engine::backend_name(Backend::vulkan), "vulkan");
}

TEST(Engine, CpuAlwaysOpens) {
  std::string note = "stale";
  auto device = engine::open_device(BackendChoice::cpu, &note);
  ASSERT_TRUE(device);
  EXPECT_EQ(device->backend(), Backend::cpu);
  EXPECT_FALSE(device->name().empty());
  EXPECT_TRUE(note.empty());
}

TEST(Engine, AutomaticPrefersAGpuAndOtherwiseSaysWhy) {
  std::string why;
  const auto vulkan = test::open_backend(Backend::vulkan, &why);
  const bool has_gpu = vulkan != nullptr && !vulkan->software_rasterizer();
  std::string note;
  auto device = engine::open_device(BackendChoice::automatic, &note);
  ASSERT_TRUE(device);
  if (has_gpu) {
    EXPECT_EQ(device->backend(), Backend::vulkan);
    EXPECT_TRUE(note.empty()) << note;
  } else {
    EXPECT_EQ(device->backend(), Backend::cpu);
    EXPECT_NE(note.find("CPU back end"), std::string::npos) << note;
    EXPECT_EQ(note.find('\n'), std::string::npos) << "the note is one line";
  }
}

// Without a GPU device node and with the loader's variables unset, `automatic` does not try
// Vulkan (an instance costs about 70 ms to say there is only lavapipe) and says why; with one,
// it tries.
TEST(Engine, AutomaticSkipsVulkanWithoutAGpuDeviceNode) {
  const char* saved_icd = std::getenv("VK_ICD_FILENAMES");
  const char* saved_driver = std::getenv("VK_DRIVER_FILES");
  const std::string icd = saved_icd ? saved_icd : "", driver = saved_driver ? saved_driver : "";
  unsetenv("VK_ICD_FILENAMES");
  unsetenv("VK_DRIVER_FILES");
  bool node = false;
  for (const char* path : {"/dev/nvidia0", "/dev/nvidiactl", "/dev/dxg"}) node = node || access(path, F_OK) == 0;
  if (DIR* dri = opendir("/dev/dri")) {
    while (const dirent* entry = readdir(dri)) node = node || std::string(entry->d_name).rfind("renderD", 0) == 0;
    closedir(dri);
  }
  std::string note;
  auto device = engine::open_device(BackendChoice::automatic, &note);
  ASSERT_TRUE(device);
  if (node) {
    EXPECT_EQ(note.find("no GPU device"), std::string::npos) << note;
  } else {
    EXPECT_EQ(device->backend(), Backend::cpu);
    EXPECT_NE(note.find("no GPU device"), std::string::npos) << note;
    EXPECT_EQ(note.find('\n'), std::string::npos) << "the note is one line";
  }
  if (saved_icd) setenv("VK_ICD_FILENAMES", icd.c_str(), 1);
  if (saved_driver) setenv("VK_DRIVER_FILES", driver.c_str(), 1);
}

#if MESHQUILT_HAS_VULKAN
// With the loader pointed at a driver manifest that does not exist, there is no device:
// `vulkan` must throw and `automatic` must fall back with a note.
TEST(Engine, MissingVulkanDriverFallsBackToCpu) {
  const char* saved_icd = std::getenv("VK_ICD_FILENAMES");
  const char* saved_driver = std::getenv("VK_DRIVER_FILES");
  const std::string icd = saved_icd ? saved_icd : "", driver = saved_driver ? saved_driver : "";
  setenv("VK_ICD_FILENAMES", "/nonexistent/meshquilt_no_driver.json", 1);
  setenv("VK_DRIVER_FILES", "/nonexistent/meshquilt_no_driver.json", 1);
  EXPECT_THROW(engine::open_device(BackendChoice::vulkan), DeviceError);
  std::string note;
  auto device = engine::open_device(BackendChoice::automatic, &note);
  EXPECT_EQ(device->backend(), Backend::cpu);
  EXPECT_NE(note.find("using the CPU back end"), std::string::npos) << note;
  if (saved_icd) setenv("VK_ICD_FILENAMES", icd.c_str(), 1); else unsetenv("VK_ICD_FILENAMES");
  if (saved_driver) setenv("VK_DRIVER_FILES", driver.c_str(), 1); else unsetenv("VK_DRIVER_FILES");
}
#else
TEST(Engine, VulkanThrowsWithoutVulkanBuild) {
  EXPECT_THROW(engine::open_device(BackendChoice::vulkan), DeviceError);
  std::string note;
  EXPECT_EQ(engine::open_device(BackendChoice::automatic, &note)->backend(), Backend::cpu);
  EXPECT_FALSE(note.empty());
}
#endif

TEST_P(EngineTest, ReportsItself) {
  EXPECT_EQ(device_->backend(), GetParam());
  EXPECT_FALSE(device_->name().empty());
  EXPECT_GE(device_->max_binding_bytes(), std::size_t{1} << 20);
}

TEST_P(EngineTest, BuffersHoldWhatIsWritten) {
  auto buffer = device_->create_buffer(1001);
  EXPECT_EQ(buffer->size(), 1001u);
  ASSERT_NE(buffer->data(), nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer->data()) % 16, 0u);
  auto bytes = buffer->as<unsigned char>();
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 7);
  for (std::size_t i = 0; i < bytes.size(); ++i) ASSERT_EQ(bytes[i], static_cast<unsigned char>(i * 7));
  auto empty = device_->create_buffer(0);
  EXPECT_EQ(empty->size(), 0u);
  EXPECT_NE(empty->data(), nullptr);
  EXPECT_THROW(device_->create_buffer(device_->max_binding_bytes() + 1), DeviceError);
}

TEST_P(EngineTest, ProbeMatchesItsFormulaAndStaysInBounds) {
  // 1000 is not a multiple of the workgroup: the tail group must not write past the count.
  const std::uint32_t n = 1000, inputs = 13, multiplier = 2654435761u;
  const std::vector<std::uint32_t> out = run_probe(n, inputs, multiplier, 40);
  for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(out[i], i * multiplier + (1000003u * (i % inputs) + 7u)) << i;
  for (std::uint32_t i = n; i < out.size(); ++i) ASSERT_EQ(out[i], 0xABABABABu) << i;
}

TEST_P(EngineTest, LargeDispatchSpillsIntoSecondGridDimension) {
  // More groups than the common x limit of 65535 (workgroup 32): the grid becomes 2D.
  const std::uint32_t n = 65535u * PROBE_WORKGROUP_SIZE + 12345u;
  const std::vector<std::uint32_t> out = run_probe(n, 1, 3);
  for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(out[i], i * 3u + 7u) << i;
}

TEST_P(EngineTest, KernelsAreCachedAndCheckTheirArguments) {
  engine::Kernel& first = device_->kernel(probe_kernel());
  engine::Kernel& second = device_->kernel(probe_kernel());
  EXPECT_EQ(&first, &second);
  EXPECT_EQ(first.name(), "probe");
  auto buffer = device_->create_buffer(64);
  kernels::probe_layout::ProbeParams params{1, 1, 1, 0};
  engine::Buffer* one[] = {buffer.get()};
  EXPECT_THROW(device_->dispatch(first, one, std::as_bytes(std::span(&params, 1)), 1), DeviceError);
  engine::Buffer* two[] = {buffer.get(), buffer.get()};
  const std::uint32_t short_push = 1;
  EXPECT_THROW(device_->dispatch(first, two, std::as_bytes(std::span(&short_push, 1)), 1), DeviceError);
  engine::KernelSpec broken = probe_kernel();
  broken.name = "probe_without_code";
  broken.cpu = nullptr;
  broken.spirv = {};
  EXPECT_THROW(device_->kernel(broken), DeviceError);
}

TEST_P(EngineTest, ZeroInvocationsDoNothingAndStatsCount) {
  const std::uint64_t before = device_->stats().dispatches;
  const std::vector<std::uint32_t> out = run_probe(0, 1, 1, 8);
  for (std::uint32_t value : out) EXPECT_EQ(value, 0xABABABABu);
  EXPECT_EQ(device_->stats().dispatches, before);
  run_probe(100, 1, 1);
  EXPECT_EQ(device_->stats().dispatches, before + 1);
  EXPECT_EQ(device_->stats().invocations, 100u);
}

MESHQUILT_ON_BACKENDS(EngineTest);

}  // namespace
}  // namespace meshquilt
