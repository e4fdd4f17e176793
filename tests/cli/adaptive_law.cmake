# --adaptive-law (docs/physics.md, "A passive adaptive law"). Included from tests/cli/CMakeLists.txt.
bad_input(adaptive_law_unknown "--adaptive-law = bogus is invalid: not a known word; allowed: one of paper, passive"
          sweep --config ${CFG} -o ${OUT} --adaptive-law bogus)
bad_input(adaptive_law_without_adaptive_simulate "--adaptive-law = passive is invalid: only with --anchorage adaptive \\(here --anchorage free\\)"
          simulate --adaptive-law passive -o ${OUT})
bad_input(adaptive_law_without_adaptive_sweep "--adaptive-law = passive is invalid: only with 'adaptive' among --anchorages"
          sweep --config ${CFG} --anchorages free constant --adaptive-law passive -o ${OUT})
add_test(NAME cli.info_adaptive_law_passive COMMAND ${RS} info --config ${CFG} --adaptive-law passive)
set_tests_properties(cli.info_adaptive_law_passive PROPERTIES
  PASS_REGULAR_EXPRESSION "adaptive_rho0.5_passive +adaptive.*adaptive_rho0.1_passive +adaptive")
add_test(NAME cli.sweep_adaptive_law_named_stored_resumed
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/adaptive_law.sh ${RS} ${CFG} ${CMAKE_CURRENT_BINARY_DIR}/adaptive_law)
# simulate reports the passive law's injected energy: exactly 0 on El Centro, where the paper's
# law injects 210 J (benchmarks/results/adaptive_law.md).
add_test(NAME cli.simulate_passive_injects_nothing
         COMMAND ${RS} simulate --record ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat --record-units g
                 --anchorage adaptive --kmin-ratio 0.1 --adaptive-law passive --overwrite
                 -o ${CMAKE_CURRENT_BINARY_DIR}/elcentro_passive.h5)
set_tests_properties(cli.simulate_passive_injects_nothing PROPERTIES
  PASS_REGULAR_EXPRESSION "outcome: safe.*injected by K_min -> K_max switches: 0 J")
