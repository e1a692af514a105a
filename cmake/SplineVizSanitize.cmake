# SPDX-License-Identifier: BSD-3-Clause
# Sanitizer and fuzzing build of SplineViz (off by default: the normal build's
# flags are not touched when both options are OFF).
#
#   SPLINEVIZ_SANITIZE=ON  AddressSanitizer (with LeakSanitizer) and
#                          UndefinedBehaviorSanitizer on everything this
#                          project compiles (the library, the Python module,
#                          the plugin, the tests). Any UB report aborts the
#                          test (-fno-sanitize-recover).
#   SPLINEVIZ_FUZZ=ON      libFuzzer targets (Testing/Fuzz); needs clang and
#                          SPLINEVIZ_SANITIZE. The library gets libFuzzer's
#                          coverage instrumentation (-fsanitize=fuzzer-no-link).
#
# scripts/test.sh --sanitize configures such a build in build-sanitize/ with
# clang (see docs/reliability.md).
option(SPLINEVIZ_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SPLINEVIZ_FUZZ "Build the libFuzzer targets (clang; implies coverage instrumentation)" OFF)

set(SPLINEVIZ_ASAN_RUNTIME "")
if (SPLINEVIZ_FUZZ AND NOT SPLINEVIZ_SANITIZE)
  message(FATAL_ERROR "SPLINEVIZ_FUZZ needs SPLINEVIZ_SANITIZE=ON")
endif ()
if (SPLINEVIZ_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "SPLINEVIZ_FUZZ needs clang (libFuzzer): configure with "
    "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
endif ()

if (SPLINEVIZ_SANITIZE)
  set(splineviz_sanitize_flags
    -fsanitize=address,undefined
    -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer)
  if (CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # Line tables are enough for symbolized stacks and keep the build small.
    list(APPEND splineviz_sanitize_flags -gline-tables-only)
  else ()
    list(APPEND splineviz_sanitize_flags -g1)
  endif ()
  add_compile_options(${splineviz_sanitize_flags})
  add_link_options(-fsanitize=address,undefined)
  if (SPLINEVIZ_FUZZ)
    add_compile_options(-fsanitize=fuzzer-no-link)
  endif ()

  # The instrumented library loaded into an uninstrumented executable
  # (pvpython, pvbatch, python3) needs the ASan runtime preloaded: the shared
  # runtime of the compiler (clang's libclang_rt.asan-<arch>.so holds the UBSan
  # handlers too; GCC's libasan.so and libubsan.so).
  if (CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    execute_process(
      COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libclang_rt.asan-${CMAKE_SYSTEM_PROCESSOR}.so
      OUTPUT_VARIABLE SPLINEVIZ_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
  else ()
    execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
      OUTPUT_VARIABLE splineviz_asan OUTPUT_STRIP_TRAILING_WHITESPACE)
    execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libubsan.so
      OUTPUT_VARIABLE splineviz_ubsan OUTPUT_STRIP_TRAILING_WHITESPACE)
    set(SPLINEVIZ_ASAN_RUNTIME "${splineviz_asan}:${splineviz_ubsan}")
  endif ()
  message(STATUS "SplineViz: sanitizer build (ASan, UBSan); runtime for Python: ${SPLINEVIZ_ASAN_RUNTIME}")

  # Options every sanitized test runs with (ctest ENVIRONMENT, see
  # Testing/CMakeLists.txt). The suppression files list only what was proven
  # to be in Mesa, VTK or Python, each with its reason.
  set(splineviz_sanitizer_dir "${PROJECT_SOURCE_DIR}/Testing/Sanitizers")
  # allocator_may_return_null: a failed huge allocation returns null as
  # without ASan (the code under test must refuse such sizes before that).
  set(SPLINEVIZ_ASAN_OPTIONS
    "strict_string_checks=1:check_initialization_order=1:allocator_may_return_null=1")
  # Mesa's DRI driver (llvmpipe: swrast_dri.so) is dlopen()ed by libGLX and
  # dlclose()d when the X display closes. What it allocated and still points
  # to from its own globals then looks leaked to LeakSanitizer, whose stacks
  # show only "<unknown module>" (the library is gone), so no suppression can
  # name it. Preloading the driver keeps it mapped to the end: its globals
  # stay roots and those blocks are reachable, as they are. Proven on
  # TestRayCastTubeBadInput: 240 bytes "leaked" in 3 blocks from the unloaded
  # module without the preload, none with it; SplineViz's own allocations are
  # still checked (their stacks are SplineViz's).
  find_file(SPLINEVIZ_DRI_DRIVER swrast_dri.so
    PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri" /usr/lib64/dri /usr/lib/dri
    NO_DEFAULT_PATH)
  set(SPLINEVIZ_CXX_TEST_PRELOAD "")
  if (SPLINEVIZ_DRI_DRIVER)
    set(SPLINEVIZ_CXX_TEST_PRELOAD "LD_PRELOAD=${SPLINEVIZ_DRI_DRIVER}")
  endif ()
  set(SPLINEVIZ_SANITIZER_ENV
    "LSAN_OPTIONS=suppressions=${splineviz_sanitizer_dir}/lsan.supp:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=${splineviz_sanitizer_dir}/ubsan.supp")
endif ()

# Called at the end of each test folder's CMakeLists.txt (set_property(TEST)
# reaches only the tests of the current folder): in the sanitizer build every
# test gets the sanitizers' options and suppression files and three times its
# time-out (sanitized code, and llvmpipe under the ASan allocator, are
# slower); PRELOAD: the test runs an uninstrumented program (pvpython,
# pvbatch, a shell script) that loads the instrumented library, so the ASan
# runtime is preloaded. No effect in the normal build.
function (splineviz_sanitize_tests)
  cmake_parse_arguments(PARSE_ARGV 0 arg "PRELOAD" "" "")
  if (NOT SPLINEVIZ_SANITIZE)
    return ()
  endif ()
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach (test IN LISTS tests)
    set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT ${SPLINEVIZ_SANITIZER_ENV})
    if (arg_PRELOAD)
      # Leak checking needs the whole process to be ours: in pvpython and
      # pvbatch every allocation's stack runs through the uninstrumented
      # interpreter and ParaView, so a suppression of those would hide
      # SplineViz's leaks too. The C++ tests and the fuzz targets (processes
      # of our own) do the leak checking; here ASan and UBSan check memory
      # errors and undefined behaviour.
      set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT
        "LD_PRELOAD=${SPLINEVIZ_ASAN_RUNTIME}"
        "ASAN_OPTIONS=detect_leaks=0:${SPLINEVIZ_ASAN_OPTIONS}")
    else ()
      set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT
        "ASAN_OPTIONS=detect_leaks=1:${SPLINEVIZ_ASAN_OPTIONS}" ${SPLINEVIZ_CXX_TEST_PRELOAD})
    endif ()
    get_property(timeout TEST "${test}" PROPERTY TIMEOUT)
    if (timeout)
      math(EXPR timeout "${timeout} * 3")
      set_property(TEST "${test}" PROPERTY TIMEOUT "${timeout}")
    endif ()
  endforeach ()
endfunction ()
