stepdeck_add_test(tst_cliarguments SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cliarguments.cpp
  LIBS stepdeck_cli LABELS unit)
# stepdeck-cli run PROGRAM (issue 20): before anything moves, and what a run prints (E-LAB).
stepdeck_add_test(tst_cli_run SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_run.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/CliRunRig.h LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_run stepdeck-cli)
# stepdeck-cli run PROGRAM on every simulator: order, one motion at a time, dwell, signal,
# refusal and --from-line, M66.
stepdeck_add_test(tst_cli_run_devices SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_run_devices.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/CliRunRig.h LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_run_devices stepdeck-cli)
# Every shipped example (docs/examples) runs to its end on its simulator (issue 28).
stepdeck_add_test(tst_cli_examples SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_examples.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/CliRunRig.h LABELS integration TIMEOUT 600
                  SPLIT exampleProgram_onItsSimulator_runsToItsEnd
                        exampleMachine_onItsSimulators_referencesAndRuns)
stepdeck_test_depends(tst_cli_examples stepdeck-cli)
stepdeck_test_definitions(tst_cli_examples STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# stepdeck-cli move and status on boards that answer as the manual allows: an SMC-IC4 that
# refuses input polls while it moves, an E-LAB board that reports motion the host did not
# command (issue 28).
stepdeck_add_test(tst_cli_devices SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_devices.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/CliRunRig.h LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_devices stepdeck-cli)
