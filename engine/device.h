#pragma once
//! The compute engine: one interface over two back ends (Vulkan and plain C++).
//!
//! Layers (after Kompute): a Device owns the back end (for Vulkan: instance, physical device,
//! logical device, queue, command buffer, fence); a Buffer is a host-mapped storage buffer; a
//! Kernel is one compute pipeline (shader module, descriptor layout, push-constant range) made
//! from a KernelSpec; Device::dispatch records bind -> push -> dispatch -> barrier, submits it
//! behind a fence and waits. The engine knows nothing of meshes; kernels live in kernels/.
//! No Vulkan type appears in this header.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace meshquilt::engine {

//! The back end a Device runs on.
enum class Backend { cpu, vulkan };

//! What the user asked for (`--backend auto|vulkan|cpu`).
enum class BackendChoice { automatic, vulkan, cpu };

//! "cpu" or "vulkan".
const char* backend_name(Backend backend);

//! Parses "auto", "vulkan" or "cpu".
//! \throw InputError (ErrorKind::invalid_option) naming the option value otherwise.
BackendChoice parse_backend_choice(std::string_view text);

//! A storage buffer, mapped into host memory for its whole life (host-visible and coherent on
//! Vulkan, plain memory on the CPU back end). Contents are undefined after creation.
class Buffer {
 public:
  virtual ~Buffer() = default;
  //! Size in bytes as requested (may be 0).
  virtual std::size_t size() const = 0;
  //! Host pointer to the first byte; valid while the buffer lives, aligned to 16 bytes.
  virtual void* data() = 0;

  //! The buffer as an array of T (size() / sizeof(T) elements).
  template <class T>
  std::span<T> as() {
    return {static_cast<T*>(data()), size() / sizeof(T)};
  }
};

//! What the CPU back end hands a kernel's C++ twin: the bound buffers (in binding order), the
//! push-constant bytes, and the range of linear invocation indices to run.
struct CpuDispatch {
  std::span<void* const> bindings;           //!< host pointer of binding i
  std::span<const std::size_t> binding_bytes; //!< size of binding i in bytes
  std::span<const std::byte> push_constants;  //!< exactly KernelSpec::push_constant_bytes
  std::uint32_t first = 0;                    //!< first linear invocation index
  std::uint32_t count = 0;                    //!< number of invocations from `first`
};

//! The C++ twin of a compute shader: runs invocations [first, first + count). It is called
//! concurrently for disjoint ranges, so it must only write what its invocations own.
using CpuKernelFunction = void (*)(const CpuDispatch& dispatch);

//! Everything a back end needs to build one kernel. A kernel's shader must
//!  - declare `layout(local_size_x = workgroup_size) in;` (y = z = 1),
//!  - bind `binding_count` storage buffers at set 0, bindings 0 .. binding_count-1,
//!  - compute its linear invocation index as
//!    `gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x`
//!    and ignore indices past its own invocation count (the grid is rounded up to whole groups
//!    and may be two-dimensional when the group count exceeds the device's x limit).
struct KernelSpec {
  std::string_view name;                  //!< unique; pipelines are cached by it
  std::span<const std::uint32_t> spirv;   //!< SPIR-V words; empty in a build without Vulkan
  std::uint32_t binding_count = 0;        //!< storage buffers, at most 16
  std::uint32_t push_constant_bytes = 0;  //!< multiple of 4, at most 128
  std::uint32_t workgroup_size = 64;      //!< the shader's local_size_x
  CpuKernelFunction cpu = nullptr;        //!< the C++ twin (required)
};

//! A compute pipeline built by a Device from a KernelSpec; owned and cached by the Device.
class Kernel {
 public:
  virtual ~Kernel() = default;
  virtual std::string_view name() const = 0;
};

//! Time taken by one dispatch.
struct DispatchTiming {
  double wall_seconds = 0.0;    //!< host clock from recording to fence signalled
  double device_seconds = -1.0; //!< device timestamps around the dispatch; < 0 when unavailable
};

//! Running totals over a Device's life (for stats JSON and benchmarks).
struct DeviceStats {
  std::uint64_t dispatches = 0;
  std::uint64_t invocations = 0;
  double wall_seconds = 0.0;
};

//! A compute device. Not thread-safe: use one Device from one thread at a time (dispatch itself
//! may run on many threads).
class Device {
 public:
  virtual ~Device() = default;
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  virtual Backend backend() const = 0;
  //! Human-readable device name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" or "CPU (2 threads)".
  virtual std::string name() const = 0;
  //! Largest buffer that can be bound to one storage binding, in bytes (128 MiB on lavapipe).
  virtual std::size_t max_binding_bytes() const = 0;
  //! Total loop iterations one shader invocation may run before the driver silently ends its
  //! loops, or 0 when unlimited. llvmpipe (lavapipe) shares 65535 iterations between all loops
  //! of a shader, counted per SIMD vector; kernels with long searches must stay below it (a
  //! single loop whose lanes each count their own iterations is safe) or detect the cut.
  virtual std::uint32_t max_loop_iterations() const = 0;
  //! True for a Vulkan implementation that runs on the CPU (llvmpipe/lavapipe).
  virtual bool software_rasterizer() const { return false; }

  //! A new host-mapped storage buffer of `bytes` bytes.
  //! \throw DeviceError when the allocation fails or exceeds max_binding_bytes().
  virtual std::unique_ptr<Buffer> create_buffer(std::size_t bytes) = 0;

  //! The kernel built from `spec`, created on first use and cached by spec.name (registering
  //! a pipeline: a kernel calls this with its spec; later calls return the same Kernel).
  //! \throw DeviceError when the spec is invalid or pipeline creation fails.
  virtual Kernel& kernel(const KernelSpec& spec) = 0;

  //! Runs `invocations` invocations of `kernel` with `bindings` bound in order and
  //! `push_constants` (KernelSpec::push_constant_bytes long), and waits for completion. Buffer
  //! contents written by the host before the call are visible to the kernel; contents written
  //! by the kernel are visible to the host after it returns. invocations == 0 does nothing.
  //! \throw DeviceError naming the failing call (Vulkan) or a binding/size mismatch.
  virtual DispatchTiming dispatch(Kernel& kernel, std::span<Buffer* const> bindings,
                                  std::span<const std::byte> push_constants,
                                  std::uint32_t invocations) = 0;

  //! Totals of all dispatches so far.
  const DeviceStats& stats() const { return stats_; }

 protected:
  Device() = default;
  void record(const DispatchTiming& timing, std::uint32_t invocations);

 private:
  DeviceStats stats_;
};

//! Opens a device. `automatic` uses Vulkan when a usable GPU exists and otherwise returns
//! the CPU back end (also when the only Vulkan device is a software one such as lavapipe, which
//! runs the same kernels several times slower than the CPU back end, and without trying Vulkan
//! when the machine has no GPU device node and the loader's VK_ICD_FILENAMES / VK_DRIVER_FILES
//! are unset), setting *note (when non-null) to one line saying why; `vulkan` requires a
//! Vulkan device; `cpu` always succeeds. *note is cleared when there is nothing to say.
//! \throw DeviceError when `vulkan` is chosen and no Vulkan device can be opened (or the build
//! has no Vulkan back end, MESHQUILT_VULKAN=OFF).
std::unique_ptr<Device> open_device(BackendChoice choice, std::string* note = nullptr);

}  // namespace meshquilt::engine
