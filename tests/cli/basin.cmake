# `rocksweep basin`: its own options' bad values, what it would ignore, an existing output; one
# line naming the option as written, exit status 2, no output left. Included from
# CMakeLists.txt, which defines bad_input(), RS, OUT, CFG and EXPECT.
set(BASIN_SMALL --theta-ratio-points 5 --theta-dot-ratio-points 5 --quiet)
bad_input(basin_theta_past_the_side "--theta-ratio-range = -8 8 is invalid: \\|theta / alpha\\| < pi / \\(2 alpha\\) = 7.23[0-9]* for this block"
          basin --config ${CFG} -o ${OUT} --theta-ratio-range -8 8)
bad_input(basin_theta_range_reversed "--theta-ratio-range = 1 -1 is invalid: LO <= HI"
          basin --config ${CFG} -o ${OUT} --theta-ratio-range 1 -1)
bad_input(basin_rate_range_one_point "--theta-dot-ratio-range = -0.45 0.45 is invalid: LO = HI exactly when --theta-dot-ratio-points is 1"
          basin --config ${CFG} -o ${OUT} --theta-dot-ratio-points 1)
bad_input(basin_rate_not_a_number "--theta-dot-ratio-range = fast is invalid: not a number; allowed: a number in \\[-100, 100\\]"
          basin --config ${CFG} -o ${OUT} --theta-dot-ratio-range fast 1)
bad_input(basin_points_zero "--theta-ratio-points = 0 is invalid: out of range; allowed: an integer in \\[1, 20000\\]"
          basin --config ${CFG} -o ${OUT} --theta-ratio-points 0)
bad_input(basin_pulse_option "--omega-ratio-points = 5 is invalid: an option of sweep; basin starts free rocking with the ground at rest"
          basin --config ${CFG} -o ${OUT} --omega-ratio-points 5 ${BASIN_SMALL})
bad_input(basin_not_h5 "--output = .*bad.h5.csv is invalid: a file name ending in .h5"
          basin --config ${CFG} -o ${OUT}.csv ${BASIN_SMALL})
bad_input(basin_too_large "--theta-ratio-points = 20000 is invalid: .*more than half of this machine"
          basin --config ${CFG} -o ${OUT} --theta-ratio-points 20000 --theta-dot-ratio-points 20000)

# An existing output is kept unless --overwrite; a small map is written and says what it wrote.
add_test(NAME cli.basin_existing_output_is_kept
         COMMAND bash -c "set -e; out=$0; rm -f $out; $1 basin --config $2 -o $out $3 $4 $5 $6 $7;
                          sum=$(md5sum < $out); if $1 basin --config $2 -o $out $3 $4 $5 $6 $7 2>err.txt; then exit 1; fi;
                          grep -q 'pass --overwrite to replace it' err.txt; [ \"$(md5sum < $out)\" = \"$sum\" ];
                          $1 basin --config $2 -o $out $3 $4 $5 $6 $7 --overwrite"
                 ${CMAKE_CURRENT_BINARY_DIR}/basin_existing.h5 ${RS} ${CFG} ${BASIN_SMALL})
set_tests_properties(cli.basin_existing_output_is_kept PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.basin_summary COMMAND ${RS} basin --config ${CFG} -o ${CMAKE_CURRENT_BINARY_DIR}/basin_summary.h5 --overwrite
                                        --scenario free --theta-ratio-points 21 --theta-dot-ratio-points 21)
set_tests_properties(cli.basin_summary PROPERTIES PASS_REGULAR_EXPRESSION "free +0\\.[0-9]+ / +0\\.[0-9]+ +0 of [0-9]+ /.*wrote .*basin_summary.h5 \\(1 scenarios x 441 states")
