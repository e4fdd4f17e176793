# `rocksweep synth` and `suite --synthetic-count`: bad input refused in one line naming the
# option (exit 2, nothing written); motions defined by (seed, index) whatever the batch; the
# written records read back by simulate; synthetic suites bitwise the same on 1-3 ranks and
# after kills. Included from CMakeLists.txt, which defines bad_input(), RS, OUT, CFG and EXPECT.
set(SYN_DIR ${CMAKE_CURRENT_BINARY_DIR}/synth_bad)
set(MODEL --arias 0.5 --d595 10 --tmid 7 --f-mid 4 --f-slope -0.1 --zeta 0.3)
function(bad_synth name regex)
  add_test(NAME cli.bad_input.${name} COMMAND ${EXPECT} 2 "${regex}" ${SYN_DIR}_${name} -- ${RS} synth -o ${SYN_DIR}_${name} ${ARGN})
endfunction()
bad_synth(synth_nothing "--arias = \\(not given\\) is invalid: required without --record \\(missing: --arias, --d595, --tmid, --f-mid, --f-slope, --zeta\\)")
bad_synth(synth_missing_one "--zeta = \\(not given\\) is invalid: required without --record \\(missing: --zeta\\)"
          --arias 0.5 --d595 10 --tmid 7 --f-mid 4 --f-slope -0.1)
bad_synth(synth_record_and_model "--record = .*elcentro_1940_NS.dat is invalid: either a record to fit or the model's parameters \\(--arias, --zeta given too\\)"
          --record ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat --record-units g --arias 0.5 --zeta 0.3)
# The option as the user wrote it: --motion-duration, not the pulse's --duration.
bad_synth(synth_motion_shorter_than_tmid "--motion-duration = 5 is invalid: a motion length in \\[t_mid, 1e5\\] s \\(t_mid = 7 s\\)"
          ${MODEL} --motion-duration 5)
bad_synth(synth_zeta_one "--zeta = 1 is invalid: out of range; allowed: a number in \\[0.01, 0.99\\]"
          --arias 0.5 --d595 10 --tmid 7 --f-mid 4 --f-slope -0.1 --zeta 1)
bad_synth(synth_duration_ratio "--d595 = 900 is invalid: D5-95 / t_mid = 128.6 must lie in \\(0.0329, 84.7\\) for a gamma envelope"
          --arias 0.5 --d595 900 --tmid 7 --f-mid 4 --f-slope -0.1 --zeta 0.3)
bad_synth(synth_filter_past_sampling "--dt = 0.06 is invalid: the filter's highest frequency where the envelope carries the motion \\(0.9938 to 24.79 s\\), 4.601 Hz, must stay below a quarter of the sampling rate: dt < 0.05434 s"
          ${MODEL} --dt 0.06)
# A record fitted in the wrong unit (El Centro is in g): refused as simulate and suite refuse it.
set(ELCENTRO_CM ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat --record-units cm/s^2)
bad_synth(synth_record_implausible_pga "--record = .*elcentro_1940_NS.dat is invalid: its peak ground acceleration as read in cm/s\\^2, .* outside the 0.005 to 5 g .*pass --record-any-pga to fit it"
          --record ${ELCENTRO_CM})
add_test(NAME cli.bad_input.suite_synthetic_record_implausible_pga
         COMMAND ${EXPECT} 2 "--record = .*elcentro_1940_NS.dat is invalid: its peak ground acceleration as read in cm/s\\^2, .* outside the 0.005 to 5 g"
                 ${OUT} -- ${RS} suite --config ${CFG} --synthetic-count 2 --record ${ELCENTRO_CM} -o ${OUT})
add_test(NAME cli.synth_record_any_pga_fits
         COMMAND bash -c "$0 synth --record-any-pga --record $1 --record-units cm/s^2 -q --overwrite -o $2 && test -s $2/suite.csv"
                 ${RS} ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat ${CMAKE_CURRENT_BINARY_DIR}/synth_any_pga)
bad_synth(synth_record_without_units "--record-units = \\(missing\\) is invalid: g, m/s\\^2 or cm/s\\^2"
          --record ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat)
add_test(NAME cli.bad_input.synth_model_option_without_count
         COMMAND ${EXPECT} 2 "--arias = 0.5 is invalid: an option of the synthetic motions, which need --synthetic-count N" ${OUT}
                 -- ${RS} suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --arias 0.5 -o ${OUT})

# Motion 2 of seed 7 is the same file whether written alone or among others; simulate reads it;
# an existing suite.csv is kept without --overwrite.
add_test(NAME cli.synth_index_defines_motion
         COMMAND bash -c "set -e; d=$0; rs=$1; shift; rm -rf $d; mkdir -p $d
                          $rs synth $@ --seed 7 --count 3 -q -o $d/all
                          $rs synth $@ --seed 7 --first 2 --count 1 -q -o $d/one
                          cmp $d/all/synthetic_s7_000002.txt $d/one/synthetic_s7_000002.txt
                          ! cmp -s $d/all/synthetic_s7_000001.txt $d/all/synthetic_s7_000002.txt
                          grep -q '^synthetic_s7_000002,synthetic_s7_000002.txt,time_accel,g,,,1,,,7,2$' $d/all/suite.csv
                          $rs simulate --record $d/one/synthetic_s7_000002.txt --record-units g -o $d/sim.csv | grep -q '^outcome: '
                          before=$(md5sum < $d/one/suite.csv)
                          if $rs synth $@ --seed 8 -q -o $d/one 2> $d/err.txt; then exit 1; fi
                          grep -q 'pass --overwrite to replace it' $d/err.txt
                          [ \"$(md5sum < $d/one/suite.csv)\" = \"$before\" ]"
                 ${CMAKE_CURRENT_BINARY_DIR}/synth_index ${RS} ${MODEL})

# A synthetic suite fitted to a shared record: 100 motions on 1, 2, 3 ranks; 10 motions killed
# and resumed (the 2000-motion run of the issue: docs/synthetic.md, "Suites").
set(FIT --record ${PROJECT_SOURCE_DIR}/tests/data/loma_prieta_1989.dat --record-units m/s^2)
add_test(NAME cli.suite_synthetic_ranks_identical
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_ranks.sh ${RS} ${CFG} - ${CMAKE_CURRENT_BINARY_DIR}/suite_syn_ranks
                 --synthetic-count 100 ${FIT})
add_test(NAME cli.suite_synthetic_kill_resume.mpirun=2
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_kill_resume.sh ${RS} ${CFG} - ${CMAKE_CURRENT_BINARY_DIR}/suite_syn_kill 2
                 --synthetic-count 10 ${FIT})
# On a floor too: made motions pass through the building as read records do, measured (PFA) once
# and made again in the cells, identically on 1, 2 and 3 ranks.
add_test(NAME cli.suite_synthetic_floor_ranks_identical
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_ranks.sh ${RS} ${CFG} - ${CMAKE_CURRENT_BINARY_DIR}/suite_syn_floor_ranks
                 --synthetic-count 6 ${FIT} --floor ground "f2: 0.5 0.05 1.3; 0.17 0.05 -0.4" --intensity-measure pfa)
# The ranks measure the motions in shares, in rounds of 1024 motions a rank (app/made_on_ranks.hpp):
# 2050 short motions on 2 ranks take two rounds, the second of one motion a rank; the file is the
# one rank's, measures and floor spectra included (~9 s).
add_test(NAME cli.suite_synthetic_measured_in_rounds.mpirun=2
         COMMAND bash -c "set -e; d=$0; rs=$1; cfg=$2; shift 2; rm -rf $d; mkdir -p $d
                          mpi=(mpirun --oversubscribe); [ $(id -u) -eq 0 ] && mpi+=(--allow-run-as-root)
                          args=(suite --config $cfg --synthetic-count 2050 \"$@\" --anchorages free --intensity-points 1
                                --intensity-range 0.3 0.3 --intensity-measure pfa -q)
                          $rs \"\${args[@]}\" --floor ground 'f2: 0.5 0.05 1.3' -o $d/np1.h5
                          \"\${mpi[@]}\" -np 2 $rs \"\${args[@]}\" --floor ground 'f2: 0.5 0.05 1.3' -o $d/np2.h5
                          h5diff --exclude-path /provenance $d/np1.h5 $d/np2.h5"
                 ${CMAKE_CURRENT_BINARY_DIR}/suite_syn_rounds ${RS} ${CFG}
                 --arias 0.05 --d595 2 --tmid 1.5 --f-mid 4 --f-slope 0 --zeta 0.3 --fc 1 --dt 0.02)
set_tests_properties(cli.suite_synthetic_ranks_identical cli.suite_synthetic_kill_resume.mpirun=2
                     cli.suite_synthetic_floor_ranks_identical cli.suite_synthetic_measured_in_rounds.mpirun=2
                     PROPERTIES TIMEOUT 300 PROCESSORS 2)

# Made on the ranks or written by synth and read back as a record suite: the same motions, so the
# same results, bit for bit (the files' 17 digits read back to the generator's bits).
add_test(NAME cli.suite_synthetic_equals_written_motions
         COMMAND bash -c "set -e; d=$0; rs=$1; cfg=$2; shift 2; rm -rf $d; mkdir -p $d
                          $rs synth $@ --count 5 -q -o $d/motions
                          $rs suite --config $cfg --suite $d/motions/suite.csv --intensity-points 5 -q -o $d/files.h5
                          $rs suite --config $cfg --synthetic-count 5 $@ --intensity-points 5 -q -o $d/made.h5
                          h5diff $d/files.h5 $d/made.h5 /suite /suite"
                 ${CMAKE_CURRENT_BINARY_DIR}/synth_made_vs_files ${RS} ${CFG} ${MODEL})

# suite --synthetic-per-record: N motions of the model fitted to each record of --suite
# (docs/synthetic.md, "Motions fitted to each record"). Contradictions refused in one line.
set(SITE ${PROJECT_SOURCE_DIR}/configs/records_suite.csv)
bad_input(suite_per_record_with_count "--synthetic-count = 3 is invalid: not with --synthetic-per-record \\(motions of one model, or of the model fitted to each record of --suite: one of the two\\)"
          suite --config ${CFG} --suite ${SITE} --synthetic-per-record 2 --synthetic-count 3 -o ${OUT})
bad_input(suite_per_record_without_suite "--synthetic-per-record = 2 is invalid: with a --suite, to each of whose records the model is fitted"
          suite --config ${CFG} --synthetic-per-record 2 -o ${OUT})
bad_input(suite_per_record_with_model "--arias = 0.5 is invalid: not with --synthetic-per-record, which fits the model to each record of --suite"
          suite --config ${CFG} --suite ${SITE} --synthetic-per-record 2 --arias 0.5 -o ${OUT})
bad_input(suite_per_record_with_record "--record-units = g is invalid: not with --synthetic-per-record, which fits the model to each record of --suite"
          suite --config ${CFG} --suite ${SITE} --synthetic-per-record 2 --record-units g -o ${OUT})
bad_input(suite_synthetic_only_alone "--synthetic-only = \\(given\\) is invalid: only with --synthetic-per-record N \\(the records then only fit the model\\)"
          suite --config ${CFG} --suite ${SITE} --synthetic-only -o ${OUT})
bad_input(suite_per_record_negative "--synthetic-per-record = -1 is invalid: out of range; allowed: an integer in \\[0, 100000000\\]"
          suite --config ${CFG} --suite ${SITE} --synthetic-per-record -1 -o ${OUT})
bad_input(suite_per_record_dt "--dt = 0.05 is invalid: the filter's highest frequency where the envelope carries the motion \\(0.7302 to 13.29 s\\), 5.293 Hz, must stay below a quarter of the sampling rate: dt < 0.04723 s \\(the model fitted to record sylmar_1994, .*records_suite.csv line 6\\)"
          suite --config ${CFG} --suite ${SITE} --synthetic-per-record 2 --dt 0.05 -o ${OUT})
set(PER_RECORD bash ${CMAKE_CURRENT_SOURCE_DIR}/suite_per_record.sh)
add_test(NAME cli.bad_input.suite_per_record_records_refused
         COMMAND ${PER_RECORD} refused ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/tests/data ${CMAKE_CURRENT_BINARY_DIR}/per_record_refused)
# Made on the ranks = synth's motions of each record's derived seed swept from files; resume checks.
add_test(NAME cli.suite_per_record_equals_written_motions
         COMMAND ${PER_RECORD} equal ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/tests/data ${CMAKE_CURRENT_BINARY_DIR}/per_record_equal)
add_test(NAME cli.suite_per_record_ranks_identical
         COMMAND ${PER_RECORD} ranks ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/tests/data ${CMAKE_CURRENT_BINARY_DIR}/per_record_ranks)
add_test(NAME cli.suite_per_record_kill_resume.mpirun=2
         COMMAND ${PER_RECORD} kill ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/tests/data ${CMAKE_CURRENT_BINARY_DIR}/per_record_kill)
set_tests_properties(cli.suite_per_record_ranks_identical cli.suite_per_record_kill_resume.mpirun=2
                     PROPERTIES TIMEOUT 300 PROCESSORS 2)
