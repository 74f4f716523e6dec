#pragma once
// One back-end fixture for the parity tests: a test body written once runs on each back end
// (Name/cpu, Name/vulkan). Where no Vulkan device exists the Vulkan runs are skipped, except
// with CI=true, where a missing device fails: CI runs them on lavapipe.

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "core/error.h"
#include "device.h"

namespace meshquilt::test {

inline bool ci() {
  const char* value = std::getenv("CI");
  return value && std::string(value) == "true";
}

// The device of `backend`, or nullptr with the reason in *why.
inline std::unique_ptr<engine::Device> open_backend(engine::Backend backend, std::string* why) {
  try {
    return engine::open_device(backend == engine::Backend::cpu ? engine::BackendChoice::cpu
                                                               : engine::BackendChoice::vulkan);
  } catch (const DeviceError& error) {
    *why = error.what();
    return nullptr;
  }
}

// Skips the running test (fails it under CI=true) when `device` could not be opened.
#define MESHQUILT_REQUIRE_DEVICE(device, why)                                     \
  do {                                                                            \
    if (!(device)) {                                                              \
      if (::meshquilt::test::ci()) FAIL() << "CI=true and no Vulkan device: " << (why); \
      GTEST_SKIP() << "no Vulkan device: " << (why);                              \
    }                                                                             \
  } while (false)

// The fixture: device() is the parameter's back end. Devices are opened once per suite and back
// end (lavapipe compiles a pipeline on its first dispatch, which would otherwise dominate every
// test); shared_device() opens another back end for the suite's plain tests.
class BackendTest : public ::testing::TestWithParam<engine::Backend> {
 protected:
  static void TearDownTestSuite() { devices().clear(); }

  static engine::Device* shared_device(engine::Backend backend, std::string* why) {
    std::unique_ptr<engine::Device>& device = devices()[backend];
    if (!device) device = open_backend(backend, why);
    return device.get();
  }

  void SetUp() override {
    if (!::testing::UnitTest::GetInstance()->current_test_info()->value_param()) return;
    std::string why;
    device_ = shared_device(GetParam(), &why);
    MESHQUILT_REQUIRE_DEVICE(device_, why);
  }

  engine::Device& device() const { return *device_; }

 private:
  static std::map<engine::Backend, std::unique_ptr<engine::Device>>& devices() {
    static std::map<engine::Backend, std::unique_ptr<engine::Device>> opened;
    return opened;
  }

  engine::Device* device_ = nullptr;
};

inline std::string backend_test_name(const ::testing::TestParamInfo<engine::Backend>& info) {
  return engine::backend_name(info.param);
}

}  // namespace meshquilt::test

// Runs every TEST_P of `suite` (a BackendTest) on both back ends.
#define MESHQUILT_ON_BACKENDS(suite)                                                                         \
  INSTANTIATE_TEST_SUITE_P(Backends, suite,                                                                  \
                           ::testing::Values(::meshquilt::engine::Backend::cpu, ::meshquilt::engine::Backend::vulkan), \
                           ::meshquilt::test::backend_test_name)
