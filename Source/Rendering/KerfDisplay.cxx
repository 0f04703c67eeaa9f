#include "KerfDisplay.h"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace kerf
{

void* ProcessDisplay(std::string& error)
{
  static std::mutex mutex;
  static void* display = nullptr;
  static pid_t owner = 0;
  std::lock_guard<std::mutex> lock(mutex);
  if (display && owner == getpid())
  {
    return display;
  }
  // A connection inherited through fork() belongs to the parent: never used, never closed here.
  display = nullptr;
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    error = "DISPLAY is not set";
    return nullptr;
  }
  // Xlib is loaded at run time (already mapped by VTK's rendering), so Kerf does not link it.
  void* xlib = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL);
  using Open = void* (*)(const char*);
  auto open = xlib ? reinterpret_cast<Open>(dlsym(xlib, "XOpenDisplay")) : nullptr;
  if (!open)
  {
    error = "libX11.so.6 cannot be loaded";
    return nullptr;
  }
  for (int attempt = 0; attempt < 4 && !display; ++attempt)
  {
    if (attempt > 0)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(50 << attempt));
    }
    display = open(name);
  }
  if (!display)
  {
    error = "DISPLAY=" + std::string(name) + " cannot be opened";
    return nullptr;
  }
  owner = getpid();
  return display;
}

} // namespace kerf
