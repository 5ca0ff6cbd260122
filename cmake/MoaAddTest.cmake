# moa_add_test(NAME SOURCES <files...> [LIBS <targets...>] [LABELS <labels...>] [ARGS <args...>])
# One cmocka test executable registered with CTest under its labels.
find_package(cmocka REQUIRED)

function(moa_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS;LABELS;ARGS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} ${CMOCKA_LIBRARIES})
  target_include_directories(${name} SYSTEM PRIVATE ${CMOCKA_INCLUDE_DIR})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  add_test(NAME ${name} COMMAND ${name} ${T_ARGS})
  set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}"
    ENVIRONMENT "MOA_SHARED_DATA=${MOA_SHARED_DATA};MOA_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
