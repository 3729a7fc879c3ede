"""The OFB plugin loaded into a ParaView of another version says so.

pvbatch TestOFBPluginVersion.py <OFB plugin>

Run with ofbOtherParaViewVersion preloaded (it makes the running ParaView report
another minor version): loading the plugin must print the plugin's error naming both
versions (the test's PASS_REGULAR_EXPRESSION).
"""
import sys

from paraview.simple import LoadPlugin

LoadPlugin(sys.argv[1], ns=globals())
