# Issue 21, items 7-9: valid input that was refused, bad input that was accepted, and messages
# that named the wrong thing. Included from CMakeLists.txt (bad_input(), RS, OUT, CFG, EXPECT).
set(IC ${CMAKE_CURRENT_BINARY_DIR}/input_checks)
file(MAKE_DIRECTORY ${IC})
set(ICDATA ${PROJECT_SOURCE_DIR}/tests/data)

# 7. h/b = 1e4 is documented as allowed: the check is on the ratio, not on atan(b/h) >= 1e-4.
add_test(NAME cli.slenderness_limit_included COMMAND ${RS} info --half-width 0.001 --half-height 10)
set_tests_properties(cli.slenderness_limit_included PROPERTIES PASS_REGULAR_EXPRESSION "b = 0.001 m, h = 10 m, R = 10 m")
add_test(NAME cli.alpha_limit_included COMMAND ${RS} info --radius 1 --alpha 1e-4)
set_tests_properties(cli.alpha_limit_included PROPERTIES PASS_REGULAR_EXPRESSION "alpha = 0.0001 rad")
bad_input(slenderness_beyond_limit "--half-height = 10.001 \\(with b = 0.001 m\\) is invalid: h / b <= 1e4"
          sweep --config ${CFG} -o ${OUT} --half-width 0.001 --half-height 10.001)

