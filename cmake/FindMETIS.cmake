# Finds METIS (metis.h, libmetis) and defines the imported target
# METIS::METIS. Looks in METIS_DIR (CMake or environment variable) first,
# then in the system's places (Debian:
# libmetis-dev).
find_path(METIS_INCLUDE_DIR metis.h
  HINTS ${METIS_DIR} $ENV{METIS_DIR} PATH_SUFFIXES include)
find_library(METIS_LIBRARY metis
  HINTS ${METIS_DIR} $ENV{METIS_DIR} PATH_SUFFIXES lib lib64)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METIS
  REQUIRED_VARS METIS_INCLUDE_DIR METIS_LIBRARY
  REASON_FAILURE_MESSAGE
    "METIS (metis.h and libmetis) is needed for the MUMPS ordering: on Debian install libmetis-dev (scripts/install-deps.sh), elsewhere pass -DMETIS_DIR=<its prefix>")

if(METIS_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS INTERFACE IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${METIS_LIBRARY}")
endif()
