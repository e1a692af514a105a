# SPDX-License-Identifier: BSD-3-Clause
# Corrects the imported Python extension modules of a ParaView/VTK CMake
# package whose export names files that are not there: Debian 13's ParaView
# 5.13 exports `vtkmodules/vtkCommonCore.so` (and the same for
# `paraview/modules/*.so`, `paraview/incubator/*.so`) while the installed
# files carry the Python ABI suffix (`vtkCommonCore.cpython-313-x86_64-linux-gnu.so`),
# so the export's own check makes find_package(ParaView) fail.
#
# For each `*Python*-targets.cmake` of the package that names such missing
# files, a corrected copy (the existing file names, the original install
# prefix) is written to the build tree and included before find_package():
# its targets are then defined, and the package's own file, finding all of
# them defined, returns without its check. Nothing outside the build tree is
# touched; packages without the fault are left alone. SplineViz itself does
# not link these modules (they are loaded by Python); only the configure-time
# check is in the way.

function (_splineviz_fix_python_imports targets_file)
  get_filename_component(dir "${targets_file}" DIRECTORY)
  get_filename_component(name "${targets_file}" NAME_WE) # e.g. VTKPython-targets
  file(READ "${targets_file}" main)
  # The install prefix as the export computes it: the file's folder, then
  # one level up per `get_filename_component(_IMPORT_PREFIX ... PATH)`.
  string(REGEX MATCHALL "get_filename_component\\(_IMPORT_PREFIX \"\\\${_IMPORT_PREFIX}\" PATH\\)"
    ups "${main}")
  set(prefix "${dir}")
  foreach (up IN LISTS ups)
    get_filename_component(prefix "${prefix}" DIRECTORY)
  endforeach ()
  file(GLOB config_files "${dir}/${name}-*.cmake")
  set(fixed_any OFF)
  set(out "${CMAKE_BINARY_DIR}/CMakeFiles/splineviz-python-imports/${name}")
  foreach (config_file IN LISTS config_files)
    file(READ "${config_file}" config)
    string(REGEX MATCHALL "\\\${_IMPORT_PREFIX}/[^\" ]+\\.so" locations "${config}")
    list(REMOVE_DUPLICATES locations)
    foreach (location IN LISTS locations)
      string(REPLACE "\${_IMPORT_PREFIX}" "${prefix}" file "${location}")
      if (EXISTS "${file}")
        continue ()
      endif ()
      string(REGEX REPLACE "\\.so$" "" stem "${file}")
      file(GLOB candidates "${stem}.*.so")
      list(LENGTH candidates n)
      if (NOT n EQUAL 1)
        return () # not the known fault: leave the package's own message
      endif ()
      string(REPLACE "${prefix}" "\${_IMPORT_PREFIX}" candidate "${candidates}")
      string(REPLACE "\"${location}\"" "\"${candidate}\"" config "${config}")
      set(fixed_any ON)
    endforeach ()
    get_filename_component(config_name "${config_file}" NAME)
    set(config_${config_name} "${config}")
    list(APPEND config_names "${config_name}")
  endforeach ()
  if (NOT fixed_any)
    return ()
  endif ()
  file(REMOVE_RECURSE "${out}")
  foreach (config_name IN LISTS config_names)
    file(WRITE "${out}/${config_name}" "${config_${config_name}}")
  endforeach ()
  # The copy computes its prefix from the original file's location.
  string(REPLACE "get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)"
    "get_filename_component(_IMPORT_PREFIX \"${targets_file}\" PATH)" main "${main}")
  file(WRITE "${out}/${name}.cmake" "${main}")
  message(STATUS "SplineViz: ${targets_file} names Python modules without their "
    "ABI suffix; using a corrected copy (${out})")
  include("${out}/${name}.cmake")
endfunction ()

# The ParaView (or VTK) packages find_package() may use (and those named in
# SPLINEVIZ_PYTHON_IMPORTS_DIRS: SplineVizConfig.cmake passes the ones
# SplineViz was built against).
set(_splineviz_package_dirs ${SPLINEVIZ_PYTHON_IMPORTS_DIRS})
foreach (_splineviz_var IN ITEMS ParaView_DIR VTK_DIR)
  if (${_splineviz_var})
    list(APPEND _splineviz_package_dirs "${${_splineviz_var}}")
  endif ()
endforeach ()
file(GLOB _splineviz_globbed
  "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-*"
  "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/vtk-*"
  "/usr/lib/cmake/paraview-*" "/usr/local/lib/cmake/paraview-*")
list(APPEND _splineviz_package_dirs ${_splineviz_globbed})
list(REMOVE_DUPLICATES _splineviz_package_dirs)
foreach (_splineviz_dir IN LISTS _splineviz_package_dirs)
  # VTK's first: ParaView's Python targets refer to VTK::vtkpythonmodules.
  file(GLOB _splineviz_vtk_targets_files "${_splineviz_dir}/vtk/*Python*-targets.cmake")
  file(GLOB _splineviz_targets_files "${_splineviz_dir}/*Python*-targets.cmake")
  list(PREPEND _splineviz_targets_files ${_splineviz_vtk_targets_files})
  foreach (_splineviz_targets_file IN LISTS _splineviz_targets_files)
    _splineviz_fix_python_imports("${_splineviz_targets_file}")
  endforeach ()
endforeach ()
unset(_splineviz_var)
unset(_splineviz_dir)
unset(_splineviz_globbed)
unset(_splineviz_package_dirs)
unset(_splineviz_targets_files)
unset(_splineviz_vtk_targets_files)
unset(_splineviz_targets_file)
