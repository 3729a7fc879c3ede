"""A client that connects to a pvserver and then never ends, for the test of
TestOFBClients.py's cleanup (OFBPlugin.Clients.Stop): called as ofbClientPipeline.py is,

    pvpython ofbHangingClient.py PLUGIN OUTPUT_DIR --url cs://localhost:PORT

it connects, loads the plugin on both sides, prints that it hangs, and sleeps."""
import sys
import time

from paraview.simple import Connect, LoadPlugin

plugin, url = sys.argv[1], sys.argv[sys.argv.index("--url") + 1]
host, port = url.split("://", 1)[-1].rsplit(":", 1)
if Connect(host, int(port), timeout=30) is None:
    raise RuntimeError("no connection to the server at %s" % url)
LoadPlugin(plugin, remote=True)
LoadPlugin(plugin, remote=False)
print("ofbHangingClient: connected to %s, hanging" % url, flush=True)
while True:
    time.sleep(60)
