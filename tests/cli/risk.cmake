# rocksweep risk (docs/risk.md): a small S. Matteo suite at PGA levels, then the risk at the
# illustrative site from the plain and the OpenQuake curve; bad hazard curves and a hazard of
# another measure than the suite's refused with one line, exit status 2, nothing written.
# Included from CMakeLists.txt, which defines RS, EXPECT.
set(RISK_DIR ${CMAKE_CURRENT_BINARY_DIR}/risk)
set(RISK_SUITE ${RISK_DIR}/suite.h5)
file(MAKE_DIRECTORY ${RISK_DIR})
add_test(NAME cli.risk.make_suite
         COMMAND ${RS} suite --config ${PROJECT_SOURCE_DIR}/configs/suite_smatteo.toml
                 --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --intensity-points 6
                 --radius-range 1.392695228684288 1.392695228684288 --radius-points 1 --quiet --overwrite -o ${RISK_SUITE})
set_tests_properties(cli.risk.make_suite PROPERTIES FIXTURES_SETUP risk_suite TIMEOUT 300 PROCESSORS 2)

add_test(NAME cli.risk.plain_and_openquake_agree
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/risk.sh ${RS} ${RISK_SUITE} ${PROJECT_SOURCE_DIR} ${RISK_DIR}/run)
set_tests_properties(cli.risk.plain_and_openquake_agree PROPERTIES FIXTURES_REQUIRED risk_suite TIMEOUT 120)

# risk_refused(NAME REGEX ARGS...): risk on the small suite must fail with exit status 2 and REGEX.
function(risk_refused name regex)
  add_test(NAME cli.risk.${name} COMMAND ${EXPECT} 2 "${regex}" ${RISK_DIR}/bad.h5 -- ${RS} risk ${ARGN} -o ${RISK_DIR}/bad.h5)
  set_tests_properties(cli.risk.${name} PROPERTIES FIXTURES_REQUIRED risk_suite)
endfunction()
file(WRITE ${RISK_DIR}/pgv.csv "PGV [m/s],annual_rate [1/yr]\n0.1,1e-2\n0.5,1e-4\n")
file(WRITE ${RISK_DIR}/rising.csv "PGA [g],annual_rate [1/yr]\n0.1,1e-2\n0.2,2e-2\n0.4,1e-4\n")
file(WRITE ${RISK_DIR}/unit.csv "PGA [m/s],annual_rate [1/yr]\n0.1,1e-2\n0.5,1e-4\n")
file(WRITE ${RISK_DIR}/no_time.csv "#,,,,,\"kind='mean', imt='PGA'\"\nlon,lat,depth,poe-0.1,poe-0.5\n11.2,43.7,-0.1,0.4,0.01\n")
risk_refused(measure_mismatch "--hazard = .*pgv.csv \\(PGV\\) is invalid: a hazard curve of the suite's intensity measure, pga_g"
             --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/pgv.csv)
risk_refused(rising_curve "rising.csv line 3: rate 0.02 above the previous 0.01 is invalid: a rate of exceedance that does not rise"
             --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/rising.csv)
risk_refused(unit "unit m/s for an acceleration is invalid: .*g, m/s\\^2 or cm/s\\^2"
             --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/unit.csv)
risk_refused(missing_investigation_time "no_time.csv line 1 is invalid: OpenQuake's first line with investigation_time=T"
             --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/no_time.csv)
risk_refused(not_a_suite_file "--suite-file = .*hazard_illustrative_pga.csv is invalid: a rocksweep suite file; it is not an HDF5 file"
             --suite-file ${PROJECT_SOURCE_DIR}/configs/hazard_illustrative_pga.csv --hazard ${RISK_DIR}/pgv.csv)
risk_refused(exposure_zero "--exposure-years = 0 is invalid: out of range"
             --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/pgv.csv --exposure-years 0)

# The figure of the risk file risk.sh wrote: legible PNG and PDF (tests/scripts/check_figure.py).
set_tests_properties(cli.risk.plain_and_openquake_agree PROPERTIES FIXTURES_SETUP risk_file)
add_test(NAME cli.risk.figure
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/scripts/check_figure.py --expect ${RISK_DIR}/figure
                 -- /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/plot_risk.py ${RISK_DIR}/run/plain.h5 -o ${RISK_DIR}/figure)
set_tests_properties(cli.risk.figure PROPERTIES FIXTURES_REQUIRED risk_file TIMEOUT 120)

# Risk-based design: the criterion is the annual rate at the site (tests/cli/design_risk.sh);
# --hazard needs --suite, and a curve of the suite's measure.
add_test(NAME cli.risk.design
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/design_risk.sh ${RS} ${PROJECT_SOURCE_DIR} ${RISK_DIR}/design)
set_tests_properties(cli.risk.design PROPERTIES TIMEOUT 180 PROCESSORS 2)
add_test(NAME cli.risk.design_hazard_needs_suite
         COMMAND ${EXPECT} 2 "--hazard = .*pgv.csv is invalid: an option of design --suite" ${RISK_DIR}/bad_design.h5 --
                 ${RS} design --config ${PROJECT_SOURCE_DIR}/configs/design.toml --hazard ${RISK_DIR}/pgv.csv -o ${RISK_DIR}/bad_design.h5)
add_test(NAME cli.risk.design_measure_mismatch
         COMMAND ${EXPECT} 2 "--hazard = .*pgv.csv \\(PGV\\) is invalid: a hazard curve of the suite's intensity measure, pga_g"
                 ${RISK_DIR}/bad_design.h5 -- ${RS} design --config ${PROJECT_SOURCE_DIR}/configs/design.toml
                 --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --hazard ${RISK_DIR}/pgv.csv -o ${RISK_DIR}/bad_design.h5)
add_test(NAME cli.risk.model_option_refused
         COMMAND ${EXPECT} 2 "--mass = 3 is invalid: an option of the commands that run a model; risk reads the suite file"
                 ${RISK_DIR}/bad.h5 -- ${RS} --mass 3 risk --suite-file ${RISK_SUITE} --hazard ${RISK_DIR}/pgv.csv -o ${RISK_DIR}/bad.h5)
set_tests_properties(cli.risk.model_option_refused PROPERTIES FIXTURES_REQUIRED risk_suite)

# A suite on several floors (scenarios SCENARIO@FLOOR): the risk of each, in the suite's order
# (tests/cli/risk_floors.sh).
add_test(NAME cli.risk.floors
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/risk_floors.sh ${RS} ${PROJECT_SOURCE_DIR} ${RISK_DIR}/floors)
set_tests_properties(cli.risk.floors PROPERTIES TIMEOUT 180 PROCESSORS 2)

# Hazard curves of SA(T) are 5 %-damped: a suite's Sa of another damping is refused, by risk
# (the suite file's) and by design (its --sa-damping), before anything is written.
file(WRITE ${RISK_DIR}/sa.csv "SA(0.5) [g],annual_rate [1/yr]\n0.1,1e-2\n1.0,1e-4\n")
add_test(NAME cli.risk.make_sa_suite
         COMMAND ${RS} suite --config ${PROJECT_SOURCE_DIR}/configs/suite_smatteo.toml
                 --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --intensity-measure sa --sa-period 0.5
                 --sa-damping 0.02 --intensity-range 0.1 1.5 --intensity-points 3 --anchorages free
                 --radius-range 1.392695228684288 1.392695228684288 --radius-points 1 --quiet --overwrite
                 -o ${RISK_DIR}/suite_sa2.h5)
set_tests_properties(cli.risk.make_sa_suite PROPERTIES FIXTURES_SETUP risk_sa_suite TIMEOUT 120)
add_test(NAME cli.risk.sa_damping_refused
         COMMAND ${EXPECT} 2 "--hazard = .*sa.csv \\(SA\\(0.5\\)\\) is invalid: a hazard curve of the suite's Sa: SA\\(T\\) curves are 5 %-damped, the suite's Sa is zeta = 0.02"
                 ${RISK_DIR}/bad.h5 -- ${RS} risk --suite-file ${RISK_DIR}/suite_sa2.h5 --hazard ${RISK_DIR}/sa.csv -o ${RISK_DIR}/bad.h5)
set_tests_properties(cli.risk.sa_damping_refused PROPERTIES FIXTURES_REQUIRED risk_sa_suite)
add_test(NAME cli.risk.design_sa_damping_refused
         COMMAND ${EXPECT} 2 "--sa-damping = 0.02 is invalid: 0.05 with an SA\\(T\\) hazard curve .*sa.csv\\): such curves are 5 %-damped"
                 ${RISK_DIR}/bad_design.h5 -- ${RS} design --config ${PROJECT_SOURCE_DIR}/configs/design.toml
                 --suite ${PROJECT_SOURCE_DIR}/configs/records_suite.csv --intensity-measure sa --sa-period 0.5
                 --sa-damping 0.02 --hazard ${RISK_DIR}/sa.csv -o ${RISK_DIR}/bad_design.h5)
# Its figure: the rate per anchorage and floor (scripts/plot_risk_floors.py), legible PNG and PDF.
set_tests_properties(cli.risk.floors PROPERTIES FIXTURES_SETUP risk_floors_file)
add_test(NAME cli.risk.floors_figure
         COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/scripts/check_figure.py --expect ${RISK_DIR}/floors_figure
                 -- /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/plot_risk_floors.py ${RISK_DIR}/floors/risk_floors.h5
                 -o ${RISK_DIR}/floors_figure)
set_tests_properties(cli.risk.floors_figure PROPERTIES FIXTURES_REQUIRED risk_floors_file TIMEOUT 120)
