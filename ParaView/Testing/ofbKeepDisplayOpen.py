"""Runs a pvbatch script with one connection to the X display open for the whole run, so
that the server does not reset between two windows (docs/testing.md, "Tests that open
windows"): ofbKeepDisplayOpen.py SCRIPT [ARGS...]."""
import runpy
import sys

import ofbParaViewTesting

ofbParaViewTesting.keep_display_open()
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
