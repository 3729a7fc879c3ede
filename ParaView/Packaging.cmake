# The plugin's Debian package, vtkofb-paraview-plugin: `cpack -G DEB` in this build tree
# (<build>/ParaView when the main project builds it). It holds the plugin folder alone
# (<prefix>/lib/<multiarch>/paraview-5.11/plugins/OFB: OFB.so and the modules compiled
# against ParaView's VTK) and depends on Debian's paraview of the version built
# against, nothing else: it installs beside the vtkofb package (Debian's VTK), with no
# file in common.
set(CPACK_PACKAGE_NAME "vtkofb-paraview-plugin")
set(CPACK_PACKAGE_VENDOR "vtkOFB")
set(CPACK_PACKAGE_CONTACT "vtkOFB maintainers <vtkofb@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Orthogonal Fragment Buffers for ParaView ${VTKOFB_PARAVIEW_VERSION}: the OFB plugin")
set(CPACK_PACKAGE_DESCRIPTION
  "The OFB plugin for ParaView ${VTKOFB_PARAVIEW_VERSION}: OFB Sampler, OFB LIC, OFB Particles,
OFB Paint Strokes, OFB Probe and the textured OBJ/glTF writer. Load it with
Tools > Manage Plugins or LoadPlugin() in pvpython and pvbatch.")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
if (EXISTS "${VTKOFB_SOURCE_DIR}/LICENSE")
  set(CPACK_RESOURCE_FILE_LICENSE "${VTKOFB_SOURCE_DIR}/LICENSE")
endif ()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
# ParaView's libraries carry its version in their names (libvtkCommonCore-pv5.11.so.1):
# the plugin works with that ParaView only.
math(EXPR vtkofb_paraview_next_minor "${ParaView_VERSION_MINOR} + 1")
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "paraview (>= ${VTKOFB_PARAVIEW_VERSION}), paraview (<< ${ParaView_VERSION_MAJOR}.${vtkofb_paraview_next_minor})")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
# The plugin's own component only (paraview_plugin_build's PLUGINS_COMPONENT and
# TARGET_COMPONENT): no headers or CMake files.
set(CPACK_INSTALL_CMAKE_PROJECTS
  "${PROJECT_BINARY_DIR};${PROJECT_NAME};paraview-plugin;/")
set(CPACK_GENERATOR "DEB")
include(CPack)
