// Build-time tool: writes the app's icon as a PNG of the given size, for the hicolor theme. The
// pixels are the ones the window uses (ui/view/window/app_icon.h), so the installed icons match it.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <stb_image_write.h>

#include "ui/view/window/app_icon.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: ydscope-render-icon SIZE OUT.png\n");
    return 2;
  }
  const int size = std::atoi(argv[1]);
  if (size < 16 || size > 1024) {
    std::fprintf(stderr, "ydscope-render-icon: SIZE must be from 16 to 1024, not '%s'\n", argv[1]);
    return 2;
  }
  const auto pixels = ydscope::ui::app_icon_rgba(size);
  if (!stbi_write_png(argv[2], size, size, 4, pixels.data(), size * 4)) {
    std::fprintf(stderr, "ydscope-render-icon: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}
