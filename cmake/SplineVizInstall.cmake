# SPDX-License-Identifier: BSD-3-Clause
# Installation of the CMake package: SplineVizConfig.cmake and its version
# file, so that another project can use the installed SplineViz with
#
#   find_package(SplineViz REQUIRED)                    # all modules
#   find_package(SplineViz REQUIRED COMPONENTS IO)      # SplineViz::IO (+ Core)
#   find_package(SplineViz REQUIRED COMPONENTS ParaView) # + SplineViz::SplineVizParaView
#
# (vtk_module_build() and vtk_module_wrap_python() install the libraries,
# headers, the targets files and the Python package; paraview_plugin_build()
# the plugin and its .plugins XML). Included at the end of the top-level
# CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(splineviz_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/splineviz")

# The VTK components each installed module needs (its public VTK
# dependencies and those of the SplineViz modules it links publicly): the
# config file finds exactly those of the components asked for, in the VTK
# SplineViz was built against.
function (_splineviz_vtk_components var module)
  set(components)
  get_target_property(links "${module}" INTERFACE_LINK_LIBRARIES)
  foreach (link IN LISTS links)
    if (link MATCHES "^SplineViz::" AND TARGET "${link}")
      _splineviz_vtk_components(link_components "${link}")
      list(APPEND components ${link_components})
    # Only modules are components (not helper targets such as VTK::PythonUsed).
    elseif (link MATCHES "^VTK::([A-Za-z0-9_]+)$" AND TARGET "${link}")
      get_property(is_module TARGET "${link}"
        PROPERTY INTERFACE_vtk_module_library_name SET)
      if (is_module)
        list(APPEND components "${CMAKE_MATCH_1}")
      endif ()
    endif ()
  endforeach ()
  list(REMOVE_DUPLICATES components)
  set("${var}" "${components}" PARENT_SCOPE)
endfunction ()
set(SPLINEVIZ_CONFIG_COMPONENTS "")
foreach (splineviz_module IN LISTS splineviz_modules splineviz_paraview_modules)
  _splineviz_vtk_components(splineviz_vtk "${splineviz_module}")
  string(REPLACE "SplineViz::" "" splineviz_component "${splineviz_module}")
  if (splineviz_component STREQUAL "SplineVizParaView")
    set(splineviz_component ParaView)
  endif ()
  string(APPEND SPLINEVIZ_CONFIG_COMPONENTS
    "set(_splineviz_vtk_components_${splineviz_component} \"${splineviz_vtk}\")\n")
endforeach ()

# The find_package() calls of the modules' non-private third-party packages.
vtk_module_export_find_packages(
  CMAKE_DESTINATION "${splineviz_cmake_destination}"
  FILE_NAME         "SplineViz-vtk-module-find-packages.cmake"
  MODULES           ${splineviz_modules} ${splineviz_paraview_modules})

# Where the plugin and the Python package are, relative to the prefix.
set(SPLINEVIZ_CONFIG_PLUGIN_SUBDIR "")
if (SPLINEVIZ_HAVE_PARAVIEW)
  set(SPLINEVIZ_CONFIG_PLUGIN_SUBDIR "${CMAKE_INSTALL_LIBDIR}/${splineviz_plugin_subdir}")
endif ()
set(SPLINEVIZ_CONFIG_VTK_DIR "${VTK_DIR}")
set(SPLINEVIZ_CONFIG_PARAVIEW_DIR "${ParaView_DIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/SplineVizConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizConfig.cmake"
  INSTALL_DESTINATION "${splineviz_cmake_destination}"
  PATH_VARS         SPLINEVIZ_PYTHON_DESTINATION
  NO_CHECK_REQUIRED_COMPONENTS_MACRO)
# 0.x: a minor version may change the API.
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizConfigVersion.cmake"
  VERSION       "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
# Users of the installed package on Debian 13 meet its ParaView's export
# fault too: the config file applies the same correction.
configure_file("${CMAKE_CURRENT_LIST_DIR}/SplineVizPythonImports.cmake"
  "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizPythonImports.cmake" COPYONLY)
install(
  FILES "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizConfig.cmake"
        "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizConfigVersion.cmake"
        "${CMAKE_BINARY_DIR}/${splineviz_cmake_destination}/SplineVizPythonImports.cmake"
  DESTINATION "${splineviz_cmake_destination}"
  COMPONENT   development)
install(
  FILES       "${PROJECT_SOURCE_DIR}/LICENSE"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}"
  COMPONENT   development)
