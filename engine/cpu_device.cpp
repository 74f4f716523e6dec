#include "cpu_device.h"

#include <sys/mman.h>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <map>
#include <new>
#include <vector>

#include "core/error.h"

namespace meshquilt::engine {
namespace {

class CpuBuffer final : public Buffer {
 public:
  explicit CpuBuffer(std::size_t bytes) : size_(bytes) {
    // A large buffer is written whole as soon as it exists (an upload): its pages are mapped in
    // one call rather than one fault each, which is dear on a virtual machine.
    if (bytes >= kMappedBytes) {
      void* mapped = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
      if (mapped != MAP_FAILED) {
        data_ = mapped;
        mapped_ = true;
        return;
      }
    }
    // Round up so aligned_alloc accepts the size and a zero-byte buffer still has a pointer.
    const std::size_t rounded = std::max<std::size_t>(16, (bytes + 15) / 16 * 16);
    data_ = std::aligned_alloc(16, rounded);
    if (!data_) throw DeviceError("cpu back end: cannot allocate a buffer of " + std::to_string(bytes) + " bytes");
  }
  ~CpuBuffer() override {
    if (mapped_) ::munmap(data_, size_);
    else std::free(data_);
  }
  std::size_t size() const override { return size_; }
  void* data() override { return data_; }

 private:
  static constexpr std::size_t kMappedBytes = std::size_t{1} << 20;
  std::size_t size_;
  void* data_ = nullptr;
  bool mapped_ = false;
};

class CpuKernel final : public Kernel {
 public:
  explicit CpuKernel(const KernelSpec& spec)
      : name_(spec.name),
        binding_count_(spec.binding_count),
        push_constant_bytes_(spec.push_constant_bytes),
        workgroup_size_(spec.workgroup_size),
        function_(spec.cpu) {}
  std::string_view name() const override { return name_; }

  std::string name_;
  std::uint32_t binding_count_;
  std::uint32_t push_constant_bytes_;
  std::uint32_t workgroup_size_;
  CpuKernelFunction function_;
};

class CpuDevice final : public Device {
 public:
  Backend backend() const override { return Backend::cpu; }
  std::string name() const override {
    return "CPU (" + std::to_string(tbb::info::default_concurrency()) + " threads)";
  }
  // Bindings are plain pointers here; the limit only keeps 32-bit indexing in kernels valid.
  std::size_t max_binding_bytes() const override { return std::size_t{1} << 31; }
  std::uint32_t max_loop_iterations() const override { return 0; }

  std::unique_ptr<Buffer> create_buffer(std::size_t bytes) override {
    if (bytes > max_binding_bytes())
      throw DeviceError("cpu back end: buffer of " + std::to_string(bytes) + " bytes exceeds the binding limit");
    return std::make_unique<CpuBuffer>(bytes);
  }

  Kernel& kernel(const KernelSpec& spec) override {
    const std::string key(spec.name);
    if (auto found = kernels_.find(key); found != kernels_.end()) return *found->second;
    if (!spec.cpu) throw DeviceError("cpu back end: kernel '" + key + "' has no C++ twin");
    if (spec.workgroup_size == 0) throw DeviceError("cpu back end: kernel '" + key + "' has workgroup size 0");
    auto created = std::make_unique<CpuKernel>(spec);
    Kernel& result = *created;
    kernels_.emplace(key, std::move(created));
    return result;
  }

  DispatchTiming dispatch(Kernel& kernel, std::span<Buffer* const> bindings,
                          std::span<const std::byte> push_constants, std::uint32_t invocations) override {
    auto& cpu_kernel = static_cast<CpuKernel&>(kernel);
    if (bindings.size() != cpu_kernel.binding_count_)
      throw DeviceError("cpu back end: kernel '" + cpu_kernel.name_ + "' needs " +
                        std::to_string(cpu_kernel.binding_count_) + " bindings, got " +
                        std::to_string(bindings.size()));
    if (push_constants.size() != cpu_kernel.push_constant_bytes_)
      throw DeviceError("cpu back end: kernel '" + cpu_kernel.name_ + "' needs " +
                        std::to_string(cpu_kernel.push_constant_bytes_) + " push-constant bytes, got " +
                        std::to_string(push_constants.size()));
    DispatchTiming timing;
    if (invocations == 0) return timing;
    const auto start = std::chrono::steady_clock::now();

    std::vector<void*> pointers(bindings.size());
    std::vector<std::size_t> sizes(bindings.size());
    for (std::size_t i = 0; i < bindings.size(); ++i) {
      pointers[i] = bindings[i]->data();
      sizes[i] = bindings[i]->size();
    }
    // Chunks of whole workgroups, like the device; a few per thread balance uneven work
    // (ring searches stop at different radii) without paying much per-task overhead.
    const std::uint32_t group = cpu_kernel.workgroup_size_;
    const std::uint32_t groups = (invocations + group - 1) / group;
    const std::uint32_t chunk_groups =
        std::max<std::uint32_t>(1, groups / (8 * static_cast<std::uint32_t>(tbb::info::default_concurrency())));
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, groups, chunk_groups),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
                        CpuDispatch call;
                        call.bindings = pointers;
                        call.binding_bytes = sizes;
                        call.push_constants = push_constants;
                        call.first = range.begin() * group;
                        const std::uint64_t end = std::min<std::uint64_t>(
                            std::uint64_t{range.end()} * group, invocations);
                        call.count = static_cast<std::uint32_t>(end - call.first);
                        cpu_kernel.function_(call);
                      });

    timing.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    record(timing, invocations);
    return timing;
  }

 private:
  std::map<std::string, std::unique_ptr<CpuKernel>, std::less<>> kernels_;
};

}  // namespace

std::unique_ptr<Device> open_cpu_device() { return std::make_unique<CpuDevice>(); }

}  // namespace meshquilt::engine
