// Put first on the include path of the modules that must not use Vulkan (compute/ocean, compute/optics,
// engine/core): any include of <vulkan/vulkan.h>, however indirect, stops their build here.
#error "this module is plain C++ and must not include Vulkan headers (docs/architecture.md, module graph)"
