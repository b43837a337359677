# Finds MUMPS's C interface in double and single precision (dmumps_c.h,
# libdmumps, libsmumps, libmumps_common) and defines the imported target
# MUMPS::MUMPS. Looks in MUMPS_DIR (CMake or environment variable) first,
# then in the system's places. The build of MUMPS with PT-Scotch (Debian:
# libmumps-ptscotch-dev, libraries *_ptscotch) is preferred: its parallel
# analysis serves `Ordering = pt-scotch`; with a MUMPS without it
# (libmumps-dev) that ordering stops with MUMPS's error. The variant found
# is MUMPS_VARIANT (ptscotch or plain).
find_path(MUMPS_INCLUDE_DIR dmumps_c.h
  HINTS ${MUMPS_DIR} $ENV{MUMPS_DIR} PATH_SUFFIXES include include/mumps)
set(MUMPS_VARIANT ptscotch)
foreach(_name dmumps smumps mumps_common)
  string(TOUPPER ${_name} _upper)
  find_library(MUMPS_${_upper}_LIBRARY NAMES ${_name}_ptscotch ${_name}
    HINTS ${MUMPS_DIR} $ENV{MUMPS_DIR} PATH_SUFFIXES lib lib64)
  if(NOT MUMPS_${_upper}_LIBRARY MATCHES "_ptscotch")
    set(MUMPS_VARIANT plain)
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS
  REQUIRED_VARS MUMPS_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY MUMPS_SMUMPS_LIBRARY
    MUMPS_MUMPS_COMMON_LIBRARY
  REASON_FAILURE_MESSAGE
    "MUMPS's C interface is needed (dmumps_c.h and libdmumps, libsmumps, libmumps_common): on Debian install libmumps-ptscotch-dev or libmumps-dev (scripts/install-deps.sh), elsewhere pass -DMUMPS_DIR=<its prefix>")

if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  message(STATUS "MUMPS: ${MUMPS_VARIANT} (${MUMPS_DMUMPS_LIBRARY})")
  add_library(MUMPS::MUMPS INTERFACE IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES
      "${MUMPS_DMUMPS_LIBRARY};${MUMPS_SMUMPS_LIBRARY};${MUMPS_MUMPS_COMMON_LIBRARY}")
endif()
