# Writes OUTPUT (a header) with the git revision of SOURCE_DIR, the project
# VERSION and the BUILD_TYPE, only when it
# changed, so that a build recompiles source/app/version.cc alone when the
# revision moves. Run at every build by the target 'revision'. The revision
# is '-dirty' when what the program is built from (source/, include/,
# CMakeLists.txt, cmake/) differs from the commit; runs, benchmarks and
# documents being edited do not count.
execute_process(
  COMMAND git describe --always --abbrev=10
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE _revision
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET
  RESULT_VARIABLE _result)
if(NOT _result EQUAL 0 OR _revision STREQUAL "")
  set(_revision "unknown")
else()
  execute_process(
    COMMAND git status --porcelain --untracked-files=no -- source include
            CMakeLists.txt cmake
    WORKING_DIRECTORY ${SOURCE_DIR}
    OUTPUT_VARIABLE _changes
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET)
  if(NOT _changes STREQUAL "")
    set(_revision "${_revision}-dirty")
  endif()
endif()
set(_text "#define DUCTILE_CONTACT_REVISION \"${_revision}\"\n#define DUCTILE_CONTACT_VERSION \"${VERSION}\"\n#define DUCTILE_CONTACT_BUILD_TYPE \"${BUILD_TYPE}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} _old)
else()
  set(_old "")
endif()
if(NOT _old STREQUAL _text)
  file(WRITE ${OUTPUT} "${_text}")
endif()
