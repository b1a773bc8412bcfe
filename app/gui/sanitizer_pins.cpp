#include "app/gui/sanitizer_pins.h"

#if defined(__SANITIZE_ADDRESS__)
#define YDSCOPE_PIN_LIBRARIES 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define YDSCOPE_PIN_LIBRARIES 1
#endif
#endif

#ifdef YDSCOPE_PIN_LIBRARIES
#include <dlfcn.h>
#include <link.h>

#include <string>
#include <vector>
#endif

namespace ydscope {

void pin_loaded_libraries_for_leak_reports() {
#ifdef YDSCOPE_PIN_LIBRARIES
  std::vector<std::string> names;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        if (info->dlpi_name && info->dlpi_name[0])
          static_cast<std::vector<std::string>*>(out)->emplace_back(info->dlpi_name);
        return 0;
      },
      &names);
  // RTLD_NOLOAD: only what is already loaded; RTLD_NODELETE: never unmapped, whatever dlclose says.
  for (const std::string& name : names) (void)dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

}  // namespace ydscope
