# Shell-driven tests: they run installed applications and out-of-tree builds, which a
# GoogleTest executable linked into the build tree cannot exercise.

# The user-plugin example: install this build, build tutorials/plugins/myMaterial against
# the exported package, run tutorials/plugins/viscoElasticBar (tests/scripts/pluginExample.sh).
add_test(NAME pluginExample
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/scripts/pluginExample.sh
                 ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
# The same cmake and compiler as this build, so the plugin's ABI matches the libraries.
set_tests_properties(pluginExample PROPERTIES
  TIMEOUT 600
  LABELS integration
  ENVIRONMENT "CMAKE=${CMAKE_COMMAND};CXX=${CMAKE_CXX_COMPILER}")
