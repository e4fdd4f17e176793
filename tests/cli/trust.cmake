# Issue 21, "data a user can lose or get wrong".
# Included from CMakeLists.txt, which defines bad_input(), RS, OUT, CFG and EXPECT.
set(TR_DATA ${PROJECT_SOURCE_DIR}/tests/data)
set(TR_DIR ${CMAKE_CURRENT_BINARY_DIR}/trust)
file(MAKE_DIRECTORY ${TR_DIR})

add_test(NAME cli.output_is_never_an_input
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/own_inputs.sh ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/configs/design.toml
                 ${TR_DATA} ${TR_DIR}/own_inputs)
set_tests_properties(cli.output_is_never_an_input PROPERTIES TIMEOUT 120)


add_test(NAME cli.suite_record_names_checked_first
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_names.sh ${RS} ${CFG} ${TR_DATA} ${TR_DIR}/suite_names)
set_tests_properties(cli.suite_record_names_checked_first PROPERTIES TIMEOUT 120)
