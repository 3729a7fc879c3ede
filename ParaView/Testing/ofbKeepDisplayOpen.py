"""Runs a pvbatch script with one connection to the X display open for the whole run, so
that the server does not reset between two windows (docs/testing.md, "Tests that open
windows"): ofbKeepDisplayOpen.py SCRIPT [ARGS...]."""
import ctypes
import ctypes.util
import runpy
import sys

try:
    _xlib = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    _xlib.XOpenDisplay.restype = ctypes.c_void_p
    _display = _xlib.XOpenDisplay(None)
except OSError:
    _display = None

sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
