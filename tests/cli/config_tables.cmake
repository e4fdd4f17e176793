# A key in the wrong table of a config is refused saying where it belongs (README, "Command
# line"): a command's option in another command's table, a model option in a command's table.
# Included from CMakeLists.txt, which defines bad_input(), RS and OUT.
set(T ${CMAKE_CURRENT_BINARY_DIR}/config_tables)
file(MAKE_DIRECTORY ${T})
file(WRITE ${T}/refine_under_simulate.toml "mass = 3361\n[simulate]\nrefine = 16\n")
bad_input(config_key_in_other_command_table
          "config key 'refine' in the \\[simulate\\] table is an option of rocksweep sweep: put it in the config's \\[sweep\\] table"
          sweep --config ${T}/refine_under_simulate.toml -o ${OUT})
file(WRITE ${T}/mass_under_sweep.toml "[sweep]\nrefine = 16\nmass = 3000\n")
bad_input(config_model_key_in_command_table
          "config key 'mass' in the \\[sweep\\] table is an option of every command: put it at the top of the config \\(or under \\[block\\], \\[pulse\\], \\[anchorage\\], \\[grid\\] or \\[numerics\\]\\)"
          sweep --config ${T}/mass_under_sweep.toml -o ${OUT})
file(WRITE ${T}/unknown_under_sweep.toml "[sweep]\nrefien = 16\n")
bad_input(config_unknown_key_in_command_table "config key 'sweep.refien' is not an option of rocksweep \\(see rocksweep --help\\)"
          sweep --config ${T}/unknown_under_sweep.toml -o ${OUT})
