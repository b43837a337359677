# Finds MUMPS's C interface in double and single precision (dmumps_c.h,
# libdmumps, libsmumps, libmumps_common) and defines the imported target
# MUMPS::MUMPS. Looks in MUMPS_DIR (CMake or environment variable) first,
# then in the system's places (Debian: libmumps-dev).
find_path(MUMPS_INCLUDE_DIR dmumps_c.h
  HINTS ${MUMPS_DIR} $ENV{MUMPS_DIR} PATH_SUFFIXES include include/mumps)
foreach(_name dmumps smumps mumps_common)
  string(TOUPPER ${_name} _upper)
  find_library(MUMPS_${_upper}_LIBRARY ${_name}
    HINTS ${MUMPS_DIR} $ENV{MUMPS_DIR} PATH_SUFFIXES lib lib64)
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS
  REQUIRED_VARS MUMPS_INCLUDE_DIR MUMPS_DMUMPS_LIBRARY MUMPS_SMUMPS_LIBRARY
    MUMPS_MUMPS_COMMON_LIBRARY
  REASON_FAILURE_MESSAGE
    "MUMPS's C interface is needed (dmumps_c.h and libdmumps, libsmumps, libmumps_common): on Debian install libmumps-dev (scripts/install-deps.sh), elsewhere pass -DMUMPS_DIR=<its prefix>")

if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS INTERFACE IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES
      "${MUMPS_DMUMPS_LIBRARY};${MUMPS_SMUMPS_LIBRARY};${MUMPS_MUMPS_COMMON_LIBRARY}")
endif()
