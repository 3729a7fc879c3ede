// Linked into every test executable that opens windows (vtkofb_mark_display_tests EXECUTABLES in
// cmake/vtkOFBTesting.cmake): keeps one connection to the X display open for the life of
// the process. An X server resets when its last client disconnects (Xvfb, as xvfb-run
// starts it, does), and a window opened while it resets cannot connect ("bad X server
// connection"): a test that closes its window and opens another, or a window opened
// just after another test's process ended, would fail now and then.
#include <X11/Xlib.h>

namespace
{
struct DisplayConnection
{
  DisplayConnection()
    : Connection(XOpenDisplay(nullptr))
  {
  }
  ~DisplayConnection()
  {
    if (this->Connection)
    {
      XCloseDisplay(this->Connection);
    }
  }
  DisplayConnection(const DisplayConnection&) = delete;
  DisplayConnection& operator=(const DisplayConnection&) = delete;
  Display* Connection;
};

// Opened before main, closed after every window of the process.
const DisplayConnection KeepDisplayOpen;
}
