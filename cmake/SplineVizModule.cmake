# SPDX-License-Identifier: BSD-3-Clause
# splineviz_add_module(): what the module folders (Core/, Filters/, IO/,
# Rendering/) have in common around vtk_module_add_module().
#
#   splineviz_add_module(SplineViz::Xxx
#     CLASSES         public, wrapped classes (vtkXxx.h/.cxx)
#     PRIVATE_CLASSES classes not installed (plain C++ or VTK-internal)
#     PRIVATE_HEADERS header-only helpers, not installed
#     SHADERS         .glsl files embedded as C strings (vtkXxx.h/.cxx of the
#                     same base name, generated in the module's build folder)
#     GLM)            the module's code includes GLM (glm/glm.hpp)
#
# The module's folder is on its build-tree include path for the modules that
# depend on it, so that their code and the tests can include its private
# headers too (nothing private is installed).
find_path(SPLINEVIZ_GLM_INCLUDE_DIR glm/glm.hpp)

function (splineviz_add_module module)
  cmake_parse_arguments(PARSE_ARGV 1 arg "GLM" ""
    "CLASSES;PRIVATE_CLASSES;PRIVATE_HEADERS;SHADERS")
  set(private_headers ${arg_PRIVATE_HEADERS})
  set(sources)
  foreach (shader IN LISTS arg_SHADERS)
    vtk_encode_string(
      INPUT         "${shader}"
      HEADER_OUTPUT shader_header
      SOURCE_OUTPUT shader_source)
    list(APPEND private_headers "${shader_header}")
    list(APPEND sources "${shader_source}")
  endforeach ()

  vtk_module_add_module("${module}"
    CLASSES         ${arg_CLASSES}
    PRIVATE_CLASSES ${arg_PRIVATE_CLASSES}
    SOURCES         ${sources}
    PRIVATE_HEADERS ${private_headers})
  vtk_module_include("${module}"
    PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>")
  if (arg_GLM AND SPLINEVIZ_GLM_INCLUDE_DIR)
    vtk_module_include("${module}" PRIVATE "${SPLINEVIZ_GLM_INCLUDE_DIR}")
  endif ()
endfunction ()
