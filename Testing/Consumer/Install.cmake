# Installs the Kerf build tree BUILD_DIR into a fresh PREFIX and empties the consumer's build
# folder CONSUMER_BUILD, so that no earlier install or cached path hides a broken package.
file(REMOVE_RECURSE "${PREFIX}" "${CONSUMER_BUILD}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "Installing ${BUILD_DIR} into ${PREFIX} failed: ${result}")
endif ()
