# Warnings and sanitizers, applied per target so that third-party headers stay quiet.
if(POSTPROC_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

function(postproc_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
endfunction()

# postproc_test(NAME sources... LIBS libs...): one GoogleTest executable, registered with ctest.
# Tests run from the tests/ folder so that data paths are relative to it.
# PREFIX (optional) goes before each test's name in ctest, so that `ctest -R PREFIX` picks a suite.
function(postproc_test name)
  cmake_parse_arguments(T "" "PREFIX" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  postproc_target_defaults(${name})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest_main)
  gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/tests DISCOVERY_TIMEOUT 60 TEST_PREFIX "${T_PREFIX}")
endfunction()
