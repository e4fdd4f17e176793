# Issue 7, "Trust at the edges": every class of bad input gets one line naming the option as
# written, the value and what is allowed; exit status 2; no output and no .tmp left.
# Included from CMakeLists.txt, which defines bad_input(), RS, OUT, CFG and EXPECT.
set(DATA ${PROJECT_SOURCE_DIR}/tests/data/elcentro_1940_NS.dat)
set(FREE ${PROJECT_SOURCE_DIR}/configs/paper_free.toml)
set(B ${CMAKE_CURRENT_BINARY_DIR})

# Values: not a number, not finite, not an integer, out of a physical range, shortened.
bad_input(mass_overflow "--mass = 1e308 is invalid: out of range; allowed: a number in \\[0.001, 1e9\\] kg"
          sweep --config ${CFG} -o ${OUT} --mass 1e308)
bad_input(mass_not_a_number "--mass = 3x is invalid: not a number; allowed: a number in \\[0.001, 1e9\\] kg"
          sweep --config ${CFG} -o ${OUT} --mass 3x)
bad_input(points_not_an_integer "--omega-ratio-points = 1.5 is invalid: not an integer; allowed: an integer in \\[1, 100000\\]"
          sweep --config ${CFG} -o ${OUT} --omega-ratio-points 1.5)
bad_input(points_not_a_number "--amplitude-ratio-points = many is invalid: not a number"
          sweep --config ${CFG} -o ${OUT} --amplitude-ratio-points many)
# bad_input_empty: as bad_input, with each argument EMPTY passed as '' (CMake drops empty ones).
function(bad_input_empty name regex)
  add_test(NAME cli.bad_input.${name}
           COMMAND bash -c "a=(\"$@\"); for i in \"\${!a[@]}\"; do [ \"\${a[$i]}\" = EMPTY ] && a[$i]=; done; exec \"$0\" \"\${a[@]}\""
                   ${EXPECT} 2 "${regex}" ${OUT} -- ${RS} ${ARGN})
endfunction()
bad_input(tolerance_too_large "--tolerance = 0.1 is invalid: out of range; allowed: a number in \\[0, 0.01\\]" sweep --config ${CFG} -o ${OUT} --tolerance 0.1)
bad_input_empty(lanes_empty "--lanes = \"\" is invalid: not a number; allowed: one of 1, 4, 8, 16"
                sweep --config ${CFG} -o ${OUT} --lanes EMPTY)
bad_input(lanes_missing "--lanes is invalid: a value is missing; allowed: one value, ONE OF 1, 4, 8, 16"
          sweep --config ${CFG} -o ${OUT} --lanes)
bad_input(lanes_not_allowed "--lanes = 3 is invalid: not one of the allowed values; allowed: one of 1, 4, 8, 16"
          sweep --config ${CFG} -o ${OUT} --lanes 3)
bad_input(max_steps_exponent "--max-steps = 1e6 is invalid: not an integer" sweep --config ${CFG} -o ${OUT} --max-steps 1e6)
bad_input(half_height_huge "--half-height = 1e308 is invalid: out of range; allowed: a number in \\[0.001, 1000\\] m"
          sweep --config ${CFG} -o ${OUT} --half-height 1e308)
bad_input(gravity_zero "--gravity = 0 is invalid: out of range; allowed: a number in \\[0.1, 100\\] m/s\\^2"
          sweep --config ${CFG} -o ${OUT} --gravity 0)
bad_input(frequency_parameter_vanishing "--frequency-parameter = 1e-200 is invalid: out of range"
          sweep -o ${OUT} --radius 1 --alpha 0.2 --frequency-parameter 1e-200)
bad_input(frequency_parameter_for_this_block "--frequency-parameter = 0.02 is invalid: p in \\[0.0313[0-9]*, 3.13[0-9]*\\] rad/s"
          sweep -o ${OUT} --radius 1 --alpha 0.2 --frequency-parameter 0.02)
bad_input(inertia_ratio_below_one "--inertia-ratio = 0.5 is invalid: out of range; allowed: a number in \\[1, 10000\\]"
          sweep -o ${OUT} --radius 1 --alpha 0.2 --inertia-ratio 0.5)
bad_input(omega_range_overflow "--omega-ratio-range = 1e308 is invalid: out of range; allowed: a number in \\[0.001, 1000\\]"
          sweep --config ${CFG} -o ${OUT} --omega-ratio-range 1e308 1e308)
bad_input(amplitude_range_zero "--amplitude-ratio-range = 0 is invalid: out of range"
          sweep --config ${CFG} -o ${OUT} --amplitude-ratio-range 0 5)
bad_input(needle "--half-height = 999 \\(with b = 0.001 m\\) is invalid: h / b <= 1e4"
          sweep --config ${CFG} -o ${OUT} --half-width 0.001 --half-height 999)
bad_input(equations_unknown "--equations = exact is invalid: not a known word; allowed: one of nonlinear, linearised"
          sweep --config ${CFG} -o ${OUT} --equations exact)
bad_input(record_steps_unknown "--record-steps = crossing is invalid: not a known word; allowed: one of samples, cross"
          suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv -o ${OUT} --record-steps crossing)
bad_input(stiffness_zero "--stiffness = 0 is invalid: out of range; allowed: a number in \\[1, 1e12\\] N/m"
          simulate --anchorage constant --stiffness 0 -o ${OUT})
bad_input(t_end_negative "--t-end = -1 is invalid: out of range" simulate -o ${OUT} --t-end -1)
string(REPEAT "9" 400 NINES)
bad_input(long_value_shortened "--mass = 9{160}[^9 ]+ is invalid: not a finite number" sweep --config ${CFG} -o ${OUT} --mass ${NINES})
bad_input(record_missing_file "--record = .*nope.dat is invalid: no such file"
          simulate --record ${B}/nope.dat --record-units g -o ${OUT})

# A physics check reported against the option the user wrote, not a derived quantity.
bad_input(theta_f_beyond_pi "--theta-f-ratios = 20 is invalid: 0 < theta_f / alpha < pi / alpha = 14.47 for this block"
          sweep --config ${CFG} -o ${OUT} --theta-f-ratios 20)
bad_input(adaptive_theta_f_beyond_pi "--adaptive-theta-f-ratio = 20 is invalid: 0 < theta_f / alpha < pi / alpha"
          sweep --config ${CFG} -o ${OUT} --adaptive-theta-f-ratio 20)
bad_input(simulate_theta_f_beyond_pi "--theta-f-ratio = 20 is invalid: 0 < theta_f / alpha < pi / alpha"
          simulate --anchorage constant --theta-f-ratio 20 -o ${OUT})
bad_input(stiffness_too_soft_to_break "--stiffness = 1 is invalid: K large enough that theta_f = 2 atan"
          simulate --anchorage constant --stiffness 1 --strength-ratio 1000 --mass 1e9 --gravity 100
          --half-width 0.001 --half-height 0.5 -o ${OUT})
bad_input(equivalent_block_too_squat "--alpha = 1.2 is invalid: a block that can rock"
          sweep -o ${OUT} --radius 1 --alpha 1.2)

# Options that mean nothing together, or one without the other: both named.
bad_input(radius_alone "--radius = 1 is invalid: only with --alpha" sweep -o ${OUT} --radius 1)
bad_input(alpha_alone "--alpha = 0.2 is invalid: only with --radius" sweep -o ${OUT} --alpha 0.2)
bad_input(radius_beside_half_width "--radius = 1 is invalid: not together with --half-width 0.30"
          sweep --config ${CFG} -o ${OUT} --radius 1 --alpha 0.2 ${SMALL})
bad_input(half_height_beside_radius "--radius = 1 is invalid: not together with --half-height 2"
          sweep -o ${OUT} --half-height 2 --radius 1 --alpha 0.2 ${SMALL})
bad_input(inertia_ratio_rectangular "--inertia-ratio = 2 is invalid: only with --radius and --alpha"
          sweep -o ${OUT} --inertia-ratio 2)
bad_input(frequency_parameter_rectangular "--frequency-parameter = 2 is invalid: not together with --half-width 0.30"
          sweep --config ${CFG} -o ${OUT} --frequency-parameter 2)
bad_input(inertia_ratio_and_p "--frequency-parameter = 2 is invalid: not together with --inertia-ratio 2"
          sweep -o ${OUT} --radius 1 --alpha 0.2 --inertia-ratio 2 --frequency-parameter 2)
bad_input(stiffness_free "--stiffness = 1e5 is invalid: only with --anchorage constant \\(here --anchorage free\\)"
          simulate --stiffness 1e5 -o ${OUT})
bad_input(stiffness_and_theta_f "--stiffness = 1e5 is invalid: not together with --theta-f-ratio 0.5"
          simulate --anchorage constant --stiffness 1e5 --theta-f-ratio 0.5 -o ${OUT})
bad_input(kmin_ratio_constant "--kmin-ratio = 0.3 is invalid: only with --anchorage adaptive"
          simulate --anchorage constant --kmin-ratio 0.3 -o ${OUT})
bad_input(theta_f_free "--theta-f-ratio = 0.5 is invalid: only with --anchorage constant or adaptive"
          simulate --theta-f-ratio 0.5 -o ${OUT})
bad_input(record_units_without_record "--record-units = g is invalid: only with --record"
          simulate --config ${CFG} --record-units g -o ${OUT})
bad_input(record_scale_without_record "--record-scale = 2 is invalid: only with --record" simulate --record-scale 2 -o ${OUT})
bad_input(pulse_with_record "--pulse = constant is invalid: not together with --record"
          simulate --record ${DATA} --record-units g --pulse constant -o ${OUT})
bad_input(omega_ratio_with_record "--omega-ratio = 3 is invalid: not together with --record"
          simulate --record ${DATA} --record-units g --omega-ratio 3 -o ${OUT})
bad_input(duration_with_sine "--duration = 1 is invalid: only with --pulse constant" simulate --duration 1 -o ${OUT})
bad_input(omega_ratio_with_constant_pulse "--omega-ratio = 3 is invalid: only with a sine pulse"
          simulate --pulse constant --duration 1 --omega-ratio 3 -o ${OUT})
bad_input(one_point_axis_drops_hi "--omega-ratio-range = 1 10 is invalid: LO = HI when --omega-ratio-points is 1"
          sweep --config ${CFG} -o ${OUT} --omega-ratio-points 1)
bad_input(kmin_ratios_without_adaptive "--kmin-ratios = 0.3 is invalid: only with 'adaptive' among --anchorages"
          sweep --config ${FREE} -o ${OUT} --kmin-ratios 0.3)
bad_input(theta_f_ratios_without_constant "--theta-f-ratios = 0.5 is invalid: only with 'constant' among --anchorages"
          sweep -o ${OUT} --anchorages free --theta-f-ratios 0.5)
bad_input(paper_dt_with_events "--paper-dt = 0.001 is invalid: only with --method paper" sweep --config ${CFG} -o ${OUT} --paper-dt 0.001)
bad_input(grid_option_for_simulate "--omega-ratio-range = 1 2 is invalid: an option of sweep and info only"
          simulate --config ${CFG} --omega-ratio-range 1 2 -o ${OUT})

# Command words and counts.
bad_input(misspelled_subcommand "'swep' is not a command of rocksweep: one of sweep, merge, simulate, info, design, basin, suite, risk" swep --config ${CFG} -o ${OUT})
bad_input(no_subcommand "a command is required: one of sweep, merge, simulate, info, design, basin, suite, risk" --config ${CFG})
bad_input(simulate_option_for_sweep "'--anchorage' is not an option of rocksweep sweep" sweep --config ${CFG} -o ${OUT} --anchorage free)
bad_input(sweep_pulse_family "--pulse = sine is invalid: not a known word; allowed: one of one-sine, n-sine, cycloidal-a"
          sweep --config ${CFG} -o ${OUT} --pulse sine)
bad_input(cycles_without_cycled_family "--cycles = 3 is invalid: only with --pulse n-sine or cycloidal-c \\(here --pulse rectangle\\)"
          sweep --config ${CFG} -o ${OUT} --pulse rectangle --cycles 3)
bad_input(phase_without_sine_family "--phase = 1 is invalid: only with --pulse one-sine or n-sine \\(here --pulse ricker\\)"
          sweep --config ${CFG} -o ${OUT} --pulse ricker --phase 1)
bad_input(option_given_twice "--mass is invalid: 2 values given; allowed: one value" sweep --config ${CFG} -o ${OUT} --mass 1 --mass 2)
bad_input(range_with_three_values "--omega-ratio-range is invalid: 3 values given; allowed: 2 values"
          sweep --config ${CFG} -o ${OUT} --omega-ratio-range 1 2 3)

# Memory: estimated and refused before anything is allocated.
bad_input(grid_beyond_memory "--omega-ratio-points = 100000 is invalid: .* 7e10 cells would need about 3.15 TB, more than half of this machine's"
          sweep --config ${CFG} -o ${OUT} --omega-ratio-points 100000 --amplitude-ratio-points 100000)
# A suite's rank 0 holds one scenario's products at the end, whatever the number of runs.
bad_input(suite_products_beyond_memory "--radius-points = 100000 is invalid: the products \\(overturning spectra, fragility\\) of 1e10 block sizes and slendernesses would need about [0-9.]+ TB"
          suite --config ${CFG} -o ${OUT} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --radius-range 0.5 3
          --radius-points 100000 --alpha-range 0.15 0.25 --alpha-points 100000)
bad_input(history_beyond_memory "--output-dt = 1e-5 is invalid: with --t-end 1000000 s, a history of 1e11 samples would need about [0-9.]+ TB"
          simulate -o ${OUT} --t-end 1e6 --output-dt 1e-5)

# Config files: the file itself.
bad_input_empty(config_empty_name "--config = \"\" is invalid: an empty file name" sweep --config EMPTY -o ${OUT})
bad_input(config_directory "--config = .* is invalid: a directory" sweep --config ${B} -o ${OUT})
function(bad_config name regex text)
  file(WRITE ${B}/${name}.toml "${text}")
  bad_input(config_${name} "--config = .*${name}.toml is invalid: line ${regex}" sweep --config ${B}/${name}.toml -o ${OUT})
endfunction()
bad_config(duplicate_key "3: key 'mass' is set twice \\(first on line 2\\)" "half-width = 0.3\nmass = 1\nmass = 2\n")
bad_config(duplicate_across_tables "3: key 'mass' is set twice \\(first on line 1\\)" "mass = 1\n[block]\nmass = 2\n")
# CMake writes no raw bytes above 127: printf makes the byte-order mark.
add_test(NAME cli.bad_input.config_bom_in_key
         COMMAND bash -c "printf 'mass = 1\\nhalf\\xEF\\xBB\\xBFwidth = 0.3\\n' > ${B}/bom_in_key.toml && exec \"$0\" \"$@\""
                 ${EXPECT} 2 "bom_in_key.toml is invalid: line 2: expected '=' after a key, found a byte-order mark \\(U\\+FEFF\\)"
                 ${OUT} -- ${RS} sweep --config ${B}/bom_in_key.toml -o ${OUT})
string(ASCII 1 CTRL)
bad_config(control_in_key "1: expected '=' after a key, found byte 0x01" "mass${CTRL}x = 1\n")
bad_config(unknown_table "2: table \\[foo\\] is not one of rocksweep's: \\[sweep\\], \\[merge\\], \\[simulate\\], \\[info\\], \\[design\\], \\[basin\\], \\[suite\\], \\[risk\\], \\[synth\\], \\[block\\]"
           "mass = 1\n[foo]\n")
bad_config(misplaced_underscore "1: '3__361' is not a number \\(an underscore must sit between two digits\\)" "mass = 3__361\n")
bad_config(unclosed_array "2: an array without its closing '\\]'" "mass = 1\nkmin-ratios = [0.5,\n 0.1\n")
bad_config(empty_array "1: an empty array" "anchorages = []\n")
bad_config(unquoted_string "1: 'nonlinear' is not a value \\(a string needs quotes; dates are not used by rocksweep\\)" "equations = nonlinear\n")
file(WRITE ${B}/command_key_at_top.toml "mass = 1000\nduration = 1\n")
bad_input(config_command_key_at_top "config key 'duration' is an option of rocksweep simulate: put it in the config's \\[simulate\\] table"
          simulate --config ${B}/command_key_at_top.toml -o ${OUT})
bad_config(inline_table "1: inline tables" "block = { mass = 1 }\n")

# Valid TOML that CLI11's reader refused reads as the flat config does: `info` prints the same.
file(WRITE ${B}/smatteo_tables.toml [=[
# S. Matteo as configs/smatteo.toml, in tables, with multi-line arrays and underscores.
[block]
"half-width" = 0.30
half-height = 1.36  # m
mass = 3_361.0
gravity = 9.81
equations = 'nonlinear'

[anchorage]
strength-ratio = 0.4
anchorages = [
  "free",
  "constant",  # Figs. 8-11
  "adaptive",
]
theta-f-ratios = [1.0, 0.5,
                  0.3333333333333333, 0.25]
kmin-ratios = [0.5, 0.1]
adaptive-theta-f-ratio = 1.0
adaptive-break = "angle"

[grid]
omega-ratio-range = [1.0, 10.0]
omega-ratio-points = 181
amplitude-ratio-range = [1.0, 22.0]
amplitude-ratio-points = 2_1_1

[numerics]
method = "events"
steps-per-period = 48
impact-threshold = 1e-3

[sweep]
chunk = 256
]=])
add_test(NAME cli.config_tables_read_as_flat
         COMMAND bash -c "diff <(\"$0\" info --config \"$1\") <(\"$0\" info --config \"$2\")" ${RS} ${CFG} ${B}/smatteo_tables.toml)
add_test(NAME cli.config_bom_at_start_is_skipped
         COMMAND bash -c "printf '\\xEF\\xBB\\xBF' | cat - \"$1\" > \"$2\" && diff <(\"$0\" info --config \"$1\") <(\"$0\" info --config \"$2\")"
                 ${RS} ${CFG} ${B}/smatteo_bom.toml)
# The config stored in every output (/provenance/config, every default spelled out) reads back.
add_test(NAME cli.provenance_config_reads_back
         COMMAND bash -c "\"$0\" info --config \"$1\" --omega-ratio-points 3 --amplitude-ratio-points 3 > \"$2.want\" &&
                          rm -f \"$2.h5\" && \"$0\" sweep --config \"$1\" --omega-ratio-points 3 --amplitude-ratio-points 3 -q -o \"$2.h5\" 2>/dev/null &&
                          /usr/bin/python3 -c \"import h5py,sys; f=h5py.File(sys.argv[1]); c=f['provenance'].attrs['config']; open(sys.argv[2],'w').write(c.decode() if isinstance(c,bytes) else str(c))\" \"$2.h5\" \"$2.toml\" &&
                          diff \"$2.want\" <(\"$0\" info --config \"$2.toml\")"
                 ${RS} ${CFG} ${B}/provenance)
# Two values that differ beyond 6 digits are two scenarios, with names that tell them apart.
add_test(NAME cli.close_kmin_ratios_are_distinct_scenarios
         COMMAND ${RS} info --config ${CFG} --anchorages adaptive --kmin-ratios 0.1 0.1000001)
set_tests_properties(cli.close_kmin_ratios_are_distinct_scenarios PROPERTIES
  PASS_REGULAR_EXPRESSION "2 scenarios.*adaptive_rho0.1 +adaptive.*adaptive_rho0.1000001 +adaptive")
add_test(NAME cli.version_on_stdout COMMAND bash -c "out=$(\"$0\" --version 2>/dev/null) && [[ $out == 'rocksweep '[0-9]* ]]" ${RS})

# rocksweep suite: its own options, and the spectra options it would otherwise ignore.
set(SUITE ${PROJECT_SOURCE_DIR}/configs/records_suite.csv)
bad_input(suite_measure "--intensity-measure = psa is invalid: not a known word; allowed: one of pga, pgv, pga-ratio, scale, sa, pfa"
          suite --config ${CFG} --suite ${SUITE} --intensity-measure psa -o ${OUT})
# Floors and Sa (docs/suite.md, "Floors"): the option as written, the value, the range.
bad_input(suite_floor_damping "--floor = f2: 0.5 1.2 1 is invalid: damping ratios 0 <= zeta < 1 \\(0.5 1.2 1\\)"
          suite --config ${CFG} --suite ${SUITE} --floor "f2: 0.5 1.2 1" -o ${OUT})
bad_input(suite_floor_numbers "--floor = f2: 0.5 0.05 is invalid: three numbers per mode"
          suite --config ${CFG} --suite ${SUITE} --floor "f2: 0.5 0.05" -o ${OUT})
bad_input(suite_floor_twice "--floor = f2 is invalid: distinct names \\(a floor is listed twice\\)"
          suite --config ${CFG} --suite ${SUITE} --floor "f2: 0.5 0.05 1" "f2: 0.3 0.05 1" -o ${OUT})
bad_input(suite_sa_period "--sa-period = 0 is invalid: out of range; allowed: a number in \\[0.001, 100\\] s"
          suite --config ${CFG} --suite ${SUITE} --intensity-measure sa --sa-period 0 -o ${OUT})
bad_input(design_two_floors "--floor = 2 floors is invalid: one --floor with design --suite"
          design --config ${CFG} --suite ${SUITE} --floor ground "f2: 0.5 0.05 1" -o ${OUT})
bad_input(design_floor_without_suite "--floor = f2: 0.5 0.05 1 is invalid: an option of design --suite"
          design --config ${CFG} --floor "f2: 0.5 0.05 1" -o ${OUT})
bad_input(simulate_floor_without_record "--floor = f2: 0.5 0.05 1 is invalid: only with --record"
          simulate --config ${CFG} --floor "f2: 0.5 0.05 1" -o ${OUT}.csv)
bad_input(suite_missing "--suite = \\(not given\\) is invalid: .*a suite of records \\(CSV\\), or --synthetic-count N" suite --config ${CFG} -o ${OUT})
bad_input(suite_no_such_file "--suite = /no/such.csv is invalid: no such file" suite --config ${CFG} --suite /no/such.csv -o ${OUT})
bad_input(suite_refine "--refine = 8 is invalid: 0 for suite" suite --config ${CFG} --suite ${SUITE} --refine 8 -o ${OUT})
bad_input(suite_spectra_grid "--omega-ratio-points = 5 is invalid: an option of sweep; the suite's ground motions are its records"
          suite --config ${CFG} --suite ${SUITE} --omega-ratio-points 5 -o ${OUT})
bad_input(suite_radius_points "--radius-points = 3 is invalid: 1 without --radius-range"
          suite --config ${CFG} --suite ${SUITE} --radius-points 3 -o ${OUT})
bad_input(suite_zero_level "--intensity-range = 0 is invalid: out of range; allowed: a number in \\(0, 1000\\]"
          suite --config ${CFG} --suite ${SUITE} --intensity-range 0 1 -o ${OUT})
bad_input(suite_reversed_radii "--radius-range = 2 1 is invalid: LO <= HI"
          suite --config ${CFG} --suite ${SUITE} --radius-range 2 1 --radius-points 3 -o ${OUT})
bad_input(suite_damage_state "--damage-states = -1 is invalid: out of range; allowed: a number in \\(0, 1000\\]"
          suite --config ${CFG} --suite ${SUITE} --damage-states -1 -o ${OUT})
bad_input(suite_alpha_points "--alpha-points = 4 is invalid: 1 without --alpha-range"
          suite --config ${CFG} --suite ${SUITE} --alpha-points 4 -o ${OUT})
bad_input(suite_squat_alpha "--alpha-range = 0.5 1 is invalid: angles below 0.9553 rad, where Housner's e"
          suite --config ${CFG} --suite ${SUITE} --alpha-range 0.5 1 --alpha-points 3 -o ${OUT})
bad_input(suite_alpha_degrees "--alpha-range = 10 is invalid: out of range; allowed: a number in \\[0.0001, 1.5708\\] rad"
          suite --config ${CFG} --suite ${SUITE} --alpha-range 10 20 --alpha-points 3 -o ${OUT})

# Parameter axes (--axis): the form, the name, the range, twice, a pulse without a phase, the
# option the axis replaces, a combination that makes no block, a command with axes of its own.
bad_input(axis_unknown "--axis = colour=1:2:3 is invalid: an axis named one of phase_rad, vertical_g"
          sweep --config ${CFG} -o ${OUT} --axis colour=1:2:3)
bad_input(axis_form "--axis = phase_rad=0:1 is invalid: NAME=LO:HI:POINTS or NAME=V1,V2,..."
          sweep --config ${CFG} -o ${OUT} --axis phase_rad=0:1)
bad_input(axis_range "--axis = vertical_g=0:1.5:3 is invalid: vertical_g values in \\[-0.99, 0.99\\]"
          sweep --config ${CFG} -o ${OUT} --axis vertical_g=0:1.5:3)
bad_input(axis_twice "--axis = phase_rad=1,2 is invalid: one axis per parameter \\(phase_rad is given twice\\)"
          sweep --config ${CFG} -o ${OUT} --axis phase_rad=0,1 --axis phase_rad=1,2)
bad_input(axis_family "--axis = phase_rad=0,1 is invalid: phase_rad only with --pulse one-sine or n-sine \\(here ricker\\)"
          sweep --config ${CFG} -o ${OUT} --pulse ricker --axis phase_rad=0,1)
bad_input(axis_and_option "--phase = 0.5 is invalid: not together with --axis phase_rad=0,1"
          sweep --config ${CFG} -o ${OUT} --phase 0.5 --axis phase_rad=0,1)
bad_input(axis_combination "--axis = alpha_rad=0.1,0.3 restitution=0.9 is invalid: 0 < e <= Housner's value 0.869.* \\(at alpha_rad = 0.3, restitution = 0.9"
          sweep --config ${CFG} -o ${OUT} --axis alpha_rad=0.1,0.3 --axis restitution=0.9)
bad_input(axis_suite "--axis = phase_rad=0,1 is invalid: only with sweep, info and merge \\(suite has axes of its own\\)"
          suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv -o ${OUT} --axis phase_rad=0,1)
bad_input(axis_theta_f_and_stiffness "--axis = stiffness_n_m=1e4,1e5 is invalid: not together with --axis theta_f_ratio=0.5,1 \\(K fixes theta_f"
          sweep --config ${CFG} -o ${OUT} --axis theta_f_ratio=0.5,1 --axis stiffness_n_m=1e4,1e5)
bad_input(axis_kmin_without_adaptive "--axis = kmin_ratio=0.1,1 is invalid: an adaptive anchorage among --anchorages"
          sweep --config ${CFG} -o ${OUT} --anchorages free constant --axis kmin_ratio=0.1,1)
bad_input(axis_and_typed_list "--theta-f-ratios = 1 0.5 is invalid: not together with --axis theta_f_ratio=0.25:2:8"
          sweep --config ${CFG} -o ${OUT} --theta-f-ratios 1 0.5 --axis theta_f_ratio=0.25:2:8)
bad_input(refine_axes_unknown "--refine-axes = phase_rad omega_ratio is invalid: two axes of the grid: amplitude_ratio, omega_ratio"
          sweep --config ${CFG} -o ${OUT} --refine 8 --refine-axes phase_rad omega_ratio)
bad_input(refine_axes_without_refine "--refine-axes = amplitude_ratio omega_ratio is invalid: only with --refine STRIDE"
          sweep --config ${CFG} -o ${OUT} --refine-axes amplitude_ratio omega_ratio)
bad_input(axis_family_without_phase "--axis = pulse_family=one-sine,ricker is invalid: families that take a phase and a vertical pulse \\(one-sine, n-sine\\) with --axis phase_rad=0,1 \\(ricker does not\\)"
          sweep --config ${CFG} -o ${OUT} --axis pulse_family=one-sine,ricker --axis phase_rad=0,1)
bad_input(axis_family_and_pulse "--pulse = ricker is invalid: not together with --axis pulse_family=one-sine,ricker"
          sweep --config ${CFG} -o ${OUT} --pulse ricker --axis pulse_family=one-sine,ricker)
bad_input(period_and_omega_ratio "--omega-ratio-range = 1 5 is invalid: not together with --period-range 0.2 2 \\(it replaces the ratio axis\\)"
          sweep --config ${CFG} -o ${OUT} --period-range 0.2 2 --omega-ratio-range 1 5)
bad_input(pga_points_alone "--pga-points = 5 is invalid: only with --pga-range LO HI"
          sweep --config ${CFG} -o ${OUT} --pga-points 5)
bad_input(period_suite "--period-range = 0.2 2 is invalid: only with sweep, info and merge \\(suite has axes of its own\\)"
          suite --config ${CFG} --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv -o ${OUT} --period-range 0.2 2)
