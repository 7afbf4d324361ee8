// A VkBuffer with its own memory. Upload and Readback buffers stay mapped for their whole life.
#pragma once
#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>

#include "vk/handle.h"

namespace lagoon::vk {

class Context;

enum class MemoryUsage {
  Device,    // GPU only: fastest for the GPU; filled through a staging copy (upload.h)
  Upload,    // host-visible, coherent: CPU writes, GPU reads (uniforms, staging)
  Readback,  // host-visible, cached where possible: GPU writes, CPU reads
};

// The usage of device buffers that shaders read and write and copies fill (uploads, clears).
inline constexpr VkBufferUsageFlags kStorageUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

class Buffer {
 public:
  Buffer() = default;
  static Buffer create(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
                       const char* debug_name = nullptr);

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  bool host_visible() const { return mapped_ != nullptr; }
  // Mapped bytes; null for Device memory that is not host-visible.
  std::byte* mapped() const { return static_cast<std::byte*>(mapped_); }
  template <typename T>
  std::span<T> mapped_as() const {
    return {reinterpret_cast<T*>(mapped_), static_cast<size_t>(size_ / sizeof(T))};
  }
  // Makes GPU writes visible to the CPU for non-coherent memory (no-op when coherent).
  void invalidate() const;
  // Makes CPU writes visible to the GPU for non-coherent memory (no-op when coherent).
  void flush() const;

 private:
  Unique<VkBuffer> buffer_;
  Unique<VkDeviceMemory> memory_;
  void* mapped_ = nullptr;
  VkDeviceSize size_ = 0;
  bool coherent_ = true;
};

}  // namespace lagoon::vk
