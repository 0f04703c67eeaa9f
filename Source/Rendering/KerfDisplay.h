// The X display the process renders on, opened once and shared by its render windows.
#pragma once

#include "KerfRenderingModule.h"

#include <string>

namespace kerf
{

/// The X display named by DISPLAY (an Xlib `Display*`), opened once per process and kept open
/// for every window Kerf renders. ParaView's VTK renders through X11 only and aborts the process
/// when its own connection fails; a connection opened and checked here, then handed to each
/// window, leaves nothing to fail later. A refused connection is tried again a few times (a busy
/// X server can refuse one for a moment). A forked child opens its own. nullptr, with the reason
/// in `error`, when there is no display to open.
KERFRENDERING_EXPORT void* ProcessDisplay(std::string& error);

} // namespace kerf
