#pragma once
// Under AddressSanitizer only (a no-op otherwise): keeps every shared library loaded so far
// mapped until the process exits. GLFW and Mesa dlclose theirs (libGL, the DRI driver, the X11
// extension libraries) while the window system shuts down, before LeakSanitizer inspects the heap
// at exit; a leak made inside a library that is gone is reported from an "<unknown module>" that
// no suppression can name. Pinned, they keep their names, and tests/sanitizers/lsan.supp can
// suppress what is theirs by library while every leak of ours is still reported.
namespace ydscope {

// Call once, while the window and its GL context still exist.
void pin_loaded_libraries_for_leak_reports();

}  // namespace ydscope
