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

# 8. Suite CSV columns count from 1; one column is not both components; ';' is named as such.
set(SUITE_HEAD "name,file,format,units,column,vertical_column")
file(WRITE ${IC}/column0.csv "${SUITE_HEAD}\nec,${ICDATA}/elcentro_1940_NS.dat,time_accel,g,0,\n")
bad_input(suite_column_zero "--suite = .*column0.csv line 2 is invalid: column '0' is not a whole number >= 1"
          suite --config ${CFG} --suite ${IC}/column0.csv -o ${OUT})
file(WRITE ${IC}/same_column.csv "${SUITE_HEAD}\nmx,${ICDATA}/mexico_city_1985_sct.txt,time_accel,g,3,3\n")
bad_input(suite_vertical_same_column
          "--suite = .*same_column.csv line 2 is invalid: column 'vertical_column' = 3: a column other than the horizontal component's \\(3\\)"
          suite --config ${CFG} --suite ${IC}/same_column.csv -o ${OUT})
file(WRITE ${IC}/semicolon.csv "name;file;format;units\nec;${ICDATA}/elcentro_1940_NS.dat;time_accel;g\n")
bad_input(suite_semicolons "--suite = .*semicolon.csv line 1 is invalid: cells separated by ',' \\(this header is separated by ';'"
          suite --config ${CFG} --suite ${IC}/semicolon.csv -o ${OUT})
bad_input(record_vertical_same_column "--record-vertical-column = 2 is invalid: a column other than the horizontal component's \\(2\\)"
          simulate --record ${ICDATA}/mexico_city_1985_sct.txt --record-units g --record-column 2 --record-vertical-column 2 -o ${OUT})
bad_input(record_vertical_default_column "--record-vertical-column = 2 is invalid: a column other than the horizontal component's \\(2\\)"
          simulate --record ${ICDATA}/mexico_city_1985_sct.txt --record-units g --record-vertical-column 2 -o ${OUT})
bad_input(damage_states_repeated "--damage-states = 0.1 0.1 is invalid: thresholds in increasing order, each once"
          suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv -o ${OUT} --damage-states 0.1 0.1)
bad_input(damage_states_decreasing "--damage-states = 0.5 0.1 is invalid: thresholds in increasing order, each once"
          suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv -o ${OUT} --damage-states 0.5 0.1)
# TOML's 0x, 0o and 0b integers reach the option as the number they write (0x0 is then out of range).
file(WRITE ${IC}/hex.toml "half-width = 0.3\nhalf-height = 1.36\nomega-ratio-points = 0x3\namplitude-ratio-points = 0b11\nanchorages = \"free\"\n")
add_test(NAME cli.config_hex_integers
         COMMAND sh -c "\"$1\" sweep --config \"$2\" --quiet --overwrite -o \"$3\" && h5dump -d /spectra/free/omega_ratio -d /spectra/free/amplitude_ratio \"$3\""
                 sh ${RS} ${IC}/hex.toml ${IC}/hex.h5)
set_tests_properties(cli.config_hex_integers PROPERTIES PASS_REGULAR_EXPRESSION "DATASPACE  SIMPLE \\{ \\( 3 \\) / \\( 3 \\) \\}.*DATASPACE  SIMPLE \\{ \\( 3 \\) / \\( 3 \\) \\}")
file(WRITE ${IC}/hex0.toml "omega-ratio-points = 0x0\n")
bad_input(config_hex_zero "--omega-ratio-points = 0 is invalid: out of range" sweep --config ${IC}/hex0.toml -o ${OUT})

# 9. Messages: -o=NAME, a record of a suite in the suite's terms, a damaged part file.
add_test(NAME cli.bad_input.output_with_equals
         COMMAND ${EXPECT} 2 "--output = =-x.h5 is invalid: a file name that does not begin with '=' \\(write -o FILE or --output=FILE\\)"
                 =-x.h5 -- ${RS} simulate --config ${CFG} -o=-x.h5)
set_tests_properties(cli.bad_input.output_with_equals PROPERTIES WORKING_DIRECTORY ${IC})
file(WRITE ${IC}/absent_column.csv "${SUITE_HEAD}\nec,${ICDATA}/elcentro_1940_NS.dat,time_accel,g,7,\n")
bad_input(suite_record_in_suite_terms "--suite = .*absent_column.csv line 2 is invalid: column 'column' = "
          suite --config ${CFG} --suite ${IC}/absent_column.csv -o ${OUT})
add_test(NAME cli.damaged_part_named
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/damaged_part.sh ${RS} ${CFG} ${IC}/damaged)
