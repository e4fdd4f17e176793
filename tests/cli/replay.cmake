# Every output replays: its own stored config, given back with --config, reproduces its result
# datasets bitwise (replay.sh). Sweeps narrowed on the command line, with every default, with an
# equivalent block and the paper's method; histories of a sine pulse, a constant one and a record;
# the merge of a sweep's parts.
set(REPLAY ${CMAKE_CURRENT_SOURCE_DIR}/replay.sh)
function(replay name)
  add_test(NAME cli.replay.${name} COMMAND bash ${REPLAY} ${RS} ${CMAKE_CURRENT_BINARY_DIR}/replay_${name} ${ARGN})
endfunction()
replay(sweep_narrowed sweep --config ${CFG} --anchorages free adaptive --kmin-ratios 0.2 --omega-ratio-points 5 --amplitude-ratio-points 4 --refine 2)
replay(sweep_defaults sweep --omega-ratio-points 3 --amplitude-ratio-points 3 --friction-coefficient 0.3)
replay(sweep_equivalent_paper sweep --radius 1.5 --alpha 0.2 --frequency-parameter 2.5 --omega-ratio-points 2 --amplitude-ratio-points 2
       --method paper --paper-dt 0.002 --scenario free --scenario constant_tf0.333333)
replay(simulate_sine simulate --config ${CFG} --anchorage adaptive --adaptive-law passive --kmin-ratio 0.1 --omega-ratio 3.5 --amplitude-ratio 3 --vertical-amplitude 0.2)
replay(simulate_constant_stiffness simulate --pulse constant --amplitude-ratio 1.3 --duration 0.638 --equations linearised
       --anchorage constant --stiffness 2e5 --no-energy-stop)
replay(simulate_record simulate --config ${CFG} --record ${PROJECT_SOURCE_DIR}/tests/data/northridge_1994_sylmar.dat --record-units m/s^2
       --record-scale 0.5 --anchorage constant --theta-f-ratio 0.5 --t-end 20)
add_test(NAME cli.replay.merge COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/replay_merge.sh ${RS} ${CFG} ${CMAKE_CURRENT_BINARY_DIR}/replay_merge)
add_test(NAME cli.record_history_keeps_no_pulse
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/record_history.sh ${RS} ${CFG} ${PROJECT_SOURCE_DIR}/tests/data/northridge_1994_sylmar.dat
                 ${CMAKE_CURRENT_BINARY_DIR}/record_history)

# A requeued job: --resume on a finished sweep does nothing, leaves the file as it was.
add_test(NAME cli.resume_complete_is_noop COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/resume_complete.sh ${RS} ${CFG} ${CMAKE_CURRENT_BINARY_DIR}/complete1 1)
add_test(NAME cli.resume_complete_is_noop.mpirun=2
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/resume_complete.sh ${RS} ${CFG} ${CMAKE_CURRENT_BINARY_DIR}/complete2 2)
add_test(NAME cli.resume_complete_part_is_noop
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/resume_complete.sh ${RS} ${CFG} ${CMAKE_CURRENT_BINARY_DIR}/complete_part 1 2/2)
set_tests_properties(cli.resume_complete_is_noop.mpirun=2 PROPERTIES PROCESSORS 2)
