# Crashes, hangs and data loss at the edges (issue 7): every case asserts the exit status, the
# message and what is left on disk. Included at the end of tests/cli/CMakeLists.txt.
set(OS_DIR ${CMAKE_CURRENT_BINARY_DIR}/output_safety)
set(OS_SMALL --omega-ratio-points 3 --amplitude-ratio-points 3 --quiet)

# simulate refuses an existing file now: the simulate tests above start from fresh outputs.
add_test(NAME cli.simulate_outputs_fresh
         COMMAND ${CMAKE_COMMAND} -E rm -f ${CMAKE_CURRENT_BINARY_DIR}/free.h5 ${CMAKE_CURRENT_BINARY_DIR}/adaptive.csv
                 ${CMAKE_CURRENT_BINARY_DIR}/housner.h5 ${CMAKE_CURRENT_BINARY_DIR}/friction.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/elcentro.h5)
set_tests_properties(cli.simulate_outputs_fresh PROPERTIES FIXTURES_SETUP simulate_fresh)
set_tests_properties(cli.simulate_free_overturns cli.simulate_adaptive_csv cli.simulate_housner_constant_pulse
                     cli.simulate_reports_sliding cli.simulate_elcentro_record
                     PROPERTIES FIXTURES_REQUIRED simulate_fresh)

# The output is claimed before computing: names that cannot be written fail at once.
add_test(NAME cli.output.proc
         COMMAND ${EXPECT} 2 "^rocksweep: error: --output = /proc/o.h5 is invalid: a location where files can be created"
                 /proc/o.h5 -- ${RS} sweep --config ${CFG} -o /proc/o.h5 ${OS_SMALL})
string(REPEAT "n" 251 OS_LONG)
add_test(NAME cli.output.name_too_long
         COMMAND ${EXPECT} 2 "^rocksweep: error: --output = .* is invalid: a file name of at most 250 bytes"
                 ${OS_DIR}/${OS_LONG}.h5 -- ${RS} sweep --config ${CFG} -o ${OS_DIR}/${OS_LONG}.h5 ${OS_SMALL})
add_test(NAME cli.output.simulate_name_too_long
         COMMAND ${EXPECT} 2 "^rocksweep: error: --output = .* is invalid: a file name of at most 250 bytes"
                 ${OS_DIR}/${OS_LONG}.h5 -- ${RS} simulate --config ${CFG} -o ${OS_DIR}/${OS_LONG}.h5)
file(MAKE_DIRECTORY ${OS_DIR})
foreach(mode tmp_dir simulate lock)
  add_test(NAME cli.output.${mode}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/output_claim.sh ${mode} ${RS} ${CFG} ${OS_DIR}/${mode})
endforeach()

# A full disk: one line, exit 1, no .tmp, the last complete file intact (skipped without mount
# namespaces).
add_test(NAME cli.full_disk COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/full_disk.sh ${RS} ${CFG} ${OS_DIR}/disk1 1)
add_test(NAME cli.full_disk.mpirun=2 COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/full_disk.sh ${RS} ${CFG} ${OS_DIR}/disk2 2)
set_tests_properties(cli.full_disk cli.full_disk.mpirun=2 PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
set_tests_properties(cli.full_disk.mpirun=2 PROPERTIES PROCESSORS 2)

# A stop request in the middle of a chunk of slow cells, then --resume to identical results.
add_test(NAME sweep_stop_slow_cells COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/stop_slow.sh ${RS} ${CFG} ${OS_DIR}/stop1 1 self)
add_test(NAME sweep_stop_slow_cells.mpirun=2
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/stop_slow.sh ${RS} ${CFG} ${OS_DIR}/stop2 2 self)
add_test(NAME sweep_stop_slow_cells_via_mpirun.mpirun=2
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/stop_slow.sh ${RS} ${CFG} ${OS_DIR}/stop3 2 mpirun)
# They time a stop: run alone, not beside other jobs competing for the same two cores.
set_tests_properties(sweep_stop_slow_cells sweep_stop_slow_cells.mpirun=2 sweep_stop_slow_cells_via_mpirun.mpirun=2
                     PROPERTIES TIMEOUT 90 RUN_SERIAL TRUE)

# --resume with another setting that shapes results is refused, the file untouched.
add_test(NAME cli.resume_with_other_settings_is_refused
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/resume_settings.sh ${RS} ${CFG} ${OS_DIR}/resume)
