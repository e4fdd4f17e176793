# rocksweep design: bad input, identical results at any rank count, resume.
# Included from CMakeLists.txt, which defines bad_input(), RS, OUT and CFG.
set(DCFG ${PROJECT_SOURCE_DIR}/configs/design.toml)
set(TINY --omega-ratio-points 3 --amplitude-ratio-points 3 --quiet)
bad_input(design_stiffness_range_reversed "--stiffness-range = 500000 100000 is invalid: two values LO HI with LO < HI"
          design --config ${DCFG} -o ${OUT} ${TINY} --stiffness-range 5e5 1e5)
bad_input(design_stiffness_range_zero "--stiffness-range = 0 is invalid: out of range; allowed: a number in \\[1, 1e12\\] N/m"
          design --config ${DCFG} -o ${OUT} ${TINY} --stiffness-range 0 1e5)
bad_input(design_kmin_ratio_above_one "--kmin-ratio-range = 2 is invalid: out of range; allowed: a number in \\[1e-6, 1\\]"
          design --config ${DCFG} -o ${OUT} ${TINY} --kmin-ratio-range 0.1 2)
bad_input(design_coarse_points "--coarse-points = 2 is invalid: out of range; allowed: an integer in \\[3, 1000\\]"
          design --config ${DCFG} -o ${OUT} ${TINY} --coarse-points 2)
bad_input(design_tolerance_zero "--tolerance = 0 is invalid: out of range"
          design --config ${DCFG} -o ${OUT} ${TINY} --tolerance 0)
bad_input(design_rotation_limit_zero "--max-rotation-ratio = 0 is invalid: out of range"
          design --config ${DCFG} -o ${OUT} ${TINY} --max-rotation-ratio 0)
bad_input(design_limit_with_refine "--refine = 8 is invalid: 0 with --max-rotation-ratio or --object-force-ratio"
          design --config ${DCFG} -o ${OUT} ${TINY} --object-force-ratio 0.3 --refine 8)
bad_input(design_scenario_option "--theta-f-ratios = 0.5 is invalid: an option of sweep and info only; design chooses its scenarios"
          design --config ${PROJECT_SOURCE_DIR}/configs/smatteo.toml -o ${OUT} ${TINY} --theta-f-ratios 0.5)
bad_input(design_resume_and_overwrite "--resume = with --overwrite is invalid"
          design --config ${DCFG} -o ${OUT} ${TINY} --resume --overwrite)
bad_input(design_block_checked "--mass = 0 is invalid: out of range" design --config ${DCFG} -o ${OUT} ${TINY} --mass 0)

foreach(np 1 2)
  add_test(NAME design_identical.mpirun=${np}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/design_ranks.sh ${RS} ${DCFG} ${CMAKE_CURRENT_BINARY_DIR}/design_ranks${np} ${np})
  set_tests_properties(design_identical.mpirun=${np} PROPERTIES TIMEOUT 120 PROCESSORS 2)
endforeach()
add_test(NAME design_resume COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/design_resume.sh ${RS} ${DCFG} ${CMAKE_CURRENT_BINARY_DIR}/design_resume)
set_tests_properties(design_resume PROPERTIES TIMEOUT 180)

# design --suite: the region's options are refused with a suite, the suite's levels without one.
set(SUITE_CSV ${PROJECT_SOURCE_DIR}/configs/records_suite.csv)
bad_input(design_levels_without_suite "--intensity-points = 4 is invalid: an option of design --suite"
          design --config ${DCFG} -o ${OUT} ${TINY} --intensity-points 4)
bad_input(design_region_with_suite "--omega-ratio-points = 3 is invalid: an option of the pulse region; with --suite the hazard is the suite's records"
          design --config ${DCFG} -o ${OUT} ${TINY} --suite ${SUITE_CSV})
bad_input(design_suite_refine "--refine = 8 is invalid: 0 with --suite"
          design --config ${DCFG} -o ${OUT} --suite ${SUITE_CSV} --refine 8 --quiet)
