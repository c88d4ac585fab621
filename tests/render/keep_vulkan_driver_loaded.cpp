// SPDX-License-Identifier: MIT
// LeakSanitizer names a leak's module only while that module is still loaded. The Vulkan loader
// unloads the driver at vkDestroyInstance, so lavapipe's small per-instance leaks would be
// reported at exit from "<unknown module>" and no suppression could match them
// (lsan_suppressions.txt). Keeping the driver and the validation layer loaded for the whole
// process lets the suppressions name them. Harmless when a library is absent.
#include <dlfcn.h>

#include <initializer_list>

namespace {

const bool kDriversKeptLoaded = [] {
  for (const char* library : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"}) {
    dlopen(library, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  }
  return true;
}();

}  // namespace
