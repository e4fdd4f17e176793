# Issue 21, "data a user can lose or get wrong": outputs that are inputs, records in the wrong
# unit, resume with other options, merge of edited parts, suite names the output cannot hold.
# Included from CMakeLists.txt, which defines bad_input(), RS, OUT, CFG and EXPECT.
set(TR_DATA ${PROJECT_SOURCE_DIR}/tests/data)
set(TR_DIR ${CMAKE_CURRENT_BINARY_DIR}/trust)
file(MAKE_DIRECTORY ${TR_DIR})

add_test(NAME cli.output_is_never_an_input
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/own_inputs.sh ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/configs/design.toml
                 ${TR_DATA} ${TR_DIR}/own_inputs)
set_tests_properties(cli.output_is_never_an_input PROPERTIES TIMEOUT 120)

# A record in the wrong unit is refused, naming the file, the unit, the PGA it implies and the
# option that accepts it; with that option it runs, and shows the PGA it was read with.
bad_input(record_in_g_read_as_gal
          "--record = .*elcentro_1940_NS.dat is invalid: its peak ground acceleration as read in cm/s\\^2, 0.3[0-9]* cm/s\\^2, is 0.000356 g \\(0.003[0-9]* m/s\\^2\\), outside the 0.005 to 5 g of a strong-motion record \\(docs/records.md\\): check its unit, or pass --record-any-pga to accept it"
          simulate --record ${TR_DATA}/elcentro_1940_NS.dat --record-units cm/s^2 -o ${OUT})
bad_input(record_in_m_s2_read_as_g
          "--record = .*northridge_1994_sylmar.dat is invalid: its peak ground acceleration as read in g, 8.2[0-9]* g, is 8.2[0-9]* g .*outside the 0.005 to 5 g"
          simulate --record ${TR_DATA}/northridge_1994_sylmar.dat --record-units g -o ${OUT})
bad_input(record_scale_does_not_hide_the_unit "--record = .*elcentro_1940_NS.dat is invalid: its peak ground acceleration as read in cm/s\\^2"
          simulate --record ${TR_DATA}/elcentro_1940_NS.dat --record-units cm/s^2 --record-scale 100 -o ${OUT})
file(WRITE ${TR_DIR}/gal_suite.csv "name,file,format,units\nel_g,${TR_DATA}/elcentro_1940_NS.dat,time_accel,g\nel_gal,${TR_DATA}/elcentro_1940_NS.dat,time_accel,cm/s^2\n")
bad_input(suite_record_in_wrong_unit
          "--suite = .*gal_suite.csv line 3 is invalid: record el_gal \\(.*elcentro_1940_NS.dat\\): its peak ground acceleration as read in cm/s\\^2, .* is 0.000356 g .*pass --record-any-pga to accept every record of the suite"
          suite --config ${CFG} --suite ${TR_DIR}/gal_suite.csv -o ${OUT})
add_test(NAME cli.record_any_pga_accepts
         COMMAND ${RS} simulate --record ${TR_DATA}/elcentro_1940_NS.dat --record-units cm/s^2 --record-any-pga --t-end 1
                 --overwrite -o ${TR_DIR}/any_pga.csv)
set_tests_properties(cli.record_any_pga_accepts PROPERTIES
  PASS_REGULAR_EXPRESSION "^record .*elcentro_1940_NS.dat: PGA 0.000356 g \\(0.003[0-9]* m/s\\^2\\) as read in cm/s\\^2, dt 0.02 s, 53.7[0-9]* s, 2688 samples\noutcome: safe")
add_test(NAME cli.suite_prints_records
         COMMAND ${RS} suite --config ${CFG} --anchorages free --suite ${TR_DIR}/gal_suite.csv --record-any-pga --intensity-points 2
                 --overwrite -o ${TR_DIR}/gal_suite.h5)
set_tests_properties(cli.suite_prints_records PROPERTIES
  PASS_REGULAR_EXPRESSION "record el_g: PGA 0.3[0-9]* g \\(3.4[0-9]* m/s\\^2\\) as read in g, dt 0.02 s, 53.7[0-9]* s, 2688 samples\nrecord el_gal: PGA 0.000356 g")
add_test(NAME cli.records_shared_plausible
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/records_plausible.sh ${RS} ${TR_DATA} ${TR_DIR}/plausible)

# sweep's side of --resume checking every option: resume_settings.sh (cli.resume_with_other_settings_is_refused).
add_test(NAME cli.suite_resume_checks_every_option
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/resume_options.sh ${RS} ${CFG} ${TR_DATA} ${TR_DIR}/resume_options)
add_test(NAME cli.merge_verifies_checksums.mpirun=2
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/merge_checksum.sh ${RS} ${CFG} ${TR_DIR}/merge_checksum)
set_tests_properties(cli.merge_verifies_checksums.mpirun=2 PROPERTIES TIMEOUT 120 PROCESSORS 2)
add_test(NAME cli.suite_record_names_checked_first
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_names.sh ${RS} ${CFG} ${TR_DATA} ${TR_DIR}/suite_names)
set_tests_properties(cli.suite_record_names_checked_first PROPERTIES TIMEOUT 120)
